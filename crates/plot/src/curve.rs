//! A curve `Σ bᵢ Vᵢ` with its control polygon for several values of the
//! shape parameter (thesis Figure 6.3: `V₀ = (0,0)`, `V₁ = (1,2)`,
//! `V₂ = (3,2)`, `V₃ = (4,0)`).

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::{PlotError, Result};
use crate::picture::Picture;
use crate::plotted::{Plotted, formula};
use crate::style::{CURVE, GREY, THIN, colour, equal_aspect, padded};
use trig_tex::plain;

/// Points per curve.
const SAMPLES: usize = 201;

/// The curve of a basis with control points `control` (one per
/// function) for each parameter setting of `plot`, over its control
/// polygon. Series: the polygon, its vertices, one curve per setting.
pub fn curve_svg(plot: &Plotted, control: &[(f64, f64)]) -> Result<Picture> {
    if control.len() != plot.functions.len() {
        return Err(PlotError::Input(format!(
            "`{}` has {} functions; {} control points given",
            plot.id,
            plot.functions.len(),
            control.len()
        )));
    }
    if control
        .iter()
        .any(|(x, y)| !x.is_finite() || !y.is_finite())
    {
        return Err(PlotError::Input("control points must be finite".into()));
    }
    let mut curves = Vec::new();
    for s in &plot.settings {
        // function-major: b_k at every sample is values[k·SAMPLES..]
        let (_, values) = plot.sample(s, SAMPLES)?;
        let pts: Vec<(f64, f64)> = (0..SAMPLES)
            .map(|i| {
                values
                    .iter()
                    .skip(i)
                    .step_by(SAMPLES)
                    .zip(control)
                    .fold((0.0, 0.0), |acc, (bi, v)| {
                        (acc.0 + bi * v.0, acc.1 + bi * v.1)
                    })
            })
            .collect();
        curves.push((s.clone(), pts));
    }
    let all = || {
        curves
            .iter()
            .flat_map(|(_, c)| c.iter())
            .chain(control.iter())
    };
    let (x, y) = equal_aspect(
        padded(all().map(|p| p.0), 0.08),
        padded(all().map(|p| p.1), 0.08),
    );
    let polygon = Look {
        mark: Mark::Line {
            width: THIN,
            dash: None,
            vertices: true,
        },
        ..Look::line(GREY, THIN)
    };
    let mut series = vec![
        Series::new("control polygon", control.iter().copied(), polygon).legend(format!(
            "control polygon {}",
            formula(&format!("V0…V{}", control.len().saturating_sub(1)))
        )),
    ];
    for (k, (s, pts)) in curves.into_iter().enumerate() {
        let label = match plot.varied {
            None => plot.id.clone(),
            Some(_) => plot.label(std::slice::from_ref(&s)),
        };
        series.push(Series::new(plain(&label), pts, Look::line(colour(k), CURVE)).legend(label));
    }
    let frame = Frame {
        title: plot.heading(&format!("{}: curve and control polygon", plot.name)),
        x_label: "x".into(),
        y_label: "y".into(),
        caption: plot.citation.clone(),
        x,
        y,
        zero_line: false,
        equal_aspect: true,
    };
    Picture::new(frame, series)
}
