//! Endpoint-derivative tables, written once over any [`Ring`]: exact (the
//! symbolic ring, parameters as symbols) or numeric (f64, MPFR).
//!
//! The jets are seeded with the *exact* atoms of each end — `s = 0, c = 1,
//! θ = 0` at the start and `s = 1, c = 0, θ = π/2` at the end (`t = 0`, `t = 1`
//! for polynomial families) — so no `sin` is ever evaluated and exact rings
//! work unchanged.
//!
//! Conventions ([`Wrt`]): derivatives with respect to the angle `θ`
//! (thesis Chapter 4 endpoint list, seed 000 appendices), with respect to
//! `u ∈ [0, 1]`, `θ = πu/2` (factor `(π/2)^k`; thesis (4.30)), or with respect
//! to a data abscissa `x` over an interval of length `h`, `θ = π(x − xᵢ)/(2h)`
//! (factor `(π/(2h))^k`; thesis 4.3). Polynomial families have no angle: for
//! them `θ` and `u` both mean their variable `t`, and `x` gives `h^{−k}`.

use std::fmt;

use trig_core::{Atoms, Basis, Domain, Ring, Variable};

use crate::jet::{Jet, angle_atoms, factorial};

/// Which end of the domain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum End {
    /// `x = a` (`u = 0`, `θ = 0`, `t = 0` for the catalog).
    Start,
    /// `x = b` (`u = 1`, `θ = π/2`, `t = 1` for the catalog).
    End,
}

impl fmt::Display for End {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            End::Start => "start",
            End::End => "end",
        })
    }
}

/// The variable derivatives are taken with respect to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Wrt {
    /// The angle `θ = ωx` of the atoms `s`, `c` (the variable itself for
    /// bases without an angle).
    Angle,
    /// The unit parameter `u ∈ [0, 1]`, `x = a + (b − a)u` (for the thesis
    /// `θ = πu/2`).
    U,
    /// A data abscissa over an interval of length `h`: `u = (x − xᵢ)/h`.
    X,
    /// The basis's own variable `x ∈ [a, b]`.
    Variable,
}

impl Wrt {
    /// How the convention is stated for a basis on `domain`: the catalog's
    /// conventions as [`Wrt::describe`] states them; for any other domain
    /// `x ∈ [a, b]` the unit parameter is `x = a + (b − a)u` with its factor
    /// `(b − a)^k`, and the angle is named only when it is not the variable.
    pub fn describe_on(&self, domain: &Domain) -> String {
        let names: Vec<&str> = domain.param_names.iter().map(String::as_str).collect();
        let legacy = [Variable::UnitAngle, Variable::Angle, Variable::Polynomial]
            .into_iter()
            .find(|v| Domain::from_variable(*v, &names) == *domain);
        if let Some(v) = legacy {
            return self.describe(v.is_trigonometric()).to_string();
        }
        let x = &domain.name;
        let (a, b) = (
            domain.start.text(&domain.param_names),
            domain.end.text(&domain.param_names),
        );
        let length = if domain.start.as_rational().is_some_and(|q| *q == 0) {
            b.clone()
        } else {
            format!("({b}) − ({a})")
        };
        let unit_angle = domain
            .angle
            .as_ref()
            .and_then(|w| w.as_rational())
            .is_some_and(|w| *w == 1);
        match self {
            Wrt::Variable => format!("with respect to {x}"),
            Wrt::Angle if domain.angle.is_none() || unit_angle => format!("with respect to {x}"),
            Wrt::Angle => format!(
                "with respect to the angle θ = ({}){x}",
                domain.angle.as_ref().map_or(String::new(), |w| w.text(&[]))
            ),
            Wrt::U => format!(
                "with respect to u, {x} = {} (factor ({length})^k)",
                if length == b {
                    format!("({b})·u")
                } else {
                    format!("{a} + ({length})·u")
                }
            ),
            Wrt::X => format!(
                "with respect to a data abscissa over an interval of length h, {x} = {a} + ({length})(x − x_i)/h"
            ),
        }
    }

    /// How the convention is stated in table headers.
    pub fn describe(&self, trigonometric: bool) -> &'static str {
        match (self, trigonometric) {
            (Wrt::Angle, true) => "with respect to the angle θ",
            (Wrt::U, true) => "with respect to u, θ = πu/2 (factor (π/2)^k)",
            (Wrt::X, true) => "with respect to x, θ = π(x − x_i)/(2h) (factor (π/(2h))^k)",
            (Wrt::Angle | Wrt::U, false) => "with respect to t",
            (Wrt::X, false) => "with respect to x, t = (x − x_i)/h (factor h^(−k))",
            (Wrt::Variable, _) => "with respect to the basis variable",
        }
    }
}

