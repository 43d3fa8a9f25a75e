//! The functions of a basis (a catalog family or a spec file's) for several values of its shape parameter
//! (thesis Figures 3.1, 3.6, 6.2).

use plotters::prelude::*;
use rug::Rational;

use crate::error::{Result, draw};
use crate::picture::{Picture, Series};
use crate::plotted::Plotted;
use crate::style::{SIZE, chart, colour, legend, padded};

/// The curves of one setting, one per function.
type Curves = Vec<Vec<(f64, f64)>>;

/// Points per function.
const SAMPLES: usize = 201;

/// SVG of every function of a basis over its domain, one colour per
/// parameter setting of `plot` (one setting, no parameters, for a basis
/// without them). Series: (functions) × settings curves plus the axis
/// `y = 0`.
pub fn basis_svg(plot: &Plotted) -> Result<Picture> {
    // settings whose functions coincide are drawn once, labelled with
    // every value (`λ = 0, 1`)
    let mut series: Vec<(Vec<Vec<Rational>>, Curves)> = Vec::new();
    for s in &plot.settings {
        // function-major: one slice of SAMPLES values per function
        let (xs, values) = plot.sample(s, SAMPLES)?;
        let curves: Curves = values
            .chunks(SAMPLES)
            .map(|column| xs.iter().copied().zip(column.iter().copied()).collect())
            .collect();
        match series.iter_mut().find(|(_, c)| *c == curves) {
            Some((same, _)) => same.push(s.clone()),
            None => series.push((vec![s.clone()], curves)),
        }
    }
    let xs = || {
        series
            .iter()
            .flat_map(|(_, cs)| cs.iter().flatten().map(|p| p.0))
    };
    let (start, end) = (
        xs().fold(f64::INFINITY, f64::min),
        xs().fold(f64::NEG_INFINITY, f64::max),
    );
    let (ylo, yhi) = padded(
        series
            .iter()
            .flat_map(|(_, cs)| cs.iter().flatten().map(|p| p.1))
            .chain([0.0, 1.0]),
        0.05,
    );
    let mut svg = String::new();
    let mut data = Vec::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let caption = format!(
            "{}: {} — {}",
            plot.id,
            plot.functions.join(", "),
            plot.citation
        );
        let mut chart = chart(
            &root,
            caption,
            (start, end),
            (ylo, yhi),
            &plot.variable,
            "basis function value",
        )?;
        chart
            .draw_series(LineSeries::new(
                [(start, 0.0), (end, 0.0)],
                BLACK.stroke_width(1),
            ))
            .map_err(draw)?;
        for (k, (same, curves)) in series.iter().enumerate() {
            let c = colour(k);
            let label = plot.label(same);
            for (j, curve) in curves.iter().enumerate() {
                let name = plot.functions.get(j).map_or("b", String::as_str);
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
