//! Prose with formulas for LaTeX ([`prose`]): text with markup is set as
//! marked ([`crate::marked`](mod@crate::marked)); generated text without markup (evidence
//! lines, labels) has its formula-like runs (`H_{2−i}(π/2 − u; β)`) found by
//! their look and set in math mode, the rest escaped ([`crate::text`]).

use crate::marked::{CLOSE, OPEN, marked, marked_with};
use crate::math::{inline_breakable, math};
use crate::symbols::is_mathy;
use crate::text::{code, text};

/// Words that stay text even between formulas.
const WORDS: &[&str] = &[
    "a", "an", "as", "at", "be", "by", "for", "if", "in", "is", "it", "no", "not", "of", "on",
    "or", "so", "to", "and", "the", "all", "are", "but", "its", "one", "two", "see", "with",
];

#[derive(Clone, Copy, PartialEq, Eq)]
enum Token {
    Math,
    Op,
    Var,
    Text,
}

/// An equation or appendix number in brackets (`(4.21)`, `(A45)`).
fn is_label(word: &str) -> bool {
    let Some(inner) = word.strip_prefix('(').and_then(|w| w.strip_suffix(')')) else {
        return false;
    };
    let number = inner.trim_start_matches(|c: char| c.is_ascii_uppercase());
    inner.len() - number.len() <= 1
        && number.starts_with(|c: char| c.is_ascii_digit())
        && number.chars().all(|c| c.is_ascii_digit() || c == '.')
        && (number.len() < inner.len() || number.contains('.'))
}

/// A product written with `*` between a number or name and a name
/// (`26624*lambda`, `2*mu`): ASCII formula text. Code (`m.*cos(t)`,
/// `(pi/2)*t`) is not one.
fn is_product(word: &str) -> bool {
    let chars: Vec<char> = word.chars().collect();
    !word.contains(".*")
        && chars
            .windows(3)
            .any(|w| w[1] == '*' && w[0].is_ascii_alphanumeric() && w[2].is_ascii_alphabetic())
}

/// A prime after a name or bracket (`R''(0)`, `b0'`), not a possessive.
fn has_prime(word: &str) -> bool {
    let core = word.trim_end_matches([',', ';', ':', '.']);
    let chars: Vec<char> = core.chars().collect();
    !core.ends_with("'s")
        && chars
            .windows(2)
            .any(|w| w[1] == '\'' && (w[0].is_ascii_alphanumeric() || w[0] == ')' || w[0] == '\''))
}

fn classify(word: &str) -> Token {
    let trimmed = word.trim_end_matches([',', ';', '.']);
    // labels stay text: `(4.21)`, `(A45)`, a claim id before a colon (`T4:`)
    let id_before_colon = trimmed.ends_with(':')
        && !trimmed.chars().any(is_mathy)
        && trimmed.contains(|c: char| c.is_ascii_alphabetic());
    if is_label(trimmed) || id_before_colon {
        return Token::Text;
    }
    if word.contains(['_', '^'])
        || is_product(trimmed)
        || has_prime(word)
        || word.chars().any(|c| is_mathy(c) || c == '\u{304}')
    {
        return Token::Math;
    }
    if !word.is_empty() && word.chars().all(|c| "=+-<>/*".contains(c)) {
        return Token::Op;
    }
    // a function of a short name applied: `Q2(0)`, `R(t;`
    let name = trimmed.trim_end_matches(':');
    let letters = name.len()
        - name
            .trim_start_matches(|c: char| c.is_ascii_alphabetic())
            .len();
    let after = name[letters..].trim_start_matches(|c: char| c.is_ascii_digit());
    if (1..=2).contains(&letters)
        && after.starts_with('(')
        && !WORDS.contains(&name[..letters].to_ascii_lowercase().as_str())
    {
        return Token::Math;
    }
    let core: String = word
        .trim_matches(|c: char| "()[],;:.".contains(c))
        .to_string();
    let number = core.trim_start_matches('-');
    if !number.is_empty()
        && number
            .chars()
            .all(|c| c.is_ascii_digit() || c == '/' || c == '.')
    {
        return Token::Var;
    }
    // a product or call of short names and numbers: `4(w1/w0)(P1`
    let letter_runs = core
        .split(|c: char| !c.is_ascii_alphabetic())
        .filter(|run| !run.is_empty());
    if core.contains(|c: char| c.is_ascii_digit())
        && core.contains(['(', ')', '/'])
        && letter_runs.clone().count() > 0
        && letter_runs.clone().all(|run| run.len() <= 2)
        && core
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "()[]/+*.,".contains(c))
    {
        return Token::Var;
    }
    let mut cs = core.chars();
    let letters = cs.by_ref().take_while(|c| c.is_ascii_alphabetic()).count();
    let rest: String = core.chars().skip(letters).collect();
    if (1..=2).contains(&letters)
        && rest.chars().all(|c| c.is_ascii_digit())
        && !WORDS.contains(&core.to_ascii_lowercase().as_str())
    {
        return Token::Var;
    }
    Token::Text
}

