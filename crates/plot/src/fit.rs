//! A fitted outline over its data (thesis Figures 6.5–6.7: solid curve over
//! the dotted boundary; 6.11–6.22: C⁰ and C¹).

use plotters::prelude::*;
use trig_fit::{Outline, OutlineFit};

use crate::error::{Result, draw};
use crate::picture::{Picture, Series};
use crate::style::{SIZE, chart, colour, equal_aspect, legend, padded};

/// Points drawn per fitted segment.
const SAMPLES: usize = 60;

/// SVG of `fit` over the data of `outline`: the data points, the C⁰ fit,
/// the refined fit if there is one, and the breakpoints.
/// Series: data points, one curve per segment per stage, breakpoints.
pub fn fit_svg(outline: &Outline, fit: &OutlineFit) -> Result<Picture> {
    let stages: Vec<(bool, String)> =
        std::iter::once((false, "C0 fit (least squares per segment)".to_string()))
            .chain(fit.after.map(|_| {
                let how = match fit.continuity {
                    Some(trig_fit::Continuity::ArcLength) => "C1 refined (chord-length parameter)",
                    _ => "C1 refined (local parameter, thesis (4.5))",
                };
                (true, how.to_string())
            }))
            .collect();
    let mut drawn = Vec::new();
    for (refined, label) in &stages {
        drawn.push((label.clone(), fit.curve(*refined, SAMPLES)?));
    }
    let data: Vec<(f64, f64)> = outline
        .contours
        .iter()
        .flatten()
        .map(|p| (p.x, p.y))
        .collect();
    let xd = padded(data.iter().map(|p| p.0), 0.05);
    let (xr, yr) = equal_aspect(xd, padded(data.iter().map(|p| p.1), 0.05), (700.0, 470.0));
    // the outline at the left, the free width (for the legend) at the right
    let xr = (xd.0, xd.0 + (xr.1 - xr.0));
    let breaks: Vec<(f64, f64)> = fit
        .segments
        .iter()
        .map(|s| {
            let [x, y] = s.control[0];
            (x, y)
        })
        .collect();
    let mut series_data = vec![Series::new("data", data.iter().copied())];
    for (label, segments) in &drawn {
        for (j, seg) in segments.iter().enumerate() {
            series_data.push(Series::new(
                format!("{label}, segment {}", j + 1),
                seg.iter().map(|p| (p.x, p.y)),
            ));
        }
    }
    series_data.push(Series::new("breakpoints", breaks.iter().copied()));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let params = if fit.optimised {
            "shape parameter optimised per segment".to_string()
        } else {
            match fit.segments.first().and_then(|s| s.params.first()) {
                Some(p) => format!("parameter {p}"),
                None => "no parameter".to_string(),
            }
        };
        let caption = format!(
            "{} fitted with {} ({}, {} segments)",
            fit.glyph,
            fit.family,
            params,
            fit.segments.len()
        );
        let mut chart = chart(
            &root,
            caption,
            (xr.0, xr.1),
            (yr.0, yr.1),
            "x (px, 512 px per em)",
            "y (px)",
        )?;
        let grey = RGBColor(150, 150, 150);
        chart
            .draw_series(data.iter().map(|&p| Circle::new(p, 1, grey.filled())))
            .map_err(draw)?
            .label(format!("data ({} points)", outline.point_count()))
            .legend(move |(x, y)| Circle::new((x + 10, y), 2, grey.filled()));
        for (k, (label, segments)) in drawn.iter().enumerate() {
            let c = colour(k);
            for (j, seg) in segments.iter().enumerate() {
                let line = chart
                    .draw_series(LineSeries::new(
                        seg.iter().map(|p| (p.x, p.y)),
                        c.stroke_width(2),
                    ))
                    .map_err(draw)?;
                if j == 0 {
                    line.label(label.clone()).legend(move |(x, y)| {
                        PathElement::new([(x, y), (x + 20, y)], c.stroke_width(2))
                    });
                }
            }
        }
        chart
            .draw_series(
                breaks
                    .iter()
                    .map(|&p| Cross::new(p, 5, BLACK.stroke_width(2))),
            )
            .map_err(draw)?
            .label("breakpoints (segment ends, interpolated)")
            .legend(move |(x, y)| Cross::new((x + 10, y), 4, BLACK.stroke_width(2)));
        legend(&mut chart)?;
        root.present().map_err(draw)?;
    }
    Ok(Picture {
        svg,
        series: series_data,
    })
}
