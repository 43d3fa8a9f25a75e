//! The pgfplots code of a [`Picture`]: by default a fragment — a
//! `tikzpicture` to `\input` into a LaTeX document that loads `pgfplots`
//! — or a whole plain `article` around it ([`PgfOptions::standalone`]);
//! with the same frame, series, looks and legend as the SVG, coordinates
//! as floats. The axis is as wide as asked (default `\linewidth`, tick
//! and axis labels included), its height in the SVG's proportion, and an
//! equal-aspect frame keeps one data unit as long on both axes
//! (`axis equal image`). Text (title, axis labels, legend entries) is
//! marked text written by the one LaTeX writer ([`trig_tex::marked()`]:
//! formulas in math, a minus sign as math);
//! tick labels are pgfplots' own, in math.

use std::fmt::Write;

use trig_tex::{article, comment, input_note, labelled, marked, plain, text};

use crate::chart::{Look, Mark};
use crate::picture::Picture;
use crate::style::{CELL_OVERLAP, PGF_LEGEND_TWO_COLUMNS, PLOT_AREA, UNIT_MM, legend_columns};

/// How the pgfplots code is written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PgfOptions {
    /// The width of the figure, a LaTeX length (`\linewidth`, `8cm`).
    pub width: String,
    /// A whole document instead of a fragment.
    pub standalone: bool,
}

impl Default for PgfOptions {
    fn default() -> Self {
        PgfOptions {
            width: r"\linewidth".into(),
            standalone: false,
        }
    }
}

/// The packages and setup a figure needs.
pub(crate) const PACKAGES: [&str; 1] = ["pgfplots"];
pub(crate) const SETUP: [&str; 1] = [r"\pgfplotsset{compat=1.16}"];

/// A number as pgfplots reads it: plain decimals in a moderate range,
/// scientific notation beyond it.
pub(crate) fn num(v: f64) -> String {
    if v == 0.0 || (1e-4..1e6).contains(&v.abs()) {
        v.to_string()
    } else {
        format!("{v:e}")
    }
}

/// The room (ems) the labels of an axis of y range `y` take beside it:
/// the y label, the widest tick label (pgfplots' ticks step about an
/// eighth of the range), and half an x tick label beyond the right end.
fn label_room(y: (f64, f64)) -> f64 {
    let magnitude = y.0.abs().max(y.1.abs()).max(1e-300);
    let integer = magnitude.log10().floor().max(0.0) + 1.0;
    let step = (y.1 - y.0).abs() / 8.0;
    let decimals = (-step.log10().floor()).max(0.0);
    let sign = if y.0 < 0.0 { 1.0 } else { 0.0 };
    let fraction = if decimals > 0.0 { decimals + 1.0 } else { 0.0 };
    // a footnotesize digit is about 0.42 em of the text font
    3.6 + 0.42 * (integer + fraction + sign)
}

/// A length in layout units, in millimetres.
fn mm(units: f64) -> String {
    format!("{}mm", (units * UNIT_MM * 1000.0).round() / 1000.0)
}

fn colour(look: &Look) -> String {
    let (r, g, b) = look.rgb;
    format!("color={{rgb,255:red,{r};green,{g};blue,{b}}}")
}

/// The options of a plot (or legend image) drawn with `look`.
fn options(look: &Look) -> String {
    let mut o = vec![colour(look)];
    if look.opacity < 1.0 {
        o.push(format!("opacity={}", look.opacity));
    }
    match look.mark {
        Mark::Line {
            width,
            dash,
            vertices,
        } => {
            o.push(format!("line width={}", mm(width)));
            if let Some(d) = dash {
                o.push(format!("dash pattern=on {} off {}", mm(d.on), mm(d.off)));
            }
            if vertices {
                o.push(format!("mark=*, mark size={}", mm(3.0)));
            } else {
                o.push("no markers".into());
            }
        }
        Mark::Dots { radius } => {
            o.push(format!("only marks, mark=*, mark size={}", mm(radius)));
        }
        Mark::Crosses => {
            o.push(format!(
                "only marks, mark=x, mark size={}, line width={}",
                mm(5.0),
                mm(1.6)
            ));
        }
        Mark::Cell => o = vec![format!("area legend, draw=none, fill, {}", o.join(", "))],
    }
    o.join(", ")
}

