//! Errors of the spec reader: every one names where (file, line, column —
//! or the formula and the position in it) and what was expected.

use std::fmt;

/// Where an error is: a file position, optionally inside a formula.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The file as given (or `<input>` for text without a file).
    pub file: String,
    /// 1-based line in the file.
    pub line: usize,
    /// 1-based column (characters) in the file.
    pub column: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.file, self.line, self.column)
    }
}

/// Why a formula could not be read: the position is a 0-based character
/// offset in the formula text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("at position {position}: {message}")]
pub struct FormulaError {
    pub position: usize,
    pub message: String,
}

impl FormulaError {
    pub(crate) fn new(position: usize, message: impl Into<String>) -> Self {
        FormulaError {
            position,
            message: message.into(),
        }
    }
}

/// Why a spec file could not be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SpecError {
    /// The file could not be read at all.
    #[error("{file}: cannot read: {reason}")]
    Io { file: String, reason: String },
    /// Not valid TOML, or a field missing, misspelt or of the wrong type.
    #[error("{at}: malformed spec file: {message}")]
    Malformed { at: Location, message: String },
    /// A value that is well-formed TOML but not what the field expects.
    #[error("{at}: {field}: {message}")]
    Invalid {
        at: Location,
        field: String,
        message: String,
    },
    /// A formula that does not parse or uses a symbol it may not use.
    #[error("{at}: in formula `{formula}` {error}")]
    Formula {
        at: Location,
        formula: String,
        error: FormulaError,
    },
}

/// Shorthand.
pub type Result<T> = std::result::Result<T, SpecError>;
