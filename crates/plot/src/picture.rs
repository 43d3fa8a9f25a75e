//! A picture: the description of a chart (`chart`) with its SVG
//! (`svg`); the pgfplots code ([`Picture::pgf`]) and the CSV rows
//! ([`Picture::rows`]) are drawn from the same description.

use crate::chart::{Frame, Look, Series};
use crate::error::{PlotError, Result};
use crate::style::MAX_COORDINATE;

/// A picture: the frame, the drawn data, and its SVG.
#[derive(Debug, Clone, PartialEq)]
pub struct Picture {
    pub frame: Frame,
    pub series: Vec<Series>,
    pub svg: String,
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

impl Picture {
    /// The CSV header of [`Picture::rows`].
    pub const HEADER: [&'static str; 4] = ["series", "point", "x", "y"];

    /// Checks the frame's ranges and draws the SVG.
    pub fn new(frame: Frame, series: Vec<Series>) -> Result<Picture> {
        check_range(&frame.x_label, frame.x)?;
        check_range(&frame.y_label, frame.y)?;
        let svg = crate::svg::render(&frame, &series)?;
        Ok(Picture { frame, series, svg })
    }

    /// The same picture without its title (a paper's caption says what it
    /// shows): the SVG drawn again without the title's band.
    pub fn without_title(self) -> Result<Picture> {
        let frame = Frame {
            title: String::new(),
            ..self.frame
        };
        Picture::new(frame, self.series)
    }

    /// The legend entries in order, each with the look of its series.
    pub fn legend(&self) -> impl Iterator<Item = (&str, &Look)> {
        self.series
            .iter()
            .filter_map(|s| s.legend.as_deref().map(|t| (t, &s.look)))
    }

    /// The data, one row per point: series label, index of the point in
    /// its series, x, y (shortest round-trip decimals).
    pub fn rows(&self) -> Vec<[String; 4]> {
        self.series
            .iter()
            .flat_map(|s| {
                s.points.iter().enumerate().map(|(k, (x, y))| {
                    [s.label.clone(), k.to_string(), x.to_string(), y.to_string()]
                })
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame() -> Frame {
        Frame {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            caption: String::new(),
            x: (0.0, 1.0),
            y: (-2.0, 1.0),
            zero_line: false,
            equal_aspect: false,
        }
    }

    #[test]
    fn rows_list_every_point_of_every_series() {
        let look = Look::line((0, 0, 0), 1.0);
        let p = Picture::new(
            frame(),
            vec![
                Series::new("a", [(0.0, 1.0), (0.5, 0.25)], look).legend("A"),
                Series::new("b", [(1.0, -2.0)], look),
            ],
        )
        .unwrap();
        let rows = p.rows();
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[1], ["a", "1", "0.5", "0.25"].map(String::from));
        assert_eq!(rows[2], ["b", "0", "1", "-2"].map(String::from));
        assert_eq!(p.legend().map(|(t, _)| t).collect::<Vec<_>>(), ["A"]);
    }

    #[test]
    fn undrawable_ranges_are_refused() {
        for (x, y) in [
            ((0.0, 0.0), (0.0, 1.0)),
            ((0.0, f64::NAN), (0.0, 1.0)),
            ((0.0, 1.0), (-1e301, 1.0)),
        ] {
            let f = Frame { x, y, ..frame() };
            assert!(Picture::new(f, vec![]).is_err(), "{x:?} {y:?}");
        }
    }
}
