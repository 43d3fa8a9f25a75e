//! A curve `Σ bᵢ Vᵢ` with its control polygon for several values of the
//! shape parameter (thesis Figure 6.3: `V₀ = (0,0)`, `V₁ = (1,2)`,
//! `V₂ = (3,2)`, `V₃ = (4,0)`).

use plotters::prelude::*;

use crate::error::{PlotError, Result, draw};
use crate::picture::{Picture, Series};
use crate::plotted::Plotted;
use crate::style::{SIZE, chart, colour, equal_aspect, legend, padded};

/// Points per curve.
const SAMPLES: usize = 201;

/// SVG of the curve of a basis with control points `control` (one per
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
    let (xr, yr) = equal_aspect(
        padded(all().map(|p| p.0), 0.08),
        padded(all().map(|p| p.1), 0.08),
        (700.0, 480.0),
    );
    let mut data = vec![Series::new("control polygon", control.iter().copied())];
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let caption = format!(
            "{} curve with its control polygon — {}",
            plot.id, plot.citation
        );
        let mut chart = chart(&root, caption, (xr.0, xr.1), (yr.0, yr.1), "x", "y")?;
        let grey = RGBColor(90, 90, 90);
        chart
            .draw_series(LineSeries::new(
                control.iter().copied(),
                grey.stroke_width(1),
            ))
            .map_err(draw)?
            .label("control polygon V0…V3")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], grey.stroke_width(1)));
        chart
            .draw_series(control.iter().map(|&p| Circle::new(p, 4, grey.filled())))
            .map_err(draw)?;
        for (k, (s, pts)) in curves.iter().enumerate() {
            let c = colour(k);
            let label = if s.is_empty() {
                plot.id.clone()
            } else {
                plot.label(std::slice::from_ref(s))
            };
            data.push(Series::new(label.clone(), pts.iter().copied()));
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), c.stroke_width(2)))
                .map_err(draw)?
                .label(label)
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], c.stroke_width(2)));
        }
        legend(&mut chart)?;
        root.present().map_err(draw)?;
    }
    Ok(Picture { svg, series: data })
}
