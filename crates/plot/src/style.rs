//! Shared look: size, colours, fonts, the chart frame and legend, the
//! bounding box with a margin, and the parameter values a plot varies.

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use rug::Rational;
use trig_core::FamilyInfo;

use crate::error::{PlotError, Result, draw};

/// Picture size in pixels.
pub const SIZE: (u32, u32) = (800, 600);

/// A colour-blind-safe palette (Okabe–Ito), cycled.
const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(120, 120, 120),
];

/// The `k`-th colour of the palette.
pub fn colour(k: usize) -> RGBColor {
    PALETTE[k % PALETTE.len()]
}

/// `[lo, hi]` of `values` widened by `margin` of the width (and never empty).
pub fn padded(values: impl Iterator<Item = f64>, margin: f64) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    let w = (hi - lo).max(1e-9);
    (lo - margin * w, hi + margin * w)
}

/// Equal x and y scales: widens the smaller of the two ranges so one data
/// unit has the same length on both axes of a `SIZE` picture's plot area.
pub fn equal_aspect(x: (f64, f64), y: (f64, f64), area: (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let (wx, wy) = (x.1 - x.0, y.1 - y.0);
    let per_px = (wx / area.0).max(wy / area.1);
    let (cx, cy) = ((x.0 + x.1) / 2.0, (y.0 + y.1) / 2.0);
    let (hx, hy) = (per_px * area.0 / 2.0, per_px * area.1 / 2.0);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// The chart every plot draws on: caption, margins, and a mesh with the axis
/// descriptions, over `x × y`.
pub type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Builds the [`Chart`] on `root`.
pub fn chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    caption: impl AsRef<str>,
    x: (f64, f64),
    y: (f64, f64),
    x_desc: &str,
    y_desc: &str,
) -> Result<Chart<'a, 'b>> {
    let mut chart = ChartBuilder::on(root)
        .caption(caption.as_ref(), ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(55)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
        .map_err(draw)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .draw()
        .map_err(draw)?;
    Ok(chart)
}

/// The legend of the labelled series, upper right on a translucent box.
pub fn legend<'a, 'b: 'a>(chart: &mut Chart<'a, 'b>) -> Result<()> {
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(draw)
}

/// The parameter settings a plot of `info` draws, one per value in `values`
/// (one empty setting for a family without parameters); `what` names the
/// plot in the error for families with several parameters.
pub fn settings(info: &FamilyInfo, values: &[Rational], what: &str) -> Result<Vec<Vec<Rational>>> {
    match info.params.len() {
        0 => Ok(vec![vec![]]),
        1 if !values.is_empty() => Ok(values.iter().map(|v| vec![v.clone()]).collect()),
        1 => Err(PlotError::Input(format!(
            "give at least one value of {}",
            info.params[0].name
        ))),
        n => Err(PlotError::Input(format!(
            "`{}` has {n} parameters; {what} plots vary one",
            info.id
        ))),
    }
}
