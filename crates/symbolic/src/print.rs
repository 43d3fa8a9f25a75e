//! Canonical printing of [`Poly`] and [`Sym`] in four forms: plain ASCII
//! (`Display`), Unicode ([`Sym::to_unicode`], for Markdown tables), LaTeX
//! ([`Sym::to_latex`]) and SymPy syntax ([`Sym::to_sympy`]: `**` for powers,
//! `sin(theta)`, `cos(theta)` for the atoms `s`, `c`, one SymPy symbol per
//! variable whatever its name — `lamda` for `lambda`, `in_` for `in`, the
//! rules of [`crate::sympy_names`]; read it with
//! `sympy.parse_expr(text, local_dict={name: Symbol(name) …})` so that
//! names such as `beta` or `zeta` stay symbols, see [`crate::sympy_symbols`]).
//! Factored forms ([`crate::FactoredQuotient`]) print in the same four.
//!
//! The output is deterministic. Terms are printed greatest first in the
//! graded lexicographic order of [`crate::monomial`]: by total degree
//! descending, then lexicographically in the variable order of
//! [`crate::var`] (parameters `m, beta, lambda, mu, eta, alpha, zeta, xi,
//! omega`, then `pi`, `s`, `c`, `t`, then other names naturally sorted).
//! Inside a monomial the variables follow the same order.
//!
//! A quotient is printed as an integer numerator over its factored
//! denominator (a rational content of the numerator moves its denominator
//! into the denominator): `(m + 2)/(beta + 1)^2`, `3*m/(2*(beta + 1))`.
//! Denominator factors are printed single variables first (in the variable
//! order), then by number of terms, then greatest leading monomial first.
//!
//! Names: plain text prints them as given. Unicode and LaTeX render the
//! Greek names (`alpha`, `beta`, `gamma`, `delta`, …, `omega`: 21 letters)
//! as letters and trailing digits as subscripts (`w0` → `w₀`, `w_{0}`);
//! LaTeX sets other multi-letter names in `\mathrm{…}`. The names and the
//! LaTeX pieces are the one LaTeX writer's ([`trig_tex::symbols::greek`],
//! [`trig_tex::expr`]).

use std::borrow::Cow;
use std::fmt::{self, Write as _};
use std::sync::OnceLock;

use rug::{Integer, Rational};
use trig_tex::expr as tex;
use trig_tex::symbols::greek;

use crate::factor::FactoredQuotient;
use crate::monomial::Monomial;
use crate::poly::Poly;
use crate::sym::Sym;
use crate::sympy_names::sympy_name;
use crate::var::{Var, split_digits};

/// The four text forms of an expression. The LaTeX pieces (names, powers,
/// fractions) come from the one LaTeX writer, [`trig_tex::expr`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Style {
    /// Plain ASCII (`*`, `^`), as `Display` prints.
    Plain,
    /// Greek letters, superscript exponents, `·`, `−`.
    Unicode,
    /// LaTeX math (without `$`).
    Latex,
    /// SymPy syntax: `**` for powers, `sin(theta)`, `cos(theta)` for the
    /// atoms `s`, `c`, one symbol per variable (`lamda` for `lambda`, `in_`
    /// for `in`: [`crate::sympy_names`]; read it with the names of
    /// [`crate::sympy_symbols`] as symbols).
    Sympy,
}

const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
const SUBSCRIPTS: [char; 10] = ['₀', '₁', '₂', '₃', '₄', '₅', '₆', '₇', '₈', '₉'];

impl Style {
    /// The minus sign.
    pub fn minus(self) -> &'static str {
        if self == Style::Unicode { "−" } else { "-" }
    }

    /// The sign of a product.
    pub fn times(self) -> &'static str {
        match self {
            Style::Plain | Style::Sympy => "*",
            Style::Unicode => "·",
            Style::Latex => " ",
        }
    }

    /// `x` in this style.
    pub fn sym(self, x: &Sym) -> String {
        sym(x, self)
    }

    /// A factored quotient in this style.
    pub fn factored(self, f: &FactoredQuotient) -> String {
        factored(f, self)
    }
}

fn digits_in(table: &[char; 10], digits: &str) -> String {
    digits
        .bytes()
        .map(|b| table[usize::from(b - b'0')])
        .collect()
}

