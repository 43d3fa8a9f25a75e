//! # trig-plot
//!
//! SVG pictures drawn with `plotters`: the basis functions of a family for
//! several parameter values (as thesis Figures 3.1, 3.6), a curve with its
//! control polygon for several parameter values (Figure 6.3), and fitted
//! outlines over their data (Figures 6.5–6.7, 6.11–6.22), and piecewise
//! interpolants with their data points (thesis 4.3). Every picture has
//! axes, axis labels, a caption and a legend.
//!
//! Each function returns a [`Picture`]: the SVG text and the drawn data
//! (series of points), which the caller writes as the figure and a CSV
//! file beside it.

pub mod basis;
pub mod curve;
pub mod error;
pub mod fit;
pub mod interp;
pub mod picture;
pub mod plotted;
pub mod region;
mod style;

pub use basis::basis_svg;
pub use curve::curve_svg;
pub use error::PlotError;
pub use fit::fit_svg;
pub use interp::{Interpolant, interp_svg};
pub use picture::{Picture, Series};
pub use plotted::Plotted;
pub use region::{RegionCell, RegionKind, region_svg};
