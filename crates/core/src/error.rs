//! Typed errors for every input the library rejects.

use thiserror::Error;

/// What can go wrong when a family, curve or surface is evaluated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum CoreError {
    /// No family of the catalog has this id.
    #[error("unknown family `{0}` (run `trig-audit list` for the catalog)")]
    UnknownFamily(String),
    /// The family is catalogued but its formulas are not available.
    #[error("family `{0}` has no formulas in our copy of its source")]
    NoFormulas(String),
    /// A parameter name the family does not have.
    #[error("family `{family}` has no parameter `{name}` (expected: {expected})")]
    UnknownParameter {
        family: String,
        name: String,
        expected: String,
    },
    /// A parameter the family needs was not given.
    #[error("family `{family}` needs parameter `{name}`")]
    MissingParameter { family: String, name: String },
    /// A value that could not be parsed.
    #[error("cannot read `{input}` as {expected}")]
    Malformed { input: String, expected: String },
    /// A parameter outside its published range.
    #[error(
        "{name} = {value} is outside the published range {range} of `{family}` (pass --allow-outside-range to evaluate anyway)"
    )]
    OutOfRange {
        family: String,
        name: String,
        value: String,
        range: String,
    },
    /// An evaluation point outside the family's domain.
    #[error("point {value} is outside the domain {domain}")]
    PointOutsideDomain { value: String, domain: String },
    /// NaN or an infinity given as input.
    #[error("{what} is not a finite number")]
    NotFinite { what: String },
    /// A denominator that vanishes for this input.
    #[error("division by zero in {quantity}")]
    DivisionByZero { quantity: String },
    /// A quantity whose formula reaches outside the knot vector.
    #[error("{quantity} is undefined: it needs {needs}, outside the knot vector")]
    Undefined { quantity: String, needs: String },
    /// A knot vector that is not usable.
    #[error("bad knot vector: {0}")]
    Knots(String),
    /// Control points, weights or functions whose counts do not match.
    #[error("{what}: expected {expected}, got {got}")]
    Count {
        what: String,
        expected: usize,
        got: usize,
    },
    /// A weight that is not positive.
    #[error("weight w{index} = {value} is not positive")]
    NonPositiveWeight { index: usize, value: String },
}

/// Result alias for this crate.
pub type Result<T, E = CoreError> = std::result::Result<T, E>;
