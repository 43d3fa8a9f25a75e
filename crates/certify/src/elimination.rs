//! The polynomial in the parameter of an end where a minimum touches 0, by
//! elimination of the variable.
//!
//! At such an end `p*` a factor `F(p, s, c)` of a basis function and its
//! derivative `G = ∂F` vanish together at a real angle `θ*` of the domain
//! (`s = sin θ`, `c = cos θ`; the formulas may hold algebraic constants
//! `sqrt(k)`). When `cos θ* ≠ −1`, `z = tan(θ/2)` is finite there and
//! `s = 2z/(1 + z²)`, `c = (1 − z²)/(1 + z²)`: the numerators `P(p, z, r…)`,
//! `Q(p, z, r…)` of `F`, `G` share the root `z*` (`1 + z*² > 0`), so the
//! resultant `Res_z(P, Q)` vanishes at `p*` (a common root makes the
//! Sylvester determinant vanish whatever the leading coefficients). Each
//! `sqrt(k)`, renamed `r`, is then eliminated by `Res_r(·, r² − k)`, the
//! product over `r = ±√k` up to sign, which vanishes at `p*` too. What is
//! left is a polynomial in `p` alone with `p*` among its roots (when it is
//! not identically zero): with a certified enclosure of `p*` that holds
//! exactly one root of it, `p*` is that root — exact ([`exact_root`]).

use rug::Rational;
use trig_core::Affine;
use trig_symbolic::{Poly, Sym};

use crate::algebraic::Algebraic;
use crate::analytic_end::{ExactValue, Problem};
use crate::resultant::resultant;
use crate::sturm::UPoly;

/// Highest degree in `z` of either numerator (the cost model: a Sylvester
/// determinant of order at most twice this, with polynomial entries).
const MAX_DEGREE: u32 = 12;

/// Most distinct `sqrt(k)` constants eliminated.
const MAX_ROOTS: usize = 2;

/// `Res_z(P, Q)` with every `sqrt(k)` eliminated, as a polynomial in
/// `param` (see the module docs), for `factor`, `derivative` polynomials in
/// `param`, `s`, `c` and constants `sqrt(k)`; `None` for anything else,
/// beyond the cost model, or when the result vanishes identically.
pub fn stationary_polynomial(factor: &Sym, derivative: &Sym, param: &str) -> Option<UPoly> {
    let mut roots: Vec<(String, i64)> = Vec::new();
    for f in [factor, derivative] {
        if !f.denominator().is_empty() {
            return None;
        }
        for v in f.variables() {
            if v == param || v == "s" || v == "c" {
                continue;
            }
            let k = v
                .strip_prefix("sqrt(")?
                .strip_suffix(')')?
                .parse::<i64>()
                .ok()?;
            if k <= 0 {
                return None;
            }
            if !roots.iter().any(|(n, _)| *n == v) {
                roots.push((v, k));
            }
        }
    }
    if roots.len() > MAX_ROOTS {
        return None;
    }
    let z = Sym::var("__z");
    let w = Sym::one() + &(z.clone() * &z);
    let s = Sym::int(2) * &z / &w;
    let c = (Sym::one() - &(z.clone() * &z)) / &w;
    let numerator = |f: &Sym| -> Option<Poly> {
        let mut g = f.try_subs("s", &s).ok()?.try_subs("c", &c).ok()?;
        for (i, (name, _)) in roots.iter().enumerate() {
            g = g.try_subs(name, &Sym::var(&format!("__r{i}"))).ok()?;
        }
        let p = g.numerator().clone();
        (p.degree_in("__z") <= MAX_DEGREE).then_some(p)
    };
    let (p, q) = (numerator(factor)?, numerator(derivative)?);
    let mut r = resultant(&p, &q, "__z");
    for (i, (_, k)) in roots.iter().enumerate() {
        let name = format!("__r{i}");
        let square = &Poly::var(&name) * &Poly::var(&name) - &Poly::int(*k);
        r = resultant(&r, &square, &name);
    }
    if r.is_zero() || r.variables().iter().any(|v| v != param) {
        return None;
    }
    UPoly::from_poly(&r, param)
}

/// Why an end found by [`exact_root`] is exact.
pub const WHY: &str = "eliminating the variable from the end's two equations by resultants (z = tan(θ/2), each sqrt(k) as a root of r² − k) leaves a polynomial in the parameter; of its square-free factors only this one has a root in the certified enclosure of the end, so the end is that root";

