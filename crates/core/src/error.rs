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
    /// A parameter outside its published range. (Commands that take
    /// `--allow-outside-range` add that hint.)
    #[error("{name} = {value} is outside the published range {range} of `{family}`")]
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
    /// A divisor that contains zero in its enclosure at the highest
    /// precision tried: neither proved zero nor proved nonzero.
    #[error("{quantity}: a denominator cannot be certified nonzero (tried up to {bits} bits)")]
    NotCertifiedNonzero { quantity: String, bits: u32 },
    /// A finite exact value beyond the range of the arithmetic (f64, or
    /// MPFR's exponent range).
    #[error("{quantity} overflows the range of the arithmetic")]
    Overflow { quantity: String },
    /// A comparison that enclosures could not decide at the highest precision.
    #[error("cannot decide {what} (tried up to {bits} bits)")]
    Undecidable { what: String, bits: u32 },
    /// An exact input that f64 cannot hold.
    #[error("{what} {kind} f64")]
    NotRepresentable { what: String, kind: String },
    /// A request beyond a documented limit of the cost model.
    #[error(
        "{what}: at most {limit} (a limit of trig-audit, to keep every request bounded in time)"
    )]
    Limit { what: String, limit: String },
    /// Input that could not be read (too large, not text, missing).
    #[error(transparent)]
    Input(#[from] crate::input::InputError),
    /// A weight that is not positive.
    #[error("weight w{index} = {value} is not positive")]
    NonPositiveWeight { index: usize, value: String },
}

/// Result alias for this crate.
pub type Result<T, E = CoreError> = std::result::Result<T, E>;
