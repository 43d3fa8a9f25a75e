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
            formula: excerpt(text.get_ref(), error.position),
            error,
        }
    }
}

/// At most [`trig_core::echo::MAX_ECHO`] characters of `formula` around
/// `position` (control characters escaped), with `…` where it is cut.
fn excerpt(formula: &str, position: usize) -> String {
    let max = trig_core::echo::MAX_ECHO;
    let count = formula.chars().count();
    if count <= max {
        return trig_core::echo(formula);
    }
    let start = position.saturating_sub(max / 2).min(count - max);
    let window: String = formula.chars().skip(start).take(max).collect();
    let before = if start > 0 { "…" } else { "" };
    let after = if start + max < count { "…" } else { "" };
    format!(
        "{before}{}{after}",
        trig_core::echo::escape_controls(&window)
    )
}
