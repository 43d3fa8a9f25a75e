//! A drawn picture: its SVG and the data it shows, series by series, for
//! the CSV file written beside it (a reader can re-plot or check it).

/// A picture: the SVG text and the drawn data.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Picture {
    pub svg: String,
    pub series: Vec<Series>,
}

/// One drawn series: its legend label (with the piece, where a curve is
/// drawn in pieces) and its points in data coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

impl Series {
    pub fn new(label: impl Into<String>, points: impl IntoIterator<Item = (f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points: points.into_iter().collect(),
        }
    }
}

impl Picture {
    /// The CSV header of [`Picture::rows`].
    pub const HEADER: [&'static str; 4] = ["series", "point", "x", "y"];

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

    #[test]
    fn rows_list_every_point_of_every_series() {
        let p = Picture {
            svg: String::new(),
            series: vec![
                Series::new("a", [(0.0, 1.0), (0.5, 0.25)]),
                Series::new("b", [(1.0, -2.0)]),
            ],
        };
        let rows = p.rows();
        assert_eq!(rows.len(), 3);
        assert_eq!(rows[1], ["a", "1", "0.5", "0.25"].map(String::from));
        assert_eq!(rows[2], ["b", "0", "1", "-2"].map(String::from));
    }
}
