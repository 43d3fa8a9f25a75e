//! Regenerates the committed outline data `data/glyphs/*.csv` from DejaVu Sans.
//!
//! ```sh
//! cargo run -p trig-fit --example extract_glyphs -- data/glyphs
//! ```
//!
//! Reads `/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf` (Debian package
//! `fonts-dejavu-core`; its version is read with `dpkg-query`), takes the
//! outline of each glyph with `ttf-parser`, scales it to [`PX_PER_EM`] pixels
//! per em (y up, origin at the glyph origin), flattens every quadratic of each
//! contour into [`PIECES`] chords and samples the contour at equal arc-length
//! steps: `n = round(L / SPACING)` points for a contour of length `L`, spacing
//! `L / n`, the first point being the contour's first on-curve point. Points
//! are written with three decimals. The tests never run this: they read the
//! committed files.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

use ttf_parser::{Face, OutlineBuilder, name_id};

const FONT: &str = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const PACKAGE: &str = "fonts-dejavu-core";
/// Pixels per em of the sampled outline.
const PX_PER_EM: f64 = 512.0;
/// Target spacing of consecutive samples, in pixels (thesis 6.3: three pixels).
const SPACING: f64 = 3.0;
/// Chords per quadratic or cubic when measuring arc length.
const PIECES: usize = 256;

/// The glyphs: file stem, code point, Unicode name.
const GLYPHS: &[(&str, char, &str)] = &[
    ("epsilon", '\u{03B5}', "GREEK SMALL LETTER EPSILON"),
    ("delta", '\u{03B4}', "GREEK SMALL LETTER DELTA"),
    (
        "ain",
        '\u{0639}',
        "ARABIC LETTER AIN (isolated form, the cmap glyph)",
    ),
];

/// Collects each contour as a polyline (curves flattened).
#[derive(Debug, Default)]
struct Flatten {
    scale: f64,
    contours: Vec<Vec<(f64, f64)>>,
    current: Vec<(f64, f64)>,
}

impl Flatten {
    fn last(&self) -> (f64, f64) {
        *self.current.last().expect("move_to comes first")
    }

    fn push(&mut self, x: f32, y: f32) {
        self.current
            .push((f64::from(x) * self.scale, f64::from(y) * self.scale));
    }
}

impl OutlineBuilder for Flatten {
    fn move_to(&mut self, x: f32, y: f32) {
        self.current.clear();
        self.push(x, y);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        self.push(x, y);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let p0 = self.last();
        let (s, p1, p2) = (
            self.scale,
            (f64::from(x1), f64::from(y1)),
            (f64::from(x), f64::from(y)),
        );
        for k in 1..=PIECES {
            let t = k as f64 / PIECES as f64;
            let (a, b, c) = ((1.0 - t) * (1.0 - t), 2.0 * t * (1.0 - t), t * t);
            self.current.push((
                a * p0.0 + s * (b * p1.0 + c * p2.0),
                a * p0.1 + s * (b * p1.1 + c * p2.1),
            ));
        }
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let p0 = self.last();
        let s = self.scale;
        let (p1, p2, p3) = (
            (f64::from(x1) * s, f64::from(y1) * s),
            (f64::from(x2) * s, f64::from(y2) * s),
            (f64::from(x) * s, f64::from(y) * s),
        );
        for k in 1..=PIECES {
            let t = k as f64 / PIECES as f64;
            let u = 1.0 - t;
            let (a, b, c, d) = (u * u * u, 3.0 * t * u * u, 3.0 * t * t * u, t * t * t);
            self.current.push((
                a * p0.0 + b * p1.0 + c * p2.0 + d * p3.0,
                a * p0.1 + b * p1.1 + c * p2.1 + d * p3.1,
            ));
        }
    }

    fn close(&mut self) {
        let mut contour = std::mem::take(&mut self.current);
        // closing edge back to the start is implicit; drop a repeated start
        if contour.len() > 1 && contour.first() == contour.last() {
            contour.pop();
        }
        self.contours.push(contour);
    }
}

