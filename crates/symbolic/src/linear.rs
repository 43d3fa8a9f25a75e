//! Reading a value as a linear combination `Σ cᵢ·vᵢ` of named variables
//! (control points), for printing formulas the way papers print them.

use crate::print::{Style, push_sign};
use crate::sym::Sym;

impl Sym {
    /// The coefficients `cᵢ = ∂self/∂vᵢ` (the nonzero ones, in the order of
    /// `vars`) when `self = Σ cᵢ·vᵢ` exactly; `None` when `self` is not such a
    /// combination (a remainder free of the variables, or a nonlinear term).
    pub fn linear_in(&self, vars: &[String]) -> Option<Vec<(String, Sym)>> {
        let terms: Vec<(String, Sym)> = vars
            .iter()
            .map(|v| (v.clone(), self.diff(v)))
            .filter(|(_, c)| !c.is_zero())
            .collect();
        let rest = terms.iter().fold(self.clone(), |acc, (v, c)| {
            acc - &(c.clone() * &Sym::var(v))
        });
        (!terms.is_empty() && rest.is_zero()).then_some(terms)
    }

    /// Unicode `c₁·v₁ + c₂·v₂ − …` when `self` is a combination of `vars`
    /// (see [`combine`]), else the plain Unicode form.
    pub fn to_combination(&self, vars: &[String]) -> String {
        self.combination_in(vars, Style::Unicode)
            .unwrap_or_else(|| self.to_unicode())
    }

    /// `self` as a combination of `vars` in `style` ([`combine`]), when it
    /// is one.
    pub fn combination_in(&self, vars: &[String], style: Style) -> Option<String> {
        let terms = self.linear_in(vars)?;
        let parts: Vec<(String, String)> = terms
            .iter()
            .map(|(v, c)| (style.sym(c), style.sym(&Sym::var(v))))
            .collect();
        Some(combine(&parts, style))
    }
}

/// `c₁·v₁ + c₂·v₂ − …` from printed coefficients and variables: a
/// coefficient `1` is left out, `−1` becomes a sign, a coefficient of one
/// term (or a product) needs no parentheses, a sum does; a constant term
/// (the variable `1`) is its coefficient.
pub fn combine(parts: &[(String, String)], style: Style) -> String {
    let mut out = String::new();
    for (i, (c, v)) in parts.iter().enumerate() {
        let (negative, body) = match c.strip_prefix(style.minus()) {
            Some(rest) if !has_top_level_sum(rest, style) => (true, rest.to_string()),
            _ => (false, c.clone()),
        };
        let term = if v == "1" {
            body
        } else if body == "1" {
            v.clone()
        } else if has_top_level_sum(&body, style) {
            format!("({body}){}{v}", style.times())
        } else {
            format!("{body}{}{v}", style.times())
        };
        push_sign(&mut out, i == 0, negative, style);
        out.push_str(&term);
    }
    out
}

/// True when `text` has a `+` or `−` outside parentheses and braces (after
/// a leading sign).
fn has_top_level_sum(text: &str, style: Style) -> bool {
    let minus = style.minus().chars().next().unwrap_or('-');
    let mut depth = 0i32;
    for (i, ch) in text.chars().enumerate() {
        match ch {
            '(' | '{' => depth += 1,
            ')' | '}' => depth -= 1,
            '+' if depth == 0 && i > 0 => return true,
            c if c == minus && depth == 0 && i > 0 => return true,
            _ => {}
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn reads_a_combination_and_rejects_a_remainder() {
        let (p0, p1, m) = (Sym::var("P0"), Sym::var("P1"), Sym::var("m"));
        let e = (m.clone() + &Sym::int(2)) * &(p1.clone() - &p0);
        let terms = e.linear_in(&names(&["P0", "P1"])).unwrap();
        assert_eq!(terms.len(), 2);
        assert_eq!(terms[1].1, m.clone() + &Sym::int(2));
        assert!(
            (e.clone() + &Sym::one())
                .linear_in(&names(&["P0", "P1"]))
                .is_none()
        );
        assert!(
            (p0.clone() * &p1)
                .linear_in(&names(&["P0", "P1"]))
                .is_none()
        );
        assert_eq!(Sym::zero().to_combination(&names(&["P0"])), "0");
    }
}