/// The Unicode form of a variable name (`lambda1` → `λ₁`): how it reads.
pub(crate) fn unicode_name(n: &str) -> String {
    name(n, Style::Unicode)
}

/// An indexed name `X_k` (`k` an index letter and an offset, or digits):
/// `y_i` is `y_i`, `y_i1` is `y_{i+1}`, `P_2` is `P_2`, `b1_2` is `b_{1,2}`
/// — the subscript, in Unicode and LaTeX, as the documents write it.
fn indexed(n: &str) -> Option<(&str, String)> {
    let (base, index) = n.rsplit_once('_')?;
    let letter = index.chars().next()?;
    let offset = &index[letter.len_utf8()..];
    let sub = if index.bytes().all(|b| b.is_ascii_digit()) {
        index.to_string()
    } else if ['i', 'j', 'k', 'n'].contains(&letter) && offset.bytes().all(|b| b.is_ascii_digit()) {
        if offset.is_empty() {
            letter.to_string()
        } else {
            format!("{letter}+{offset}")
        }
    } else {
        return None;
    };
    let (prefix, digits) = split_digits(base);
    if prefix.is_empty() || prefix.contains('_') {
        return None;
    }
    let sub = if digits.is_empty() {
        sub
    } else {
        format!("{digits},{sub}")
    };
    Some((prefix, sub))
}

/// A subscript in Unicode characters (digits, `i`, `j`, `k`, `n`, `+`, `,`).
fn unicode_subscript(sub: &str) -> String {
    sub.chars()
        .map(|ch| match ch {
            '0'..='9' => SUBSCRIPTS[ch as usize - '0' as usize],
            'i' => 'ᵢ',
            'j' => 'ⱼ',
            'k' => 'ₖ',
            'n' => 'ₙ',
            '+' => '₊',
            other => other,
        })
        .collect()
}

fn name(n: &str, style: Style) -> String {
    if style == Style::Sympy {
        return sympy_name(n);
    }
    // the ring's root atoms: `sqrt(2)` is `\sqrt{2}` in LaTeX
    if style == Style::Latex
        && let Some(radicand) = n.strip_prefix("sqrt(").and_then(|r| r.strip_suffix(')'))
    {
        return format!("\\sqrt{{{radicand}}}");
    }
    if style != Style::Plain
        && let Some((prefix, sub)) = indexed(n)
    {
        return match style {
            Style::Unicode => {
                let base = greek(prefix).map_or_else(|| prefix.to_string(), String::from);
                format!("{base}{}", unicode_subscript(&sub))
            }
            _ => tex::name(prefix, &sub),
        };
    }
    let (prefix, digits) = split_digits(n);
    if style == Style::Plain || prefix.is_empty() {
        return n.to_string();
    }
    match style {
        Style::Unicode => {
            let base = greek(prefix).map_or_else(|| prefix.to_string(), String::from);
            format!("{base}{}", digits_in(&SUBSCRIPTS, digits))
        }
        _ => tex::name(prefix, digits),
    }
}

/// [`name`] of a variable, formed once per variable and style (variables
/// are interned for the life of the process, a bounded set, see [`Var`]).
fn var_name(v: &Var, style: Style) -> &'static str {
    const _: () = assert!(Style::Sympy as usize + 1 == crate::var::PRINT_STYLES);
    v.printed(style as usize, || name(v.name(), style))
}

fn power(base: String, e: u32, style: Style) -> String {
    match (e, style) {
        (1, _) => base,
        (_, Style::Plain) => format!("{base}^{e}"),
        (_, Style::Sympy) => format!("{base}**{e}"),
        (_, Style::Unicode) => format!("{base}{}", digits_in(&SUPERSCRIPTS, &e.to_string())),
        (_, Style::Latex) => tex::power(&base, e),
    }
}

