//! Where a nonnegativity range can end.
//!
//! Let `f = N/D` in `z` (Weierstrass `z = tan(θ/2)`, or `t`) on `z ∈ [0, 1]`.
//! The set of parameters `p` for which `f(·; p) ≥ 0` is closed where `D ≠ 0`,
//! and at a point `p*` of its boundary the minimum over `z` is `0`, attained
//! at some `z*`: in the interior, `N` and `∂N/∂z` vanish together there, so
//! the resultant `Res_z(N, ∂N/∂z)` vanishes at `p*`; at an end, `N(0, p*) = 0`
//! or `N(1, p*) = 0`. Factors `z` and `1 − z` that divide `N` identically do
//! not change its sign inside and are removed first (else `N(0, p) ≡ 0`
//! says nothing). The same conditions on every denominator factor catch
//! the parameters where a pole enters the domain. Hence every boundary
//! point is a root of one of these *boundary polynomials* — a necessary
//! condition, so extra roots only add candidates, never lose an end.

use trig_symbolic::{Poly, Sym};

use crate::domain::in_z;
use crate::resultant::{from_coefficients, resultant};

/// One boundary polynomial in the parameters, with where it comes from.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    pub poly: Poly,
    /// True when it comes from a denominator (a pole may enter there).
    pub pole: bool,
    /// `"discriminant of b1"`, `"b0 at z = 0"`, …
    pub origin: String,
}

/// The boundary polynomials of the functions `fs` (named `names`), or why
/// they cannot be computed (a resultant that vanishes identically: a
/// repeated factor in `z`).
pub fn candidates(
    fs: &[Sym],
    names: &[&str],
    trigonometric: bool,
) -> Result<Vec<Candidate>, String> {
    let zz = Poly::var("z") * &Poly::var("z") + &Poly::one();
    let mut out = Vec::new();
    for (f, name) in fs.iter().zip(names) {
        let fz = in_z(f, trigonometric);
        let mut parts = vec![(fz.numerator().clone(), false)];
        for factor in fz.denominator().keys() {
            let mut factor = factor.clone();
            while factor.degree_in("z") > 0 {
                match factor.exact_div(&zz) {
                    Some(q) => factor = q,
                    None => break,
                }
            }
            parts.push((factor, true));
        }
        for (p, pole) in parts {
            for (poly, what) in conditions(&p, name)? {
                if poly.as_constant().is_none() {
                    out.push(Candidate {
                        poly,
                        pole,
                        origin: what,
                    });
                }
            }
        }
    }
    Ok(out)
}

/// Necessary conditions at the ends of the domain: with `f = N/D`, the
/// factors `z`, `1 − z` that divide `N` identically removed (`N = zᵏ(1 − z)ʲM`),
/// `f` has the sign of `M(e)·D(e)` next to the end `e`. So wherever
/// `D(e)` is a nonzero constant, every parameter where `f ≥ 0` satisfies
/// `g = M(e)·sign D(e) ≥ 0` — a condition on the parameters alone, valid
/// on the whole parameter space. Returned for `e = 0, 1` when available.
pub fn end_conditions(f: &Sym, trigonometric: bool) -> Vec<Poly> {
    let fz = in_z(f, trigonometric);
    let m = strip_ends(fz.numerator());
    let d = fz.denominator_poly();
    [Poly::zero(), Poly::one()]
        .iter()
        .filter_map(|e| {
            let sign = d.subs("z", e).as_constant()?;
            if sign == 0 {
                return None;
            }
            let g = m.subs("z", e);
            Some(if sign < 0 { -g } else { g })
        })
        .collect()
}

/// `N` with the factors `z` and `1 − z` that divide it identically removed.
fn strip_ends(n: &Poly) -> Poly {
    let z = Poly::var("z");
    let one_minus = Poly::one() - &z;
    let mut m = n.clone();
    while !m.is_zero() && m.degree_in("z") > 0 && m.subs("z", &Poly::zero()).is_zero() {
        m = m.exact_div(&z).unwrap_or(m);
    }
    while !m.is_zero() && m.degree_in("z") > 0 && m.subs("z", &Poly::one()).is_zero() {
        match m.exact_div(&one_minus) {
            Some(q) => m = q,
            None => break,
        }
    }
    m
}

/// The end values and the discriminant condition of one polynomial.
fn conditions(n: &Poly, name: &str) -> Result<Vec<(Poly, String)>, String> {
    if n.degree_in("z") == 0 {
        return Ok(vec![(n.clone(), format!("{name} (free of the variable)"))]);
    }
    let m = strip_ends(n);
    let mut out = vec![
        (m.subs("z", &Poly::zero()), format!("{name} at the start")),
        (m.subs("z", &Poly::one()), format!("{name} at the end")),
    ];
    if m.degree_in("z") >= 2 {
        // the leading coefficient in z: a root can escape to z = ∞ there
        let cs = m.coefficients_in("z");
        let lead = cs.last().cloned().unwrap_or_default();
        let disc = resultant(&m, &from_coefficients(&derivative(&cs), "z"), "z");
        if disc.is_zero() {
            return squarefree_conditions(&m, name);
        }
        out.push((disc, format!("discriminant of {name}")));
        out.push((lead, format!("leading coefficient of {name}")));
    }
    Ok(out)
}

/// The conditions of a polynomial with a repeated factor (its discriminant
/// vanishes identically): exact factorisation first. A factor of even
/// multiplicity is a square and never changes the sign; each factor of odd
/// multiplicity gives its own end values, discriminant and leading
/// coefficient, and two of them their resultant (where their zeros meet,
/// the product's sign pattern can change). A parameter where the product's
/// minimum touches 0 is a root of one of these.
fn squarefree_conditions(m: &Poly, name: &str) -> Result<Vec<(Poly, String)>, String> {
    let odd: Vec<Poly> = m
        .factor()
        .factors
        .into_iter()
        .filter(|(_, e)| e % 2 == 1)
        .map(|(g, _)| g)
        .collect();
    let mut out = Vec::new();
    for (k, g) in odd.iter().enumerate() {
        let part = format!("factor {} of {name}", k + 1);
        if g.degree_in("z") == 0 {
            out.push((g.clone(), format!("{part} (free of the variable)")));
            continue;
        }
        out.extend(conditions(g, &part)?);
        for (j, h) in odd.iter().enumerate().skip(k + 1) {
            if h.degree_in("z") > 0 {
                out.push((
                    resultant(g, h, "z"),
                    format!("resultant of factors {} and {} of {name}", k + 1, j + 1),
                ));
            }
        }
    }
    Ok(out)
}

fn derivative(cs: &[Poly]) -> Vec<Poly> {
    cs.iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c.scale(&rug::Rational::from(i as u64)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thesis_b0_has_boundary_roots_at_plus_and_minus_one() {
        // b0 = (1 − s)²(1 − m s): in z, (1 − z)⁴(1 + z² − 2mz)/(1 + z²)³
        let (s, m) = (Sym::var("s"), Sym::var("m"));
        let u = Sym::one() - &s;
        let b0 = u.clone() * &u * &(Sym::one() - &(m * &s));
        let c = candidates(&[b0], &["b0"], true).unwrap();
        let disc = c
            .iter()
            .find(|c| c.origin.starts_with("discriminant"))
            .unwrap();
        // 4m² − 4 up to a constant
        let mm = Poly::var("m") * &Poly::var("m") - &Poly::one();
        assert!(
            disc.poly
                .exact_div(&mm)
                .is_some_and(|q| q.as_constant().is_some()),
            "{}",
            disc.poly
        );
    }
}
