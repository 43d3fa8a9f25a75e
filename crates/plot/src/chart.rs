//! A chart as data: its frame (title, axis labels, ranges) and its
//! series, each with its look and legend entry — what every output
//! format (SVG, pgfplots, CSV) draws from. The title, the axis labels and
//! the legend entries are marked text (`⟪…⟫` around formulas,
//! [`trig_tex::marked()`]): set in math by the pgfplots code, in Unicode by
//! the SVG; a series' own label (the CSV's) is plain text.

/// The frame of a picture: title, axis labels and the ranges shown.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    /// What a caption may say beside the title (the source of a basis):
    /// written as a comment of the pgfplots code.
    pub caption: String,
    pub x: (f64, f64),
    pub y: (f64, f64),
    /// Draw the line `y = 0` (the point of positivity plots).
    pub zero_line: bool,
    /// One data unit as long on both axes (curves, outlines): the ranges
    /// are set for it (`style::equal_aspect`) and the pgfplots axis
    /// keeps it at any width.
    pub equal_aspect: bool,
}

/// A dash pattern: `on` units drawn, then `off` units blank.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dash {
    pub on: f64,
    pub off: f64,
}

/// How a series is drawn (sizes in units of `style::UNIT_MM`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mark {
    /// A polyline, solid or dashed; `vertices` marks its points.
    Line {
        width: f64,
        dash: Option<Dash>,
        vertices: bool,
    },
    /// A filled dot at each point.
    Dots { radius: f64 },
    /// A cross at each point.
    Crosses,
    /// The filled rectangle spanned by the two points of the series
    /// (opaque: adjacent cells are drawn overlapping by a hair, so that no
    /// seam shows between them).
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
                dash: None,
                vertices: false,
            },
        }
    }

    /// The same look with the dash pattern `dash` (a line).
    pub fn dashed(mut self, dash: Option<Dash>) -> Self {
        if let Mark::Line { dash: d, .. } = &mut self.mark {
            *d = dash;
        }
        self
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