/// The exponent `e` as [`power`] writes it after a base (nothing for 1),
/// formed once per style for the exponents met in practice.
fn exponent_suffix(e: u32, style: Style) -> Cow<'static, str> {
    const FORMED: u32 = 64;
    static SUFFIXES: OnceLock<Vec<[String; 4]>> = OnceLock::new();
    if e >= FORMED {
        return Cow::Owned(power(String::new(), e, style));
    }
    let table = SUFFIXES.get_or_init(|| {
        (0..FORMED)
            .map(|e| {
                [Style::Plain, Style::Unicode, Style::Latex, Style::Sympy]
                    .map(|style| power(String::new(), e, style))
            })
            .collect()
    });
    Cow::Borrowed(&table[e as usize][style as usize])
}

/// Writes the monomial `m` (not `1`) to `out`, factors joined by the
/// style's product sign.
fn push_monomial(out: &mut String, m: &Monomial, style: Style) {
    for (i, (v, e)) in m.factors().enumerate() {
        if i > 0 {
            out.push_str(style.times());
        }
        out.push_str(var_name(v, style));
        out.push_str(&exponent_suffix(e, style));
    }
}

fn poly(p: &Poly, style: Style) -> String {
    if p.is_zero() {
        return "0".to_string();
    }
    let mut out = String::new();
    for (i, (m, q)) in p.terms().enumerate() {
        push_sign(&mut out, i == 0, q.signum() < 0, style);
        let q = q.abs();
        let unit = q == 1;
        if m.is_one() || !unit {
            if style == Style::Latex && !q.is_integer() {
                out.push_str(&tex::frac(&q.numer().to_string(), &q.denom().to_string()));
            } else {
                let _ = write!(out, "{q}");
            }
        }
        if !m.is_one() {
            if !unit {
                out.push_str(style.times());
            }
            push_monomial(&mut out, m, style);
        }
    }
    out
}

/// The sign before a term of a sum: `−` (no space) or nothing before the
/// first term, ` − ` or ` + ` before the others.
pub(crate) fn push_sign(out: &mut String, first: bool, negative: bool, style: Style) {
    match (first, negative) {
        (true, true) => out.push_str(style.minus()),
        (true, false) => {}
        (false, true) => {
            out.push(' ');
            out.push_str(style.minus());
            out.push(' ');
        }
        (false, false) => out.push_str(" + "),
    }
}

fn sym(x: &Sym, style: Style) -> String {
    if x.denominator().is_empty() {
        return poly(x.numerator(), style);
    }
    let k = x
        .numerator()
        .terms()
        .fold(Integer::from(1), |acc, (_, q)| acc.lcm(&q.denom()));
    let n = x.numerator().scale(&Rational::from(k.clone()));
    let mut items = Vec::new();
    if k != 1 {
        items.push(k.to_string());
    }
    let several = items.len() + x.denominator().len() > 1;
    let mut factors: Vec<(&Poly, &u32)> = x.denominator().iter().collect();
    factors.sort_by(|(a, _), (b, _)| {
        let lead = |p: &Poly| p.leading_term().map(|(m, _)| m.clone());
        a.len()
            .cmp(&b.len())
            .then_with(|| lead(b).cmp(&lead(a)))
            .then_with(|| a.cmp(b))
    });
    for (f, e) in factors {
        let text = poly(f, style);
        let wrap = f.len() > 1 && (style != Style::Latex || several || *e > 1);
        let base = if wrap { format!("({text})") } else { text };
        items.push(power(base, *e, style));
    }
    let den = items.join(style.times());
    if style == Style::Latex {
        let negative = n.len() == 1 && n.leading_term().is_some_and(|(_, q)| *q < 0);
        return if negative {
            format!("-{}", tex::frac(&poly(&-n, style), &den))
        } else {
            tex::frac(&poly(&n, style), &den)
        };
    }
    let num = if n.len() > 1 {
        format!("({})", poly(&n, style))
    } else {
        poly(&n, style)
    };
    if several {
        format!("{num}/({den})")
    } else {
        format!("{num}/{den}")
    }
}

impl Poly {
    /// Unicode form (Greek letters, superscript exponents, `·`, `−`).
    pub fn to_unicode(&self) -> String {
        poly(self, Style::Unicode)
    }

    /// LaTeX form.
    pub fn to_latex(&self) -> String {
        poly(self, Style::Latex)
    }

