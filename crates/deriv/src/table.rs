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

use trig_core::{Atoms, Basis, Ring};

use crate::jet::{Jet, angle_atoms, polynomial_atoms};

/// Which end of the domain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum End {
    /// `u = 0` (`θ = 0`, `t = 0`).
    Start,
    /// `u = 1` (`θ = π/2`, `t = 1`).
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
    /// The angle `θ` (`t` for polynomial families).
    Angle,
    /// `u ∈ [0, 1]` with `θ = πu/2`.
    U,
    /// A data abscissa `x` over an interval of length `h`.
    X,
}

impl Wrt {
    /// How the convention is stated in table headers.
    pub fn describe(&self, trigonometric: bool) -> &'static str {
        match (self, trigonometric) {
            (Wrt::Angle, true) => "with respect to the angle θ",
            (Wrt::U, true) => "with respect to u, θ = πu/2 (factor (π/2)^k)",
            (Wrt::X, true) => "with respect to x, θ = π(x − x_i)/(2h) (factor (π/(2h))^k)",
            (Wrt::Angle | Wrt::U, false) => "with respect to t",
            (Wrt::X, false) => "with respect to x, t = (x − x_i)/h (factor h^(−k))",
        }
    }
}

impl fmt::Display for Wrt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Wrt::Angle => "angle",
            Wrt::U => "u",
            Wrt::X => "x",
        })
    }
}

/// `dθ/d(variable)` for the convention: 1, π/2 or π/(2h) (1, 1, 1/h for
/// polynomial bases). `h` is the interval length for [`Wrt::X`] and supplies
/// the ring context.
pub fn rate<T: Ring>(basis: impl Basis, wrt: Wrt, h: &T) -> T {
    let trig = basis.variable().is_trigonometric();
    let half_pi = h.pi() * &h.ratio(1, 2);
    match (wrt, trig) {
        (Wrt::Angle, _) | (Wrt::U, false) => h.int(1),
        (Wrt::U, true) => half_pi,
        (Wrt::X, true) => half_pi / h,
        (Wrt::X, false) => h.int(1) / h,
    }
}

/// Jet atoms at one end of the basis's domain, built from exact values.
pub fn end_atoms<T: Ring, const K: usize>(
    basis: impl Basis,
    end: End,
    like: &T,
) -> Atoms<Jet<T, K>> {
    let (zero, one) = (like.int(0), like.int(1));
    if basis.variable().is_trigonometric() {
        match end {
            End::Start => angle_atoms(&zero, &one, zero.clone()),
            End::End => angle_atoms(&one, &zero, like.pi() * &like.ratio(1, 2)),
        }
    } else {
        polynomial_atoms(match end {
            End::Start => zero,
            End::End => one,
        })
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
    let atoms = end_atoms::<T, K>(&basis, end, h);
    let params: Vec<Jet<T, K>> = params.iter().cloned().map(Jet::constant).collect();
    scale(basis.eval(&atoms, &params), &rate(&basis, wrt, h))
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
    let atoms = end_atoms::<T, K>(&basis, end, h);
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
    scale(vec![curve], &rate(&basis, wrt, h)).remove(0)
}

fn sum<T: Ring>(mut terms: impl Iterator<Item = T>) -> T {
    let first = terms.next().expect("at least one term");
    terms.fold(first, |acc, x| acc + &x)
}

/// One-sided derivatives at one knot of a uniform piecewise basis function.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotDerivatives<T> {
    /// Knot index `0…4` (knots at `n = 0, 1, 2, 3, 4`).
    pub knot: usize,
    /// Limits from the left (`None` at the first knot), orders `0..K`.
    pub left: Option<Vec<T>>,
    /// Limits from the right (`None` at the last knot), orders `0..K`.
    pub right: Option<Vec<T>>,
}

/// One-sided derivatives at the five knots of the uniform B-spline basis
/// function assembled from `basis`'s segment functions (piece `k` is
/// function `3 − k`, see `trig_core::piecewise`). With [`Wrt::U`] they are
/// derivatives in the global knot parameter `n` (unit spacing).
///
/// # Panics
/// If the basis has fewer than four functions.
pub fn knot_derivatives<T: Ring, const K: usize>(
    basis: impl Basis,
    params: &[T],
    wrt: Wrt,
    h: &T,
) -> Vec<KnotDerivatives<T>> {
    use trig_core::piecewise::{PIECES, segment_function};
    let start = endpoint_derivatives::<T, K>(&basis, params, End::Start, wrt, h);
    let end = endpoint_derivatives::<T, K>(&basis, params, End::End, wrt, h);
    (0..=PIECES)
        .map(|knot| KnotDerivatives {
            knot,
            left: (knot > 0).then(|| end[segment_function(knot - 1)].clone()),
            right: (knot < PIECES).then(|| start[segment_function(knot)].clone()),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

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
