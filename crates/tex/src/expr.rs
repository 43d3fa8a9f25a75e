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

/// `\frac{a}{b}` as `(a)/(b)` (brackets left out around one symbol): a
/// fraction cannot break across lines, its inline form breaks at the
/// operators of its numerator.
pub fn inline_fractions(latex: &str) -> String {
    const FRAC: &str = r"\frac{";
    let Some(at) = latex.find(FRAC) else {
        return latex.to_string();
    };
    // the group opened at byte `open` (a `{`) and the rest after its `}`
    let group = |open: usize| -> Option<(&str, &str)> {
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
    };
    let Some((num, rest)) = group(at + FRAC.len() - 1) else {
        return latex.to_string();
    };
    let Some((den, rest)) = rest
        .starts_with('{')
        .then(|| group(latex.len() - rest.len()))
        .flatten()
    else {
        return latex.to_string();
    };
    let wrap = |s: &str| {
        let s = inline_fractions(s);
        if s.contains([' ', '+', '-']) {
            format!("({s})")
        } else {
            s
        }
    };
    format!(
        "{}{}/{}{}",
        &latex[..at],
        wrap(num),
        wrap(den),
        inline_fractions(rest)
    )
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
    fn fractions_inline() {
        assert_eq!(
            inline_fractions(r"(\frac{-m w_{1} - 2}{w_{0}^{2}}) P_{0} + \frac{1}{2}"),
            r"((-m w_{1} - 2)/w_{0}^{2}) P_{0} + 1/2"
        );
    }
}
