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

impl Sym {
    /// `self` as a combination of `vars` in `style`, one term per line, as
    /// a long formula is set in a paper: `c₁·v₁`, then `+ c₂·v₂`, `− c₃·v₃`;
    /// each coefficient collected by the symbols `by` it is polynomial in
    /// (the `G` factors `α`, `β`: `c = Σ cₘ·m` over their monomials `m`) and
    /// each part factored where that is not longer. `None` when `self` is
    /// not such a combination.
    pub fn combination_lines(
        &self,
        vars: &[String],
        by: &[String],
        style: Style,
    ) -> Option<Vec<String>> {
        let terms = self.linear_in(vars)?;
        Some(
            terms
                .iter()
                .enumerate()
                .map(|(i, (v, c))| {
                    let point = style.sym(&Sym::var(v));
                    let coefficient =
                        by_factors(c, by, style).unwrap_or_else(|| c.shortest_in(style));
                    let term = combine(&[(coefficient, point)], style);
                    if i == 0 {
                        return term;
                    }
                    match term.strip_prefix(style.minus()) {
                        Some(rest) => format!("{} {rest}", style.minus()),
                        None => format!("+ {term}"),
                    }
                })
                .collect(),
        )
    }
}

impl Sym {
    /// `self` in `style` as a factor of a product, factored where that is
    /// not longer (a sum counted with the parentheses it needs there).
    pub fn shortest_in(&self, style: Style) -> String {
        let expanded = style.sym(self);
        let f = self.factored();
        if f.trivial {
            return expanded;
        }
        let factored = style.factored(&f);
        let width = |t: &str| t.chars().count() + 2 * usize::from(has_top_level_sum(t, style));
        if width(&factored) <= width(&expanded) {
            factored
        } else {
            expanded
        }
    }
}

/// A coefficient in `style` collected by the monomials of `by`, when it is
/// a polynomial of more than one of them (`−(2·(μ₁ + 1)·α² + (μ₁ + 2)/2·β)`,
/// a common sign taken out, each part [`Sym::shortest_in`]).
fn by_factors(c: &Sym, by: &[String], style: Style) -> Option<String> {
    let parts = collected(c, by);
    if parts.len() < 2 {
        return None;
    }
    // a common sign is taken out when it leaves fewer minus signs in each part
    let minuses = |x: &Sym| x.shortest_in(style).matches(style.minus()).count();
    let negative = parts.iter().all(|(_, k)| minuses(&-k.clone()) < minuses(k));
    let sign = if negative { Sym::int(-1) } else { Sym::one() };
    let printed: Vec<(String, String)> = parts
        .iter()
        .map(|(m, k)| ((k.clone() * &sign).shortest_in(style), style.sym(m)))
        .collect();
    let sum = combine(&printed, style);
    Some(if negative {
        format!("{}({sum})", style.minus())
    } else {
        sum
    })
}

/// `c = Σ cₘ·m` over the monomials `m` of the symbols `by` (each `cₘ` free
/// of them), highest degree first; one part `(1, c)` when `c` is not a
/// polynomial in them (a denominator depends on one).
fn collected(c: &Sym, by: &[String]) -> Vec<(Sym, Sym)> {
    let mut parts = vec![(Sym::one(), c.clone())];
    for v in by {
        if c.denominator_poly().degree_in(v) > 0 {
            return vec![(Sym::one(), c.clone())];
        }
        let mut next = Vec::new();
        for (m, k) in parts {
            let mut d = k;
            let mut factorial = Sym::one();
            let degree = d.numerator().degree_in(v);
            let mut powers = Vec::new();
            for e in 0..=degree {
                if e > 0 {
                    d = d.diff(v);
                    factorial = factorial * &Sym::int(i64::from(e));
                }
                let at_zero = d.subs(v, &Sym::zero()) / &factorial;
                if !at_zero.is_zero() {
                    let mut power = m.clone();
                    for _ in 0..e {
                        power = power * &Sym::var(v);
                    }
                    powers.push((power, at_zero));
                }
            }
            powers.reverse();
            next.extend(powers);
        }
        parts = next;
    }
    parts
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

    #[test]
    fn long_combinations_one_term_per_line_coefficients_factored() {
        let v = |n: &str| Sym::var(n);
        let a = v("alpha");
        // (2α² + 4α)·P1 − P2: the coefficient factored as 2α(α + 2)
        let x = (Sym::int(2) * &a * &a + &(Sym::int(4) * &a)) * &v("P1") - &v("P2");
        let lines = x
            .combination_lines(&names(&["P1", "P2"]), &[], Style::Unicode)
            .unwrap();
        assert_eq!(lines, ["2·α·(α + 2)·P₁", "− P₂"]);
        assert!(
            v("alpha")
                .combination_lines(&names(&["P1"]), &[], Style::Unicode)
                .is_none()
        );
        // collected by the factors: −(4(λ + 2)(μ + 1)α² + (λ + 2)(μ + 2)β)/(2(λ + 2))
        let (l, m, b) = (v("lambda"), v("mu"), v("beta"));
        let two = Sym::int(2);
        let c = -(Sym::int(4) * &(l.clone() + &two) * &(m.clone() + &Sym::one()) * &a * &a
            + &((l.clone() + &two) * &(m.clone() + &two) * &b))
            / &(two.clone() * &(l + &two));
        let x = c * &v("P2") + &v("P3");
        let lines = x
            .combination_lines(
                &names(&["P2", "P3"]),
                &names(&["alpha", "beta"]),
                Style::Unicode,
            )
            .unwrap();
        assert_eq!(lines[0], "−((2·μ + 2)·α² + (1/2·μ + 1)·β)·P₂", "{lines:?}");
    }

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
