//! # trig-fit
//!
//! Least-squares fitting of cubic (trigonometric) curve segments to outline
//! data, as in the thesis's Chapter 6 (seed `001_cf6c2ede0355a863.txt`), for
//! any four-function, end-point-interpolating family of the catalog:
//!
//! 1. outline data: closed contours of points ([`data`]);
//! 2. corners (automatic rule or explicit) and segments ([`corners`]);
//! 3. chord-length parameters (6.9)–(6.10) ([`chord`]);
//! 4. inner control points by least squares with fixed ends (6.11)–(6.18) ([`lsq`]);
//! 5. optionally a per-segment shape parameter by golden-section search ([`optimise`]);
//! 6. error metrics of 6.7 ([`metrics`]);
//! 7. optionally a C¹ refinement of the joined segments ([`refine`]).
//!
//! [`pipeline::fit_outline`] runs all of it.
//!
//! Surfaces: a gridded height field ([`grid`]) fitted by tensor-product
//! patches joined C⁰ or C¹ ([`space`], [`surface::fit_surface`]).

pub mod banded;
pub mod basis;
pub mod chord;
pub mod corners;
pub mod data;
pub mod error;
pub mod grid;
pub mod lsq;
pub mod metrics;
pub mod optimise;
pub mod pipeline;
pub mod refine;
pub mod space;
pub mod surface;

pub use basis::{NumericBasis, SegmentBasis};
pub use corners::{CornerRule, Corners, Span};
pub use data::{Outline, P2};
pub use error::{FitError, Result};
pub use grid::Grid;
pub use metrics::{Metrics, Summary, THESIS_THRESHOLD};
pub use pipeline::{FitOptions, OutlineFit, SegmentFit, Shape, fit_outline};
pub use refine::Continuity;
pub use space::Join;
pub use surface::{PatchStats, Scope, Stats, SurfaceFit, SurfaceOptions, fit_surface};
