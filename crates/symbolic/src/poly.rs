//! Sparse multivariate polynomials over ℚ in named variables, kept reduced
//! modulo `s² + c² − 1`.
//!
//! Every polynomial is stored in normal form: no monomial contains `s²`
//! (each `s^k`, `k ≥ 2`, is rewritten with `s² = 1 − c²`). Since
//! `{cⁱ, s·cⁱ}` is a basis of `ℚ[…][s, c]/(s² + c² − 1)` over the other
//! variables, the normal form is unique: two polynomials are equal in the
//! quotient ring exactly when their normal forms are equal, and a normal
//! form is zero exactly when the element is zero.

use std::collections::btree_map::Entry;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

use rug::{Integer, Rational};

use crate::coef::Coef;
use crate::monomial::Monomial;
use crate::var::Var;

/// A polynomial `Σ cᵢ·mᵢ` with rational coefficients, in normal form
/// modulo `s² + c² − 1`. The derived order (used to key denominator
/// factors) is structural and has no mathematical meaning.
#[derive(Clone, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Poly {
    terms: BTreeMap<Monomial, Coef>,
}

impl Poly {
    /// The zero polynomial.
    pub fn zero() -> Poly {
        Poly::default()
    }

    /// The constant `1`.
    pub fn one() -> Poly {
        Poly::coef_term(Monomial::one(), Coef::ONE)
    }

    /// The constant `q`.
    pub fn constant(q: Rational) -> Poly {
        Poly::term(Monomial::one(), q)
    }

    /// The integer `n`.
    pub fn int(n: i64) -> Poly {
        Poly::coef_term(Monomial::one(), Coef::int(n))
    }

    /// The variable `name`.
    pub fn var(name: &str) -> Poly {
        Poly::coef_term(Monomial::var(Var::new(name), 1), Coef::ONE)
    }

    /// The single term `q·m` (reduced).
    pub fn term(m: Monomial, q: Rational) -> Poly {
        Poly::coef_term(m, Coef::from(q))
    }

    /// The single term `q·m` (reduced).
    pub(crate) fn coef_term(m: Monomial, q: Coef) -> Poly {
        let mut p = Poly::zero();
        p.add_term(m, q);
        p
    }

    /// True for the zero polynomial.
    /// The polynomial of terms already in normal form (no power ≥ 2 of a
    /// reduced atom, no zero coefficient).
    pub(crate) fn from_normal_terms(terms: BTreeMap<Monomial, Coef>) -> Poly {
        Poly { terms }
    }

