//! The sign of an exponential function on `x ∈ [0, p]` for every
//! parameter `p ≥ p₀ ≥ 0` — unbounded ranges included — by a certificate
//! of positive coefficients.
//!
//! On the domain `[0, p]` with the atoms `y = exp(κx)` and `Y = exp(κp)`
//! (`κ > 0`; hyperbolic functions are written in them exactly), every point
//! satisfies `1 ≤ y ≤ Y`. Writing `y = 1 + u`, `Y = 1 + u + v` maps that set
//! into the quadrant `u, v ≥ 0`; a polynomial whose coefficients in `u, v`
//! are all `≥ 0` (all `≤ 0`) is `≥ 0` (`≤ 0`) there. A function is decided
//! factor by factor (factors of even multiplicity are squares): it is
//! `≥ 0` when the signs of its odd factors and its unit multiply to `+`.
//! Sufficient only: `None` when a factor has coefficients of both signs or
//! the function is not of this kind. Exact rational arithmetic throughout.
//!
//! Example: the quadratic H-Bézier middle function
//! `(cosh α − cosh(α − t) − cosh t + 1)/(cosh α − 1)` is
//! `(y − 1)(Y − y)(Y + 1)/(y(Y − 1)²)` in these atoms: every odd factor
//! (`u`, `v`, `2 + u + v`, `1 + u`) has positive coefficients.

use rug::Rational;
use trig_core::{Affine, Domain};
use trig_symbolic::Sym;

use crate::atoms::{Kind, param_atoms};

/// The sign of the coefficients of `g` after the substitution: `1` all
/// `≥ 0`, `−1` all `≤ 0`, `None` mixed (or `g` zero).
fn coefficient_sign(g: &Sym, y: &str, big_y: &str) -> Option<i32> {
    let (u, v) = (Sym::var("__u"), Sym::var("__v"));
    let one = Sym::one();
    let h = g.subs(big_y, &(one.clone() + &u + &v)).subs(y, &(one + &u));
    if !h.denominator().is_empty() || h.is_zero() {
        return None;
    }
    let signs: Vec<bool> = h.numerator().terms().map(|(_, q)| *q > 0).collect();
    if signs.iter().all(|p| *p) {
        Some(1)
    } else if signs.iter().all(|p| !*p) {
        Some(-1)
    } else {
        None
    }
}

/// `Some(true)` when `f ≥ 0` on `[0, p]` for every `p ≥ lo` (`lo ≥ 0`)
/// is certified; `None` when the method does not apply or does not decide.
pub fn nonnegative(f: &Sym, domain: &Domain, lo: &Rational) -> Option<bool> {
    let kappa = domain.exp.clone()?;
    let shape = domain.param_names.len() == 1
        && domain.start == Affine::default()
        && domain.end == Affine::param(0)
        && domain.angle.is_none()
        && kappa > 0
        && *lo >= 0;
    if !shape {
        return None;
    }
    let big_y = param_atoms(domain)
        .into_iter()
        .find(|a| a.kind == Kind::Exp && a.base == kappa)?
        .name;
    if !f.variables().iter().all(|v| v == "E" || *v == big_y) {
        return None;
    }
    let q = f.factored();
    let mut sign = if q.unit < 0 { -1 } else { 1 };
    for (g, e) in q.num.iter().chain(&q.den) {
        if e % 2 == 1 {
            sign *= coefficient_sign(&Sym::from_poly(g.clone()), "E", &big_y)?;
        }
    }
    (sign > 0).then_some(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `t ∈ [0, α]` with `E = exp(t)` and `exp(alpha)`.
    fn exponential() -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: None,
            uses_variable: false,
            exp: Some(Rational::from(1)),
            param_angles: Vec::new(),
            param_exps: vec![(0, Rational::from(1))],
        }
    }

    #[test]
    fn exponential_bernstein_and_h_bezier_functions_on_a_half_line() {
        // README B7/C5: b1 = 3w(1 − w)², w = (E − 1)/(exp α − 1), ≥ 0 for every α > 0
        let d = exponential();
        let (e, ea, one) = (Sym::var("E"), Sym::var("exp(alpha)"), Sym::one());
        let w = (e.clone() - &one) / &(ea.clone() - &one);
        let b1 = Sym::int(3) * &w * &(one.clone() - &w) * &(one.clone() - &w);
        assert_eq!(nonnegative(&b1, &d, &Rational::new()), Some(true));
        // README C3: 1 − b0 − b2 of the quadratic H-Bézier basis (cosh in E, exp α)
        let cosh = |x: &Sym| (x.clone() + &(one.clone() / x)) / &Sym::int(2);
        let den = cosh(&ea) - &one;
        let b0 = (cosh(&(ea.clone() / &e)) - &one) / &den;
        let b2 = (cosh(&e) - &one) / &den;
        let b1 = one.clone() - &b0 - &b2;
        assert_eq!(nonnegative(&b1, &d, &Rational::new()), Some(true));
        // 1 − 2w changes sign on the domain: not certified
        let bad = one.clone() - &(Sym::int(2) * &w);
        assert_eq!(nonnegative(&bad, &d, &Rational::new()), None);
        // −w is certified ≤ 0, so not ≥ 0
        assert_eq!(nonnegative(&-w, &d, &Rational::new()), None);
    }
}
