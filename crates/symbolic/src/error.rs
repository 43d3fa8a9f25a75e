//! Errors of exact evaluation, substitution and renaming.

use std::fmt;

/// Why an expression could not be evaluated or substituted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SymError {
    /// A variable of the expression has no value.
    UnboundVariable(String),
    /// A denominator factor (printed) vanishes at the given values.
    ZeroDenominator(String),
    /// A renaming of variables that is not a plain one-to-one renaming
    /// (why, in words).
    Rename(String),
}

impl fmt::Display for SymError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SymError::UnboundVariable(name) => write!(f, "no value for the variable `{name}`"),
            SymError::ZeroDenominator(factor) => {
                write!(f, "the denominator factor `{factor}` vanishes")
            }
            SymError::Rename(why) => write!(f, "cannot rename: {why}"),
        }
    }
}

impl std::error::Error for SymError {}
