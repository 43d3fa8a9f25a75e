//! LaTeX math: formula text (`H_{2−i}(π/2 − u; β)`, `b0'(0) = 3/A`,
//! `sin α`) in math mode ([`math`]), and the ways a formula is set in text
//! (inline, or on its own line scaled to fit).
//!
//! The one math writer of the crate: function names upright (`\sin`,
//! `\operatorname{sgn}`), a letter's trailing digits as its index (`P1` →
//! `P_{1}`), primes as primes (`R''`, `b′`), `a/b` of simple operands as
//! `\frac{a}{b}`, Unicode super- and subscripts as scripts, `x̄` as
//! `\bar{x}`. Any input gives valid LaTeX: a stray `_` or `^` is escaped, a
//! second script on the same base is set on an empty group, braces that are
//! not a script's group are literal braces.

use crate::symbols::{MATH, SUB, SUPER, TEXT, greek, lookup, math_symbol};

/// A formula (LaTeX math) inline in text: `$…$`.
pub fn inline_math(latex: &str) -> String {
    format!("${latex}$")
}

/// A formula (LaTeX math) inline in running text: `$…$`, with a line
/// break allowed after each `, ` and `; ` (a list of conditions).
pub(crate) fn inline_breakable(latex: &str) -> String {
    inline_math(
        &latex
            .replace(", ", r",\allowbreak ")
            .replace("; ", r";\allowbreak "),
    )
}

/// A long formula (LaTeX math) on its own line, scaled down only if wider
/// than the line (`\fitmath`, defined by [`crate::PREAMBLE`] and by
/// [`crate::FRAGMENT_SETUP`]).
pub fn fitted_math(latex: &str) -> String {
    format!(r"\fitmath{{{latex}}}")
}

/// Names set upright as operators (`\sin`); the others of
/// [`OPERATOR_NAMES`] are set with `\operatorname`.
const FUNCTIONS: &[&str] = &[
    "sin", "cos", "tan", "cot", "sec", "csc", "sinh", "cosh", "tanh", "coth", "arcsin", "arccos",
    "arctan", "exp", "log", "ln", "lg", "max", "min", "det", "gcd", "deg", "lim", "sup", "inf",
    "arg", "dim", "ker",
];

/// A formula-like piece of text in LaTeX math (without `$`).
pub fn math(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let pieces = fractions(pieces(&chars, true));
    join(&pieces)
}

/// A formula (as [`math`] reads it) in Unicode for a reader without LaTeX
/// (an SVG's text): a letter's trailing digits and `_{…}` or `_x` as
/// subscripts (`b0` → `b₀`, `P_{12}` → `P₁₂`) where every character has a
/// subscript form, a Greek name as its letter (`beta` → `β`); the rest as
/// written.
pub(crate) fn unicode(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let sub = |run: &[char]| -> Option<String> {
        let mapped: Option<String> = run
            .iter()
            .map(|c| {
                SUB.iter()
                    .find(|(_, s)| s.len() == c.len_utf8() && s.starts_with(*c))
                    .map(|(u, _)| *u)
            })
            .collect();
        mapped.filter(|m| !m.is_empty())
    };
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if ch.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_alphabetic() {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            match greek(&word) {
                Some(letter) => out.push(letter),
                None => out.push_str(&word),
            }
            let digits = i;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            match sub(&chars[digits..i]) {
                Some(s) if !FUNCTIONS.contains(&word.as_str()) => out.push_str(&s),
                _ => out.extend(&chars[digits..i]),
            }
            continue;
        }
        if ch == '_' {
            let (run, next) = match chars.get(i + 1) {
                Some('{') => match closing(&chars, i + 1, '{', '}') {
                    Some(end) => (&chars[i + 2..end], end + 1),
                    None => (&chars[i..i], i),
                },
                Some(_) => (&chars[i + 1..i + 2], i + 2),
                None => (&chars[i..i], i),
            };
            if let Some(s) = sub(run) {
                out.push_str(&s);
                i = next;
                continue;
            }
        }
        out.push(ch);
        i += 1;
    }
    out
}

