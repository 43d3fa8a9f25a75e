//! Text for LaTeX: prose escaped, every Unicode character of the reports
//! mapped (Greek letters, operators, super- and subscripts, dashes, quotes,
//! the glyph names of thesis Chapter 6), and formula-like runs of a
//! statement (`H_{2−i}(π/2 − u; β)`) set in math mode. The output is ASCII
//! and compiles with pdfLaTeX; a character without a mapping is written as
//! `[U+XXXX]` (and [`unmapped`] finds such characters, so a test can insist
//! there are none).

/// Characters set in math mode, with their LaTeX (math) form.
const MATH: &[(char, &str)] = &[
    ('α', r"\alpha"),
    ('β', r"\beta"),
    ('γ', r"\gamma"),
    ('δ', r"\delta"),
    ('ε', r"\varepsilon"),
    ('ϵ', r"\epsilon"),
    ('ζ', r"\zeta"),
    ('η', r"\eta"),
    ('θ', r"\theta"),
    ('λ', r"\lambda"),
    ('μ', r"\mu"),
    ('ξ', r"\xi"),
    ('π', r"\pi"),
    ('ρ', r"\rho"),
    ('σ', r"\sigma"),
    ('φ', r"\varphi"),
    ('ψ', r"\psi"),
    ('ω', r"\omega"),
    ('Σ', r"\Sigma"),
    ('Δ', r"\Delta"),
    ('Π', r"\Pi"),
    ('−', "-"),
    ('≥', r"\geq"),
    ('≤', r"\leq"),
    ('≠', r"\neq"),
    ('≈', r"\approx"),
    ('≡', r"\equiv"),
    ('∈', r"\in"),
    ('⊂', r"\subset"),
    ('↦', r"\mapsto"),
    ('→', r"\to"),
    ('⇒', r"\Rightarrow"),
    ('⇔', r"\Leftrightarrow"),
    ('∞', r"\infty"),
    ('·', r"\cdot"),
    ('×', r"\times"),
    ('÷', r"\div"),
    ('±', r"\pm"),
    ('∓', r"\mp"),
    ('′', "'"),
    ('√', r"\surd"),
    ('∂', r"\partial"),
    ('‖', r"\|"),
    ('⌊', r"\lfloor"),
    ('⌋', r"\rfloor"),
    ('⋯', r"\cdots"),
    ('□', r"\square"),
    ('ℚ', r"\mathbb{Q}"),
    ('ℤ', r"\mathbb{Z}"),
    ('𝔽', r"\mathbb{F}"),
    ('°', r"^{\circ}"),
];

/// Superscript characters and what they raise.
const SUPER: &[(char, &str)] = &[
    ('⁰', "0"),
    ('¹', "1"),
    ('²', "2"),
    ('³', "3"),
    ('⁴', "4"),
    ('⁵', "5"),
    ('⁶', "6"),
    ('⁷', "7"),
    ('⁸', "8"),
    ('⁹', "9"),
    ('⁺', "+"),
    ('⁻', "-"),
    ('⁽', "("),
    ('⁾', ")"),
    ('ⁱ', "i"),
    ('ⁿ', "n"),
    ('ʲ', "j"),
    ('ᵀ', "T"),
    ('ᵃ', "a"),
    ('ᵇ', "b"),
    ('ᵈ', "d"),
    ('ᵉ', "e"),
    ('ᵏ', "k"),
];

/// Subscript characters and what they lower.
const SUB: &[(char, &str)] = &[
    ('₀', "0"),
    ('₁', "1"),
    ('₂', "2"),
    ('₃', "3"),
    ('₄', "4"),
    ('₅', "5"),
    ('₆', "6"),
    ('₇', "7"),
    ('₈', "8"),
    ('₉', "9"),
    ('₋', "-"),
    ('ᵢ', "i"),
    ('ⱼ', "j"),
    ('ₖ', "k"),
    ('ₙ', "n"),
];

