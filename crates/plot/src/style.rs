//! Shared look: size, colours, fonts, and the bounding box with a margin.

use plotters::style::RGBColor;

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