/// What a piece of a formula is, for fractions, scripts and spacing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// A letter, a number, a symbol that can be a fraction's operand.
    Atom,
    /// A sub- or superscript (with its `_`/`^`), or a prime.
    Sub,
    Sup,
    Prime,
    /// An upright function name (`\sin`).
    Function,
    Space,
    Slash,
    Open,
    Close,
    /// An operator, a relation, punctuation.
    Other,
}

#[derive(Debug, Clone)]
struct Piece {
    tex: String,
    kind: Kind,
}

fn piece(tex: impl Into<String>, kind: Kind) -> Piece {
    Piece {
        tex: tex.into(),
        kind,
    }
}

/// Whether `ch` is a Greek letter (`α`–`ω`, `Α`–`Ω`).
fn greek_letter(ch: char) -> bool {
    matches!(ch, 'α'..='ω' | 'Α'..='Ω' | 'ϵ' | 'ϑ' | 'ϕ')
}

/// The pieces of `chars`; `top` is false inside a script group (where a
/// letter's digits are not its index).
fn pieces(chars: &[char], top: bool) -> Vec<Piece> {
    let mut out: Vec<Piece> = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if chars.get(i + 1) == Some(&'\u{304}') {
            out.push(piece(format!(r"\bar{{{}}}", atom(ch)), Kind::Atom));
            i += 2;
            continue;
        }
        if let Some((table, kind, op)) = [(SUPER, Kind::Sup, '^'), (SUB, Kind::Sub, '_')]
            .into_iter()
            .find(|(t, _, _)| lookup(t, ch).is_some())
        {
            let mut run = String::new();
            while let Some(s) = chars.get(i).and_then(|c| lookup(table, *c)) {
                run.push_str(s);
                i += 1;
            }
            out.push(piece(format!("{op}{{{run}}}"), kind));
            continue;
        }
        if ch.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && chars[i].is_ascii_alphabetic() {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            // `sqrt(2)`: a radical over its bracketed argument
            if word == "sqrt"
                && chars.get(i) == Some(&'(')
                && let Some(end) = closing(chars, i, '(', ')')
            {
                let inner = join(&pieces(&chars[i + 1..end], top));
                out.push(piece(format!(r"\sqrt{{{inner}}}"), Kind::Atom));
                i = end + 1;
                continue;
            }
            out.extend(word_pieces(&word));
            // trailing digits: the index of a letter or name (`P1`,
            // `lambda2`); inside a script they are part of it (`b_{j0}`)
            let digits_start = i;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
            if top && i > digits_start && !FUNCTIONS.contains(&word.as_str()) {
                let digits: String = chars[digits_start..i].iter().collect();
                out.push(piece(format!("_{{{digits}}}"), Kind::Sub));
            } else {
                i = digits_start;
            }
            continue;
        }
        if ch.is_ascii_digit() {
            let start = i;
            while i < chars.len()
                && (chars[i].is_ascii_digit()
                    || (chars[i] == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)))
            {
                i += 1;
            }
            out.push(piece(
                chars[start..i].iter().collect::<String>(),
                Kind::Atom,
            ));
            continue;
        }
        match ch {
            '_' | '^' => {
                let kind = if ch == '_' { Kind::Sub } else { Kind::Sup };
                let (group, next) = script(chars, i + 1);
                match group {
                    Some(inner) => out.push(piece(format!("{ch}{{{inner}}}"), kind)),
                    None => out.push(piece(
                        if ch == '_' {
                            r"\_"
                        } else {
                            r"\text{\textasciicircum}"
                        },
                        Kind::Other,
                    )),
                }
                i = next;
                continue;
            }
            '\'' | '′' => out.push(piece("'", Kind::Prime)),
            '″' => out.push(piece("''", Kind::Prime)),
            '‴' => out.push(piece("'''", Kind::Prime)),
            ' ' | '\t' | '\n' => {
                if out.last().is_none_or(|p| p.kind != Kind::Space) {
                    out.push(piece(" ", Kind::Space));
                }
            }
            '/' => out.push(piece("/", Kind::Slash)),
            '(' | '[' => out.push(piece(ch.to_string(), Kind::Open)),
            ')' | ']' => out.push(piece(ch.to_string(), Kind::Close)),
            '{' => out.push(piece(r"\{", Kind::Open)),
            '}' => out.push(piece(r"\}", Kind::Close)),
            'Σ' => out.push(piece(r"\sum", Kind::Other)),
            'Π' => out.push(piece(r"\prod", Kind::Other)),
            // `m1*`, `p*`: a star on its operand; `2*P3`: a product
            '*' if chars
                .get(i + 1)
                .is_some_and(|c| c.is_alphanumeric() || *c == '(') =>
            {
                out.push(piece(r"\cdot", Kind::Other));
            }
            '*' => out.push(piece("^{*}", Kind::Sup)),
            '°' => out.push(piece(r"^{\circ}", Kind::Sup)),
            _ => {
                let kind = if lookup(MATH, ch).is_some_and(|m| {
                    m.starts_with('\\')
                        && m[1..].chars().all(char::is_alphabetic)
                        && ch.is_alphabetic()
                }) {
                    Kind::Atom
                } else {
                    Kind::Other
                };
                out.push(piece(atom(ch), kind));
                // a Greek letter's trailing digits are its index (`λ1`, `α0`)
                let digits = chars[i + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_digit())
                    .count();
                if top && kind == Kind::Atom && greek_letter(ch) && digits > 0 {
                    let index: String = chars[i + 1..=i + digits].iter().collect();
                    out.push(piece(format!("_{{{index}}}"), Kind::Sub));
                    i += digits;
                }
            }
        }
        i += 1;
    }
    out
}

