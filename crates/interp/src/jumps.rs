//! Exact jumps of the derivatives of orders 0–3 (in `x`) at the interior
//! knots of an assembled interpolant, and the continuity order they show.
//!
//! For the graph `y = P(x)` of a function, tangent continuity (G¹) is the
//! continuity of `P'` and curvature continuity (G²) additionally that of
//! `P''` (the curvature `P''/(1 + P'²)^{3/2}`), so the same jumps decide the
//! parametric and the geometric orders.

use rug::Rational;
use trig_core::Ring;
use trig_deriv::End;

use crate::scheme::Spline;

/// One-sided derivatives and their jumps at an interior knot.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotJump<T> {
    /// Index of the knot `x_k` (0-based; the thesis's tables count from 1).
    pub knot: usize,
    pub x: Rational,
    /// `P^{(k)}(x_k⁻)`, `k = 0…3`.
    pub left: Vec<T>,
    /// `P^{(k)}(x_k⁺)`.
    pub right: Vec<T>,
    /// `right − left`.
    pub jumps: Vec<T>,
}

impl<T: Ring> KnotJump<T> {
    /// The largest `k` with jumps of orders `0…k` all exactly zero, or `None`
    /// when the interpolant is discontinuous (exact for exact rings).
    pub fn continuity_order(&self) -> Option<usize> {
        self.jumps
            .iter()
            .take_while(|j| j.is_zero())
            .count()
            .checked_sub(1)
    }
}

/// The jumps at every interior knot.
pub fn knot_jumps<T: Ring>(spline: &Spline<T>) -> Vec<KnotJump<T>> {
    spline
        .pieces
        .windows(2)
        .enumerate()
        .map(|(i, w)| {
            let left = w[0].derivatives(End::End);
            let right = w[1].derivatives(End::Start);
            let jumps = right
                .iter()
                .zip(&left)
                .map(|(r, l)| r.clone() - l)
                .collect();
            KnotJump {
                knot: i + 1,
                x: w[1].x0.clone(),
                left,
                right,
                jumps,
            }
        })
        .collect()
}