    /// Whether `s` or `c` (a trigonometric atom) occurs.
    pub(crate) fn is_trig(&self) -> bool {
        self.terms
            .keys()
            .any(|m| m.factors().any(|(v, _)| v.is_trig()))
    }

    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value when the polynomial is a constant.
    pub fn as_constant(&self) -> Option<Rational> {
        match self.terms.len() {
            0 => Some(Rational::new()),
            1 => self
                .terms
                .iter()
                .next()
                .filter(|(m, _)| m.is_one())
                .map(|(_, q)| q.to_rational()),
            _ => None,
        }
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// True when there are no terms (the zero polynomial).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The terms, greatest monomial first (the printing order).
    pub fn terms(&self) -> impl DoubleEndedIterator<Item = (&Monomial, &Coef)> {
        self.terms.iter().rev()
    }

    /// The greatest term.
    pub fn leading_term(&self) -> Option<(&Monomial, &Coef)> {
        self.terms.last_key_value()
    }

    /// Degree in the variable `name`.
    pub fn degree_in(&self, name: &str) -> u32 {
        Var::find(name).map_or(0, |v| self.degree_in_var(v))
    }

    /// Degree in the variable `v`.
    pub(crate) fn degree_in_var(&self, v: Var) -> u32 {
        self.terms
            .keys()
            .map(|m| m.exponent_of(v))
            .max()
            .unwrap_or(0)
    }

    /// Total degree (0 for constants and for zero).
    pub fn total_degree(&self) -> u64 {
        self.terms.keys().map(Monomial::degree).max().unwrap_or(0)
    }

    /// The names of the variables that occur.
    pub fn variables(&self) -> BTreeSet<String> {
        crate::var::names(self.vars())
    }

    /// The variables, in order of first occurrence.
    pub(crate) fn vars(&self) -> Vec<Var> {
        let mut out = Vec::new();
        self.collect_vars(&mut out);
        out
    }

    /// Adds to `out` every variable of `self` not already there (a name is
    /// formed once per variable, not once per occurrence).
    pub(crate) fn collect_vars(&self, out: &mut Vec<Var>) {
        for m in self.terms.keys() {
            for (v, _) in m.factors() {
                if !out.contains(v) {
                    out.push(*v);
                }
            }
        }
    }

    /// Adds `q·m`, rewriting every power `vᵏ` (`k ≥ 2`) of a reduced atom
    /// by its square rule ([`Var::square`]): `sᵏ = s^(k mod 2)·(1 − c²)^⌊k/2⌋`
    /// for a sine atom with cosine partner `c`, `sqrt(p)ᵏ = sqrt(p)^(k mod 2)·p^⌊k/2⌋`.
    pub(crate) fn add_term(&mut self, m: Monomial, q: Coef) {
        if q.is_zero() {
            return;
        }
        let Some((v, k)) = m.factors().find(|(v, e)| *e >= 2 && v.is_reduced()) else {
            self.accumulate(m, q);
            return;
        };
        let v = *v;
        let (rest, _) = m.split_off(v);
        let base = rest.mul(&Monomial::var(v, k % 2));
        let j = k / 2;
        match v.square().expect("a reduced atom has a square rule") {
            (None, p) => {
                let coef = q.mul(&Coef::from(&Integer::from(rug::ops::Pow::pow(&p, j))));
                self.add_term(base, coef);
            }
            (Some(cosine), _) => {
                let mut binom = Integer::from(1);
                for i in 0..=j {
                    let mut coef = q.mul(&Coef::from(&binom));
                    if i % 2 == 1 {
                        coef = coef.neg();
                    }
                    self.add_term(base.mul(&Monomial::var(cosine, 2 * i)), coef);
                    binom = binom * (j - i) / (i + 1);
                }
            }
        }
    }

    fn accumulate(&mut self, m: Monomial, q: Coef) {
        match self.terms.entry(m) {
            Entry::Occupied(mut e) => {
                let sum = e.get().add(&q);
                if sum.is_zero() {
                    e.remove();
                } else {
                    *e.get_mut() = sum;
                }
            }
            Entry::Vacant(e) => {
                e.insert(q);
            }
        }
    }

    /// `q·self`.
    pub fn scale(&self, q: &Rational) -> Poly {
        self.scale_by(&Coef::from(q))
    }

    /// `q·self`.
    pub(crate) fn scale_by(&self, q: &Coef) -> Poly {
        if q.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self
                .terms
                .iter()
                .map(|(m, c)| (m.clone(), c.mul(q)))
                .collect(),
        }
    }

    /// `self + q·m·d` in place.
    pub(crate) fn add_scaled(&mut self, d: &Poly, m: &Monomial, q: &Coef) {
        for (md, cd) in &d.terms {
            self.add_term(m.mul(md), q.mul(cd));
        }
    }

    /// `selfⁿ`.
    pub fn pow(&self, n: u32) -> Poly {
        crate::power::by_squaring(self, n, Poly::one(), |a, b| a * b)
    }

    /// The positive rational `g` such that `self / g` has coprime integer
    /// coefficients (zero for the zero polynomial).
    pub fn content(&self) -> Rational {
        let mut num = Integer::new();
        let mut den = Integer::from(1);
        for q in self.terms.values() {
            num.gcd_mut(&q.numer());
            den.lcm_mut(&q.denom());
        }
        Rational::from((num, den))
    }

    /// `self / content`: coprime integer coefficients, same sign.
    pub fn primitive_part(&self) -> Poly {
        if self.is_zero() {
            return Poly::zero();
        }
        self.scale(&self.content().recip())
    }

    /// `(u, p)` with `self = u·p`, `p` primitive with positive leading
    /// coefficient (for zero: `(0, 0)`).
    pub fn canonical(&self) -> (Rational, Poly) {
        let mut u = self.content();
        if self.leading_term().is_some_and(|(_, q)| q.signum() < 0) {
            u = -u;
        }
        if u == 0 {
            return (u, Poly::zero());
        }
        let p = self.scale(&u.clone().recip());
        (u, p)
    }

    /// The coefficients `[p₀, p₁, …]` of `self = Σ pᵢ·nameⁱ`, each free of
    /// `name` (`[0]` for the zero polynomial).
    pub fn coefficients_in(&self, name: &str) -> Vec<Poly> {
        let Some(v) = Var::find(name) else {
            return vec![self.clone()];
        };
        let mut out = vec![Poly::zero(); self.degree_in_var(v) as usize + 1];
        for (m, q) in &self.terms {
            let (rest, e) = m.split_off(v);
            out[e as usize].add_term(rest, q.clone());
        }
        out
    }