impl Picture {
    /// The picture as pgfplots code (see [`PgfOptions`]).
    pub fn pgf(&self, options_of: &PgfOptions) -> String {
        let f = &self.frame;
        let what = if f.title.is_empty() {
            "trig-audit plot".to_string()
        } else {
            format!("{} (trig-audit plot)", text(&plain(&f.title)))
        };
        let mut out = input_note(
            &format!("{what}; the data is in the CSV file of the same name"),
            &PACKAGES,
            &SETUP,
        );
        if !f.caption.is_empty() {
            out.push_str(&comment(&format!("source: {}", text(&plain(&f.caption)))));
        }
        out.push_str("\\begin{tikzpicture}\n\\begin{axis}[\n");
        // column-major as in the SVG: transposed, `legend columns` counts rows
        let plain_entries: Vec<String> = self.legend().map(|(t, _)| plain(t)).collect();
        let columns = legend_columns(
            plain_entries.iter().map(String::as_str),
            PGF_LEGEND_TWO_COLUMNS,
        );
        let rows = self.legend().count().div_ceil(columns).max(1);
        let width = &options_of.width;
        let ratio = PLOT_AREA.1 / PLOT_AREA.0;
        let mut lines = Vec::new();
        if !f.title.is_empty() {
            lines.push(format!("title={{{}}},", labelled(&f.title)));
        }
        lines.extend([
            format!("xlabel={{{}}},", marked(&f.x_label)),
            format!("ylabel={{{}}},", marked(&f.y_label)),
            format!("xmin={}, xmax={},", num(f.x.0), num(f.x.1)),
            format!("ymin={}, ymax={},", num(f.y.0), num(f.y.1)),
            // the axis alone, its labels beside it within the width
            format!(
                "scale only axis, width={{{width}-{labels:.1}em}}, height={{{ratio:.3}*({width}-{labels:.1}em)}},",
                labels = label_room(f.y)
            ),
        ]);
        if f.equal_aspect {
            lines.push("axis equal image,".into());
        }
        lines.extend([
            "grid=major, grid style={black!12}, tick align=outside, scaled ticks=false,".into(),
            // a long title wraps within the axis width
            format!(
                r"title style={{font=\small, align=center, text width={{{width}-{labels:.1}em}}}}, label style={{font=\small}}, tick label style={{font=\footnotesize}},",
                labels = label_room(f.y)
            ),
            format!(
                "legend columns={rows}, transpose legend, legend cell align=left, legend style={{font=\\footnotesize, draw=none, at={{(0.5,0)}}, anchor=north, yshift=-3.2em, /tikz/every even column/.append style={{column sep=4mm}}}},"
            ),
        ]);
        for line in lines {
            let _ = writeln!(out, "  {line}");
        }
        out.push_str("]\n");
        for (entry, look) in self.legend() {
            let _ = writeln!(
                out,
                "\\addlegendimage{{{}}}\n\\addlegendentry{{{}}}",
                options(look),
                marked(entry)
            );
        }
        if f.zero_line {
            let _ = writeln!(
                out,
                "\\addplot[forget plot, black, line width={}] coordinates {{({},0) ({},0)}};",
                mm(0.8),
                num(f.x.0),
                num(f.x.1)
            );
        }
        // a cell a hair beyond its edges: no seam between neighbours
        let (hx, hy) = (
            CELL_OVERLAP * (f.x.1 - f.x.0) / PLOT_AREA.0,
            CELL_OVERLAP * (f.y.1 - f.y.0) / PLOT_AREA.1,
        );
        for s in self.series.iter().filter(|s| !s.points.is_empty()) {
            out.push_str(&comment(&text(&s.label)));
            if let (Mark::Cell, [a, b]) = (s.look.mark, &s.points[..]) {
                let mut fill = colour(&s.look).replace("color=", "fill=");
                if s.look.opacity < 1.0 {
                    let _ = write!(fill, ", fill opacity={}", s.look.opacity);
                }
                let _ = writeln!(
                    out,
                    "\\fill[{fill}] (axis cs:{},{}) rectangle (axis cs:{},{});",
                    num(a.0 - hx),
                    num(a.1 - hy),
                    num(b.0 + hx),
                    num(b.1 + hy)
                );
                continue;
            }
            let _ = writeln!(
                out,
                "\\addplot[forget plot, {}] coordinates {{",
                options(&s.look)
            );
            for chunk in s.points.chunks(4) {
                let line: Vec<String> = chunk
                    .iter()
                    .map(|(x, y)| format!("({},{})", num(*x), num(*y)))
                    .collect();
                let _ = writeln!(out, "  {}", line.join(" "));
            }
            out.push_str("};\n");
        }
        out.push_str("\\end{axis}\n\\end{tikzpicture}\n");
        if options_of.standalone {
            article(&PACKAGES, &SETUP, &out)
        } else {
            out
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart::{Frame, Series};

    #[test]
    fn numbers_are_plain_or_scientific() {
        assert_eq!(num(0.0), "0");
        assert_eq!(num(-0.25), "-0.25");
        assert_eq!(num(123456.5), "123456.5");
        assert_eq!(num(2.5e-7), "2.5e-7");
        assert_eq!(num(-3e300), "-3e300");
    }

    #[test]
    fn every_series_and_legend_entry_is_written() {
        let line = Look::line((0, 114, 178), 1.6);
        let dots = Look::marks((0, 0, 0), Mark::Dots { radius: 4.0 });
        let cell = Look {
            opacity: 0.5,
            ..Look::marks((0, 158, 115), Mark::Cell)
        };
        let p = Picture::new(
            Frame {
                title: "T & λ".into(),
                x_label: "x".into(),
                y_label: "y".into(),
                caption: String::new(),
                x: (0.0, 2.0),
                y: (-1.0, 1.0),
                zero_line: true,
                equal_aspect: false,
            },
            vec![
                Series::new("curve, piece 1", [(0.0, 0.0), (1.0, 0.5)], line).legend("curve"),
                Series::new("curve, piece 2", [(1.0, 0.5), (2.0, 1.0)], line),
                Series::new("data", [(0.0, 0.0), (2.0, 1.0)], dots).legend("data"),
                Series::new("cell", [(0.0, -1.0), (1.0, 0.0)], cell).legend("inside"),
            ],
        )
        .unwrap();
        let tex = p.pgf(&PgfOptions::default());
        assert!(tex.contains(r"title={T \& $\lambda$},"), "{tex}");
        assert!(tex.contains("xmin=0, xmax=2,"));
        assert!(
            tex.contains(
                r"scale only axis, width={\linewidth-5.3em}, height={0.629*(\linewidth-5.3em)},"
            ),
            "{tex}"
        );
        assert!(!tex.contains("axis equal image"));
        assert_eq!(tex.matches(r"\addlegendentry{").count(), 3);
        assert_eq!(tex.matches(r"\addplot[forget plot").count(), 3 + 1);
        assert!(tex.contains("  (1,0.5) (2,1)\n"));
        assert!(tex.contains("only marks, mark=*, mark size=0.8mm"));
        // a cell a hair beyond its corners (0.3 units of 696 across 2)
        assert!(tex.contains(r"\fill[fill={rgb,255:red,0;green,158;blue,115}, fill opacity=0.5] (axis cs:-0.000862"), "{tex}");
        assert!(tex.ends_with("\\end{axis}\n\\end{tikzpicture}\n"));
        assert!(
            tex.starts_with("% T \\& $\\lambda$ (trig-audit plot)"),
            "{tex}"
        );
    }

    #[test]
    fn width_title_standalone_minus_and_equal_aspect() {
        let dashed =
            Look::line((0, 0, 0), 1.6).dashed(Some(crate::chart::Dash { on: 7.0, off: 4.0 }));
        let frame = Frame {
            title: String::new(),
            x_label: "x".into(),
            y_label: "y".into(),
            caption: String::new(),
            x: (0.0, 1.0),
            y: (0.0, 1.0),
            zero_line: false,
            equal_aspect: true,
        };
        let p = Picture::new(
            frame,
            vec![
                Series::new("legend only", [], dashed).legend("λ = −1"),
                Series::new("curve", [(0.0, 0.0), (1.0, 1.0)], dashed),
            ],
        )
        .unwrap();
        let options = PgfOptions {
            width: "8cm".into(),
            standalone: true,
        };
        let tex = p.pgf(&options);
        assert!(
            tex.starts_with(
                "\\documentclass{article}\n\\usepackage{pgfplots}\n\\pgfplotsset{compat=1.16}\n"
            ),
            "{tex}"
        );
        assert!(
            tex.contains("width={8cm-") && tex.contains("axis equal image,"),
            "{tex}"
        );
        assert!(!tex.contains("title={"), "{tex}");
        assert!(tex.contains(r"\addlegendentry{$\lambda$ = $-$1}"), "{tex}");
        assert!(tex.contains("dash pattern=on 1.4mm off 0.8mm"), "{tex}");
        // the legend-only series draws nothing
        assert_eq!(tex.matches(r"\addplot[forget plot").count(), 1, "{tex}");
    }
}
