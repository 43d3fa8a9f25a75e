//! The functions of a basis (a catalog family or a spec file's) for several values of its shape parameter
//! (thesis Figures 3.1, 3.6, 6.2), alone or against another basis.

use trig_core::Affine;

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::{PlotError, Result};
use crate::picture::Picture;
use crate::plotted::Plotted;
use crate::style::{CURVE, colour, padded};

/// The curves of one setting, one per function.
type Curves = Vec<Vec<(f64, f64)>>;

/// Points per function.
const SAMPLES: usize = 201;

/// Every function of a basis over its domain, one colour per parameter
/// setting of `plot` (one setting, no parameters, for a basis without
/// them). Series: (functions) × settings curves; settings whose functions
/// coincide are drawn once, labelled with every value (`λ = 0, 1`).
pub fn basis_svg(plot: &Plotted) -> Result<Picture> {
    let title = format!(
        "{}: {} — {}",
        plot.id,
        plot.functions.join(", "),
        plot.citation
    );
    picture(title, &[plot])
}

/// `plot` (solid) and `versus` (dashed) over each other, the same colour
/// for the same parameter value: what a listing computes beside what is
/// printed. Both must have the same variable, functions and settings.
pub fn basis_versus_svg(plot: &Plotted, versus: &Plotted) -> Result<Picture> {
    if plot.variable != versus.variable
        || plot.functions.len() != versus.functions.len()
        || plot.settings != versus.settings
    {
        return Err(PlotError::Input(format!(
            "`{}` and `{}` cannot be drawn over each other: their variables, numbers of functions or parameter values differ",
            plot.id, versus.id
        )));
    }
    let title = format!(
        "{} (solid) versus {} (dashed): {}",
        plot.id,
        versus.id,
        plot.functions.join(", ")
    );
    picture(title, &[plot, versus])
}

/// The picture of `plots`, the first solid, the others dashed; with more
/// than one, every label names its basis.
fn picture(title: String, plots: &[&Plotted]) -> Result<Picture> {
    let mut series = Vec::new();
    for (p, plot) in plots.iter().enumerate() {
        // (index of the first setting, the settings drawn together, curves)
        let mut groups: Vec<(usize, Vec<Vec<Affine>>, Curves)> = Vec::new();
        for (k, s) in plot.settings.iter().enumerate() {
            // function-major: one slice of SAMPLES values per function
            let (xs, values) = plot.sample(s, SAMPLES)?;
            let curves: Curves = values
                .chunks(SAMPLES)
                .map(|column| xs.iter().copied().zip(column.iter().copied()).collect())
                .collect();
            match groups.iter_mut().find(|(_, _, c)| *c == curves) {
                Some((_, same, _)) => same.push(s.clone()),
                None => groups.push((k, vec![s.clone()], curves)),
            }
        }
        for (k, same, curves) in groups {
            let look = Look {
                mark: Mark::Line {
                    width: CURVE,
                    dashed: p > 0,
                    vertices: false,
                },
                ..Look::line(colour(k), CURVE)
            };
            let label = match plots.len() {
                1 => plot.label(&same),
                _ => format!("{}: {}", plot.id, plot.label(&same)),
            };
            for (j, curve) in curves.into_iter().enumerate() {
                let name = plot.functions.get(j).map_or("b", String::as_str);
                let s = Series::new(format!("{name}, {label}"), curve, look);
                series.push(if j == 0 { s.legend(label.clone()) } else { s });
            }
        }
    }
    let all = || series.iter().flat_map(|s: &Series| s.points.iter());
    let x = (
        all().map(|p| p.0).fold(f64::INFINITY, f64::min),
        all().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max),
    );
    let y = padded(all().map(|p| p.1).chain([0.0, 1.0]), 0.05);
    let frame = Frame {
        title,
        x_label: plots[0].variable.clone(),
        y_label: "basis function value".into(),
        x,
        y,
        zero_line: true,
    };
    Picture::new(frame, series)
}