    /// The polynomial with the variable `name` replaced by `value`.
    pub fn subs(&self, name: &str, value: &Poly) -> Poly {
        let Some(v) = Var::find(name) else {
            return self.clone();
        };
        let mut powers = vec![Poly::one()];
        let mut out = Poly::zero();
        for (m, q) in &self.terms {
            let (rest, e) = m.split_off(v);
            while powers.len() <= e as usize {
                let next = powers.last().map(|p| p * value).unwrap_or_default();
                powers.push(next);
            }
            out.add_scaled(&powers[e as usize], &rest, q);
        }
        out
    }

    /// The partial derivative `∂/∂name` of this representative.
    ///
    /// For `s` and `c` the result depends on the representative (the
    /// relation `s² + c² = 1` ties them); use a derivation such as
    /// [`crate::Sym::d_angle`] instead.
    pub fn diff(&self, name: &str) -> Poly {
        let v = Var::new(name);
        let mut out = Poly::zero();
        for (m, q) in &self.terms {
            let (rest, e) = m.split_off(v);
            if e > 0 {
                let m = rest.mul(&Monomial::var(v, e - 1));
                out.add_term(m, q.mul(&Coef::int(i64::from(e))));
            }
        }
        out
    }
}

impl fmt::Debug for Poly {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({self})")
    }
}

impl Add<&Poly> for &Poly {
    type Output = Poly;
    fn add(self, rhs: &Poly) -> Poly {
        self.clone() + rhs
    }
}

impl Add<&Poly> for Poly {
    type Output = Poly;
    fn add(mut self, rhs: &Poly) -> Poly {
        for (m, q) in &rhs.terms {
            self.accumulate(m.clone(), q.clone());
        }
        self
    }
}

impl Sub<&Poly> for &Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        self.clone() - rhs
    }
}

impl Sub<&Poly> for Poly {
    type Output = Poly;
    fn sub(mut self, rhs: &Poly) -> Poly {
        for (m, q) in &rhs.terms {
            self.accumulate(m.clone(), q.neg());
        }
        self
    }
}

impl Mul<&Poly> for &Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        let mut out = Poly::zero();
        for (ma, qa) in &self.terms {
            for (mb, qb) in &rhs.terms {
                out.add_term(ma.mul(mb), qa.mul(qb));
            }
        }
        out
    }
}

impl Mul<&Poly> for Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        &self * rhs
    }
}

impl Neg for Poly {
    type Output = Poly;
    fn neg(mut self) -> Poly {
        for q in self.terms.values_mut() {
            *q = q.neg();
        }
        self
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        -self.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: &str) -> Poly {
        Poly::var(n)
    }

    fn q(n: i64, d: i64) -> Poly {
        Poly::constant(Rational::from((n, d)))
    }

    #[test]
    fn pythagoras_reduces_to_zero() {
        let p = v("s").pow(2) + &v("c").pow(2) - &Poly::one();
        assert!(p.is_zero());
        let p = (v("s") + &v("c")).pow(2) - &(q(2, 1) * &v("s") * &v("c")) - &Poly::one();
        assert!(p.is_zero());
    }

    #[test]
    fn high_powers_of_s() {
        // s⁵ = s(1 − c²)²
        let lhs = v("s").pow(5);
        let omc2 = Poly::one() - &v("c").pow(2);
        assert_eq!(lhs, v("s") * &omc2 * &omc2);
        assert_eq!(lhs.degree_in("s"), 1);
    }

    #[test]
    fn content_and_canonical() {
        let p = q(-3, 2) * &v("m") + &q(9, 4);
        assert_eq!(p.content(), Rational::from((3, 4)));
        assert_eq!(p.primitive_part(), q(-2, 1) * &v("m") + &q(3, 1));
        let (u, c) = p.canonical();
        assert_eq!(u, Rational::from((-3, 4)));
        assert_eq!(c, q(2, 1) * &v("m") - &q(3, 1));
    }

    #[test]
    fn substitution_and_derivative() {
        let p = v("m").pow(2) * &v("s") + &v("m");
        let r = p.subs("m", &(v("beta") + &Poly::one()));
        let b1 = v("beta") + &Poly::one();
        assert_eq!(r, &b1 * &b1 * &v("s") + &b1);
        // substituting c := s gives s·s = 1 − c² after reduction
        assert_eq!(
            v("c").pow(2).subs("c", &v("s")),
            Poly::one() - &v("c").pow(2)
        );
        assert_eq!(p.diff("m"), q(2, 1) * &v("m") * &v("s") + &Poly::one());
        assert_eq!(p.diff("beta"), Poly::zero());
        assert_eq!(p.variables().into_iter().collect::<Vec<_>>(), ["m", "s"]);
        assert_eq!(p.total_degree(), 3);
        assert_eq!(q(5, 3).as_constant(), Some(Rational::from((5, 3))));
        assert_eq!(p.as_constant(), None);
    }
}