impl fmt::Display for Wrt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Wrt::Angle => "angle",
            Wrt::U => "u",
            Wrt::X => "x",
            Wrt::Variable => "variable",
        })
    }
}

/// True when the jets are seeded in the angle `θ` (formulas in `s`, `c`
/// alone, as the catalog's trigonometric families), otherwise in the
/// variable `x`.
fn seeded_in_angle(domain: &Domain) -> bool {
    domain.is_pure_trigonometric()
}

/// `d(seed)/d(wrt)`: the factor by which one derivative in the seed
/// variable (`θ` or `x`) exceeds one in the convention `wrt`. With
/// `ω = dθ/dx` and the domain length `L = b − a`: `1, ω, ωL, ωL/h` for
/// `θ`-seeded jets (angle, variable, u, data abscissa), `1/ω, 1, L, L/h`
/// for `x`-seeded ones. `h` is the interval length for [`Wrt::X`] and
/// supplies the ring context; `params` are the shape parameters (`L` may
/// depend on them).
pub fn rate<T: Ring>(basis: impl Basis, wrt: Wrt, h: &T, params: &[T]) -> T {
    let domain = basis.domain();
    let omega = domain.angle_rate(h);
    let length = domain.end_value(h, params) - &domain.start_value(h, params);
    let one = h.int(1);
    let in_x = match wrt {
        Wrt::Angle => one.clone() / &omega,
        Wrt::Variable => one,
        Wrt::U => length,
        Wrt::X => length / h,
    };
    if seeded_in_angle(&domain) {
        in_x * &omega
    } else {
        in_x
    }
}

/// The series of `sin(ω(x₀ + ε))`, `cos(ω(x₀ + ε))`, `exp(κ(x₀ + ε))` from
/// their exact values at `x₀`: coefficients `ωᵏ·(s₀, c₀, −s₀, −c₀, …)/k!`
/// and `κᵏe₀/k!`, built in the ring.
fn scaled_atoms<T: Ring, const K: usize>(at: &Atoms<T>, omega: &T, kappa: &T) -> Atoms<Jet<T, K>> {
    let Atoms { s, c, .. } = angle_atoms::<T, K>(&at.s, &at.c, at.t.clone());
    let powers = |r: &T| -> Vec<T> {
        let mut out = vec![r.int(1)];
        for k in 1..K {
            out.push(out[k - 1].clone() * r);
        }
        out
    };
    let (w, kk) = (powers(omega), powers(kappa));
    let scale = |jet: &Jet<T, K>, p: &[T]| {
        Jet::from_coeffs(std::array::from_fn(|k| jet.coeffs()[k].clone() * &p[k]))
    };
    let exp = Jet::from_coeffs(std::array::from_fn(|k| {
        at.e.clone() * &kk[k] / &factorial(&at.e, k)
    }));
    Atoms {
        s: scale(&s, &w),
        c: scale(&c, &w),
        t: Jet::variable(at.t.clone()),
        e: exp,
    }
}

/// Jet atoms at one end of the basis's domain, built from the exact atoms
/// there ([`Domain::atoms_at`]): seeded in `θ` for formulas in `s`, `c`
/// alone, in `x` otherwise (see [`rate`]).
///
/// # Panics
/// When the ring cannot form the atoms at the end exactly (the exact ring
/// at an angle that is not a multiple of π/12, or `exp` of a nonzero
/// constant); spec files are refused for that when read.
pub fn end_atoms<T: Ring, const K: usize>(
    basis: impl Basis,
    end: End,
    like: &T,
    params: &[T],
) -> Atoms<Jet<T, K>> {
    let domain = basis.domain();
    let x = match end {
        End::Start => &domain.start,
        End::End => &domain.end,
    };
    let at = domain
        .atoms_at(x, like, params)
        .expect("the ring forms the atoms at the ends (validated when the basis is read)");
    if seeded_in_angle(&domain) {
        let theta = x
            .times(domain.angle.as_ref().expect("an angle"))
            .map_or_else(
                || at.t.clone() * &domain.angle_rate(like),
                |a| a.eval(like, params),
            );
        angle_atoms(&at.s, &at.c, theta)
    } else {
        let omega = domain.angle_rate(like);
        let kappa = domain
            .exp
            .as_ref()
            .map_or_else(|| like.int(0), |k| like.rational(k));
        scaled_atoms(&at, &omega, &kappa)
    }
}

