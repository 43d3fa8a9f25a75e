//! The names of the SymPy forms ([`crate::Style::Sympy`]): one SymPy symbol
//! per variable of the exact ring, whatever its name.
//!
//! A form is read with `sympy.parse_expr(text, local_dict={n: Symbol(n) for
//! n in symbols})` (the names of [`sympy_symbols`]), so that names SymPy
//! also has as functions (`beta`, `gamma`, `zeta`) stay symbols. A name is
//! spelled as it is, except where SymPy would refuse it, read it as
//! something else, or merge it with another:
//!
//! * `pi` (the number π) is SymPy's `pi`; `s`, `c` are `sin(theta)`,
//!   `cos(theta)`; the atoms `sin(X)`, `cos(X)`,
//!   `exp(X)` of a parameter multiple `X` are SymPy's functions of `X`
//!   (the parameter in `X` named by these rules), `sqrt(p)` is `sqrt(p)`;
//! * `lambda` (a Python keyword) is `lamda`, SymPy's own spelling, and
//!   `lambda1` is `lamda1`;
//! * a name in [`RENAMED`] (a Python keyword or constant, a function or
//!   constant the forms themselves write, SymPy's one-letter names), a
//!   name `lamda…` (the spelling of `lambda…`) and a name ending in `_`
//!   get one `_` appended: `in` is `in_`, `None` is `None_`, `lamda` is
//!   `lamda_`, `w_` is `w__`, `E` (the exponential atom `exp(κx)`) is `E_`.
//!
//! The map is injective (an appended `_` marks every renamed name, and no
//! name kept as it is ends in `_`), deterministic, and the same for every
//! expression of a report, so two variables never share a symbol and the
//! SymPy name of a variable is undone by the same rules: strip one
//! trailing `_`; `lamda…` without it is `lambda…`.

use crate::var::{COS, PI, SIN, split_digits};

/// Names that get a trailing `_` in SymPy forms: Python's keywords (and
/// its constants `None`, `True`, `False`), the functions and constants the
/// forms write (`sin`, `Interval`, `pi`, …, and `theta`, the angle of `s`,
/// `c`), and SymPy's one-letter names and infinities.
pub const RENAMED: &[&str] = &[
    // Python keywords
    "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue",
    "def", "del", "elif", "else", "except", "finally", "for", "from", "global", "if", "import",
    "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try", "while",
    "with", "yield", // what the forms write
    "sin", "cos", "exp", "sqrt", "pi", "theta", "atan2", "asin", "acos", "Max", "Min", "Float",
    "Rational", "Interval", "Symbol", // SymPy's one-letter names, infinities
    "E", "I", "S", "N", "O", "Q", "oo", "zoo", "nan",
];

/// The SymPy spelling of the variable `n` of the exact ring (see the
/// module's rules): a symbol, or a function of one for an atom.
pub(crate) fn sympy_name(n: &str) -> String {
    match n {
        SIN => "sin(theta)".to_string(),
        COS => "cos(theta)".to_string(),
        PI => PI.to_string(),
        _ => match atom(n) {
            Some((f, arg, Some(p))) => format!("{f}({})", arg.replacen(p, &sympy_symbol(p), 1)),
            Some((f, arg, None)) => format!("{f}({arg})"),
            None => sympy_symbol(n),
        },
    }
}

/// The SymPy symbol of a name that is not an atom: `lambda…` is `lamda…`,
/// a name SymPy would refuse, misread or merge gets a trailing `_`.
pub fn sympy_symbol(n: &str) -> String {
    let (prefix, digits) = split_digits(n);
    if prefix == "lambda" && !digits.is_empty() {
        format!("lamda{digits}")
    } else if n == "lambda" {
        "lamda".to_string()
    } else if prefix == "lamda" || n.ends_with('_') || RENAMED.contains(&n) {
        format!("{n}_")
    } else {
        n.to_string()
    }
}

/// An atom `f(arg)` of the exact ring (`sin`, `cos`, `exp` of a parameter
/// multiple `[-][k*]p[/d]`, `sqrt` of a prime): the function, the argument
/// and the parameter it names (none for `sqrt`).
fn atom(n: &str) -> Option<(&str, &str, Option<&str>)> {
    let (f, rest) = n.split_once('(')?;
    let arg = rest.strip_suffix(')')?;
    if f == "sqrt" {
        return arg
            .bytes()
            .all(|b| b.is_ascii_digit())
            .then_some((f, arg, None));
    }
    if !["sin", "cos", "exp"].contains(&f) {
        return None;
    }
    let body = arg.strip_prefix('-').unwrap_or(arg);
    let body = body.split_once('*').map_or(body, |(_, p)| p);
    let p = body.split_once('/').map_or(body, |(p, _)| p);
    let name = p
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && p.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    name.then_some((f, arg, Some(p)))
}

/// The SymPy symbol names an expression with the variables `names` uses
/// (`theta` for `s`, `c`; the parameter of an atom `exp(X)`, none for
/// `sqrt(p)`; `lamda` for `lambda`, …), sorted, without `pi` (SymPy's own
/// constant).
pub fn sympy_symbols<'a>(names: impl IntoIterator<Item = &'a str>) -> Vec<String> {
    let mut out: Vec<String> = names
        .into_iter()
        .filter(|n| *n != PI)
        .filter_map(|n| match n {
            SIN | COS => Some("theta".to_string()),
            _ => match atom(n) {
                Some((_, _, p)) => p.map(sympy_symbol),
                None => Some(sympy_symbol(n)),
            },
        })
        .collect();
    out.sort();
    out.dedup();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every name gets its own symbol: the renamed names never meet a kept
    /// one nor each other.
    #[test]
    fn injective_and_safe() {
        let mut names: Vec<String> = [
            "lambda", "lamda", "lambda1", "lamda1", "lambda_", "lamda_", "in", "in_", "in__", "E",
            "E_", "None", "None_", "beta", "w1", "theta", "theta_", "I", "S", "N", "P0",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect();
        names.extend(RENAMED.iter().map(|s| s.to_string()));
        let mut seen = std::collections::BTreeMap::new();
        for n in &names {
            let s = sympy_symbol(n);
            if let Some(other) = seen.insert(s.clone(), n.clone()) {
                assert_eq!(&other, n, "{other} and {n} share the SymPy symbol {s}");
            }
            assert!(!RENAMED.contains(&s.as_str()), "{n} → {s}");
            assert!(
                !s.starts_with("lamda") || n.starts_with("lambda") || s.ends_with('_'),
                "{n} → {s}"
            );
        }
        assert_eq!(sympy_symbol("lambda"), "lamda");
        assert_eq!(sympy_symbol("lamda"), "lamda_");
        assert_eq!(sympy_symbol("in"), "in_");
        assert_eq!(sympy_symbol("beta"), "beta");
    }

    #[test]
    fn atoms_name_their_parameter() {
        assert_eq!(sympy_name("exp(in)"), "exp(in_)");
        assert_eq!(sympy_name("sin(-3*lambda/2)"), "sin(-3*lamda/2)");
        assert_eq!(sympy_name("cos(alpha)"), "cos(alpha)");
        assert_eq!(sympy_name("sqrt(2)"), "sqrt(2)");
        assert_eq!(sympy_name("E"), "E_");
        assert_eq!(
            sympy_symbols(["exp(lambda)", "sqrt(3)", "pi", "s", "c", "E", "None"]),
            ["E_", "None_", "lamda", "theta"]
        );
    }
}