    /// SymPy syntax: `**` for powers, `sin(theta)`, `cos(theta)` for the
    /// atoms `s`, `c`, one symbol per variable ([`crate::sympy_names`];
    /// read it with the names of [`crate::sympy_symbols`] as symbols).
    pub fn to_sympy(&self) -> String {
        poly(self, Style::Sympy)
    }
}

impl fmt::Display for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&poly(self, Style::Plain))
    }
}

impl Sym {
    /// Unicode form (Greek letters, superscript exponents, `·`, `−`).
    pub fn to_unicode(&self) -> String {
        sym(self, Style::Unicode)
    }

    /// LaTeX form.
    pub fn to_latex(&self) -> String {
        sym(self, Style::Latex)
    }

    /// SymPy syntax: `**` for powers, `sin(theta)`, `cos(theta)` for the
    /// atoms `s`, `c`, one symbol per variable ([`crate::sympy_names`];
    /// read it with the names of [`crate::sympy_symbols`] as symbols).
    pub fn to_sympy(&self) -> String {
        sym(self, Style::Sympy)
    }
}

/// `unit · Π numᵉ / Π denᵉ` in `style`.
fn factored(f: &FactoredQuotient, style: Style) -> String {
    let negative = f.unit < 0;
    let a = Rational::from(f.unit.abs_ref());
    let item = |p: &Poly, e: u32| {
        let text = poly(p, style);
        let base = if p.len() > 1 {
            format!("({text})")
        } else {
            text
        };
        power(base, e, style)
    };
    let mut num: Vec<String> = Vec::new();
    if *a.numer() != 1 || f.num.is_empty() {
        num.push(a.numer().to_string());
    }
    num.extend(f.num.iter().map(|(p, e)| item(p, *e)));
    let mut den: Vec<String> = Vec::new();
    if *a.denom() != 1 {
        den.push(a.denom().to_string());
    }
    den.extend(f.den.iter().map(|(p, e)| item(p, *e)));
    let sign = if negative { style.minus() } else { "" };
    let num = num.join(style.times());
    if den.is_empty() {
        return format!("{sign}{num}");
    }
    let several = den.len() > 1;
    let den = den.join(style.times());
    match style {
        Style::Latex => format!("{sign}{}", tex::frac(&num, &den)),
        _ if several => format!("{sign}{num}/({den})"),
        _ => format!("{sign}{num}/{den}"),
    }
}

impl FactoredQuotient {
    /// Plain ASCII.
    pub fn to_plain(&self) -> String {
        factored(self, Style::Plain)
    }

    /// Unicode.
    pub fn to_unicode(&self) -> String {
        factored(self, Style::Unicode)
    }

    /// LaTeX.
    pub fn to_latex(&self) -> String {
        factored(self, Style::Latex)
    }

    /// SymPy syntax.
    pub fn to_sympy(&self) -> String {
        factored(self, Style::Sympy)
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&sym(self, Style::Plain))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sympy_symbols;

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    fn forms(x: &Sym) -> [String; 3] {
        [x.to_string(), x.to_unicode(), x.to_latex()]
    }

    /// Indexed names print with their subscript as the documents write
    /// it, never as an underscore before a subscript digit (`y_i₁`).
    #[test]
    fn roots_are_radicals_in_latex() {
        let r = &v("sqrt(2)") * &v("lambda");
        assert_eq!(r.to_latex(), r"\lambda \sqrt{2}");
        assert_eq!(r.to_string(), "lambda*sqrt(2)");
    }

    #[test]
    fn indexed_names() {
        for (name, unicode, latex) in [
            ("y_i", "yᵢ", "y_{i}"),
            ("y_i1", "yᵢ₊₁", "y_{i+1}"),
            ("D_i2", "Dᵢ₊₂", "D_{i+2}"),
            ("P_2", "P₂", "P_{2}"),
            ("b1_2", "b₁,₂", "b_{1,2}"),
            ("dt_i1", "dtᵢ₊₁", r"\mathrm{dt}_{i+1}"),
            ("w1", "w₁", "w_{1}"),
        ] {
            assert_eq!(v(name).to_unicode(), unicode, "{name}");
            assert_eq!(v(name).to_latex(), latex, "{name}");
            assert_eq!(v(name).to_string(), name);
            assert_eq!(v(name).to_sympy(), name);
        }
    }

