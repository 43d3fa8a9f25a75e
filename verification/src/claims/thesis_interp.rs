//! Seed 001, the thesis: helpers the remaining Rust claims of other files
//! use (the claims of section 4.3 are data: `identity`,
//! `interpolant-continuity`, `interpolant-nonnegative`).

use trig_core::Family;
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_interp::{DataSet, Scheme, Spline, Variant};
use trig_symbolic::Sym;
use trig_verdict::verdict::Verdict;

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

pub(super) fn sym_spline(
    name: &str,
    scheme: Scheme,
    variant: Variant,
) -> Result<Spline<Sym>, String> {
    let data = DataSet::named(name).map_err(|e| e.to_string())?;
    trig_judge::interpolant::exact_spline(&data, scheme, variant)
}

/// The certified minima of the built-in table `name` with
/// `scheme`/`variant`, as a verdict (`trig_judge::interpolant::positivity`).
pub(super) fn positivity(name: &str, scheme: Scheme, variant: Variant) -> Verdict {
    match DataSet::named(name) {
        Ok(data) => trig_judge::interpolant::positivity(&data, scheme, variant),
        Err(e) => Verdict::not_checkable(e.to_string()),
    }
}