/// Prose with formulas. Text with markup ([`crate::marked`](mod@crate::marked)) is set as
/// marked; generated text without markup (evidence lines, labels) has its
/// formula-like runs found by their look: whitespace-separated runs of
/// formula-like words (subscripts, superscripts, Unicode symbols, with the
/// operators and short variable names between them) set as one formula
/// each, the rest escaped. Printed statements carry markup and never go
/// through this guess.
pub fn prose(line: &str) -> String {
    if line.contains([OPEN, CLOSE]) {
        return marked(line);
    }
    // `code spans` (commands, file names) in typewriter, the rest as prose
    if line.contains('`') {
        return line
            .split('`')
            .enumerate()
            .map(
                |(i, part)| {
                    if i % 2 == 1 { code(part) } else { prose(part) }
                },
            )
            .collect();
    }
    let words: Vec<&str> = line.split(' ').collect();
    let kinds: Vec<Token> = words.iter().map(|w| classify(w)).collect();
    // a word ending a clause: `,`, `;` or `:` outside brackets
    let mut depth = 0i32;
    let ends: Vec<bool> = words
        .iter()
        .map(|w| {
            for c in w.chars() {
                match c {
                    '(' | '[' | '{' => depth += 1,
                    ')' | ']' | '}' => depth -= 1,
                    _ => {}
                }
            }
            depth <= 0 && w.ends_with([',', ';', ':'])
        })
        .collect();
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < words.len() {
        if kinds[i] == Token::Text {
            out.push(text(words[i]));
            i += 1;
            continue;
        }
        let start = i;
        while i < words.len() && kinds[i] != Token::Text {
            i += 1;
            if ends[i - 1] {
                break;
            }
        }
        let run = &words[start..i];
        if kinds[start..i].contains(&Token::Math) {
            // punctuation ending the run, and a bracket it does not open,
            // belong to the sentence, not the formula
            let joined = run.join(" ");
            let mut formula = joined.as_str();
            loop {
                let unopened = formula.ends_with(')')
                    && formula.matches(')').count() > formula.matches('(').count();
                if formula.ends_with([',', ';', ':', '.']) || unopened {
                    formula = &formula[..formula.len() - 1];
                } else {
                    break;
                }
            }
            let punctuation = &joined[formula.len()..];
            out.push(format!("{}{punctuation}", inline_breakable(&math(formula))));
        } else {
            out.extend(run.iter().map(|w| text(w)));
        }
    }
    out.join(" ")
}

/// Marked text whose prose may hold formulas of its own (a basis's title
/// beside marked values, as a figure's heading): the marked formulas set
/// as [`marked`] sets them, the prose between them as [`prose`] sets
/// generated text.
pub fn labelled(line: &str) -> String {
    marked_with(line, prose)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn headings_set_marked_and_unmarked_formulas() {
        assert_eq!(
            labelled("cubic basis b_i(u; m) at ⟪μ = 1/2⟫"),
            r"cubic basis $b_{i}(u;\allowbreak m)$ at $\mu = \frac{1}{2}$"
        );
        assert_eq!(labelled("plain & simple"), r"plain \& simple");
    }

    #[test]
    fn statements_set_their_formulas_in_math() {
        assert_eq!(
            prose("H_i(u; β) = H_{2−i}(π/2 − u; β) (as printed)"),
            r"$H_{i}(u;\allowbreak \beta) = H_{2-i}(\frac{\pi}{2} - u;\allowbreak \beta)$ (as printed)"
        );
        assert_eq!(
            prose("x² + y²³ ≥ 0 for all x"),
            r"$x^{2} + y^{23} \geq 0$ for all x"
        );
        assert_eq!(prose("the set {1, 2}"), r"the set \{1, 2\}");
        assert_eq!(prose("in θ, exact"), r"in $\theta$, exact");
        assert_eq!(
            prose("(factor (π/2)^k), exact"),
            r"(factor $(\frac{\pi}{2})^{k}$), exact"
        );
        assert_eq!(prose("P_{i,j} x̄"), r"$P_{i,j} \bar{x}$");
        assert_eq!(math("(1 + z²)^(−3) F^(4)"), r"(1 + z^{2})^{(-3)} F^{(4)}");
        assert_eq!(prose("b_{j+2,i} of {a_b}"), r"$b_{j+2,i}$ of $\{a_{b}\}$");
        // primes are math, labels and claim ids text
        assert_eq!(
            prose("R''(0) − printed (A45) (4.21) Han's"),
            r"$R''(0) -$ printed (A45) (4.21) Han's"
        );
        assert_eq!(
            prose("R'(0) − 4(w1/w0)(P1 −P0) (as printed)"),
            r"$R'(0) - 4(\frac{w_{1}}{w_{0}})(P_{1} -P_{0})$ (as printed)"
        );
        assert_eq!(
            prose("Condition 1, Q2(0); T4 holds"),
            r"Condition 1, $Q_{2}(0)$; T4 holds"
        );
        assert_eq!(
            prose("reading of T4: H_i(u) = 1"),
            r"reading of T4: $H_{i}(u) = 1$"
        );
        // ASCII products and a fraction before a colon are formulas
        assert_eq!(
            prose("root of 3*lambda^2 - 26624*lambda - 8192 = 0 in"),
            r"root of $3\cdot\lambda^{2} - 26624\cdot\lambda - 8192 = 0$ in"
        );
        assert_eq!(
            prose("z = 1/4 (θ ≈ 0.49, s = 8/17, c = 15/17): value"),
            r"$z = \frac{1}{4} (\theta \approx 0.49,\allowbreak s = \frac{8}{17},\allowbreak c = \frac{15}{17})$: value"
        );
        assert_eq!(
            prose("run `trig-audit audit` now"),
            r"run \texttt{trig-audit audit} now"
        );
    }
}
