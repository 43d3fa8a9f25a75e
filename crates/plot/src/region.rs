//! The region of two shape parameters where a basis is nonnegative: the
//! classified cells of a window of the parameter plane (certified inside,
//! certified outside, undecided along the edge) with the printed box. Each
//! kind is drawn in one opaque colour, its cells overlapping by a hair
//! (`style::CELL_OVERLAP`): a set of cells reads as one area, with
//! no seams between them.

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::Result;
use crate::picture::Picture;
use crate::plotted::formula;
use crate::style::{BLACK, CURVE, colour, over_white};

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

/// What the cells of each kind were certified to be, for the legend.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CellLabels {
    pub inside: &'static str,
    pub outside: &'static str,
    pub edge: &'static str,
}

impl CellLabels {
    /// The region where every function is `≥ 0`.
    pub const NONNEGATIVE: CellLabels = CellLabels {
        inside: "certified inside (every function ≥ 0)",
        outside: "certified outside (a function < 0)",
        edge: "undecided (the edge, or where the negative function changes)",
    };
    /// Where the functions are linearly independent.
    pub const INDEPENDENT: CellLabels = CellLabels {
        inside: "certified independent (a maximal minor of one strict sign on the cell)",
        outside: "dependent on the whole cell",
        edge: "undecided (where a point of the exceptional set may lie)",
    };
    /// The region where the basis is totally positive.
    pub const TOTALLY_POSITIVE: CellLabels = CellLabels {
        inside: "certified inside (totally positive: every minor of the factorisation ≥ 0)",
        outside: "certified outside (a necessary condition fails)",
        edge: "undecided (the edge, or beyond the certificate)",
    };
}

/// The classified window; `printed` is the printed box (its
/// infinite sides clipped to the window).
pub fn region_svg(
    title: &str,
    axes: (&str, &str),
    cells: &[RegionCell],
    printed: Option<((f64, f64), (f64, f64))>,
    labels: CellLabels,
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
    let styles = [
        (RegionKind::Inside, colour(2), 0.55, labels.inside),
        (RegionKind::Outside, colour(1), 0.35, labels.outside),
        (RegionKind::Edge, (200, 200, 200), 0.9, labels.edge),
    ];
    // each cell as two points: its lower-left and upper-right corners
    let mut series = Vec::new();
    for (kind, rgb, opacity, label) in styles {
        // opaque, so overlapping neighbours leave no seam: the set as it is
        let look = Look::marks(over_white(rgb, opacity), Mark::Cell);
        let count = cells.iter().filter(|c| c.kind == kind).count();
        for (k, c) in cells.iter().filter(|c| c.kind == kind).enumerate() {
            let s = Series::new(
                format!("{kind:?} cell {}", k + 1).to_lowercase(),
                [(c.x.0, c.y.0), (c.x.1, c.y.1)],
                look,
            );
            series.push(if k == 0 {
                s.legend(format!("{label}: {count}"))
            } else {
                s
            });
        }
    }
    if let Some(((a, b), (c, d))) = printed {
        // the box clipped to the window, as a closed path
        let (a, b) = (a.clamp(x.0, x.1), b.clamp(x.0, x.1));
        let (c, d) = (c.clamp(y.0, y.1), d.clamp(y.0, y.1));
        series.push(
            Series::new(
                "printed box (clipped to the window)",
                [(a, c), (b, c), (b, d), (a, d), (a, c)],
                Look::line(BLACK, CURVE),
            )
            .legend("printed box"),
        );
    }
    let frame = Frame {
        title: title.into(),
        x_label: formula(axes.0),
        y_label: formula(axes.1),
        caption: String::new(),
        x,
        y,
        zero_line: false,
        equal_aspect: false,
    };
    Picture::new(frame, series)
}