/// The pieces of an ASCII word: a function name upright, a Greek name as
/// its letter, one or two letters as themselves (a product `mn`), a longer
/// word as an operator name.
fn word_pieces(word: &str) -> Vec<Piece> {
    if FUNCTIONS.contains(&word) {
        return vec![piece(format!(r"\{word}"), Kind::Function)];
    }
    if let Some(letter) = greek(word).and_then(math_symbol) {
        return vec![piece(letter, Kind::Atom)];
    }
    if word.len() <= 2 {
        return word
            .chars()
            .map(|c| piece(c.to_string(), Kind::Atom))
            .collect();
    }
    vec![piece(format!(r"\operatorname{{{word}}}"), Kind::Function)]
}

/// The script after `_`/`^` at `at`: its LaTeX (a `{…}` or `(…)` group,
/// the digits of a number, one character) and the index after it; `None`
/// when nothing follows that can be a script.
fn script(chars: &[char], at: usize) -> (Option<String>, usize) {
    match chars.get(at) {
        Some('{') => match closing(chars, at, '{', '}') {
            Some(end) => (Some(join(&pieces(&chars[at + 1..end], false))), end + 1),
            None => (None, at),
        },
        // `^(−3)`, `F^(4)`: the bracketed group is the script
        Some('(') => match closing(chars, at, '(', ')') {
            Some(end) => (Some(join(&pieces(&chars[at..=end], false))), end + 1),
            None => (None, at),
        },
        Some(c) if c.is_ascii_digit() => {
            let end = (at..chars.len())
                .find(|&k| !chars[k].is_ascii_digit())
                .unwrap_or(chars.len());
            (Some(chars[at..end].iter().collect()), end)
        }
        Some(c)
            if c.is_whitespace()
                || matches!(c, '_' | '^' | '}' | ')' | ',' | ';')
                || lookup(SUB, *c).is_some()
                || lookup(SUPER, *c).is_some() =>
        {
            (None, at)
        }
        Some(&c) => (Some(join(&pieces(&[c], false))), at + 1),
        None => (None, at),
    }
}

/// The index of the `close` matching the `open` at `at`, if any.
fn closing(chars: &[char], at: usize, open: char, close: char) -> Option<usize> {
    let mut depth = 0usize;
    for (k, c) in chars.iter().enumerate().skip(at) {
        if *c == open {
            depth += 1;
        } else if *c == close {
            depth -= 1;
            if depth == 0 {
                return Some(k);
            }
        }
    }
    None
}

