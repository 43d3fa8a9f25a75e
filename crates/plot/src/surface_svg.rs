//! The SVG of a [`SurfaceFigure`]: an orthographic picture from the
//! figure's view, the facets (two triangles per grid cell) filled with
//! Lambert shading — brightness `0.3 + 0.7·|n·l|` for the unit normal `n`
//! and a light `l` from the viewer's side and above — and drawn far to near
//! (the painter's algorithm, by the mean depth of each triangle); then the
//! control nets over them (red polylines along the net rows and columns,
//! red circles at the points, as the thesis draws them), and the title.
//! 160 mm wide, coordinates in millimetres to 0.01 mm.

use std::fmt::Write;

use crate::error::Result;
use crate::surface::{SurfaceFigure, dot, normal};

/// The width of the picture, mm.
const WIDTH: f64 = 160.0;

/// The margin around the drawing, mm.
const MARGIN: f64 = 6.0;

/// The height of the title line, mm.
const TITLE: f64 = 9.0;

/// The radius of a control point's circle, mm.
const POINT: f64 = 0.9;

/// One triangle to fill: its corners on the screen, depth, colour.
struct Facet {
    corners: [[f64; 2]; 3],
    depth: f64,
    rgb: (u8, u8, u8),
}

/// A coordinate to 0.01 mm.
fn c(x: f64) -> String {
    let r = (x * 100.0).round() / 100.0;
    if r == 0.0 { "0".into() } else { r.to_string() }
}

