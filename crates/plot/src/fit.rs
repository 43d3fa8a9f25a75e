//! A fitted outline over its data (thesis Figures 6.5–6.7: solid curve over
//! the dotted boundary; 6.11–6.22: C⁰ and C¹).

use trig_fit::{Outline, OutlineFit};

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::Result;
use crate::picture::Picture;
use crate::plotted::formula;
use crate::style::{BLACK, CURVE, LIGHT_GREY, colour, equal_aspect, padded};

/// Points drawn per fitted segment.
const SAMPLES: usize = 60;

/// `fit` over the data of `outline`: the data points, the C⁰ fit,
/// the refined fit if there is one, and the breakpoints.
/// Series: data points, one curve per segment per stage, breakpoints.
/// `symbols` are the printed symbols of the basis's parameters, `searched`
/// the one an optimised fit searched: the title names it and states the
/// fixed values of the others (`⟪λ⟫ optimised per segment, ⟪μ = 0.5⟫`).
pub fn fit_svg(
    outline: &Outline,
    fit: &OutlineFit,
    symbols: &[String],
    searched: Option<usize>,
) -> Result<Picture> {
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
    let (x, y) = equal_aspect(
        padded(data.iter().map(|p| p.0), 0.05),
        padded(data.iter().map(|p| p.1), 0.05),
    );
    let breaks: Vec<(f64, f64)> = fit
        .segments
        .iter()
        .map(|s| {
            let [x, y] = s.control[0];
            (x, y)
        })
        .collect();
    let mut series = vec![
        Series::new(
            "data",
            data,
            Look::marks(LIGHT_GREY, Mark::Dots { radius: 1.0 }),
        )
        .legend(format!("data ({} points)", outline.point_count())),
    ];
    for (k, (label, segments)) in drawn.into_iter().enumerate() {
        for (j, seg) in segments.into_iter().enumerate() {
            let s = Series::new(
                format!("{label}, segment {}", j + 1),
                seg.iter().map(|p| (p.x, p.y)),
                Look::line(colour(k), CURVE),
            );
            series.push(if j == 0 { s.legend(label.clone()) } else { s });
        }
    }
    series.push(
        Series::new("breakpoints", breaks, Look::marks(BLACK, Mark::Crosses))
            .legend("breakpoints (segment ends, interpolated)"),
    );
    let fixed: Vec<String> = match fit.segments.first() {
        Some(s) => symbols
            .iter()
            .zip(&s.params)
            .enumerate()
            .filter(|(k, _)| !fit.optimised || Some(*k) != searched)
            .map(|(_, (p, v))| formula(&format!("{p} = {}", v.to_string().replace('-', "−"))))
            .collect(),
        None => Vec::new(),
    };
    let mut params = Vec::new();
    if fit.optimised {
        params.push(match searched.and_then(|k| symbols.get(k)) {
            Some(p) => format!("{} optimised per segment", formula(p)),
            None => "shape parameter optimised per segment".to_string(),
        });
    }
    params.extend(fixed);
    let params = if params.is_empty() {
        "no parameter".to_string()
    } else {
        params.join(", ")
    };
    let frame = Frame {
        title: format!(
            "{} fitted with {} ({}, {} segments)",
            fit.glyph,
            fit.family,
            params,
            fit.segments.len()
        ),
        x_label: "x (px, 512 px per em)".into(),
        y_label: "y (px)".into(),
        caption: String::new(),
        x,
        y,
        zero_line: false,
        equal_aspect: true,
    };
    Picture::new(frame, series)
}
