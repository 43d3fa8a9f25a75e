//! Exact division in the quotient ring `ℚ[x₁, …][s, c]/(s² + c² − 1)`
//! ([`Poly::exact_div`]): by one term, term by term; by a divisor free of
//! `s`, the division algorithm; otherwise through the divisor's conjugates,
//! after a modular image has had its chance to refuse
//! ([`proves_not_divisor`]).

use crate::modular::proves_not_divisor;
use crate::poly::Poly;
use crate::var::Var;

impl Poly {
    /// The quotient `self / d` in the quotient ring, when it exists
    /// (`None` when `d` does not divide `self`, or `d = 0`).
    ///
    /// Exact and complete. A divisor free of `s` is handled by the division
    /// algorithm (graded lex order), which for a single divisor leaves
    /// remainder zero exactly when the division is exact. A divisor
    /// `d = d₀ + d₁s` is first made free of `s` through its conjugate
    /// `d̄ = d₀ − d₁s`: `self/d = self·d̄ / (d·d̄)`, and
    /// `d·d̄ = d₀² − d₁²(1 − c²)`. So `(1 − c²)/s = s` is found.
    pub fn exact_div(&self, d: &Poly) -> Option<Poly> {
        if d.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(Poly::zero());
        }
        // By a term free of reduced atoms, term by term: the quotient ring
        // is free over ℚ[x₁, …] with basis cⁱ, s·cⁱ, and multiplying by such
        // a term creates no s², so it divides exactly when it divides every
        // term (and the quotient keeps the order of the terms).
        if let Some((m, q)) = d.terms().next()
            && d.len() == 1
            && m.factors().all(|(v, _)| !v.is_reduced())
        {
            return self
                .terms()
                .map(|(n, c)| Some((n.checked_div(m)?, c.checked_div(q)?)))
                .collect::<Option<_>>()
                .map(Poly::from_normal_terms);
        }
        // Degrees in variables other than s, c add up under multiplication
        // (the quotient ring is an integral domain, free over them).
        let mut degrees: Vec<(Var, u32)> = Vec::new();
        for (m, _) in d.terms() {
            for (v, e) in m.factors().filter(|(v, _)| !v.is_trig()) {
                match degrees.iter_mut().find(|(w, _)| w == v) {
                    Some((_, d)) => *d = (*d).max(e),
                    None => degrees.push((*v, e)),
                }
            }
        }
        if degrees.iter().any(|(v, e)| *e > self.degree_in_var(*v)) {
            return None;
        }
        // Make the divisor free of every reduced atom (sine, radical)
        // through its conjugates (`d₀ + d₁s ↦ d₀ − d₁s`), multiplying `self`
        // alike: `d·d̄` is even in the atom, so its normal form lacks it.
        // That costs a product of `self`: a modular image may refuse first.
        if !d.reduced_atoms().is_empty() && proves_not_divisor(d, self) {
            return None;
        }
        let (mut num, mut den) = (self.clone(), d.clone());
        while let Some(atom) = den.reduced_atoms().into_iter().next() {
            let conj = den.subs(atom.name(), &-Poly::var(atom.name()));
            num = &num * &conj;
            den = &den * &conj;
        }
        num.divide_free_of_sin(&den)
    }

    /// The sine atoms (`s`, `sin(X)`) and radicals that occur.
    fn reduced_atoms(&self) -> Vec<Var> {
        let mut out: Vec<Var> = Vec::new();
        for (m, _) in self.terms() {
            for (v, _) in m.factors() {
                if v.is_reduced() && !out.contains(v) {
                    out.push(*v);
                }
            }
        }
        out
    }

    /// Division algorithm by a nonzero divisor free of `s` (no reduction
    /// can occur, so this is division in the polynomial ring).
    fn divide_free_of_sin(&self, d: &Poly) -> Option<Poly> {
        let (lm_d, lc_d) = d.leading_term()?;
        let mut r = self.clone();
        let mut q = Poly::zero();
        while let Some((lm_r, lc_r)) = r.leading_term() {
            let m = lm_r.checked_div(lm_d)?;
            let coef = lc_r
                .checked_div(lc_d)
                .expect("a stored coefficient is nonzero");
            r.add_scaled(d, &m, &coef.neg());
            q.add_term(m, coef);
        }
        Some(q)
    }
}

#[cfg(test)]
mod tests {
    use rug::Rational;

    use super::*;

    fn v(n: &str) -> Poly {
        Poly::var(n)
    }

    fn q(n: i64, d: i64) -> Poly {
        Poly::constant(Rational::from((n, d)))
    }

    #[test]
    fn exact_division() {
        let a = v("m") + &q(2, 1);
        let b = v("beta") - &v("s");
        let p = &a * &b;
        assert_eq!(p.exact_div(&a), Some(b.clone()));
        assert_eq!(p.exact_div(&b), Some(a.clone()));
        assert_eq!(p.exact_div(&(v("m") + &q(1, 1))), None);
        assert_eq!(a.exact_div(&Poly::zero()), None);
        // (1 − c)(1 + c) = s²: divisible through the relation
        let s2 = v("s").pow(2);
        assert_eq!(
            s2.exact_div(&(Poly::one() - &v("c"))),
            Some(Poly::one() + &v("c"))
        );
        assert_eq!(s2.exact_div(&v("s")), Some(v("s")));
        let sp = (v("s") + &v("c")) * &(v("m") - &v("s"));
        assert_eq!(sp.exact_div(&(v("s") + &v("c"))), Some(v("m") - &v("s")));
        assert_eq!(sp.exact_div(&(v("s") - &v("c"))), None);
        // s·c·(1+m) / (s·c)
        let sc = &v("s") * &v("c");
        assert_eq!((&sc * &a).exact_div(&sc), Some(a));
        // by one term: term by term (c is not reduced), none when a term
        // is not divisible
        let t = q(3, 2) * &v("m") * &v("c");
        let r = &v("m") * &(v("m") + &v("beta"));
        assert_eq!((&t * &r).exact_div(&t), Some(r.clone()));
        assert_eq!((&t * &r).exact_div(&v("m").pow(3)), None);
        assert_eq!(s2.exact_div(&v("c")), None);
    }
}
