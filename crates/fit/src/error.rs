//! Typed errors of the fitting pipeline.

use thiserror::Error;
use trig_core::CoreError;

/// What can go wrong when outline data is read or fitted.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FitError {
    /// The data file cannot be read (missing, unreadable); `what` names
    /// the data (`outline data`, `grid`).
    #[error("cannot read {what} `{path}`: {reason}")]
    Read {
        what: &'static str,
        path: String,
        reason: String,
    },
    /// A line of the data file is not `contour,x,y` with finite numbers.
    #[error("{origin}, line {line}: {reason}")]
    Malformed {
        origin: String,
        line: usize,
        reason: String,
    },
    /// A segment (or a whole contour) with too few points for the least-squares fit.
    #[error(
        "segment {segment} has {got} data points; a segment needs at least {needed} (its two end points and two inner points for V1, V2)"
    )]
    TooFewPoints {
        segment: usize,
        got: usize,
        needed: usize,
    },
    /// A grid row with a different number of heights than the first row.
    #[error(
        "{origin}, line {line}: {got} heights in this row, the first row has {expected}: a grid must be rectangular"
    )]
    GridShape {
        origin: String,
        line: usize,
        expected: usize,
        got: usize,
    },
    /// A height that is NaN or infinite.
    #[error("{origin}, line {line}: height {column} is not finite (NaN or infinite)")]
    NonFinite {
        origin: String,
        line: usize,
        column: usize,
    },
    /// An explicit corner index that is not an index of the data.
    #[error("corner index {index} is out of range: the outline has {count} points (indices 0..{})", count.saturating_sub(1))]
    CornerOutOfRange { index: usize, count: usize },
    /// A family the pipeline cannot fit (wrong number of functions, no end-point interpolation).
    #[error("family `{family}` cannot be fitted: {reason}")]
    Unsuitable { family: String, reason: String },
    /// A least-squares or constrained system without a unique solution.
    #[error("{what}: the linear system is singular")]
    Singular { what: String },
    /// A segment whose data points all coincide (no chord length).
    #[error("segment {segment}: all its data points coincide, no chord-length parameterisation")]
    Degenerate { segment: usize },
    /// An option value that cannot be used.
    #[error("bad option: {0}")]
    Option(String),
    /// An error of the catalog (parameters, ranges).
    #[error(transparent)]
    Core(#[from] CoreError),
}

/// Result alias for this crate.
pub type Result<T, E = FitError> = std::result::Result<T, E>;
