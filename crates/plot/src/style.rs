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

/// Largest coordinate magnitude a picture's axes can span: beyond it the
/// axis arithmetic (widths, tick steps) leaves the range of f64.
pub const MAX_COORDINATE: f64 = 1e300;

/// `[lo, hi]` of `values` widened by `margin` of the width (and never
/// empty: at least a relative 10⁻⁹ of the magnitude). Widths are computed
/// in halves, so no intermediate overflows; non-finite values make the
/// range non-finite, which [`chart`] refuses.
pub fn padded(values: impl Iterator<Item = f64>, margin: f64) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        if v.is_nan() {
            (f64::NAN, f64::NAN)
        } else {
            (a.min(v), b.max(v))
        }
    });
    let half = (hi / 2.0 - lo / 2.0)
        .max(1e-9 * lo.abs().max(hi.abs()) / 2.0)
        .max(5e-10);
    (lo - 2.0 * margin * half, hi + 2.0 * margin * half)
}

/// Equal x and y scales: widens the smaller of the two ranges so one data
/// unit has the same length on both axes of a `SIZE` picture's plot area.
pub fn equal_aspect(x: (f64, f64), y: (f64, f64), area: (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let (hx, hy) = (x.1 / 2.0 - x.0 / 2.0, y.1 / 2.0 - y.0 / 2.0);
    let per_px = (hx / area.0).max(hy / area.1);
    let (cx, cy) = (x.0 / 2.0 + x.1 / 2.0, y.0 / 2.0 + y.1 / 2.0);
    let (hx, hy) = (per_px * area.0, per_px * area.1);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}

/// Refuses axis ranges that cannot be drawn: non-finite, beyond
/// ±[`MAX_COORDINATE`], or empty.
fn check_range(axis: &str, r: (f64, f64)) -> Result<()> {
    let inside = |v: f64| v.is_finite() && v.abs() <= MAX_COORDINATE;
    if !(inside(r.0) && inside(r.1)) {
        return Err(PlotError::Input(format!(
            "the {axis} values reach beyond ±{MAX_COORDINATE:e} (or are not finite); such a picture cannot be drawn"
        )));
    }
    if r.1 <= r.0 {
        return Err(PlotError::Input(format!("the {axis} range is empty")));
    }
    Ok(())
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
    check_range(x_desc, x)?;
    check_range(y_desc, y)?;
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
