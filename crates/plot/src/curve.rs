//! A curve `Σ bᵢ Vᵢ` with its control polygon for several values of the
//! shape parameter (thesis Figure 6.3: `V₀ = (0,0)`, `V₁ = (1,2)`,
//! `V₂ = (3,2)`, `V₃ = (4,0)`).

use plotters::prelude::*;
use rug::Rational;
use trig_core::{Batch, Family};

use crate::error::{PlotError, Result, draw};
use crate::picture::{Picture, Series};
use crate::style::{SIZE, chart, colour, equal_aspect, legend, padded, settings};

/// Points per curve.
const SAMPLES: usize = 201;

/// SVG of the curve of `family` with control points `control` (one per
/// function) for each parameter value (one empty setting for families
/// without parameters), over its control polygon.
/// Series: the polygon, its vertices, one curve per value.
pub fn curve_svg(
    family: Family,
    control: &[(f64, f64)],
    values: &[Rational],
    allow_outside: bool,
) -> Result<Picture> {
    let info = family.info();
    if control.len() != info.functions.len() {
        return Err(PlotError::Input(format!(
            "`{}` has {} functions; {} control points given",
            info.id,
            info.functions.len(),
            control.len()
        )));
    }
    if control
        .iter()
        .any(|(x, y)| !x.is_finite() || !y.is_finite())
    {
        return Err(PlotError::Input("control points must be finite".into()));
    }
    let settings = settings(&info, values, "curve")?;
    let end = info.variable.end(&1.0_f64);
    let mut curves = Vec::new();
    for s in &settings {
        let pairs: Vec<(String, String)> = info
            .params
            .iter()
            .zip(s)
            .map(|(p, v)| (p.name.to_string(), v.to_string()))
            .collect();
        family.params_from_pairs(&pairs, allow_outside)?;
        let xs: Vec<f64> = (0..SAMPLES)
            .map(|i| end * i as f64 / (SAMPLES - 1) as f64)
            .collect();
        // function-major: b_k at every sample is values[k·SAMPLES..]
        let values = Batch::new(family, s, &0.0, true)?.eval(&xs)?;
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
            info.id, info.citation
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
            let label = match s.first() {
                Some(v) => format!("{} = {}", info.params[0].symbol, v),
                None => info.id.to_string(),
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
