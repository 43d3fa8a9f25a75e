//! Text for LaTeX: prose escaped (the ten special characters, every mapped
//! Unicode character, math symbols as inline math), and formula-like runs
//! of a statement (`H_{2−i}(π/2 − u; β)`) set in math mode ([`prose`]).
//! The output is ASCII and compiles with pdfLaTeX.

use crate::math::{inline_math, math};
use crate::symbols::{TEXT, is_mathy, lookup};

/// Words that stay text even between formulas.
const WORDS: &[&str] = &[
    "a", "an", "as", "at", "be", "by", "for", "if", "in", "is", "it", "no", "not", "of", "on",
    "or", "so", "to", "and", "the", "all", "are", "but", "its", "one", "two", "see", "with",
];

/// Escapes text for LaTeX: the ten special characters, and every mapped
/// Unicode character (math symbols as inline math).
pub fn text(line: &str) -> String {
    let chars: Vec<char> = line.chars().collect();
    let mut out = String::with_capacity(line.len());
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if is_mathy(ch) {
            // a run of math characters, with the ASCII between them, as one formula
            let start = i;
            while i < chars.len() && (is_mathy(chars[i]) || chars[i] == '\u{304}') {
                i += 1;
            }
            let run: String = chars[start..i].iter().collect();
            out.push_str(&inline_math(&math(&run)));
            continue;
        }
        match ch {
            '\\' => out.push_str(r"\textbackslash{}"),
            '{' | '}' | '$' | '&' | '#' | '_' | '%' => {
                out.push('\\');
                out.push(ch);
            }
            '^' => out.push_str(r"\textasciicircum{}"),
            '~' => out.push_str(r"\textasciitilde{}"),
            '<' => out.push_str(r"\textless{}"),
            '>' => out.push_str(r"\textgreater{}"),
            '|' => out.push_str(r"\textbar{}"),
            '"' => out.push_str("''"),
            _ if ch.is_ascii() => out.push(ch),
            _ => match lookup(TEXT, ch) {
                Some(t) => out.push_str(t),
                None => out.push_str(&format!("[U+{:04X}]", u32::from(ch))),
            },
        }
        i += 1;
    }
    out
}

/// Escaped text that may break after `/`, `)`, `]`, `-`, `+` and `,` (a
/// long path or printed formula in `\texttt`).
pub fn breakable(line: &str) -> String {
    let mut out = String::new();
    for ch in line.chars() {
        out.push_str(&text(&ch.to_string()));
        if matches!(ch, '/' | ')' | ']' | '-' | '+' | ',') {
            out.push_str(r"\allowbreak{}");
        }
    }
    out
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Token {
    Math,
    Op,
    Var,
    Text,
}

fn classify(word: &str) -> Token {
    if word.contains(['_', '^']) || word.chars().any(|c| is_mathy(c) || c == '\u{304}') {
        return Token::Math;
    }
    if !word.is_empty() && word.chars().all(|c| "=+-<>/*".contains(c)) {
        return Token::Op;
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

/// Prose with formulas: whitespace-separated runs of formula-like words
/// (subscripts, superscripts, Unicode symbols, with the operators and short
/// variable names between them) set as one formula each, the rest escaped.
pub fn prose(line: &str) -> String {
    // `code spans` (commands, file names) in typewriter, the rest as prose
    if line.contains('`') {
        return line
            .split('`')
            .enumerate()
            .map(|(i, part)| {
                if i % 2 == 1 {
                    format!(r"\texttt{{{}}}", text(part))
                } else {
                    prose(part)
                }
            })
            .collect();
    }
    let words: Vec<&str> = line.split(' ').collect();
    let kinds: Vec<Token> = words.iter().map(|w| classify(w)).collect();
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
            out.push(format!("{}{punctuation}", inline_math(&math(formula))));
        } else {
            out.extend(run.iter().map(|w| text(w)));
        }
    }
    out.join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_special_characters_are_escaped() {
        assert_eq!(
            text(r"50% of {a_b} & $x^2 # ~\"),
            r"50\% of \{a\_b\} \& \$x\textasciicircum{}2 \# \textasciitilde{}\textbackslash{}"
        );
        assert_eq!(
            text("θ ↦ π/2 − θ, b₀ ≥ 0 — “ok”"),
            r"$\theta $ $\mapsto $ $\pi $/2 $-$ $\theta $, b$_{0}$ $\geq $ 0 --- ``ok''"
        );
    }

    #[test]
    fn statements_set_their_formulas_in_math() {
        assert_eq!(
            prose("H_i(u; β) = H_{2−i}(π/2 − u; β) (as printed)"),
            r"$H_{i}(u; \beta ) = H_{2-i}(\pi /2 - u; \beta )$ (as printed)"
        );
        assert_eq!(
            prose("x² + y²³ ≥ 0 for all x"),
            r"$x^{2} + y^{23} \geq  0$ for all x"
        );
        assert_eq!(prose("the set {1, 2}"), r"the set \{1, 2\}");
        assert_eq!(prose("in θ, exact"), r"in $\theta $, exact");
        assert_eq!(
            prose("(factor (π/2)^k), exact"),
            r"(factor $(\pi /2)^{k}$), exact"
        );
        assert_eq!(prose("P_{i,j} x̄"), r"$P_{i,j} \bar{x}$");
        assert_eq!(math("(1 + z²)^(−3) F^(4)"), r"(1 + z^{2})^{(-3)} F^{(4)}");
        assert_eq!(prose("b_{j+2,i} of {a_b}"), r"$b_{j+2,i}$ of $\{a_{b}\}$");
        assert_eq!(
            prose("run `trig-audit audit` now"),
            r"run \texttt{trig-audit audit} now"
        );
    }

    #[test]
    fn unknown_characters_are_marked() {
        assert_eq!(text("☃"), "[U+2603]");
        assert_eq!(breakable("a/b"), r"a/\allowbreak{}b");
    }
}
