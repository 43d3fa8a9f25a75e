//! Errors of exact evaluation and substitution.

use std::fmt;

/// Why an expression could not be evaluated or substituted.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum SymError {
    /// A variable of the expression has no value.
    UnboundVariable(String),
    /// A denominator factor (printed) vanishes at the given values.
    ZeroDenominator(String),
}

impl fmt::Display for SymError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SymError::UnboundVariable(name) => write!(f, "no value for the variable `{name}`"),
            SymError::ZeroDenominator(factor) => {
                write!(f, "the denominator factor `{factor}` vanishes")
            }
        }
    }
}

impl std::error::Error for SymError {}
