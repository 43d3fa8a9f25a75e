//! Seed 001, the thesis: helpers the remaining Rust claims of other files
//! use (the claims of section 4.3 are data: `identity`,
//! `interpolant-continuity`, `interpolant-nonnegative`).

use trig_interp::{DataSet, Scheme, Spline, Variant};
use trig_symbolic::Sym;

pub(super) fn sym_spline(
    name: &str,
    scheme: Scheme,
    variant: Variant,
) -> Result<Spline<Sym>, String> {
    let data = DataSet::named(name).map_err(|e| e.to_string())?;
    trig_judge::interpolant::exact_spline(&data, scheme, variant)
}
