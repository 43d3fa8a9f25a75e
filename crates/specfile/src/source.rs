//! Positions in a spec file: byte offsets of TOML spans mapped to lines and
//! columns, and the errors that point there.

use toml::Spanned;

use crate::error::{FormulaError, Location, Result, SpecError};

/// The text of a spec file and its name, for locating errors.
pub(crate) struct Source<'a> {
    pub file: &'a str,
    pub text: &'a str,
}

impl Source<'_> {
    /// The line and column of a byte offset.
    pub fn at(&self, offset: usize) -> Location {
        let offset = offset.min(self.text.len());
        let before = self.text.get(..offset).unwrap_or("");
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        Location {
            file: self.file.to_string(),
            line,
            column,
        }
    }

    /// An invalid field value at `span`.
    pub fn invalid<T>(
        &self,
        span: std::ops::Range<usize>,
        field: &str,
        message: String,
    ) -> Result<T> {
        Err(SpecError::Invalid {
            at: self.at(span.start),
            field: field.into(),
            message,
        })
    }

    /// A formula error at its position inside the (single-line) string.
    pub fn formula_error(&self, text: &Spanned<String>, error: FormulaError) -> SpecError {
        let mut at = self.at(text.span().start);
        at.column += 1 + error.position;
        SpecError::Formula {
            at,
            formula: text.get_ref().clone(),
            error,
        }
    }
}