/// Pieces that can be the operand of a fraction.
fn operand(kind: Kind) -> bool {
    matches!(kind, Kind::Atom | Kind::Sub | Kind::Sup | Kind::Prime)
}

/// `a/b` with simple operands (letters, numbers, their scripts; no space,
/// no bracket) as `\frac{a}{b}`, unless a function name comes before `a`
/// (`sin α/2` stays as printed) or the fraction is part of a chain.
fn fractions(pieces: Vec<Piece>) -> Vec<Piece> {
    let mut out: Vec<Piece> = Vec::new();
    let mut i = 0;
    while i < pieces.len() {
        if pieces[i].kind == Kind::Slash {
            let left = out.iter().rev().take_while(|p| operand(p.kind)).count();
            let right = pieces[i + 1..]
                .iter()
                .take_while(|p| operand(p.kind))
                .count();
            let first_left = out.len() - left;
            let before = out[..first_left]
                .iter()
                .rev()
                .find(|p| p.kind != Kind::Space)
                .map(|p| p.kind);
            let adjacent_before = out[..first_left].last().map(|p| p.kind);
            let after = pieces.get(i + 1 + right).map(|p| p.kind);
            let simple = left > 0
                && right > 0
                && out[first_left].kind == Kind::Atom
                && pieces[i + 1].kind == Kind::Atom
                && before != Some(Kind::Function)
                && !matches!(adjacent_before, Some(Kind::Close | Kind::Slash))
                && !matches!(after, Some(Kind::Open | Kind::Slash));
            if simple {
                let num = join(&out.split_off(first_left));
                let den = join(&pieces[i + 1..i + 1 + right]);
                out.push(piece(format!(r"\frac{{{num}}}{{{den}}}"), Kind::Atom));
                i += 1 + right;
                continue;
            }
        }
        out.push(pieces[i].clone());
        i += 1;
    }
    out
}

/// The LaTeX of pieces: a space between a command and a following letter,
/// an empty group before a second superscript (or prime) or subscript of
/// one base (`x^{2}{}'`, `y_{i}{}_{1}`).
fn join(pieces: &[Piece]) -> String {
    let mut out = String::new();
    let (mut sup, mut sub) = (false, false);
    let mut previous: Option<Kind> = None;
    for p in pieces {
        match p.kind {
            Kind::Sup | Kind::Prime => {
                // `''` is one run of primes; `'^{2}` one superscript
                let merges = previous == Some(Kind::Prime);
                if sup && !merges {
                    out.push_str("{}");
                    sub = false;
                }
                sup = true;
            }
            Kind::Sub => {
                if sub {
                    out.push_str("{}");
                    sup = false;
                }
                sub = true;
            }
            Kind::Space => {}
            _ => (sup, sub) = (false, false),
        }
        let word = out.len()
            - out
                .trim_end_matches(|c: char| c.is_ascii_alphabetic())
                .len();
        let command = word > 0 && out[..out.len() - word].ends_with('\\');
        if command && p.tex.starts_with(|c: char| c.is_ascii_alphanumeric()) {
            out.push(' ');
        }
        out.push_str(&p.tex);
        previous = Some(p.kind);
    }
    out
}

