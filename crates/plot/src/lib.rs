//! # trig-plot
//!
//! Figures for a paper: the basis functions of a family for several
//! parameter values (as thesis Figures 3.1, 3.6), alone or over another
//! basis (a listing beside the printed formulas), a curve with its
//! control polygon for several parameter values (Figure 6.3), and fitted
//! outlines over their data (Figures 6.5–6.7, 6.11–6.22), and piecewise
//! interpolants with their data points (thesis 4.3), the region of two
//! shape parameters, and the error map of a fitted surface. Every picture
//! has axes, axis labels, a title (left out with
//! [`Picture::without_title`] where a caption says it) and a legend below
//! the chart; functions are told apart by colour, parameter
//! values by line style.
//!
//! Each function returns a [`Picture`]: a description (frame, series with
//! their looks and legend entries) from which come the SVG (drawn with
//! `plotters`, 160 mm wide, coordinates to 0.02 mm, serif text), the
//! pgfplots code ([`Picture::pgf`]: a fragment to `\input`, as wide as
//! asked) and the CSV rows ([`Picture::rows`]).

pub mod basis;
mod chart;
pub mod curve;
pub mod error;
pub mod error_map;
pub mod fit;
pub mod interp;
pub mod mesh;
mod pgf;
pub mod picture;
pub mod plotted;
pub mod region;
mod style;
pub mod surface;
pub mod surface_pgf;
pub mod surface_svg;
mod svg;

pub use basis::{basis_svg, basis_versus_svg};
pub use chart::{Dash, Frame, Look, Mark, Series};
pub use curve::curve_svg;
pub use error::PlotError;
pub use error_map::error_map_svg;
pub use fit::fit_svg;
pub use interp::{Interpolant, interp_svg};
pub use mesh::{Mesh, MeshFormat};
pub use pgf::PgfOptions;
pub use picture::Picture;
pub use plotted::{Choice, Plotted};
pub use region::{CellLabels, RegionCell, RegionKind, region_svg};
pub use surface::{PATCH_COLOURS, SurfaceFigure, SurfacePatch, View};
pub use surface_pgf::surface_pgf;
pub use surface_svg::surface_svg;