/// `n = round(L / SPACING)` points at equal arc-length steps around a closed polyline.
fn resample(poly: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let closed: Vec<(f64, f64)> = poly.iter().chain(poly.first()).copied().collect();
    let dist = |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).hypot(a.1 - b.1);
    let mut cumulative = vec![0.0];
    for w in closed.windows(2) {
        cumulative.push(cumulative.last().expect("nonempty") + dist(w[0], w[1]));
    }
    let total = *cumulative.last().expect("nonempty");
    let n = ((total / SPACING).round() as usize).max(4);
    let step = total / n as f64;
    let mut out = Vec::with_capacity(n);
    let mut seg = 0;
    for j in 0..n {
        let target = j as f64 * step;
        while cumulative[seg + 1] < target {
            seg += 1;
        }
        let len = cumulative[seg + 1] - cumulative[seg];
        let f = if len > 0.0 {
            (target - cumulative[seg]) / len
        } else {
            0.0
        };
        let (a, b) = (closed[seg], closed[seg + 1]);
        out.push((a.0 + f * (b.0 - a.0), a.1 + f * (b.1 - a.1)));
    }
    out
}

fn package_version() -> String {
    let out = Command::new("dpkg-query")
        .args(["-W", "-f=${Version}", PACKAGE])
        .output()
        .expect("dpkg-query is needed to record the font package version");
    assert!(out.status.success(), "{PACKAGE} is not installed");
    String::from_utf8(out.stdout).expect("utf-8 version")
}

fn main() {
    let dir = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("data/glyphs"), PathBuf::from);
    let data = std::fs::read(FONT).expect("read the DejaVu Sans font file");
    let face = Face::parse(&data, 0).expect("parse the font");
    let font_version = face
        .names()
        .into_iter()
        .find(|n| n.name_id == name_id::VERSION && n.is_unicode())
        .and_then(|n| n.to_string())
        .expect("the font's version string");
    let package = package_version();
    let scale = PX_PER_EM / f64::from(face.units_per_em());
    for (stem, ch, uname) in GLYPHS {
        let gid = face.glyph_index(*ch).expect("glyph in the font");
        let mut builder = Flatten {
            scale,
            ..Flatten::default()
        };
        face.outline_glyph(gid, &mut builder).expect("an outline");
        let mut text = String::new();
        let _ = writeln!(
            text,
            "# trig-audit outline data (regenerate, never edit by hand)"
        );
        let _ = writeln!(
            text,
            "# glyph: U+{:04X} {uname} ({ch}), glyph id {}",
            *ch as u32, gid.0
        );
        let _ = writeln!(
            text,
            "# font: {FONT}, name-table version \"{font_version}\", Debian package {PACKAGE} {package}"
        );
        let _ = writeln!(
            text,
            "# scale: {PX_PER_EM} px per em = font units x {PX_PER_EM}/{}; y up; origin at the glyph origin",
            face.units_per_em()
        );
        let _ = writeln!(
            text,
            "# sampling: each closed contour flattened ({PIECES} chords per curve), n = round(L/{SPACING}) points at equal arc-length steps L/n, starting at the contour's first on-curve point; 3 decimals"
        );
        let _ = writeln!(
            text,
            "# regenerate: cargo run -p trig-fit --example extract_glyphs -- data/glyphs"
        );
        let _ = writeln!(text, "contour,x,y");
        for (k, contour) in builder.contours.iter().enumerate() {
            for (x, y) in resample(contour) {
                let _ = writeln!(text, "{k},{x:.3},{y:.3}");
            }
        }
        let path = Path::new(&dir).join(format!("{stem}.csv"));
        std::fs::write(&path, text).expect("write the data file");
        println!("{}: {} contour(s)", path.display(), builder.contours.len());
    }
}
