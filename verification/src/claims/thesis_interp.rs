//! Seed 001, the thesis: helpers the remaining Rust claims of other files
//! use (the claims of section 4.3 are data: `identity`,
//! `interpolant-continuity`, `interpolant-nonnegative`).

use trig_core::Family;
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_symbolic::Sym;

/// Derivatives of orders 0…2 of `Σ b_j(·; m) P_j` at `end` in `wrt`.
pub(super) fn derivs(points: &[Sym], m: &Sym, end: End, wrt: Wrt, h: &Sym) -> Vec<Sym> {
    curve_endpoint_derivatives::<Sym, 3>(
        Family::ThesisCubic,
        std::slice::from_ref(m),
        points,
        None,
        end,
        wrt,
        h,
    )
}
