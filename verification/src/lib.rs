//! # trig-verification
//!
//! The audit crate: it will hold every published claim as data (id, source,
//! statement as printed) and the checkers that decide them exactly (see
//! `shared/claims.md`). In this first stage it provides the catalog-wide
//! exact checks that later claims build on.

use trig_core::{Family, Ring};

/// The families of the catalog that have formulas.
pub fn audited_families() -> impl Iterator<Item = Family> {
    Family::ALL.into_iter().filter(Family::has_formulas)
}

/// The value of every function of `family` at the left end of its domain
/// (`θ = 0` or `t = 0`), in any ring: atoms `s = 0`, `c = 1`, `t = 0`.
pub fn left_end_values<T: Ring>(family: Family, like: &T, params: &[T]) -> Vec<T> {
    let atoms = trig_core::Atoms {
        s: like.int(0),
        c: like.int(1),
        t: like.int(0),
    };
    family.eval(&atoms, params)
}
