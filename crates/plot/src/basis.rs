//! The functions of a basis (a catalog family or a spec file's) for several values of its shape parameter
//! (thesis Figures 3.1, 3.6, 6.2), alone or against another basis.

use trig_core::Affine;

use crate::chart::{Frame, Look, Series};
use crate::error::{PlotError, Result};
use crate::picture::Picture;
use crate::plotted::{Plotted, formula};
use crate::style::{CURVE, GREY, colour, dash, padded};
use trig_tex::plain;

/// The curves of one setting, one per function.
type Curves = Vec<Vec<(f64, f64)>>;

/// Points per function.
const SAMPLES: usize = 201;

/// Every function of a basis over its domain: a colour per function, a
/// line style (solid, dashed, dotted, …) per parameter setting of `plot`
/// (one setting, no parameters, for a basis without them). Series:
/// (functions) × settings curves; settings whose functions coincide are
/// drawn once, labelled with every value (`λ = 0, 1`). The legend lists
/// the functions by colour, then the settings by line style.
pub fn basis_svg(plot: &Plotted) -> Result<Picture> {
    picture(plot.heading(&plot.name), &[plot])
}

/// `plot` (wide and light) and `versus` (thin) over each other, the same
/// colour for the same function and the same line style for the same
/// parameter value: what a listing computes beside what is printed (where
/// they agree the thin line runs inside the wide one). Both must have the
/// same variable, functions and settings.
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
    let title = plot.heading(&format!("{} (wide) versus {} (thin)", plot.id, versus.id));
    picture(title, &[plot, versus])
}

/// How the `p`-th of the plots drawn together is drawn: alone, or the
/// first wide and light, the others thin.
fn stroke(p: usize, plots: usize) -> (f64, f64) {
    match (plots, p) {
        (1, _) => (CURVE, 1.0),
        (_, 0) => (4.0 * CURVE, 0.4),
        _ => (CURVE, 1.0),
    }
}

/// The picture of `plots` (see [`basis_svg`], [`basis_versus_svg`]).
fn picture(title: String, plots: &[&Plotted]) -> Result<Picture> {
    // the legend first: functions by colour, settings by line style, plots by width
    let entry = |label: &str, look: Look| {
        Series::new(format!("legend: {}", plain(label)), [], look).legend(label)
    };
    let mut series: Vec<Series> = plots[0]
        .functions
        .iter()
        .enumerate()
        .map(|(j, name)| entry(&formula(name), Look::line(colour(j), CURVE)))
        .collect();
    let mut drawn: Vec<Series> = Vec::new();
    let mut styles: Vec<(usize, String)> = Vec::new();
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
        let (width, opacity) = stroke(p, plots.len());
        for (k, same, curves) in groups {
            let label = plot.label(&same);
            if plot.varied.is_some() && !styles.iter().any(|(d, _)| *d == k) {
                styles.push((k, label.clone()));
            }
            let label = match plots.len() {
                1 => label,
                _ => format!("{}: {label}", plot.id),
            };
            for (j, curve) in curves.into_iter().enumerate() {
                let name = plot.functions.get(j).map_or("b", String::as_str);
                let look = Look {
                    opacity,
                    ..Look::line(colour(j), width).dashed(dash(k))
                };
                drawn.push(Series::new(plain(&format!("{name}, {label}")), curve, look));
            }
        }
    }
    for (k, label) in styles {
        series.push(entry(&label, Look::line(GREY, CURVE).dashed(dash(k))));
    }
    if plots.len() > 1 {
        for (p, plot) in plots.iter().enumerate() {
            let (width, opacity) = stroke(p, plots.len());
            let look = Look {
                opacity,
                ..Look::line(GREY, width)
            };
            series.push(entry(&plot.id, look));
        }
    }
    series.extend(drawn);
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
        caption: plots[0].citation.clone(),
        x,
        y,
        zero_line: true,
        equal_aspect: false,
    };
    Picture::new(frame, series)
}