/// One character in math mode.
fn atom(ch: char) -> String {
    if let Some(m) = lookup(MATH, ch) {
        return m.to_string();
    }
    match ch {
        '\\' => r"\backslash".into(),
        '$' | '&' | '#' | '%' => format!(r"\{ch}"),
        '~' => r"\sim".into(),
        '"' => r"\text{''}".into(),
        '…' => r"\ldots".into(),
        _ if ch.is_ascii() => ch.to_string(),
        _ => match lookup(TEXT, ch) {
            Some(t) => format!(r"\text{{{t}}}"),
            None => format!(r"\text{{[U+{:04X}]}}", u32::from(ch)),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_in_unicode_have_subscripts() {
        assert_eq!(unicode("b0"), "b₀");
        assert_eq!(unicode("λ = −1/2, t ∈ [0, π/2]"), "λ = −1/2, t ∈ [0, π/2]");
        assert_eq!(unicode("beta_0 + P_{12} − V0…V3"), "β₀ + P₁₂ − V₀…V₃");
        // no subscript form, a function name's digits: as written
        assert_eq!(unicode("x_{a} sin2 2.5"), "x_{a} sin2 2.5");
        assert_eq!(unicode("x_"), "x_");
    }

    #[test]
    fn names_indices_functions_and_primes() {
        assert_eq!(math("P1 − P0"), "P_{1} - P_{0}");
        assert_eq!(math("R''(0)"), "R''(0)");
        assert_eq!(math("b0′(0) = 1"), "b_{0}'(0) = 1");
        assert_eq!(
            math("(μ1 + 2)/(λ2 + 2)"),
            r"(\mu_{1} + 2)/(\lambda_{2} + 2)"
        );
        assert_eq!(
            math("α0(0) = α1′(1), 2α"),
            r"\alpha_{0}(0) = \alpha_{1}'(1), 2\alpha"
        );
        assert_eq!(math("tan α + cos(x)"), r"\tan \alpha + \cos(x)");
        assert_eq!(math("λ·sqrt(2) + 2 = 0"), r"\lambda\cdot\sqrt{2} + 2 = 0");
        assert_eq!(math("sinh t"), r"\sinh t");
        assert_eq!(math("sgn x"), r"\operatorname{sgn} x");
        assert_eq!(math("Σ b_i = 1"), r"\sum b_{i} = 1");
        assert_eq!(math("x̄ ≥ 0"), r"\bar{x} \geq 0");
    }

    #[test]
    fn simple_quotients_are_fractions() {
        assert_eq!(math("π/2 − u"), r"\frac{\pi}{2} - u");
        assert_eq!(math("3π/2"), r"\frac{3\pi}{2}");
        assert_eq!(math("πu/2"), r"\frac{\pi u}{2}");
        assert_eq!(math("b3'''(0) = 1/A"), r"b_{3}'''(0) = \frac{1}{A}");
        // brackets, a function before, a chain: as printed
        assert_eq!(math("(P1 − P0)/2"), "(P_{1} - P_{0})/2");
        assert_eq!(math("sin α/(1 − cos α)"), r"\sin \alpha/(1 - \cos \alpha)");
        assert_eq!(math("sin α/2"), r"\sin \alpha/2");
        assert_eq!(math("a/b/c"), "a/b/c");
        assert_eq!(math("H_{2−i}(π/2)"), r"H_{2-i}(\frac{\pi}{2})");
    }

    #[test]
    fn scripts_of_any_form_are_valid() {
        assert_eq!(math("(1 + z²)^(−3) F^(4)"), "(1 + z^{2})^{(-3)} F^{(4)}");
        assert_eq!(math("P_2"), "P_{2}");
        assert_eq!(math("P_12"), "P_{12}");
        assert_eq!(math("P_"), r"P\_");
        assert_eq!(math("a_ b"), r"a\_ b");
        assert_eq!(math("P₁₂"), "P_{12}");
        assert_eq!(math("P_₁"), r"P\__{1}");
        assert_eq!(math("x²'"), "x^{2}{}'");
        assert_eq!(math("x₁₂_3"), "x_{12}{}_{3}");
        assert_eq!(math("x^2^3"), "x^{2}{}^{3}");
        assert_eq!(math("{1, 2}"), r"\{1, 2\}");
        assert_eq!(math("h_{i+1"), r"h\_\{i+1");
        assert_eq!(math("y_i₁"), "y_{i}{}_{1}");
        assert_eq!(math("P′₀″"), "P'_{0}{}''");
        assert_eq!(
            math("b_{j0} m1* 2*P3 p*"),
            r"b_{j0} m_{1}^{*} 2\cdot P_{3} p^{*}"
        );
    }
}
