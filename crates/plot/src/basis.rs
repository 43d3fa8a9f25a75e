//! The functions of a family for several values of its shape parameter
//! (thesis Figures 3.1, 3.6, 6.2).

use plotters::prelude::*;
use rug::Rational;
use trig_core::{Batch, Family};

use crate::error::{Result, draw};
use crate::picture::{Picture, Series};
use crate::style::{SIZE, chart, colour, legend, padded, settings};

/// The curves of one setting, one per function.
type Curves = Vec<Vec<(f64, f64)>>;

/// Points per function.
const SAMPLES: usize = 201;

/// SVG of every function of `family` over its domain, one colour per
/// parameter value in `values` (exact values, checked against the published
/// range unless `allow_outside`). Families without parameters take one
/// empty value list: pass `&[]` and get one series per function.
/// Series: (functions) × max(1, values) curves plus the axis `y = 0`.
pub fn basis_svg(family: Family, values: &[Rational], allow_outside: bool) -> Result<Picture> {
    let info = family.info();
    let settings = settings(&info, values, "basis")?;
    for s in &settings {
        let pairs: Vec<(String, String)> = info
            .params
            .iter()
            .zip(s)
            .map(|(p, v)| (p.name.to_string(), v.to_string()))
            .collect();
        family.params_from_pairs(&pairs, allow_outside)?;
    }
    let end = info.variable.end(&1.0_f64);
    let xs: Vec<f64> = (0..SAMPLES)
        .map(|i| end * i as f64 / (SAMPLES - 1) as f64)
        .collect();
    // settings whose functions coincide are drawn once, labelled with
    // every value (`λ = 0, 1`)
    let mut series: Vec<(Vec<Vec<Rational>>, Curves)> = Vec::new();
    for s in &settings {
        // function-major: one slice of SAMPLES values per function
        let values = Batch::new(family, s, &0.0, true)?.eval(&xs)?;
        let curves: Curves = values
            .chunks(SAMPLES)
            .map(|column| xs.iter().copied().zip(column.iter().copied()).collect())
            .collect();
        match series.iter_mut().find(|(_, c)| *c == curves) {
            Some((same, _)) => same.push(s.clone()),
            None => series.push((vec![s.clone()], curves)),
        }
    }
    let (ylo, yhi) = padded(
        series
            .iter()
            .flat_map(|(_, cs)| cs.iter().flatten().map(|p| p.1))
            .chain([0.0, 1.0]),
        0.05,
    );
    let variable = match info.variable {
        trig_core::Variable::UnitAngle => "u (angle θ = πu/2)",
        trig_core::Variable::Angle => "t (angle, radians)",
        trig_core::Variable::Polynomial => "t",
    };
    let mut svg = String::new();
    let mut data = Vec::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let caption = format!(
            "{}: {} — {}",
            info.id,
            info.functions.join(", "),
            info.citation
        );
        let mut chart = chart(
            &root,
            caption,
            (0.0, end),
            (ylo, yhi),
            variable,
            "basis function value",
        )?;
        chart
            .draw_series(LineSeries::new(
                [(0.0, 0.0), (end, 0.0)],
                BLACK.stroke_width(1),
            ))
            .map_err(draw)?;
        for (k, (same, curves)) in series.iter().enumerate() {
            let c = colour(k);
            let label = match info.params.first() {
                Some(p) if !same[0].is_empty() => {
                    let vals: Vec<String> = same.iter().map(|s| s[0].to_string()).collect();
                    format!("{} = {}", p.symbol, vals.join(", "))
                }
                _ => info.functions.join(", "),
            };
            for (j, curve) in curves.iter().enumerate() {
                let name = info.functions.get(j).copied().unwrap_or("b");
                data.push(Series::new(
                    format!("{name}, {label}"),
                    curve.iter().copied(),
                ));
                let drawn = chart
                    .draw_series(LineSeries::new(curve.iter().copied(), c.stroke_width(2)))
                    .map_err(draw)?;
                if j == 0 {
                    drawn.label(label.clone()).legend(move |(x, y)| {
                        PathElement::new([(x, y), (x + 20, y)], c.stroke_width(2))
                    });
                }
            }
        }
        legend(&mut chart)?;
        root.present().map_err(draw)?;
    }
    Ok(Picture { svg, series: data })
}