/// The root of a stationary end exactly: the end's parameter polynomial
/// ([`stationary_polynomial`]), split into its square-free factors, with
/// exactly one root among them all in the certified enclosure `(lo, hi)`
/// (none at its ends) — the end, which is a root of it. Only for a pure
/// trigonometric domain with constant ends whose angles lie in `(−π, π)`
/// (so `cos θ ≠ −1` and `z = tan(θ/2)` is finite at the end's point), and
/// a parameter axis in plain units.
pub fn exact_root(
    problem: &Problem<'_>,
    factor: &Sym,
    derivative: &Sym,
    lo: &Rational,
    hi: &Rational,
) -> Option<ExactValue> {
    let d = problem.domain;
    if problem.pi || !d.is_pure_trigonometric() || !d.start.is_constant() || !d.end.is_constant() {
        return None;
    }
    let rate = d.angle.as_ref()?;
    let within = |x: &Affine| -> Option<bool> {
        let theta = rate.times(x)?;
        let pi = Affine::pi_times(Rational::from(1));
        let below = trig_core::certified::affine_sign(&pi.plus(&theta.scale(&Rational::from(-1))));
        let above = trig_core::certified::affine_sign(&pi.plus(&theta));
        Some(below.ok()?.is_gt() && above.ok()?.is_gt())
    };
    if !(within(&d.start)? && within(&d.end)?) {
        return None;
    }
    let p = stationary_polynomial(factor, derivative, &d.param_names[0])?;
    let mut roots = Vec::new();
    for (f, _) in p.squarefree_factors() {
        if f.sign_at(lo) == 0 || f.sign_at(hi) == 0 {
            return None;
        }
        roots.extend(f.isolate(lo, hi).into_iter().map(|iv| (f.clone(), iv)));
    }
    let [(f, (a, b))] = <[_; 1]>::try_from(roots).ok()?;
    let root = Algebraic::new(&f, a, b);
    Some(match &root.rational {
        Some(q) => ExactValue::Rational(q.clone()),
        None => ExactValue::Algebraic(root),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_end_of_a_half_angle_basis_is_a_root_of_its_quartic() {
        // the half-angle basis of examples/half-angle-lambda.toml: the
        // factor of b1 and its derivative in t (atoms of θ = t/2), as the
        // audit prints them; the left end −√(1 + √2/2) is a root of
        // 2λ⁴ − 4λ² + 1
        let v = |n: &str| Sym::var(n);
        let (l, s, c, r) = (v("lambda"), v("s"), v("c"), v("sqrt(2)"));
        let q = |a: i64, b: i64| Sym::rational(Rational::from((a, b)));
        let c2 = c.clone() * &c;
        let c3 = c2.clone() * &c;
        let f = Sym::int(2) * &l * &r * &c3 + &(Sym::int(2) * &l * &s * &c2)
            - &(Sym::int(2) * &l * &c3)
            + &(l.clone() * &r * &s)
            - &(Sym::int(2) * &l * &r * &c)
            - &(Sym::int(2) * &l * &s)
            + &(Sym::int(2) * &l * &c)
            + &(Sym::int(2) * &s * &c)
            + &(Sym::int(2) * &c2)
            - &Sym::int(2);
        let g = -(Sym::int(3) * &l * &r * &s * &c2)
            + &(Sym::int(3) * &l * &s * &c2)
            + &(Sym::int(3) * &l * &c3)
            + &(l.clone() * &r * &s)
            + &(q(1, 2) * &l * &r * &c)
            - &(l.clone() * &s)
            - &(Sym::int(3) * &l * &c)
            - &(Sym::int(2) * &s * &c)
            + &(Sym::int(2) * &c2)
            - &Sym::one();
        let p = stationary_polynomial(&f, &g, "lambda").expect("a polynomial in λ");
        let quartic = UPoly::new(
            [1, 0, -4, 0, 2]
                .iter()
                .map(|&k| Rational::from(k))
                .collect(),
        );
        assert!(
            p.squarefree_factors()
                .iter()
                .any(|(f, _)| f.integer_primitive() == quartic),
            "{}",
            p.display("λ")
        );
        // anything else than λ, s, c and sqrt(k) is not eliminated here
        assert!(stationary_polynomial(&(f.clone() * &v("t")), &g, "lambda").is_none());
        assert!(stationary_polynomial(&(f * &v("cos(lambda)")), &g, "lambda").is_none());
    }
}
