//! The pgfplots code of a [`SurfaceFigure`]: by default a fragment — a
//! `tikzpicture` to `\input` into a document that loads `pgfplots` — or a
//! whole `article` around it ([`PgfOptions::standalone`]). Each patch is an
//! `\addplot3[surf]` of its samples (one scanline per row, `mesh/rows`
//! given), coloured in its own shades by height; each control net row and
//! column a red polyline with its points marked; the view is the figure's
//! (`view={azimuth}{elevation}`) and the axes keep one unit as long in x,
//! y and z (`unit vector ratio=1 1 1`).

use std::fmt::Write;

use trig_tex::{article, comment, input_note, labelled, plain, text};

use crate::pgf::{PACKAGES, PgfOptions, SETUP, num};
use crate::surface::SurfaceFigure;

/// A point as pgfplots reads it.
fn point(p: &[f64; 3]) -> String {
    format!("({},{},{})", num(p[0]), num(p[1]), num(p[2]))
}

/// The pgfplots code of `figure`.
pub fn surface_pgf(figure: &SurfaceFigure, options: &PgfOptions) -> crate::error::Result<String> {
    figure.check()?;
    let what = if figure.title.is_empty() {
        "trig-audit plot surface".to_string()
    } else {
        format!("{} (trig-audit plot surface)", text(&plain(&figure.title)))
    };
    let mut out = input_note(&what, &PACKAGES, &SETUP);
    out.push_str("\\begin{tikzpicture}\n\\begin{axis}[\n");
    if !figure.title.is_empty() {
        let _ = writeln!(out, "  title={{{}}},", labelled(&figure.title));
    }
    let _ = writeln!(
        out,
        "  view={{{}}}{{{}}}, width={{{}}}, unit vector ratio=1 1 1,\n  xlabel={{$x$}}, ylabel={{$y$}}, zlabel={{$z$}}, label style={{font=\\small}}, tick label style={{font=\\footnotesize}},",
        num(figure.view.azimuth),
        num(figure.view.elevation),
        options.width
    );
    out.push_str("]\n");
    for (k, patch) in figure.patches.iter().enumerate() {
        let (r, g, b) = patch.rgb;
        let dark = |v: u8| v / 2;
        out.push_str(&comment(&format!("patch {k}: its samples, row by row")));
        let _ = writeln!(
            out,
            "\\addplot3[surf, shader=faceted, faceted color=black!40, colormap={{patch{k}}}{{rgb255=({},{},{}) rgb255=({r},{g},{b})}}, mesh/rows={}] coordinates {{",
            dark(r),
            dark(g),
            dark(b),
            patch.grid.len()
        );
        for row in &patch.grid {
            let line: Vec<String> = row.iter().map(point).collect();
            let _ = writeln!(out, "  {}\n", line.join(" "));
        }
        out.push_str("};\n");
        out.push_str(&comment(&format!("patch {k}: its control net")));
        let columns = patch.net.first().map_or(0, Vec::len);
        let lines = patch
            .net
            .iter()
            .cloned()
            .chain((0..columns).map(|j| patch.net.iter().map(|row| row[j]).collect()));
        for line in lines {
            let points: Vec<String> = line.iter().map(point).collect();
            let _ = writeln!(
                out,
                "\\addplot3[red, thin, mark=*, mark size=0.8pt] coordinates {{{}}};",
                points.join(" ")
            );
        }
    }
    out.push_str("\\end{axis}\n\\end{tikzpicture}\n");
    Ok(if options.standalone {
        article(&PACKAGES, &SETUP, &out)
    } else {
        out
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::surface::{PATCH_COLOURS, SurfacePatch, View};

    #[test]
    fn a_fragment_with_one_scanline_per_row_and_the_net() {
        let figure = SurfaceFigure {
            title: "S at ⟪m = 1⟫".into(),
            patches: vec![SurfacePatch {
                grid: vec![
                    vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.5]],
                    vec![[1.0, 0.0, 0.0], [1.0, 1.0, 2.0]],
                ],
                net: vec![vec![[0.0, 0.0, 0.0], [1.0, 1.0, 2.0]]],
                rgb: PATCH_COLOURS[0],
            }],
            view: View::default(),
        };
        let tex = surface_pgf(&figure, &PgfOptions::default()).unwrap();
        assert!(tex.contains("view={-37.5}{30}"), "{tex}");
        assert!(
            tex.contains(
                "mesh/rows=2] coordinates {\n  (0,0,0) (0,1,0.5)\n\n  (1,0,0) (1,1,2)\n\n};"
            ),
            "{tex}"
        );
        // one net row and two net columns
        assert_eq!(tex.matches("\\addplot3[red").count(), 3);
        assert!(tex.contains("title={S at $m = 1$}"), "{tex}");
        assert!(!tex.contains("\\documentclass"));
        let whole = surface_pgf(
            &figure,
            &PgfOptions {
                standalone: true,
                ..PgfOptions::default()
            },
        )
        .unwrap();
        assert!(whole.starts_with("\\documentclass{article}"));
    }
}
