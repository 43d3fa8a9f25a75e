//! The LaTeX of expression pieces: variable names, powers, fractions,
//! numbers. The exact ring prints its expressions with these
//! (`trig_symbolic`'s LaTeX style), the tables their numbers.

use crate::math::math;
use crate::symbols::{greek, math_symbol};

/// A variable's name in math: a Greek name as its letter (`beta` →
/// `\beta`), one ASCII letter as itself, a longer ASCII name upright
/// (`\mathrm{foo}`), any other name through the math writer (`P_`, `y_i`,
/// `R''`, `P₁`); trailing `digits` as a subscript (`w0` → `w_{0}`,
/// `P_` and `2` → `P_{2}`, `y_i` and `1` → `y_{i}{}_{1}`).
pub fn name(prefix: &str, digits: &str) -> String {
    let prefix = if digits.is_empty() {
        prefix
    } else {
        prefix.strip_suffix('_').unwrap_or(prefix)
    };
    if let Some(letter) = greek(prefix).and_then(math_symbol) {
        return indexed(letter, digits);
    }
    if prefix.len() > 1 && prefix.chars().all(|c| c.is_ascii_alphabetic()) {
        return indexed(&format!(r"\mathrm{{{prefix}}}"), digits);
    }
    if digits.is_empty() {
        math(prefix)
    } else {
        math(&format!("{prefix}_{{{digits}}}"))
    }
}

/// `base` (a name without scripts) with `digits` as its index.
fn indexed(base: &str, digits: &str) -> String {
    if digits.is_empty() {
        base.to_string()
    } else {
        format!("{base}_{{{digits}}}")
    }
}

/// `base` raised to `exponent`: `base^{exponent}`.
pub fn power(base: &str, exponent: u32) -> String {
    format!("{base}^{{{exponent}}}")
}

/// The fraction `\frac{numerator}{denominator}`.
pub fn frac(numerator: &str, denominator: &str) -> String {
    format!(r"\frac{{{numerator}}}{{{denominator}}}")
}

/// A decimal number, scientific notation as a power of ten: `1.5e-3` →
/// `1.5 \times 10^{-3}`.
pub fn number(text: &str) -> String {
    match text.split_once('e') {
        Some((m, e)) => format!("{m} \\times 10^{{{e}}}"),
        None => text.to_string(),
    }
}

/// The group `{…}` opened at byte `open` of `latex`: its content and the
/// text after its closing brace.
fn group(latex: &str, open: usize) -> Option<(&str, &str)> {
    let mut depth = 0usize;
    for (k, c) in latex[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some((&latex[open + 1..open + k], &latex[open + k + 1..]));
                }
            }
            _ => {}
        }
    }
    None
}

/// The approximate width of LaTeX math in ems of its font (Computer
/// Modern, text style): letters and digits half an em, a binary operator
/// or relation with its spacing over an em, scripts at 70 %, an inline
/// fraction as wide as its wider part at 70 %. What a table needs to
/// decide whether a row fits the line; it errs on the wide side.
pub fn width(latex: &str) -> f64 {
    const FRAC: &str = r"\frac{";
    let mut w = 0.0;
    let mut rest = latex;
    while let Some(c) = rest.chars().next() {
        if rest.starts_with(FRAC)
            && let Some((num, after)) = group(rest, FRAC.len() - 1)
            && let Some((den, after)) = after.starts_with('{').then(|| group(after, 0)).flatten()
        {
            w += 0.7 * width(num).max(width(den)) + 0.2;
            rest = after;
            continue;
        }
        if (c == '^' || c == '_')
            && rest[1..].starts_with('{')
            && let Some((script, after)) = group(rest, 1)
        {
            w += 0.7 * width(script);
            rest = after;
            continue;
        }
        if c == '\\' {
            let name: String = rest[1..]
                .chars()
                .take_while(char::is_ascii_alphabetic)
                .collect();
            let len = 1 + name.len().max(1).min(rest.len() - 1);
            w += match name.as_str() {
                "" => 0.2,
                "cdot" | "times" | "pm" | "mp" => 1.2,
                "leq" | "geq" | "neq" | "to" | "mapsto" => 1.35,
                "left" | "right" | "mathrm" | "text" | "operatorname" => 0.0,
                _ => 0.6,
            };
            rest = &rest[len..];
            continue;
        }
        w += match c {
            ' ' | '{' | '}' => 0.0,
            '+' | '-' => 1.25,
            '=' | '<' | '>' => 1.35,
            '(' | ')' | '[' | ']' | '/' | '|' => 0.45,
            ',' | ';' => 0.45,
            'A'..='Z' => 0.8,
            _ => 0.55,
        };
        rest = &rest[c.len_utf8()..];
    }
    w
}

