//! Greatest common divisors of polynomials over ℚ in several variables.
//!
//! For polynomials free of the trigonometric atoms `s`, `c` the ring is
//! `ℚ[x₁, …, x_k]`, a unique factorisation domain, and the gcd is computed
//! by the recursive primitive remainder sequence: with a main variable `x`,
//! `gcd(a, b) = gcd(cont a, cont b) · pp(last nonzero prem)`, where the
//! contents (gcds of the coefficients in `x`) are computed recursively in
//! the remaining variables. A numerator `N = Σ nⱼ·mⱼ` in the normal-form
//! basis `{cⁱ, s·cⁱ}` and a factor `f` free of `s`, `c` share exactly the
//! divisors of `gcd(f, n₁, n₂, …)`, since that basis is free over
//! `ℚ[x₁, …, x_k]` ([`common_factor`]).
//!
//! Used by [`crate::Sym`] to keep fractions in lowest terms:
//! `(m + 2)/(m² − 4) = 1/(m − 2)`. Most pairs are coprime, and a modular
//! image proves that cheaply (`modular::coprime`) before the exact
//! remainder sequence runs.

use std::collections::{BTreeMap, BTreeSet};

use crate::monomial::Monomial;
use crate::poly::Poly;

/// `gcd(a, b)` for polynomials free of `s` and `c`: primitive, positive
/// leading coefficient; `gcd(0, 0) = 0`. `None` when either involves `s`
/// or `c` (the quotient ring is not a unique factorisation domain).
pub fn gcd(a: &Poly, b: &Poly) -> Option<Poly> {
    if a.is_trig() || b.is_trig() {
        return None;
    }
    Some(gcd_free(a, b))
}

/// A nonconstant common divisor of `num` (any polynomial) and `f` (free
/// of `s`, `c`), when one exists: the gcd of `f` and the coefficients of
/// `num` as a polynomial in every variable that `f` lacks (`s`, `c`
/// included) — those coefficients lie in the ring of `f`'s own variables,
/// over which the monomials in the other variables (in normal form) are a
/// free basis, so the common divisors are the same and the gcds stay small.
pub fn common_factor(num: &Poly, f: &Poly) -> Option<Poly> {
    if f.is_trig() || f.as_constant().is_some() {
        return None;
    }
    let mut coefficients: Vec<Poly> = coefficients_over(num, &f.variables())
        .into_values()
        .collect();
    coefficients.sort_by_key(Poly::len);
    if crate::modular::coprime(f, &coefficients) {
        return None;
    }
    let mut g = f.clone();
    for coefficient in &coefficients {
        g = gcd_free(&g, coefficient);
        if g.as_constant().is_some() {
            return None;
        }
    }
    Some(g)
}

/// The coefficients of `p` as a polynomial in the variables outside
/// `keep`, keyed by their monomials; each coefficient involves only `keep`.
pub(crate) fn coefficients_over(p: &Poly, keep: &BTreeSet<String>) -> BTreeMap<Monomial, Poly> {
    let mut out: BTreeMap<Monomial, Poly> = BTreeMap::new();
    for (m, q) in p.terms() {
        let (inside, outside) = m.partition(|v| keep.contains(v.name()));
        out.entry(outside).or_default().add_term(inside, q.clone());
    }
    out
}

/// The gcd in `ℚ[x₁, …, x_k]`, normalised by [`Poly::canonical`].
pub(crate) fn gcd_free(a: &Poly, b: &Poly) -> Poly {
    if a.is_zero() {
        return b.canonical().1;
    }
    if b.is_zero() {
        return a.canonical().1;
    }
    if a.as_constant().is_some() || b.as_constant().is_some() {
        return Poly::one();
    }
    // Monomial content first: it is cheap and often all there is.
    let monomial = monomial_content(a).gcd(&monomial_content(b));
    let one = rug::Rational::from(1);
    let m = Poly::term(monomial.clone(), one);
    let (a, b) = if monomial.is_one() {
        (a.clone(), b.clone())
    } else {
        let divide = |p: &Poly| p.exact_div(&m).expect("monomial content divides");
        (divide(a), divide(b))
    };
    let Some(x) = a.variables().into_iter().chain(b.variables()).next() else {
        return m;
    };
    // Two cheap exits before the remainder sequence, whose recursive
    // contents grow with the number of variables: most pairs met in a
    // content computation are coprime (a modular image proves it), and a
    // common factor is often the smaller polynomial itself.
    let (small, large) = if a.len() <= b.len() {
        (&a, &b)
    } else {
        (&b, &a)
    };
    if crate::modular::coprime(small, std::slice::from_ref(large)) {
        return m;
    }
    if large.exact_div(small).is_some() {
        return (&m * small).canonical().1;
    }
    let (ca, pa) = split_content(&a, &x);
    let (cb, pb) = split_content(&b, &x);
    let content = gcd_free(&ca, &cb);
    let primitive = primitive_gcd(pa, pb, &x);
    (&(&m * &content) * &primitive).canonical().1
}

/// The gcd of all monomials of `p`.
pub(crate) fn monomial_content(p: &Poly) -> Monomial {
    p.terms()
        .map(|(m, _)| m.clone())
        .reduce(|a, b| a.gcd(&b))
        .unwrap_or_default()
}

