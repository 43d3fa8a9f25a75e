//! How the judges name a basis's domain: its ends as printed (`0`, `π/2`,
//! `α`), the functions' exact values there, and the derivative
//! conventions stated for its variable.

use trig_core::{Affine, Basis};
use trig_deriv::{End, Wrt};
use trig_symbolic::Sym;

/// The parameters of `basis` as symbols of the exact ring.
pub fn param_symbols(basis: &impl Basis) -> Vec<Sym> {
    basis.param_names().iter().map(|p| Sym::var(p)).collect()
}

/// An exact end or map value as printed in reports (`π/2`, `α`).
pub fn pretty(a: &Affine, basis: &impl Basis) -> String {
    let symbols: Vec<String> = basis.parameters().into_iter().map(|p| p.symbol).collect();
    a.text(&symbols)
        .replace("pi", "π")
        .replace(" - ", " − ")
        .replace('-', "−")
}

/// The end of the domain as printed (`0`, `π/2`, `1`, `α`).
pub fn end_text(basis: &impl Basis, end: End) -> String {
    pretty(&end_point(basis, end), basis)
}

fn end_point(basis: &impl Basis, end: End) -> Affine {
    let domain = basis.domain();
    match end {
        End::Start => domain.start,
        End::End => domain.end,
    }
}

/// `f` at an end of the domain: the atoms there substituted exactly.
///
/// # Panics
/// If the atoms are not exact at the ends, which every basis checks when
/// it is made (the catalog's variables; spec files when read).
pub fn value_at(basis: &impl Basis, f: &Sym, end: End) -> Sym {
    let atoms = basis
        .domain()
        .atoms_at(&end_point(basis, end), &Sym::one(), &param_symbols(basis))
        .expect("exact atoms at the ends (checked when the basis was made)");
    f.subs("s", &atoms.s)
        .subs("c", &atoms.c)
        .subs("t", &atoms.t)
        .subs("E", &atoms.e)
}

/// The derivative convention `wrt` as stated for the basis's domain.
pub fn describe_wrt(basis: &impl Basis, wrt: Wrt) -> String {
    wrt.describe_on(&basis.domain())
}
