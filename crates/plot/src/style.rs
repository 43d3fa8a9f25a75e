//! Shared look: the layout (a 160 mm wide figure in units of 0.2 mm),
//! the font, colours and dash patterns, the bounding box with a margin,
//! equal scales.

use crate::chart::Dash;

/// The font family of the SVG's text: serif, as a paper's text (the
/// pgfplots code takes the document's own font).
pub const FONT_FAMILY: &str = "serif";

/// Millimetres per layout unit: the figure is [`WIDTH`] units = 160 mm wide.
pub const UNIT_MM: f64 = 0.2;

/// Width of a figure, in units.
pub const WIDTH: u32 = 800;

/// Height of the part above the legend (title, plot area, axis labels).
pub const CHART_HEIGHT: u32 = 560;

/// Height of the title line.
pub const TITLE_HEIGHT: u32 = 36;

/// Space left of the plot area (tick labels, y label).
pub const Y_LABEL_AREA: u32 = 72;

/// Space below the plot area (tick labels, x label).
pub const X_LABEL_AREA: u32 = 54;

/// Margin around the chart.
pub const MARGIN: u32 = 16;

/// The plot area (inside the axes), in units: what equal scales refer to
/// and what the pgfplots axis is sized to.
pub const PLOT_AREA: (f64, f64) = (
    (WIDTH - Y_LABEL_AREA - 2 * MARGIN) as f64,
    (CHART_HEIGHT - TITLE_HEIGHT - X_LABEL_AREA - 2 * MARGIN) as f64,
);

/// Font sizes (units): title, axis labels, tick labels, legend.
pub const FONT_TITLE: f64 = 17.0;
pub const FONT_LABEL: f64 = 15.0;
pub const FONT_TICK: f64 = 13.0;
pub const FONT_LEGEND: f64 = 14.0;

/// Line widths (units): a curve, a thin line (axes of reference, polygons).
pub const CURVE: f64 = 1.6;
pub const THIN: f64 = 0.8;

/// Legend lines up to this many characters go in two columns: in the
/// SVG (160 mm wide), and in the pgfplots code (a default article's
/// `\linewidth`, 345 pt, in a footnote-size font).
pub const SVG_LEGEND_TWO_COLUMNS: usize = 42;
pub const PGF_LEGEND_TWO_COLUMNS: usize = 30;

/// The number of legend columns for the legend `entries`: two when every
/// entry has at most `two_columns` characters.
pub fn legend_columns<'a>(mut entries: impl Iterator<Item = &'a str>, two_columns: usize) -> usize {
    if entries.all(|t| t.chars().count() <= two_columns) {
        2
    } else {
        1
    }
}

/// Black and greys.
pub const BLACK: (u8, u8, u8) = (0, 0, 0);
pub const GREY: (u8, u8, u8) = (110, 110, 110);
pub const LIGHT_GREY: (u8, u8, u8) = (160, 160, 160);

/// A colour-blind-safe palette (Okabe–Ito), cycled.
const PALETTE: [(u8, u8, u8); 7] = [
    (0, 114, 178),
    (213, 94, 0),
    (0, 158, 115),
    (204, 121, 167),
    (230, 159, 0),
    (86, 180, 233),
    (120, 120, 120),
];

/// The `k`-th colour of the palette.
pub fn colour(k: usize) -> (u8, u8, u8) {
    PALETTE[k % PALETTE.len()]
}

/// `rgb` at `opacity` over white, as an opaque colour.
pub fn over_white(rgb: (u8, u8, u8), opacity: f64) -> (u8, u8, u8) {
    let mix = |c: u8| (f64::from(c) * opacity + 255.0 * (1.0 - opacity)).round() as u8;
    (mix(rgb.0), mix(rgb.1), mix(rgb.2))
}

/// Dash patterns (units) after the solid line, cycled: dashed, dotted,
/// long dashes, sparse dots.
const DASHES: [Dash; 4] = [
    Dash { on: 7.0, off: 4.0 },
    Dash { on: 1.6, off: 3.2 },
    Dash { on: 16.0, off: 5.0 },
    Dash { on: 3.0, off: 8.0 },
];

/// The `k`-th line style: solid for `k = 0`, then the [`DASHES`] cycled.
pub fn dash(k: usize) -> Option<Dash> {
    k.checked_sub(1).map(|j| DASHES[j % DASHES.len()])
}

/// How far a cell of a region is drawn beyond its edges (units): adjacent
/// opaque cells overlap by this hair, so no seam shows between them.
pub const CELL_OVERLAP: f64 = 0.3;

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
/// unit has the same length on both axes of the [`PLOT_AREA`].
pub fn equal_aspect(x: (f64, f64), y: (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let area = PLOT_AREA;
    let (hx, hy) = (x.1 / 2.0 - x.0 / 2.0, y.1 / 2.0 - y.0 / 2.0);
    let per_px = (hx / area.0).max(hy / area.1);
    let (cx, cy) = (x.0 / 2.0 + x.1 / 2.0, y.0 / 2.0 + y.1 / 2.0);
    let (hx, hy) = (per_px * area.0, per_px * area.1);
    ((cx - hx, cx + hx), (cy - hy, cy + hy))
}
