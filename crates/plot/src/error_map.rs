//! The error map of a surface fit: one cell per grid point, coloured by
//! the absolute error `|S(uᵢ, vⱼ) − zᵢⱼ|` in classes (the legend names each
//! class's interval and its number of points), the patch boundaries drawn
//! over it. The classes halve from the largest error down:
//! `(max/2, max]`, `(max/4, max/2]`, … `[0, max/32]`, light yellow to dark
//! red.

use trig_fit::SurfaceFit;

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::{PlotError, Result};
use crate::picture::Picture;
use crate::style::{BLACK, THIN, equal_aspect};

/// Colour classes, smallest errors first.
const RAMP: [(u8, u8, u8); 6] = [
    (255, 255, 204),
    (254, 217, 118),
    (253, 141, 60),
    (240, 59, 32),
    (189, 0, 38),
    (99, 0, 30),
];

/// The class of `e` for the largest error `max`: 5 for `(max/2, max]`,
/// 4 for `(max/4, max/2]`, … 0 for `[0, max/32]`.
fn class(e: f64, max: f64) -> usize {
    let mut upper = max;
    for k in (1..RAMP.len()).rev() {
        if e > upper / 2.0 {
            return k;
        }
        upper /= 2.0;
    }
    0
}

/// The error map of `fit` on a grid with `spacing` (data units per grid
/// step, the same in both directions): row `i` at `x = i·spacing`,
/// column `j` at `y = j·spacing`.
pub fn error_map_svg(title: &str, fit: &SurfaceFit, spacing: f64) -> Result<Picture> {
    let (rows, cols) = (fit.error.nrows(), fit.error.ncols());
    if rows < 2 || cols < 2 || !(spacing.is_finite() && spacing > 0.0) {
        return Err(PlotError::Input(format!(
            "an error map needs a grid of at least 2 × 2 points and a positive spacing ({rows} × {cols}, {spacing})"
        )));
    }
    let max = fit.overall.max;
    let half = spacing / 2.0;
    let mut classes: Vec<Vec<Series>> = vec![Vec::new(); RAMP.len()];
    for i in 0..rows {
        for j in 0..cols {
            let e = fit.error[(i, j)].abs();
            let k = class(e, max);
            let (x, y) = (i as f64 * spacing, j as f64 * spacing);
            classes[k].push(Series::new(
                format!("error at row {} column {}", i + 1, j + 1),
                [(x - half, y - half), (x + half, y + half)],
                Look::marks(RAMP[k], Mark::Cell),
            ));
        }
    }
    let mut series = Vec::with_capacity(rows * cols + fit.patches.0 + fit.patches.1 + 2);
    for (k, mut cells) in classes.into_iter().enumerate().rev() {
        let count = cells.len();
        if let Some(first) = cells.first_mut() {
            let hi = max / f64::powi(2.0, (RAMP.len() - 1 - k) as i32);
            let lo = if k == 0 { 0.0 } else { hi / 2.0 };
            let open = if k == 0 { "[" } else { "(" };
            first.legend = Some(format!(
                "|error| in {open}{lo:.3}, {hi:.3}]: {count} points"
            ));
        }
        series.extend(cells);
    }
    let (width, height) = ((rows - 1) as f64 * spacing, (cols - 1) as f64 * spacing);
    let boundary = Look::line(BLACK, THIN);
    for k in 0..=fit.patches.0 {
        let x = width * k as f64 / fit.patches.0 as f64;
        let s = Series::new(
            format!("patch boundary u = {k}/{}", fit.patches.0),
            [(x, -half), (x, height + half)],
            boundary,
        );
        series.push(if k == 0 {
            s.legend("patch boundaries")
        } else {
            s
        });
    }
    for l in 0..=fit.patches.1 {
        let y = height * l as f64 / fit.patches.1 as f64;
        series.push(Series::new(
            format!("patch boundary v = {l}/{}", fit.patches.1),
            [(-half, y), (width + half, y)],
            boundary,
        ));
    }
    let (x, y) = equal_aspect((-half, width + half), (-half, height + half));
    let frame = Frame {
        title: title.into(),
        x_label: format!("x (row index × {spacing})"),
        y_label: format!("y (column index × {spacing})"),
        caption: String::new(),
        x,
        y,
        zero_line: false,
        equal_aspect: true,
    };
    Picture::new(frame, series)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_halve_from_the_largest_error() {
        let max = 32.0;
        assert_eq!(class(32.0, max), 5);
        assert_eq!(class(16.5, max), 5);
        assert_eq!(class(16.0, max), 4);
        assert_eq!(class(8.5, max), 4);
        assert_eq!(class(1.5, max), 1);
        assert_eq!(class(1.0, max), 0);
        assert_eq!(class(0.0, max), 0);
        assert_eq!(class(0.0, 0.0), 0);
    }
}