    #[test]
    fn polynomial() {
        let m = v("m");
        let x = -(m.clone() * &m) + &(Sym::rational(Rational::from((3, 2))) * &m) - &Sym::int(2);
        assert_eq!(
            forms(&x),
            [
                "-m^2 + 3/2*m - 2",
                "−m² + 3/2·m − 2",
                r"-m^{2} + \frac{3}{2} m - 2"
            ]
        );
        assert_eq!(forms(&Sym::zero()), ["0", "0", "0"]);
    }

    #[test]
    fn quotient() {
        let b1 = v("beta") + &Sym::int(1);
        // factors are not discovered by factorisation: divide twice
        let x = (v("m") + &Sym::int(2)) / &b1 / &b1;
        assert_eq!(
            forms(&x),
            [
                "(m + 2)/(beta + 1)^2",
                "(m + 2)/(β + 1)²",
                r"\frac{m + 2}{(\beta + 1)^{2}}"
            ]
        );
        let y = Sym::int(-3) * &v("m") / &(Sym::int(2) * &b1);
        assert_eq!(
            forms(&y),
            [
                "-3*m/(2*(beta + 1))",
                "−3·m/(2·(β + 1))",
                r"-\frac{3 m}{2 (\beta + 1)}"
            ]
        );
        let z = Sym::int(1) / &(b1 * &v("pi") * &v("s"));
        assert_eq!(
            forms(&z),
            [
                "1/(pi*s*(beta + 1))",
                "1/(π·s·(β + 1))",
                r"\frac{1}{\pi s (\beta + 1)}"
            ]
        );
    }

    #[test]
    fn term_order_and_names() {
        // degree first, then parameters before pi, s, c, t, other names
        let x = v("P10")
            + &v("P2")
            + &v("t")
            + &v("c")
            + &v("s")
            + &v("pi")
            + &v("zeta")
            + &v("m")
            + &(v("s") * &v("c") * &v("w0"))
            + &(v("lambda") * &v("lambda"));
        assert_eq!(
            x.to_string(),
            "s*c*w0 + lambda^2 + m + zeta + pi + s + c + t + P2 + P10"
        );
        assert_eq!(
            x.to_unicode(),
            "s·c·w₀ + λ² + m + ζ + π + s + c + t + P₂ + P₁₀"
        );
        assert_eq!(
            x.to_latex(),
            r"s c w_{0} + \lambda^{2} + m + \zeta + \pi + s + c + t + P_{2} + P_{10}"
        );
        assert_eq!((v("h12") * &v("G")).to_latex(), r"G h_{12}");
        assert_eq!(v("foo").to_latex(), r"\mathrm{foo}");
        // s² is printed in its reduced form
        assert_eq!((v("s") * &v("s")).to_string(), "-c^2 + 1");
    }

    #[test]
    fn sympy_syntax_and_factored_forms() {
        let x = (v("lambda") * &v("s") * &v("s") - &(Sym::int(3) * &v("beta") * &v("c")))
            / &(Sym::int(2) * &(v("m") + &Sym::int(2)));
        assert_eq!(
            x.to_sympy(),
            "(-lamda*cos(theta)**2 - 3*beta*cos(theta) + lamda)/(2*(m + 2))"
        );
        assert_eq!(
            sympy_symbols(x.variables().iter().map(String::as_str)),
            ["beta", "lamda", "m", "theta"]
        );
        let (m1, m2) = (v("m1"), v("m2"));
        let y = Sym::int(-3) * &(m1.clone() - &m2) * &(m2.clone() + &Sym::int(2))
            / &(Sym::int(4) * &(m1 + &Sym::int(2)));
        let f = y.factored();
        assert_eq!(f.to_plain(), "-3*(m1 - m2)*(m2 + 2)/(4*(m1 + 2))");
        assert_eq!(f.to_unicode(), "−3·(m₁ − m₂)·(m₂ + 2)/(4·(m₁ + 2))");
        assert_eq!(
            f.to_latex(),
            r"-\frac{3 (m_{1} - m_{2}) (m_{2} + 2)}{4 (m_{1} + 2)}"
        );
        assert_eq!(f.to_sympy(), "-3*(m1 - m2)*(m2 + 2)/(4*(m1 + 2))");
    }
}
