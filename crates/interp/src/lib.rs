//! # trig-interp
//!
//! The positivity-preserving interpolation schemes of thesis section 4.3
//! (seed 001): the C¹ (4.21), C² (4.25, with (4.22)–(4.24)), G¹ (4.26)–(4.27)
//! and G² (4.28)–(4.34) schemes, built on the thesis's data Tables 4.1–4.6
//! ([`data`]) with the arithmetic-mean derivative estimates ([`slopes`]),
//! generically over [`trig_core::Ring`]: exact (`Sym`, π a symbol), rational
//! intervals ([`interval`], for certification) and f64 ([`plot`]).
//!
//! Every piece uses the catalog's thesis cubic basis (3.7)
//! (`Family::ThesisCubic`) and `trig_deriv`'s endpoint derivatives in `x`;
//! printed formulas are typed once, as printed, in [`scheme`], beside the
//! corrected variants derived from the same end conditions.

pub mod data;
pub mod interval;
pub mod jumps;
pub mod kind;
pub mod minimum;
pub mod piece;
pub mod plot;
pub mod scheme;
pub mod slopes;

pub use data::{DataSet, Table};
pub use interval::Interval;
pub use jumps::{KnotJump, knot_jumps};
pub use kind::{Scheme, Variant};
pub use minimum::{PieceMinimum, Proof, certified_minimum};
pub use piece::Piece;
pub use plot::{PlotSegment, f64_segments};
pub use scheme::{Spline, build};

/// The basis every piece is built on: the thesis cubic (3.7).
pub const BASIS: trig_core::Family = trig_core::Family::ThesisCubic;

/// What can go wrong building or certifying an interpolant.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InterpError {
    #[error(
        "unknown data set `{0}` (expected thesis-table-4.1, thesis-table-4.2, thesis-table-4.3, thesis-table-4.4, thesis-table-4.5 or thesis-table-4.6)"
    )]
    UnknownData(String),
    #[error("unknown scheme `{0}` (expected c1, c2, g1 or g2)")]
    UnknownScheme(String),
    #[error("`{data}` has no `{column}` column, which the {scheme} scheme needs")]
    MissingColumn {
        data: String,
        column: String,
        scheme: Scheme,
    },
    #[error("malformed data: {0}")]
    Malformed(String),
    #[error("singular scheme: {0}")]
    Singular(String),
    #[error("cannot certify: {0}")]
    Enclosure(String),
}