/// Table-cell math from an expression's LaTeX: a fraction stays
/// `\frac{a}{b}` when it is at most `room` ems wide ([`width`]), a wider
/// one is written inline as `(a)/(b)` so the line can break inside it;
/// a fraction followed by a factor is set off by a thin space
/// (`\frac{15}{8}\, m \pi^{6}`).
pub fn cell_math(latex: &str, room: f64) -> String {
    const FRAC: &str = r"\frac{";
    let Some(at) = latex.find(FRAC) else {
        return latex.to_string();
    };
    let parts = group(latex, at + FRAC.len() - 1).and_then(|(num, rest)| {
        let (den, rest) = rest.starts_with('{').then(|| group(rest, 0)).flatten()?;
        Some((num, den, rest))
    });
    let Some((num, den, rest)) = parts else {
        return latex.to_string();
    };
    let fraction = if width(num).max(width(den)) * 0.7 <= room {
        let tail = rest.trim_start();
        let factor = tail.starts_with(|c: char| c.is_ascii_alphabetic() || c == '(')
            || (tail.starts_with('\\') && !tail.starts_with(r"\cdot") && !tail.starts_with(r"\,"));
        let space = if factor { r"\, " } else { "" };
        format!(
            r"\frac{{{}}}{{{}}}{space}",
            cell_math(num, room),
            cell_math(den, room)
        )
    } else {
        let wrap = |s: &str| {
            let s = cell_math(s, room);
            if s.contains([' ', '+', '-']) {
                format!("({s})")
            } else {
                s
            }
        };
        format!("{}/{}", wrap(num), wrap(den))
    };
    let rest = cell_math(rest, room);
    let rest = if fraction.ends_with(' ') {
        rest.trim_start().to_string()
    } else {
        rest
    };
    format!("{}{fraction}{rest}", &latex[..at])
}

/// Math in which a run of digits may break after every tenth digit that
/// another follows (`\allowbreak`): a proved decimal of 60 digits is wider
/// than a column.
pub fn breakable_digits(latex: &str) -> String {
    let mut out = String::new();
    let mut run = 0usize;
    let chars: Vec<char> = latex.chars().collect();
    for (i, &c) in chars.iter().enumerate() {
        out.push(c);
        run = if c.is_ascii_digit() { run + 1 } else { 0 };
        if run > 0 && run % 10 == 0 && chars.get(i + 1).is_some_and(char::is_ascii_digit) {
            out.push_str(r"\allowbreak ");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_powers_fractions_and_numbers() {
        assert_eq!(name("beta", ""), r"\beta");
        assert_eq!(name("h", "12"), "h_{12}");
        assert_eq!(name("foo", ""), r"\mathrm{foo}");
        assert_eq!(name("gamma", "1"), r"\gamma_{1}");
        assert_eq!(name("foo", "1"), r"\mathrm{foo}_{1}");
        // names with scripts, primes and underscores of their own
        assert_eq!(name("P_", "2"), "P_{2}");
        assert_eq!(name("b1_", "2"), "b_{1}{}_{2}");
        assert_eq!(name("y_i", "1"), "y_{i}{}_{1}");
        assert_eq!(name("P₁", ""), "P_{1}");
        assert_eq!(name("R''", ""), "R''");
        assert_eq!(name("P′", "0"), "P'_{0}");
        assert_eq!(name("x_", ""), r"x\_");
        assert_eq!(power("(m + 1)", 2), "(m + 1)^{2}");
        assert_eq!(frac("1", "2"), r"\frac{1}{2}");
        assert_eq!(number("1.5e-3"), r"1.5 \times 10^{-3}");
        assert_eq!(number("0.25"), "0.25");
    }

    #[test]
    fn table_cells_keep_fractions_that_fit() {
        assert_eq!(
            cell_math(r"\frac{15}{8} m \pi^{6}", 10.0),
            r"\frac{15}{8}\, m \pi^{6}"
        );
        assert_eq!(cell_math(r"-\frac{1}{2}", 10.0), r"-\frac{1}{2}");
        // a fraction wider than the room is written inline, its parts kept
        let long = r"\frac{a + b + c + d + e + f}{2 \frac{1}{3}}";
        assert_eq!(
            cell_math(long, 3.0),
            r"(a + b + c + d + e + f)/(2 \frac{1}{3})"
        );
        assert!(width("a + b") > width("ab"));
        assert!(width(r"\frac{1}{2}") < width("1/2"));
    }

    #[test]
    fn long_digit_runs_may_break() {
        let digits = "1".repeat(25);
        assert_eq!(
            breakable_digits(&format!("-0.{digits}")),
            format!(r"-0.{0}\allowbreak {0}\allowbreak 11111", "1".repeat(10))
        );
        assert_eq!(breakable_digits("12345 x_{10}"), "12345 x_{10}");
        assert_eq!(breakable_digits(&"2".repeat(10)), "2".repeat(10));
    }

    #[test]
    fn fractions_inline() {
        assert_eq!(
            cell_math(r"(\frac{-m w_{1} - 2}{w_{0}^{2}}) P_{0} + \frac{1}{2}", 0.0),
            r"((-m w_{1} - 2)/w_{0}^{2}) P_{0} + 1/2"
        );
    }
}
