//! A picture as data: its frame (title, axis labels, ranges) and its
//! series, each with its look and legend entry. The SVG ([`crate::svg`]),
//! the pgfplots code ([`Picture::pgf`]) and the CSV rows
//! ([`Picture::rows`]) are all drawn from this one description.

use crate::error::{PlotError, Result};
use crate::style::MAX_COORDINATE;

/// The frame of a picture: title, axis labels and the ranges shown.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub x: (f64, f64),
    pub y: (f64, f64),
    /// Draw the line `y = 0` (the point of positivity plots).
    pub zero_line: bool,
}

/// How a series is drawn (sizes in units of [`crate::style::UNIT_MM`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mark {
    /// A polyline; `vertices` marks its points.
    Line {
        width: f64,
        dashed: bool,
        vertices: bool,
    },
    /// A filled dot at each point.
    Dots { radius: f64 },
    /// A cross at each point.
    Crosses,
    /// The filled rectangle spanned by the two points of the series.
    Cell,
}

/// Colour, opacity and mark of a series.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    pub rgb: (u8, u8, u8),
    pub opacity: f64,
    pub mark: Mark,
}

impl Look {
    /// An opaque polyline.
    pub fn line(rgb: (u8, u8, u8), width: f64) -> Self {
        Look {
            rgb,
            opacity: 1.0,
            mark: Mark::Line {
                width,
                dashed: false,
                vertices: false,
            },
        }
    }

    /// An opaque mark `mark`.
    pub fn marks(rgb: (u8, u8, u8), mark: Mark) -> Self {
        Look {
            rgb,
            opacity: 1.0,
            mark,
        }
    }
}

/// One drawn series: its label in the data (with the piece, where a curve
/// is drawn in pieces), its points in data coordinates, its look, and its
/// legend entry (the first series of a group carries it).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub look: Look,
    pub legend: Option<String>,
}

impl Series {
    pub fn new(
        label: impl Into<String>,
        points: impl IntoIterator<Item = (f64, f64)>,
        look: Look,
    ) -> Self {
        Series {
            label: label.into(),
            points: points.into_iter().collect(),
            look,
            legend: None,
        }
    }

    /// The series with the legend entry `text`.
    pub fn legend(mut self, text: impl Into<String>) -> Self {
        self.legend = Some(text.into());
        self
    }
}

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
            x: (0.0, 1.0),
            y: (-2.0, 1.0),
            zero_line: false,
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