/// Characters set as text.
const TEXT: &[(char, &str)] = &[
    ('…', r"\ldots{}"),
    ('—', "---"),
    ('–', "--"),
    ('“', "``"),
    ('”', "''"),
    ('‘', "`"),
    ('’', "'"),
    ('›', r"$\rangle$"),
    ('§', r"\S{}"),
    ('½', r"$\frac{1}{2}$"),
    ('é', r"\'{e}"),
    ('ع', r"\textit{ain}"),
    ('\u{304}', ""),
];

/// Words that stay text even between formulas.
const WORDS: &[&str] = &[
    "a", "an", "as", "at", "be", "by", "for", "if", "in", "is", "it", "no", "not", "of", "on",
    "or", "so", "to", "and", "the", "all", "are", "but", "its", "one", "two", "see", "with",
];

fn lookup(table: &[(char, &'static str)], ch: char) -> Option<&'static str> {
    table.iter().find(|(c, _)| *c == ch).map(|(_, s)| *s)
}

fn is_mathy(ch: char) -> bool {
    lookup(MATH, ch).is_some() || lookup(SUPER, ch).is_some() || lookup(SUB, ch).is_some()
}

/// Characters of `text` no table maps (non-ASCII only).
pub fn unmapped(text: &str) -> Vec<char> {
    let mut out: Vec<char> = text
        .chars()
        .filter(|c| !c.is_ascii() && !is_mathy(*c) && lookup(TEXT, *c).is_none())
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// Escapes text for LaTeX: the ten special characters, and every mapped
/// Unicode character (math symbols as inline math).
pub fn tex_escape(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
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
            out.push('$');
            out.push_str(&to_math(&run));
            out.push('$');
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

/// A formula-like piece of text in LaTeX math (without `$`): `_`/`^` with
/// their groups, Unicode symbols, runs of super- and subscripts merged,
/// `x̄` as `\bar{x}`, literal braces escaped.
pub fn to_math(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    // a stack of open braces: true = a grouping brace of `_`/`^`
    let mut braces: Vec<bool> = Vec::new();
    while i < chars.len() {
        let ch = chars[i];
        if chars.get(i + 1) == Some(&'\u{304}') {
            out.push_str(&format!(r"\bar{{{}}}", atom(ch)));
            i += 2;
            continue;
        }
        for (table, op) in [(SUPER, '^'), (SUB, '_')] {
            if lookup(table, ch).is_some() {
                let mut run = String::new();
                while let Some(s) = chars.get(i).and_then(|c| lookup(table, *c)) {
                    run.push_str(s);
                    i += 1;
                }
                out.push_str(&format!("{op}{{{run}}}"));
            }
        }
        let Some(&ch) = chars.get(i) else { break };
        if lookup(SUPER, ch).is_some() || lookup(SUB, ch).is_some() {
            continue;
        }
        match ch {
            '_' | '^' => {
                out.push(ch);
                match chars.get(i + 1) {
                    Some('{') => {
                        out.push('{');
                        braces.push(true);
                        i += 2;
                    }
                    // `^(−3)`, `F^(4)`: the bracketed group is the script
                    Some('(') if let Some(end) = closing(&chars, i + 1) => {
                        let group: String = chars[i + 1..=end].iter().collect();
                        out.push_str(&format!("{{{}}}", to_math(&group)));
                        i = end + 1;
                    }
                    Some(&next) => {
                        out.push_str(&format!("{{{}}}", atom(next)));
                        i += 2;
                    }
                    None => {
                        out.push_str("{}");
                        i += 1;
                    }
                }
                continue;
            }
            '{' => {
                out.push_str(r"\{");
                braces.push(false);
            }
            '}' => match braces.pop() {
                Some(true) => out.push('}'),
                _ => out.push_str(r"\}"),
            },
            _ => out.push_str(&atom(ch)),
        }
        i += 1;
    }
    for grouping in braces.into_iter().rev() {
        if grouping {
            out.push('}');
        }
    }
    out
}

/// The index of the `)` closing the `(` at `open`, if any.
fn closing(chars: &[char], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (k, c) in chars.iter().enumerate().skip(open) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

/// One character in math mode.
fn atom(ch: char) -> String {
    if let Some(m) = lookup(MATH, ch) {
        // a command needs a space before a following letter
        return if m.starts_with('\\') && m.chars().last().is_some_and(char::is_alphabetic) {
            format!("{m} ")
        } else {
            m.to_string()
        };
    }
    match ch {
        '\\' => r"\backslash ".into(),
        '$' | '&' | '#' | '%' => format!(r"\{ch}"),
        '~' => r"\sim ".into(),
        // an apostrophe after a superscript would be a second one
        '\'' => r"\text{'}".into(),
        '"' => r"\text{''}".into(),
        ' ' => " ".into(),
        _ if ch.is_ascii() => ch.to_string(),
        _ => match lookup(TEXT, ch) {
            Some(t) => format!(r"\text{{{t}}}"),
            None => format!(r"\text{{[U+{:04X}]}}", u32::from(ch)),
        },
    }
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
pub fn tex_inline(text: &str) -> String {
    // `code spans` (commands, file names) in typewriter, the rest as prose
    if text.contains('`') {
        return text
            .split('`')
            .enumerate()
            .map(|(i, part)| {
                if i % 2 == 1 {
                    format!(r"\texttt{{{}}}", tex_escape(part))
                } else {
                    tex_inline(part)
                }
            })
            .collect();
    }
    let words: Vec<&str> = text.split(' ').collect();
    let kinds: Vec<Token> = words.iter().map(|w| classify(w)).collect();
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < words.len() {
        if kinds[i] == Token::Text {
            out.push(tex_escape(words[i]));
            i += 1;
            continue;
        }
        let start = i;
        while i < words.len() && kinds[i] != Token::Text {
            i += 1;
        }
        let run = &words[start..i];
        if kinds[start..i].contains(&Token::Math) {
            out.push(format!("${}$", to_math(&run.join(" "))));
        } else {
            out.extend(run.iter().map(|w| tex_escape(w)));
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
            tex_escape(r"50% of {a_b} & $x^2 # ~\"),
            r"50\% of \{a\_b\} \& \$x\textasciicircum{}2 \# \textasciitilde{}\textbackslash{}"
        );
        assert_eq!(
            tex_escape("θ ↦ π/2 − θ, b₀ ≥ 0 — “ok”"),
            r"$\theta $ $\mapsto $ $\pi $/2 $-$ $\theta $, b$_{0}$ $\geq $ 0 --- ``ok''"
        );
    }

    #[test]
    fn statements_set_their_formulas_in_math() {
        assert_eq!(
            tex_inline("H_i(u; β) = H_{2−i}(π/2 − u; β) (as printed)"),
            r"$H_{i}(u; \beta ) = H_{2-i}(\pi /2 - u; \beta )$ (as printed)"
        );
        assert_eq!(
            tex_inline("x² + y²³ ≥ 0 for all x"),
            r"$x^{2} + y^{23} \geq  0$ for all x"
        );
        assert_eq!(tex_inline("the set {1, 2}"), r"the set \{1, 2\}");
        assert_eq!(tex_inline("P_{i,j} x̄"), r"$P_{i,j} \bar{x}$");
        assert_eq!(
            to_math("(1 + z²)^(−3) F^(4)"),
            r"(1 + z^{2})^{(-3)} F^{(4)}"
        );
        assert_eq!(
            tex_inline("b_{j+2,i} of {a_b}"),
            r"$b_{j+2,i}$ of $\{a_{b}\}$"
        );
        assert_eq!(
            tex_inline("run `trig-audit audit` now"),
            r"run \texttt{trig-audit audit} now"
        );
    }

    #[test]
    fn unknown_characters_are_reported() {
        assert_eq!(unmapped("αβ ع x ☃"), vec!['☃']);
        assert_eq!(tex_escape("☃"), "[U+2603]");
    }
}