/// Escapes text for SVG.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Draws `figure`; returns the SVG text.
pub fn surface_svg(figure: &SurfaceFigure) -> Result<String> {
    figure.check()?;
    let view = figure.view;
    let [_, _, towards] = view.axes();
    let light = {
        let l = [towards[0], towards[1], towards[2] + 0.8];
        let n = dot(&l, &l).sqrt();
        l.map(|x| x / n)
    };
    // the screen box of everything drawn
    let projected: Vec<[f64; 3]> = figure.points().map(|p| view.project(p)).collect();
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for p in &projected {
        x0 = x0.min(p[0]);
        x1 = x1.max(p[0]);
        y0 = y0.min(p[1]);
        y1 = y1.max(p[1]);
    }
    let span = (x1 - x0).max(y1 - y0).max(1e-12);
    let scale = (WIDTH - 2.0 * MARGIN) / span.max((x1 - x0).max(1e-12));
    let top = if figure.title.is_empty() {
        MARGIN
    } else {
        MARGIN + TITLE
    };
    let height = top + (y1 - y0) * scale + MARGIN;
    let screen = |p: &[f64; 3]| -> [f64; 3] {
        let q = view.project(p);
        [
            MARGIN + (q[0] - x0) * scale + (WIDTH - 2.0 * MARGIN - (x1 - x0) * scale) / 2.0,
            top + (y1 - q[1]) * scale,
            q[2],
        ]
    };
    let mut facets = Vec::new();
    for patch in &figure.patches {
        let g = &patch.grid;
        for i in 0..g.len() - 1 {
            for j in 0..g[i].len() - 1 {
                for tri in [
                    [&g[i][j], &g[i + 1][j], &g[i + 1][j + 1]],
                    [&g[i][j], &g[i + 1][j + 1], &g[i][j + 1]],
                ] {
                    let n = normal(tri[0], tri[1], tri[2]);
                    let length = dot(&n, &n).sqrt();
                    let lambert = if length > 0.0 {
                        (dot(&n, &light) / length).abs()
                    } else {
                        1.0
                    };
                    let shade = 0.3 + 0.7 * lambert;
                    let (r, gr, b) = patch.rgb;
                    let s = |v: u8| (f64::from(v) * shade).round() as u8;
                    let corners = tri.map(&screen);
                    facets.push(Facet {
                        depth: corners.iter().map(|p| p[2]).sum::<f64>() / 3.0,
                        corners: corners.map(|p| [p[0], p[1]]),
                        rgb: (s(r), s(gr), s(b)),
                    });
                }
            }
        }
    }
    facets.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}mm\" height=\"{h}mm\" viewBox=\"0 0 {w} {h}\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n",
        w = c(WIDTH),
        h = c(height)
    );
    if !figure.title.is_empty() {
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"{}\" font-family=\"serif\" font-size=\"3.6\" text-anchor=\"middle\">{}</text>",
            c(WIDTH / 2.0),
            c(MARGIN + 4.5),
            escape(&trig_tex::unicode(&figure.title))
        );
    }
    out.push_str("<g stroke-width=\"0.08\" stroke-linejoin=\"round\">\n");
    for f in &facets {
        let (r, g, b) = f.rgb;
        let points: Vec<String> = f
            .corners
            .iter()
            .map(|p| format!("{},{}", c(p[0]), c(p[1])))
            .collect();
        let _ = writeln!(
            out,
            "<polygon points=\"{}\" fill=\"rgb({r},{g},{b})\" stroke=\"rgb({r},{g},{b})\"/>",
            points.join(" ")
        );
    }
    out.push_str("</g>\n<g fill=\"none\" stroke=\"rgb(200,30,30)\" stroke-width=\"0.3\">\n");
    for patch in &figure.patches {
        let net = &patch.net;
        let columns = net.first().map_or(0, Vec::len);
        let lines = net
            .iter()
            .cloned()
            .chain((0..columns).map(|j| net.iter().map(|row| row[j]).collect()));
        for line in lines {
            let points: Vec<String> = line
                .iter()
                .map(|p| {
                    let s = screen(p);
                    format!("{},{}", c(s[0]), c(s[1]))
                })
                .collect();
            let _ = writeln!(out, "<polyline points=\"{}\"/>", points.join(" "));
        }
        for p in net.iter().flatten() {
            let s = screen(p);
            let _ = writeln!(
                out,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>",
                c(s[0]),
                c(s[1]),
                c(POINT)
            );
        }
    }
    out.push_str("</g>\n</svg>\n");
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{PATCH_COLOURS, SurfacePatch, View};

    /// Two unit squares, one above the other: the nearer (higher, seen
    /// from above) is drawn last.
    #[test]
    fn nearer_facets_are_drawn_last_and_shaded() {
        let square = |z: f64, rgb| SurfacePatch {
            grid: vec![
                vec![[0.0, 0.0, z], [0.0, 1.0, z]],
                vec![[1.0, 0.0, z], [1.0, 1.0, z]],
            ],
            net: vec![vec![[0.0, 0.0, z], [1.0, 1.0, z]]],
            rgb,
        };
        let figure = SurfaceFigure {
            title: "two ⟪m⟫ squares".into(),
            patches: vec![square(1.0, PATCH_COLOURS[0]), square(0.0, PATCH_COLOURS[1])],
            view: View::default(),
        };
        let svg = surface_svg(&figure).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let fills: Vec<&str> = doc
            .descendants()
            .filter(|n| n.has_tag_name("polygon"))
            .map(|n| n.attribute("fill").unwrap())
            .collect();
        assert_eq!(fills.len(), 4);
        // the lower (blue) square first, the upper (orange) one over it
        assert!(
            fills[0].ends_with(&format!("{})", shade_of(PATCH_COLOURS[1].2))),
            "{fills:?}"
        );
        assert!(
            fills[3].starts_with("rgb(") && !fills[3].contains(",130,"),
            "{fills:?}"
        );
        assert!(svg.contains("two m squares"), "{svg}");
        assert_eq!(
            doc.descendants()
                .filter(|n| n.has_tag_name("circle"))
                .count(),
            4
        );
    }

    /// A flat square seen from `View::default()` is lit by `|n·l|`.
    fn shade_of(v: u8) -> u8 {
        let [_, _, t] = View::default().axes();
        let l = [t[0], t[1], t[2] + 0.8];
        let lambert = l[2] / dot(&l, &l).sqrt();
        (f64::from(v) * (0.3 + 0.7 * lambert)).round() as u8
    }
}
