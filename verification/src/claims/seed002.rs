//! Seed 002 (Dube & Mishra 2017): the rational quartic trigonometric Bézier
//! curve's ends, for the local-control claims that still need them in Rust
//! (its claims are data: documents/quartic-bezier2017/document.toml).

use trig_core::Family;
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_symbolic::Sym;

/// `R, R', R''` (in θ) of the rational curve at `θ = 0` and `θ = π/2`, with
/// control points `P0…P5` and weights `w0…w5` as symbols.
pub(super) fn rational_ends(p: &[Sym], w: &[Sym]) -> (Vec<Sym>, Vec<Sym>) {
    let at = |end| {
        curve_endpoint_derivatives::<Sym, 3>(
            Family::Seed002Quartic,
            &[],
            p,
            Some(w),
            end,
            Wrt::Angle,
            &Sym::one(),
        )
    };
    (at(End::Start), at(End::End))
}
