//! The region of two shape parameters where a basis is nonnegative: the
//! classified cells of a window of the parameter plane (certified inside,
//! certified outside, undecided along the edge) with the printed box.

use plotters::prelude::*;

use crate::error::{Result, draw};
use crate::picture::{Picture, Series};
use crate::style::{SIZE, chart, colour, legend};

/// How a cell was classified.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RegionKind {
    /// Every function certified nonnegative on the cell.
    Inside,
    /// One function certified negative on the whole cell at one point.
    Outside,
    /// Not decided at the depth limit (the region's edge).
    Edge,
}

/// One cell `[x₀, x₁] × [y₀, y₁]` of the window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegionCell {
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub kind: RegionKind,
}

/// SVG of the classified window; `printed` is the printed box (its
/// infinite sides clipped to the window).
pub fn region_svg(
    title: &str,
    axes: (&str, &str),
    cells: &[RegionCell],
    printed: Option<((f64, f64), (f64, f64))>,
) -> Result<Picture> {
    let x = cells
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |a, c| {
            (a.0.min(c.x.0), a.1.max(c.x.1))
        });
    let y = cells
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |a, c| {
            (a.0.min(c.y.0), a.1.max(c.y.1))
        });
    if !(x.0.is_finite() && x.1 > x.0 && y.0.is_finite() && y.1 > y.0) {
        return Err(crate::PlotError::Input("no cells to draw".into()));
    }
    // room on the right for the legend
    let xr = (x.0, x.1 + 0.75 * (x.1 - x.0));
    // each cell as two points: its lower-left and upper-right corners
    let mut data: Vec<Series> = cells
        .iter()
        .enumerate()
        .map(|(k, c)| {
            Series::new(
                format!("{:?} cell {}", c.kind, k + 1).to_lowercase(),
                [(c.x.0, c.y.0), (c.x.1, c.y.1)],
            )
        })
        .collect();
    if let Some(((a, b), (c, d))) = printed {
        data.push(Series::new("printed box", [(a, c), (b, d)]));
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let mut chart = chart(&root, title, xr, y, axes.0, axes.1)?;
        let styles = [
            (
                RegionKind::Inside,
                colour(2).mix(0.55),
                "certified inside (every function ≥ 0)",
            ),
            (
                RegionKind::Outside,
                colour(1).mix(0.35),
                "certified outside (a function < 0)",
            ),
            (
                RegionKind::Edge,
                RGBColor(200, 200, 200).mix(0.9),
                "undecided (the edge, or where the negative function changes)",
            ),
        ];
        for (kind, style, label) in styles {
            let rects: Vec<_> = cells
                .iter()
                .filter(|c| c.kind == kind)
                .map(|c| Rectangle::new([(c.x.0, c.y.0), (c.x.1, c.y.1)], style.filled()))
                .collect();
            let count = rects.len();
            chart
                .draw_series(rects)
                .map_err(draw)?
                .label(format!("{label}: {count}"))
                .legend(move |(px, py)| {
                    Rectangle::new([(px, py - 5), (px + 14, py + 5)], style.filled())
                });
        }
        if let Some(((a, b), (c, d))) = printed {
            let clip = |v: f64, lo: f64, hi: f64| v.clamp(lo, hi);
            let corners = [
                (clip(a, x.0, x.1), clip(c, y.0, y.1)),
                (clip(b, x.0, x.1), clip(c, y.0, y.1)),
                (clip(b, x.0, x.1), clip(d, y.0, y.1)),
                (clip(a, x.0, x.1), clip(d, y.0, y.1)),
                (clip(a, x.0, x.1), clip(c, y.0, y.1)),
            ];
            chart
                .draw_series(std::iter::once(PathElement::new(
                    corners.to_vec(),
                    BLACK.stroke_width(2),
                )))
                .map_err(draw)?
                .label("printed box")
                .legend(|(px, py)| {
                    PathElement::new([(px, py), (px + 20, py)], BLACK.stroke_width(2))
                });
        }
        legend(&mut chart)?;
        root.present().map_err(draw)?;
    }
    Ok(Picture { svg, series: data })
}