/// `(cont_x p, pp_x p)`: the gcd of the coefficients of `p` in `x`, and
/// `p` divided by it.
pub(crate) fn split_content(p: &Poly, x: &str) -> (Poly, Poly) {
    let content =
        p.coefficients_in(x)
            .iter()
            .filter(|c| !c.is_zero())
            .fold(Poly::zero(), |g, c| {
                if g.as_constant().is_some_and(|q| q != 0) {
                    g
                } else {
                    gcd_free(&g, c)
                }
            });
    let primitive = p.exact_div(&content).expect("the content divides");
    (content, primitive)
}

/// The gcd of two polynomials primitive in `x`, by the primitive
/// pseudo-remainder sequence.
fn primitive_gcd(mut a: Poly, mut b: Poly, x: &str) -> Poly {
    if a.degree_in(x) < b.degree_in(x) {
        std::mem::swap(&mut a, &mut b);
    }
    while !b.is_zero() {
        if b.degree_in(x) == 0 {
            // A nonzero polynomial free of x that divides a primitive one.
            return Poly::one();
        }
        let r = pseudo_remainder(&a, &b, x);
        a = b;
        b = if r.is_zero() {
            r
        } else {
            split_content(&r, x).1
        };
    }
    a
}

/// `lc(b)ᵏ·a mod b` in `x` (some `k ≥ 0`): a nonzero multiple of `lc(b)`
/// only changes the result by a factor free of `x`, which the caller's
/// primitive part removes.
fn pseudo_remainder(a: &Poly, b: &Poly, x: &str) -> Poly {
    let db = b.degree_in(x);
    let lead_b = b.coefficients_in(x).pop().unwrap_or_default();
    let mut r = a.clone();
    while !r.is_zero() && r.degree_in(x) >= db {
        let dr = r.degree_in(x);
        let lead_r = r.coefficients_in(x).pop().unwrap_or_default();
        let shift = Poly::term(
            Monomial::var(crate::Var::new(x), dr - db),
            rug::Rational::from(1),
        );
        r = &(&r * &lead_b) - &(&(&lead_r * &shift) * b);
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::var::{COS, SIN};

    fn v(name: &str) -> Poly {
        Poly::var(name)
    }

    fn n(k: i64) -> Poly {
        Poly::int(k)
    }

    #[test]
    fn univariate() {
        let m = v("m");
        let m2 = m.pow(2);
        assert_eq!(gcd(&(&m2 - &n(4)), &(&m + &n(2))), Some(&m + &n(2)));
        let square = &(&m2 + &(&n(4) * &m)) + &n(4);
        assert_eq!(gcd(&(&m2 - &n(4)), &square), Some(&m + &n(2)));
        assert_eq!(gcd(&(&m2 - &n(4)), &(&m - &n(3))), Some(Poly::one()));
        let a = &(&n(6) * &m) + &n(12);
        let b = &(&n(4) * &m2) - &n(16);
        assert_eq!(gcd(&a, &b), Some(&m + &n(2)));
    }

    #[test]
    fn several_variables() {
        let (l, u) = (v("lambda"), v("mu"));
        let g = &(&l + &u) - &n(1);
        let a = &g * &(&l.pow(2) + &u);
        let b = &g * &(&(&l - &u.pow(3)) + &n(2));
        assert_eq!(gcd(&a, &b), Some(g.clone()));
        let h = &(&l * &u) * &g;
        assert_eq!(gcd(&h, &(&u.pow(2) * &(&l + &n(1)))), Some(u.clone()));
        assert_eq!(gcd(&a, &Poly::zero()), Some(a.canonical().1));
        // The sign and the rational content are normalised away.
        assert_eq!(gcd(&(&n(-3) * &a), &b), Some(g));
    }

    /// A quotient basis with eight parameters met in a C² join: a common
    /// factor `1 + a₁ + … + a₈` of an expanded square and a large cofactor
    /// (the remainder sequence alone ran for minutes here).
    #[test]
    fn eight_variables_with_a_common_factor() {
        let a: Vec<Poly> = (1..=8).map(|k| v(&format!("a{k}"))).collect();
        let g = a.iter().fold(n(1), |acc, x| &acc + x);
        let cofactor = a.iter().enumerate().fold(n(3), |acc, (k, x)| {
            &acc + &(&n(k as i64 + 1) * &(x * &a[(k + 3) % 8]).pow(2))
        });
        let square = g.pow(2);
        let large = &(&g * &cofactor) * &(&a[0] - &n(2));
        assert_eq!(gcd(&square, &large), Some(g.clone()));
        assert_eq!(gcd(&large, &square), Some(g.clone()));
        assert_eq!(gcd(&square, &cofactor), Some(Poly::one()));
        assert_eq!(common_factor(&(&v(SIN) * &large), &square), Some(g));
    }

    #[test]
    fn trig_numerators_share_parameter_factors_only() {
        let (m, s, c) = (v("m"), v(SIN), v(COS));
        let num = &(&m + &n(2)) * &(&(&(&s * &c) + &(&n(3) * &c.pow(2))) - &m);
        let f = &m.pow(2) - &n(4);
        assert_eq!(common_factor(&num, &f), Some(&m + &n(2)));
        assert_eq!(common_factor(&(&s + &m), &f), None);
        assert_eq!(gcd(&s, &m), None);
    }
}
