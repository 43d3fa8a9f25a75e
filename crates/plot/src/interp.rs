//! Piecewise interpolants `y = P(x)` with their data points (thesis 4.3:
//! positivity-preserving interpolation, Figures 4.x). The caller supplies the
//! sampled pieces (crate `trig-interp` builds them), so this picture knows
//! nothing of the schemes.

use plotters::prelude::*;

use crate::error::{PlotError, Result, draw};
use crate::picture::{Picture, Series};
use crate::style::{SIZE, chart, colour, legend, padded};

/// One interpolant: its legend label and its pieces, each a sampled polyline.
#[derive(Debug, Clone, PartialEq)]
pub struct Interpolant {
    pub label: String,
    pub pieces: Vec<Vec<(f64, f64)>>,
}

/// SVG of `interpolants` over `data`, with the line `y = 0` (positivity is
/// the point of thesis 4.3). Series: the axis, one curve per piece per
/// interpolant, the data points.
pub fn interp_svg(
    title: &str,
    data: &[(f64, f64)],
    interpolants: &[Interpolant],
) -> Result<Picture> {
    let all = || {
        data.iter()
            .chain(interpolants.iter().flat_map(|i| i.pieces.iter().flatten()))
    };
    if data.is_empty() || all().any(|(x, y)| !x.is_finite() || !y.is_finite()) {
        return Err(PlotError::Input(
            "interpolant plots need finite data and curves".into(),
        ));
    }
    let xr = padded(all().map(|p| p.0), 0.03);
    let yr = padded(all().map(|p| p.1).chain([0.0]), 0.08);
    let mut data_series = vec![Series::new("data points", data.iter().copied())];
    for i in interpolants {
        for (j, piece) in i.pieces.iter().enumerate() {
            data_series.push(Series::new(
                format!("{}, piece {}", i.label, j + 1),
                piece.iter().copied(),
            ));
        }
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let mut chart = chart(&root, title, (xr.0, xr.1), (yr.0, yr.1), "x", "y = P(x)")?;
        chart
            .draw_series(LineSeries::new(
                [(xr.0, 0.0), (xr.1, 0.0)],
                BLACK.stroke_width(1),
            ))
            .map_err(draw)?;
        for (k, interp) in interpolants.iter().enumerate() {
            let c = colour(k);
            for (j, piece) in interp.pieces.iter().enumerate() {
                let line = chart
                    .draw_series(LineSeries::new(piece.iter().copied(), c.stroke_width(2)))
                    .map_err(draw)?;
                if j == 0 {
                    line.label(interp.label.clone()).legend(move |(x, y)| {
                        PathElement::new([(x, y), (x + 20, y)], c.stroke_width(2))
                    });
                }
            }
        }
        chart
            .draw_series(data.iter().map(|&p| Circle::new(p, 4, BLACK.filled())))
            .map_err(draw)?
            .label("data points")
            .legend(|(x, y)| Circle::new((x + 10, y), 4, BLACK.filled()));
        legend(&mut chart)?;
        root.present().map_err(draw)?;
    }
    Ok(Picture {
        svg,
        series: data_series,
    })
}
