//! Unicode symbols and their LaTeX: Greek letters, operators, super- and
//! subscripts, dashes, quotes, and the glyph names of thesis Chapter 6 —
//! every non-ASCII character the reports print. A character without a
//! mapping is written as `[U+XXXX]`, and [`unmapped`] finds such characters
//! so that a test can insist there are none.

/// Characters set in math mode, with their LaTeX (math) form.
pub(crate) const MATH: &[(char, &str)] = &[
    ('α', r"\alpha"),
    ('β', r"\beta"),
    ('γ', r"\gamma"),
    ('δ', r"\delta"),
    ('ε', r"\varepsilon"),
    ('ϵ', r"\epsilon"),
    ('ζ', r"\zeta"),
    ('η', r"\eta"),
    ('θ', r"\theta"),
    ('κ', r"\kappa"),
    ('λ', r"\lambda"),
    ('μ', r"\mu"),
    ('ν', r"\nu"),
    ('ξ', r"\xi"),
    ('π', r"\pi"),
    ('ρ', r"\rho"),
    ('σ', r"\sigma"),
    ('τ', r"\tau"),
    ('φ', r"\varphi"),
    ('χ', r"\chi"),
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
    ('″', "''"),
    ('∫', r"\int "),
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
pub(crate) const SUPER: &[(char, &str)] = &[
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
pub(crate) const SUB: &[(char, &str)] = &[
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
pub(crate) const TEXT: &[(char, &str)] = &[
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

pub(crate) fn lookup(table: &[(char, &'static str)], ch: char) -> Option<&'static str> {
    table.iter().find(|(c, _)| *c == ch).map(|(_, s)| *s)
}

pub(crate) fn is_mathy(ch: char) -> bool {
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

/// The Greek letters variables are named by (`beta`, `lambda1`), as
/// expressions print them.
const GREEK: [(&str, char); 21] = [
    ("alpha", 'α'),
    ("beta", 'β'),
    ("chi", 'χ'),
    ("delta", 'δ'),
    ("epsilon", 'ε'),
    ("eta", 'η'),
    ("gamma", 'γ'),
    ("kappa", 'κ'),
    ("lambda", 'λ'),
    ("mu", 'μ'),
    ("nu", 'ν'),
    ("omega", 'ω'),
    ("phi", 'φ'),
    ("pi", 'π'),
    ("psi", 'ψ'),
    ("rho", 'ρ'),
    ("sigma", 'σ'),
    ("tau", 'τ'),
    ("theta", 'θ'),
    ("xi", 'ξ'),
    ("zeta", 'ζ'),
];

/// The Greek letter a variable name spells (`beta` → `β`), if any.
pub fn greek(name: &str) -> Option<char> {
    GREEK.iter().find(|(n, _)| *n == name).map(|(_, c)| *c)
}

/// The LaTeX math form of a mapped math symbol (`β` → `\beta`).
pub fn math_symbol(ch: char) -> Option<&'static str> {
    lookup(MATH, ch)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_characters_are_reported_and_greek_names_map() {
        assert_eq!(unmapped("αβ ع x ☃"), vec!['☃']);
        assert_eq!(greek("lambda"), Some('λ'));
        assert_eq!(greek("gamma"), Some('γ'));
        assert_eq!(greek("gammas"), None);
        assert_eq!(math_symbol('λ'), Some(r"\lambda"));
    }
}