/// Derivatives of orders `0..K` of every function of `basis` at `end`, in
/// the convention `wrt`, as `[function][order]`. `params` are the shape
/// parameters (symbols or numbers), `h` the interval length for [`Wrt::X`]
/// (any value otherwise; it also supplies the ring context).
pub fn endpoint_derivatives<T: Ring, const K: usize>(
    basis: impl Basis,
    params: &[T],
    end: End,
    wrt: Wrt,
    h: &T,
) -> Vec<Vec<T>> {
    let atoms = end_atoms::<T, K>(&basis, end, h, params);
    let jparams: Vec<Jet<T, K>> = params.iter().cloned().map(Jet::constant).collect();
    scale(basis.eval(&atoms, &jparams), &rate(&basis, wrt, h, params))
}

/// The derivatives of orders `0..K` of each jet, the `k`-th multiplied by `rateᵏ`.
fn scale<T: Ring, const K: usize>(jets: Vec<Jet<T, K>>, rate: &T) -> Vec<Vec<T>> {
    jets.iter()
        .map(|jet| {
            let mut factor = rate.int(1);
            jet.derivatives()
                .into_iter()
                .map(|d| {
                    let v = d * &factor;
                    factor = factor.clone() * rate;
                    v
                })
                .collect()
        })
        .collect()
}

/// Derivatives of orders `0..K` of the curve `Σ bᵢ Pᵢ` — or, with weights,
/// of the rational curve `Σ wᵢ bᵢ Pᵢ / Σ wᵢ bᵢ` — at `end`. `points` are
/// scalars: one coordinate of each control point, or symbols `P0, P1, …` for
/// the exact form as a combination of control points.
///
/// # Panics
/// If `points` (or `weights`) do not have one entry per function.
pub fn curve_endpoint_derivatives<T: Ring, const K: usize>(
    basis: impl Basis,
    params: &[T],
    points: &[T],
    weights: Option<&[T]>,
    end: End,
    wrt: Wrt,
    h: &T,
) -> Vec<T> {
    let atoms = end_atoms::<T, K>(&basis, end, h, params);
    let jparams: Vec<Jet<T, K>> = params.iter().cloned().map(Jet::constant).collect();
    let functions = basis.eval(&atoms, &jparams);
    assert_eq!(
        functions.len(),
        points.len(),
        "one control point per function"
    );
    let weighted: Vec<Jet<T, K>> = match weights {
        Some(w) => {
            assert_eq!(w.len(), functions.len(), "one weight per function");
            functions
                .iter()
                .zip(w)
                .map(|(b, wi)| b.clone() * &Jet::constant(wi.clone()))
                .collect()
        }
        None => functions,
    };
    let numerator = sum(weighted
        .iter()
        .zip(points)
        .map(|(b, p)| b.clone() * &Jet::constant(p.clone())));
    let curve = match weights {
        Some(_) => numerator / &sum(weighted.into_iter()),
        None => numerator,
    };
    scale(vec![curve], &rate(&basis, wrt, h, params)).remove(0)
}

fn sum<T: Ring>(mut terms: impl Iterator<Item = T>) -> T {
    let first = terms.next().expect("at least one term");
    terms.fold(first, |acc, x| acc + &x)
}

/// One-sided derivatives at one knot of a uniform piecewise basis function.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotDerivatives<T> {
    /// Knot index `0…n` (knots at `0, 1, …, n` for `n` pieces).
    pub knot: usize,
    /// Limits from the left (`None` at the first knot), orders `0..K`.
    pub left: Option<Vec<T>>,
    /// Limits from the right (`None` at the last knot), orders `0..K`.
    pub right: Option<Vec<T>>,
}

