//! One piece of an interpolant: `P_i(x) = Σ_j b_j(u; m_i) V_j` on
//! `[x_i, x_i + h_i]`, `u = (x − x_i)/h_i`, with the catalog's thesis cubic
//! basis (3.7) `trig_core::Family::ThesisCubic` (never re-typed), and its
//! derivatives at the ends from `trig_deriv` (jets seeded with the exact end
//! atoms), in any convention [`Wrt`] — `x` for the schemes of 4.3.

use rug::Rational;
use trig_core::{Atoms, Family, Real, Ring};
use trig_deriv::{End, Wrt, curve_endpoint_derivatives, endpoint_derivatives};

use crate::InterpError;

/// Highest derivative order the schemes and knot jumps use, plus one.
pub const ORDERS: usize = 4;

/// One piece: interval, shape parameter and control points `V_0 … V_3`
/// (the thesis's `V_i, W_i, X_i, Y_i`).
#[derive(Debug, Clone, PartialEq)]
pub struct Piece<T> {
    /// `x_i`.
    pub x0: Rational,
    /// `h_i = x_{i+1} − x_i`.
    pub h: Rational,
    /// `m_i`.
    pub m: Rational,
    /// `[V_i, W_i, X_i, Y_i]`.
    pub points: [T; 4],
}

impl<T: Ring> Piece<T> {
    /// Derivatives of orders `0…3` of the piece at one end, with respect to
    /// `x` (`d/dx = (π/(2h)) d/dθ`).
    pub fn derivatives(&self, end: End) -> Vec<T> {
        derivatives_of(&self.points, &self.m, &self.h, end, Wrt::X)
    }
}

impl<T: Real> Piece<T> {
    /// The value at `x` (any `x`; the piece is meant for `[x_i, x_i + h_i]`):
    /// `θ = π(x − x_i)/(2h_i)`, `s = sin θ`, `c = cos θ`.
    pub fn eval(&self, x: &T) -> T {
        let like = &self.points[0];
        let u = (x.clone() - &like.rational(&self.x0)) / &like.rational(&self.h);
        let theta = u * &(like.pi() * &like.ratio(1, 2));
        let (s, c) = theta.sin_cos();
        let atoms = Atoms {
            s,
            c,
            e: like.int(1),
            t: theta,
        };
        let b = Family::ThesisCubic.eval(&atoms, &[like.rational(&self.m)]);
        b.iter()
            .zip(&self.points)
            .fold(like.int(0), |acc, (bj, vj)| acc + &(bj.clone() * vj))
    }
}

/// Derivatives of orders `0…3` of `Σ b_j(·; m) V_j` at `end` in `wrt`.
pub fn derivatives_of<T: Ring>(
    points: &[T; 4],
    m: &Rational,
    h: &Rational,
    end: End,
    wrt: Wrt,
) -> Vec<T> {
    let like = &points[0];
    curve_endpoint_derivatives::<T, ORDERS>(
        Family::ThesisCubic,
        &[like.rational(m)],
        points,
        None,
        end,
        wrt,
        &like.rational(h),
    )
}

/// A linear condition on a piece: its derivative of `order` at `end` equals `target`.
#[derive(Debug, Clone)]
pub struct Condition<T> {
    pub end: End,
    pub order: usize,
    pub target: T,
}

/// The inner control points `V_1, V_2` forced by two linear conditions when
/// `V_0`, `V_3` are known: `Σ_j b_j^{(k)}(end) V_j = target` for each
/// condition, the basis derivatives `b_j^{(k)}` from
/// [`trig_deriv::endpoint_derivatives`] in `wrt`, solved by Cramer's rule.
/// A vanishing determinant (e.g. `m = −2`) is an error.
pub fn inner_points<T: Ring>(
    m: &Rational,
    h: &Rational,
    wrt: Wrt,
    v0: &T,
    v3: &T,
    conditions: [Condition<T>; 2],
) -> Result<(T, T), InterpError> {
    let like = v0;
    let table = |end| {
        endpoint_derivatives::<T, ORDERS>(
            Family::ThesisCubic,
            &[like.rational(m)],
            end,
            wrt,
            &like.rational(h),
        )
    };
    let (start, finish) = (table(End::Start), table(End::End));
    let row = |c: &Condition<T>| {
        let b = match c.end {
            End::Start => &start,
            End::End => &finish,
        };
        let k = c.order;
        let rhs = c.target.clone() - &(b[0][k].clone() * v0) - &(b[3][k].clone() * v3);
        (b[1][k].clone(), b[2][k].clone(), rhs)
    };
    let (a11, a12, r1) = row(&conditions[0]);
    let (a21, a22, r2) = row(&conditions[1]);
    let det = a11.clone() * &a22 - &(a12.clone() * &a21);
    if det.is_zero() {
        return Err(InterpError::Singular(format!(
            "the conditions on the inner control points are singular for m = {m} (determinant {det:?})"
        )));
    }
    let v1 = (r1.clone() * &a22 - &(a12 * &r2)) / &det;
    let v2 = (a11 * &r2 - &(a21 * &r1)) / &det;
    Ok((v1, v2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inner_points_meet_their_conditions_in_f64() {
        let (m, h) = (Rational::from((1, 2)), Rational::from(2));
        let conditions = [
            Condition {
                end: End::Start,
                order: 1,
                target: 0.7,
            },
            Condition {
                end: End::End,
                order: 1,
                target: -1.3,
            },
        ];
        let (v1, v2) = inner_points(&m, &h, Wrt::X, &3.0, &5.0, conditions).unwrap();
        let p = [3.0, v1, v2, 5.0];
        let s = derivatives_of(&p, &m, &h, End::Start, Wrt::X);
        let e = derivatives_of(&p, &m, &h, End::End, Wrt::X);
        assert!((s[0] - 3.0).abs() < 1e-12 && (e[0] - 5.0).abs() < 1e-12);
        assert!((s[1] - 0.7).abs() < 1e-12 && (e[1] + 1.3).abs() < 1e-12);
        // m = −2 kills the first derivatives: singular
        let bad = [
            Condition {
                end: End::Start,
                order: 1,
                target: 0.0,
            },
            Condition {
                end: End::End,
                order: 1,
                target: 0.0,
            },
        ];
        assert!(inner_points(&Rational::from(-2), &h, Wrt::X, &0.0, &1.0, bad).is_err());
    }

    #[test]
    fn a_piece_evaluates_to_its_end_points() {
        let piece = Piece {
            x0: Rational::from(1),
            h: Rational::from(2),
            m: Rational::from((1, 2)),
            points: [3.0, 4.0, 7.0, 5.0],
        };
        assert!((piece.eval(&1.0) - 3.0).abs() < 1e-12);
        assert!((piece.eval(&3.0) - 5.0).abs() < 1e-12);
    }
}
