//! The cost model of the commands: every request is bounded before its
//! work starts, in every input dimension, and a request beyond a bound is a
//! one-line error naming the limit ([`trig_core::CoreError::Limit`]). The
//! bounds, and the time each allows on the reference machine of
//! BENCHMARKS.md, are listed in the README ("Limits").
//!
//! Certified arithmetic is counted in [`trig_core::work`] units (never
//! timed): one evaluation climbs within
//! [`trig_core::certified::WORK_BUDGET`], a whole command within
//! [`COMMAND_WORK`].

use std::collections::BTreeSet;

use trig_core::Basis;
use trig_core::CoreError;
use trig_deriv::JoinKind;
use trig_symbolic::{Poly, Sym, symbolic_atoms, var};

/// Work units of certified arithmetic one command may spend in all
/// (`eval --at-file`: every point; about a minute on the reference
/// machine).
pub const COMMAND_WORK: u64 = 4_000_000_000;

/// Most points of `eval --at-file`.
pub const MAX_POINTS: u64 = 1_000_000;

/// Most values `eval --at-file --format json` holds until the end (the
/// JSON is one array per column; the text format streams instead).
pub const MAX_JSON_VALUES: u64 = 200_000;

/// Most bytes of value text `eval --at-file --format json` holds.
pub const MAX_JSON_BYTES: u64 = 64 << 20;

/// `what` beyond `limit`.
pub fn limit(what: impl Into<String>, limit: impl Into<String>) -> CoreError {
    CoreError::Limit {
        what: what.into(),
        limit: limit.into(),
    }
}

/// The work of `points` points predicted from the first point's `units`,
/// checked against [`COMMAND_WORK`].
pub fn check_points_work(points: u64, units: u64) -> Result<(), CoreError> {
    let total = points.saturating_mul(units);
    if total > COMMAND_WORK {
        return Err(limit(
            format!("--at-file with {points} points at {units} work units each ({total} in all)"),
            format!("{COMMAND_WORK} work units of certified arithmetic per command"),
        ));
    }
    Ok(())
}

/// Most terms the entries of an exact table may be predicted to hold
/// ([`table_terms`]); about 10 s on the reference machine at the bound.
pub const MAX_TABLE_TERMS: u64 = 30_000;

/// The symbols of `x` that stay symbols in a table's entries: every
/// variable but the atoms of the variable (`s`, `c`, `t`, `E`) and `π`.
fn symbols(x: &Sym) -> BTreeSet<String> {
    let atoms = [var::SIN, var::COS, var::T, var::EXP, var::PI];
    let mut names = x.variables();
    names.retain(|n| !atoms.contains(&n.as_str()));
    names
}

/// The total degree of `p` in the symbols `names`.
fn degree_in(p: &Poly, names: &BTreeSet<String>) -> u64 {
    p.terms()
        .map(|(m, _)| m.partition(|v| names.contains(v.name())).0.degree())
        .max()
        .unwrap_or(0)
}

/// `C(n + k, k)`: the number of monomials of degree at most `k` in `n`
/// symbols (saturating).
fn monomials(n: u64, k: u64) -> u64 {
    let (n, k) = (u128::from(n), u128::from(k));
    let mut c: u128 = 1;
    for i in 1..=n.min(k) {
        c = c * (n + k - i + 1) / i;
        if c > u128::from(u64::MAX) {
            return u64::MAX;
        }
    }
    c as u64
}

/// The predicted size, in terms, of the exact table of `functions` (the
/// basis with its parameters as symbols) up to derivative order `order`;
/// with `weights`, of the rational curve `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`.
///
/// The `k`-th Taylor coefficient of a quotient `N/D` at an end is a
/// polynomial of degree `dN + k·δ` over `D(end)^{k+1}` in the `v` symbols
/// of `N` and `D` (`δ` the degree of `D` in them): at most
/// `C(v + k·δ, v)` terms. For the rational curve the quotient is
/// `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`, one combination per control point (`n` of them),
/// counted as `C(n + p + k, k)` in the `n` weights and the `p` symbols of
/// the functions (the degree in the weights grows by one per order). The
/// time a table takes grows like this count (BENCHMARKS.md: 0.2–0.4 ms per
/// predicted term, measured from 4 to 64 functions, orders 1 to 8).
pub fn table_terms(functions: &[Sym], order: usize, weights: bool) -> u64 {
    let k = order as u64;
    if weights {
        let n = functions.len() as u64;
        let params: BTreeSet<String> = functions.iter().flat_map(symbols).collect();
        return n.saturating_mul(monomials(n + params.len() as u64, k));
    }
    functions
        .iter()
        .map(|f| {
            let names = symbols(f);
            let delta = degree_in(&f.denominator_poly(), &names);
            monomials(names.len() as u64, k.saturating_mul(delta))
        })
        .fold(0u64, u64::saturating_add)
}

