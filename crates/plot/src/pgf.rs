//! The pgfplots code of a [`Picture`]: a `tikzpicture` to `\input` into a
//! LaTeX document (which loads `pgfplots`), with the same frame, series,
//! looks and legend as the SVG, coordinates as floats. The axis has the
//! size of the SVG's plot area, so equal scales stay equal. Text (title,
//! axis labels, legend entries) is written by the one LaTeX writer,
//! [`trig_tex`].

use std::fmt::Write;

use trig_tex::{comment, text};

use crate::chart::{Look, Mark};
use crate::picture::Picture;
use crate::style::{PLOT_AREA, UNIT_MM, X_LABEL_AREA, legend_columns};

/// A number as pgfplots reads it: plain decimals in a moderate range,
/// scientific notation beyond it.
fn num(v: f64) -> String {
    if v == 0.0 || (1e-4..1e6).contains(&v.abs()) {
        v.to_string()
    } else {
        format!("{v:e}")
    }
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
            dashed,
            vertices,
        } => {
            o.push(format!("line width={}", mm(width)));
            if dashed {
                o.push(format!("dash pattern=on {} off {}", mm(6.0), mm(4.0)));
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
    /// The picture as pgfplots code.
    pub fn pgf(&self) -> String {
        let f = &self.frame;
        let mut out = comment(&format!(
            "{} (trig-audit plot; the data is in the CSV file of the same name)",
            text(&f.title)
        ));
        out.push_str(&comment(
            r"needs \usepackage{pgfplots} with \pgfplotsset{compat=1.16} or later",
        ));
        out.push_str("\\begin{tikzpicture}\n\\begin{axis}[\n");
        let below = (f64::from(X_LABEL_AREA) + 8.0) / PLOT_AREA.1;
        // column-major as in the SVG: transposed, `legend columns` counts rows
        let columns = legend_columns(self.legend().map(|(t, _)| t));
        let rows = self.legend().count().div_ceil(columns).max(1);
        for line in [
            format!("title={{{}}},", text(&f.title)),
            format!("xlabel={{{}}},", text(&f.x_label)),
            format!("ylabel={{{}}},", text(&f.y_label)),
            format!("xmin={}, xmax={},", num(f.x.0), num(f.x.1)),
            format!("ymin={}, ymax={},", num(f.y.0), num(f.y.1)),
            format!(
                "scale only axis, width={}, height={},",
                mm(PLOT_AREA.0),
                mm(PLOT_AREA.1)
            ),
            "grid=major, grid style={black!12}, tick align=outside,".into(),
            r"title style={font=\small}, label style={font=\small}, tick label style={font=\footnotesize},".into(),
            format!(
                "legend columns={rows}, transpose legend, legend cell align=left, legend style={{font=\\footnotesize, draw=none, at={{(0.5,-{below:.3})}}, anchor=north, /tikz/every even column/.append style={{column sep=4mm}}}},"
            ),
        ] {
            let _ = writeln!(out, "  {line}");
        }
        out.push_str("]\n");
        for (entry, look) in self.legend() {
            let _ = writeln!(
                out,
                "\\addlegendimage{{{}}}\n\\addlegendentry{{{}}}",
                options(look),
                text(entry)
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
        for s in &self.series {
            out.push_str(&comment(&text(&s.label)));
            if let (Mark::Cell, [a, b]) = (s.look.mark, &s.points[..]) {
                let mut fill = colour(&s.look).replace("color=", "fill=");
                if s.look.opacity < 1.0 {
                    let _ = write!(fill, ", fill opacity={}", s.look.opacity);
                }
                let _ = writeln!(
                    out,
                    "\\fill[{fill}] (axis cs:{},{}) rectangle (axis cs:{},{});",
                    num(a.0),
                    num(a.1),
                    num(b.0),
                    num(b.1)
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
        out
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
                x: (0.0, 2.0),
                y: (-1.0, 1.0),
                zero_line: true,
            },
            vec![
                Series::new("curve, piece 1", [(0.0, 0.0), (1.0, 0.5)], line).legend("curve"),
                Series::new("curve, piece 2", [(1.0, 0.5), (2.0, 1.0)], line),
                Series::new("data", [(0.0, 0.0), (2.0, 1.0)], dots).legend("data"),
                Series::new("cell", [(0.0, -1.0), (1.0, 0.0)], cell).legend("inside"),
            ],
        )
        .unwrap();
        let tex = p.pgf();
        assert!(tex.contains(r"title={T \& $\lambda$},"), "{tex}");
        assert!(tex.contains("xmin=0, xmax=2,"));
        assert!(tex.contains("width=139.2mm, height=87.6mm"), "{tex}");
        assert_eq!(tex.matches(r"\addlegendentry{").count(), 3);
        assert_eq!(tex.matches(r"\addplot[forget plot").count(), 3 + 1);
        assert!(tex.contains("  (1,0.5) (2,1)\n"));
        assert!(tex.contains("only marks, mark=*, mark size=0.8mm"));
        assert!(tex.contains(r"\fill[fill={rgb,255:red,0;green,158;blue,115}, fill opacity=0.5] (axis cs:0,-1) rectangle (axis cs:1,0);"), "{tex}");
        assert!(tex.ends_with("\\end{axis}\n\\end{tikzpicture}\n"));
    }
}
