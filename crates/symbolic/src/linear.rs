//! Reading a value as a linear combination `Σ cᵢ·vᵢ` of named variables
//! (control points), for printing formulas the way papers print them.

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

    /// Unicode `(c₁)·v₁ + (c₂)·v₂ + …` when `self` is a combination of `vars`,
    /// else the plain Unicode form.
    pub fn to_combination(&self, vars: &[String]) -> String {
        match self.linear_in(vars) {
            Some(terms) => terms
                .iter()
                .map(|(v, c)| format!("({})·{}", c.to_unicode(), Sym::var(v).to_unicode()))
                .collect::<Vec<_>>()
                .join(" + "),
            None => self.to_unicode(),
        }
    }
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