/// Refuses an exact table predicted beyond [`MAX_TABLE_TERMS`].
pub fn check_table(
    what: &str,
    functions: &[Sym],
    order: usize,
    weights: bool,
) -> Result<(), CoreError> {
    let terms = table_terms(functions, order, weights);
    if terms > MAX_TABLE_TERMS {
        return Err(limit(
            format!(
                "{what} (its {} functions and their parameters predict {terms} terms at order {order})",
                functions.len()
            ),
            format!(
                "{MAX_TABLE_TERMS} predicted terms per exact table (lower --order, or use --numeric)"
            ),
        ));
    }
    Ok(())
}

/// Refuses a join predicted beyond [`MAX_TABLE_TERMS`]: solving the
/// conditions of order `K` substitutes each forced point into the next
/// (dividing by the pivots), so the degree of the solved points grows like
/// `K²` in the `v` symbols of both segments: `C(v + K², v)` terms per
/// function.
pub fn check_join(
    basis: &impl Basis,
    kind: JoinKind,
    first: &[Sym],
    second: &[Sym],
) -> Result<(), CoreError> {
    let atoms = symbolic_atoms();
    let order = (kind.order() * kind.order()) as u64;
    let terms = basis
        .eval(&atoms, first)
        .iter()
        .zip(basis.eval(&atoms, second))
        .map(|(a, b)| {
            let v = symbols(a).union(&symbols(&b)).count() as u64;
            monomials(v, order)
        })
        .fold(0u64, u64::saturating_add);
    if terms > MAX_TABLE_TERMS {
        return Err(limit(
            format!(
                "join --kind {kind} (the functions and their parameters predict {terms} terms)"
            ),
            format!(
                "{MAX_TABLE_TERMS} predicted terms per exact computation (a lower --kind, or --params same)"
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::{Described, Family, SEED000_NONUNIFORM};

    fn functions(basis: &impl Basis) -> Vec<Sym> {
        let params: Vec<Sym> = basis.param_names().iter().map(|p| Sym::var(p)).collect();
        basis.eval(&symbolic_atoms(), &params)
    }

    /// `gen(n)`: `n` polynomial functions without parameters, a weighted
    /// sum that vanishes nowhere (the cases of issue 22).
    fn generic(n: usize) -> Vec<Sym> {
        let t = Sym::var(var::T);
        (0..n)
            .map(|i| Sym::one() + &(Sym::int(i as i64 + 1) * &t) + &(t.clone() * &t))
            .collect()
    }

    #[test]
    fn monomials_count_binomially_and_saturate() {
        assert_eq!(monomials(0, 7), 1);
        assert_eq!(monomials(8, 6), 3003);
        assert_eq!(monomials(64, 1), 65);
        assert_eq!(monomials(200, 200), u64::MAX);
    }

    /// Every catalog family is within the bounds at the highest orders the
    /// commands accept, and in every join.
    #[test]
    fn the_catalog_is_within_every_bound() {
        for family in Family::ALL
            .into_iter()
            .filter(|f| f.has_formulas() && Described::id(f) != SEED000_NONUNIFORM.id)
        {
            let f = functions(&family);
            assert!(table_terms(&f, 12, false) <= MAX_TABLE_TERMS, "{family:?}");
            assert!(table_terms(&f, 6, true) <= MAX_TABLE_TERMS, "{family:?}");
            let names = family.param_names();
            let copy = |k: &str| -> Vec<Sym> {
                names
                    .iter()
                    .map(|p| Sym::var(&format!("{p}_{k}")))
                    .collect()
            };
            for kind in ["c3", "g2"] {
                let kind: JoinKind = kind.parse().expect("kind");
                check_join(&family, kind, &copy("1"), &copy("2")).expect("within");
            }
        }
    }

    /// The sizes issue 22 found past 40–60 s are refused; the measured
    /// tables of a few seconds are not (BENCHMARKS.md).
    #[test]
    fn the_blow_ups_of_issue_22_are_predicted_beyond_the_bound() {
        assert!(table_terms(&generic(64), 6, true) > MAX_TABLE_TERMS);
        assert!(table_terms(&generic(16), 6, true) > MAX_TABLE_TERMS);
        assert!(table_terms(&generic(16), 4, true) > MAX_TABLE_TERMS);
        assert!(table_terms(&generic(16), 3, true) <= MAX_TABLE_TERMS);
        assert!(table_terms(&generic(8), 6, true) <= MAX_TABLE_TERMS);
        assert!(table_terms(&generic(64), 12, false) <= MAX_TABLE_TERMS);
        // an 8-parameter quotient: the degree grows by one per order
        let t = Sym::var(var::T);
        let a: Vec<Sym> = (1..=8).map(|k| Sym::var(&format!("a{k}"))).collect();
        let d = a
            .iter()
            .fold((Sym::one(), Sym::one()), |(sum, power), ak| {
                let power = power * &t;
                (sum + &(ak.clone() * &power), power)
            })
            .0;
        let quotient: Vec<Sym> = a.iter().take(4).map(|ak| ak.clone() / &d).collect();
        assert!(table_terms(&quotient, 12, false) > MAX_TABLE_TERMS);
        assert!(table_terms(&quotient, 7, false) <= MAX_TABLE_TERMS);
    }
}
