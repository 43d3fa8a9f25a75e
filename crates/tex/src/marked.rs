//! Text with explicit math markup: the runs between [`OPEN`] and [`CLOSE`]
//! (`⟪b0'(0) = 3/A⟫ for ⟪m ∈ [−2, 1]⟫`) are formulas, the rest is prose.
//! Printed statements are stored this way, so that their math is known
//! rather than guessed: [`plain`] is the text as printed (what the Markdown
//! and JSON reports show), [`marked`] its LaTeX — formulas through the one
//! math writer ([`crate::math`]), prose escaped ([`crate::text`]).

use crate::math::{inline_breakable, math, unicode as unicode_formula};
use crate::text::{code, text};

/// Opens a formula in marked text (never in a seed).
pub const OPEN: char = '⟪';
/// Closes a formula in marked text.
pub const CLOSE: char = '⟫';

/// What is wrong with the markup of a text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MarkupError {
    /// A formula opened inside another, at this character index.
    #[error("formula opened inside a formula at {0}")]
    Nested(usize),
    /// A close without an open, at this character index.
    #[error("{CLOSE} without {OPEN} at {0}")]
    Unopened(usize),
    /// A formula opened at this character index is never closed.
    #[error("{OPEN} at {0} is never closed")]
    Unclosed(usize),
    /// An empty formula at this character index.
    #[error("empty formula at {0}")]
    Empty(usize),
}

/// The text as printed: the markup removed.
pub fn plain(text: &str) -> String {
    text.chars().filter(|c| *c != OPEN && *c != CLOSE).collect()
}

/// The text as a reader without LaTeX sees it (an SVG's text): the markup
/// removed, each formula's indices as Unicode subscripts (`⟪b0⟫` → `b₀`,
/// `⟪beta_1⟫` → `β₁`); the prose as printed.
pub fn unicode(text: &str) -> String {
    runs(text)
        .into_iter()
        .map(|(formula, run)| if formula { unicode_formula(&run) } else { run })
        .collect()
}

/// Checks the markup: formulas balanced, not nested, not empty.
pub fn check(text: &str) -> Result<(), MarkupError> {
    let mut open: Option<usize> = None;
    let mut previous = None;
    for (i, ch) in text.chars().enumerate() {
        match (ch, open) {
            (OPEN, Some(_)) => return Err(MarkupError::Nested(i)),
            (OPEN, None) => open = Some(i),
            (CLOSE, None) => return Err(MarkupError::Unopened(i)),
            (CLOSE, Some(at)) => {
                if previous == Some(OPEN) {
                    return Err(MarkupError::Empty(at));
                }
                open = None;
            }
            _ => {}
        }
        previous = Some(ch);
    }
    match open {
        Some(at) => Err(MarkupError::Unclosed(at)),
        None => Ok(()),
    }
}

/// The runs of marked text: `(is_formula, text)`. A formula left open runs
/// to the end; a stray close is dropped.
fn runs(text: &str) -> Vec<(bool, String)> {
    let mut out: Vec<(bool, String)> = vec![(false, String::new())];
    for ch in text.chars() {
        let inside = out.last().is_some_and(|r| r.0);
        match ch {
            OPEN if !inside => out.push((true, String::new())),
            CLOSE if inside => out.push((false, String::new())),
            OPEN | CLOSE => {}
            _ => {
                if let Some(last) = out.last_mut() {
                    last.1.push(ch);
                }
            }
        }
    }
    out.retain(|r| !r.1.is_empty());
    out
}

/// Marked text in LaTeX: each formula inline in math (breaking after its
/// commas and semicolons), the prose escaped
/// (its Unicode math symbols as inline math, `code spans` in typewriter).
/// Any input gives valid LaTeX.
pub fn marked(line: &str) -> String {
    marked_with(line, prose_run)
}

/// Marked text with its formulas set in math and the text between them set
/// by `between`.
pub(crate) fn marked_with(line: &str, between: impl Fn(&str) -> String) -> String {
    runs(line)
        .into_iter()
        .map(|(formula, run)| {
            if formula {
                inline_breakable(&math(&run))
            } else {
                between(&run)
            }
        })
        .collect()
}

/// Prose of marked text: escaped, `code spans` in typewriter.
fn prose_run(run: &str) -> String {
    run.split('`')
        .enumerate()
        .map(|(i, part)| if i % 2 == 1 { code(part) } else { text(part) })
        .collect()
}

/// Marked text shortened to at most `max` characters as printed, ending
/// with `…` when cut (an open formula closed before it).
pub fn truncate(line: &str, max: usize) -> String {
    if plain(line).chars().count() <= max {
        return line.to_string();
    }
    let mut out = String::new();
    let mut shown = 0;
    let mut inside = false;
    for ch in line.chars() {
        if shown + 1 >= max && ch != CLOSE {
            break;
        }
        match ch {
            OPEN => inside = true,
            CLOSE => inside = false,
            _ => shown += 1,
        }
        out.push(ch);
    }
    let mut out = out.trim_end().to_string();
    if out.ends_with(OPEN) {
        out.pop();
        inside = false;
    }
    if inside {
        out.push(CLOSE);
    }
    out.push('…');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_text_is_the_text_as_printed() {
        assert_eq!(
            plain("⟪b0'(0) = 1⟫ for ⟪m ∈ [−2, 1]⟫"),
            "b0'(0) = 1 for m ∈ [−2, 1]"
        );
        assert_eq!(plain("no math"), "no math");
    }

    #[test]
    fn unicode_text_has_subscripts_in_formulas_only() {
        assert_eq!(
            unicode("⟪b0⟫ at ⟪μ = 1/2⟫, seed000"),
            "b₀ at μ = 1/2, seed000"
        );
        assert_eq!(unicode("no math"), "no math");
    }

    #[test]
    fn markup_is_checked() {
        assert_eq!(check("⟪a⟫ and ⟪b⟫"), Ok(()));
        assert_eq!(check("⟪a ⟪b⟫⟫"), Err(MarkupError::Nested(3)));
        assert_eq!(check("a⟫"), Err(MarkupError::Unopened(1)));
        assert_eq!(check("⟪a"), Err(MarkupError::Unclosed(0)));
        assert_eq!(check("x ⟪⟫"), Err(MarkupError::Empty(2)));
    }

    #[test]
    fn formulas_are_math_and_prose_is_text() {
        assert_eq!(
            marked("reading of T4 (A45): ⟪H_i(u) = H_{2−i}(1 − u)⟫"),
            r"reading of T4 (A45): $H_{i}(u) = H_{2-i}(1 - u)$"
        );
        assert_eq!(
            marked("⟪R''(π/2)⟫, \"tan\" ≥ 0"),
            r"$R''(\frac{\pi}{2})$, ''tan'' $\geq$ 0"
        );
        // unbalanced markup still gives valid LaTeX
        assert_eq!(marked("a⟫ ⟪b_"), r"a $b\_$");
        assert_eq!(marked("run `x_y`"), r"run \texttt{x\_y}");
    }

    #[test]
    fn truncation_closes_an_open_formula() {
        assert_eq!(truncate("⟪a + b⟫ c", 20), "⟪a + b⟫ c");
        assert_eq!(truncate("⟪a + b + c⟫", 5), "⟪a +⟫…");
        assert_eq!(truncate("ab ⟪cd⟫", 4), "ab…");
        assert_eq!(plain(&truncate("⟪a + b + c⟫ d", 5)), "a +…");
    }
}