/// One-sided derivatives at the `n + 1` knots of the uniform B-spline basis
/// function assembled from `basis`'s `n` segment functions (piece `k` is
/// function `n − 1 − k`: four pieces for the catalog's cubic families, see
/// `trig_core::piecewise`). With [`Wrt::U`] they are derivatives in the
/// global knot parameter (unit spacing).
pub fn knot_derivatives<T: Ring, const K: usize>(
    basis: impl Basis,
    params: &[T],
    wrt: Wrt,
    h: &T,
) -> Vec<KnotDerivatives<T>> {
    let start = endpoint_derivatives::<T, K>(&basis, params, End::Start, wrt, h);
    let end = endpoint_derivatives::<T, K>(&basis, params, End::End, wrt, h);
    let pieces = start.len();
    let function = |piece: usize| pieces - 1 - piece;
    (0..=pieces)
        .map(|knot| KnotDerivatives {
            knot,
            left: (knot > 0).then(|| end[function(knot - 1)].clone()),
            right: (knot < pieces).then(|| start[function(knot)].clone()),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    #[test]
    fn conventions_are_stated_for_the_domain() {
        // the catalog's: as printed in its tables
        let thesis = trig_core::Described::domain(&Family::ThesisCubic);
        assert_eq!(Wrt::U.describe_on(&thesis), Wrt::U.describe(true));
        // a C-curve on [0, α]: t = αu, factor α^k; its angle is t itself
        let mut c_curve = Domain::from_variable(Variable::Angle, &["alpha"]);
        c_curve.end = trig_core::Affine::param(0);
        assert_eq!(
            Wrt::U.describe_on(&c_curve),
            "with respect to u, t = (alpha)·u (factor (alpha)^k)"
        );
        assert_eq!(Wrt::Angle.describe_on(&c_curve), "with respect to t");
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * (1.0 + b.abs())
    }

    #[test]
    fn thesis_cubic_first_derivatives_match_the_hand_derivation() {
        // b₀ = (1−s)²(1−ms): d/dθ at θ = 0 (s' = c = 1) is −2(1−ms) − m(1−s)²·1 = −(m+2).
        // b₁ = ms(1−s)² − 2s(s−1): d/dθ at 0 is m + 2.
        let m = 0.6;
        let t =
            endpoint_derivatives::<f64, 3>(Family::ThesisCubic, &[m], End::Start, Wrt::Angle, &1.0);
        assert!(close(t[0][1], -(m + 2.0)));
        assert!(close(t[1][1], m + 2.0));
        assert!(close(t[2][1], 0.0) && close(t[3][1], 0.0));
        // in u the first derivative gains π/2
        let u = endpoint_derivatives::<f64, 3>(Family::ThesisCubic, &[m], End::Start, Wrt::U, &1.0);
        assert!(close(u[0][1], -(m + 2.0) * std::f64::consts::FRAC_PI_2));
        // in x over h = 2, π/(2h) = π/4
        let x = endpoint_derivatives::<f64, 3>(Family::ThesisCubic, &[m], End::Start, Wrt::X, &2.0);
        assert!(close(x[0][1], -(m + 2.0) * std::f64::consts::FRAC_PI_4));
    }

    #[test]
    fn cubic_bspline_knot_jumps_vanish_up_to_order_two_and_not_three() {
        let knots = knot_derivatives::<f64, 4>(Family::BSpline3, &[], Wrt::U, &1.0);
        for k in &knots[1..4] {
            let (l, r) = (k.left.as_ref().unwrap(), k.right.as_ref().unwrap());
            for order in 0..3 {
                assert!(close(l[order], r[order]), "knot {} order {order}", k.knot);
            }
            assert!(
                !close(l[3], r[3]),
                "third derivative jumps at knot {}",
                k.knot
            );
        }
        // B(1) = 1/6, B(2) = 2/3
        assert!(close(knots[1].right.as_ref().unwrap()[0], 1.0 / 6.0));
        assert!(close(knots[2].right.as_ref().unwrap()[0], 2.0 / 3.0));
    }

    #[test]
    fn bezier_curve_end_derivative_is_three_times_the_first_leg() {
        let pts = [0.0, 1.0, 3.0, 4.0];
        let d = curve_endpoint_derivatives::<f64, 2>(
            Family::Bernstein3,
            &[],
            &pts,
            None,
            End::Start,
            Wrt::U,
            &1.0,
        );
        assert!(close(d[0], 0.0) && close(d[1], 3.0));
        // equal weights leave a rational curve unchanged
        let w = [2.0; 4];
        let r = curve_endpoint_derivatives::<f64, 2>(
            Family::Bernstein3,
            &[],
            &pts,
            Some(&w),
            End::Start,
            Wrt::U,
            &1.0,
        );
        assert!(close(r[1], 3.0));
    }
}
