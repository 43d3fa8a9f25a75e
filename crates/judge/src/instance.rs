//! An instance of identities that hold: both sides of each at one real
//! point. A proof that `lhs = rhs` identically refutes its negation ("the
//! functions are not normalised", "no such curve lies on this conic") for
//! every value at once; the instance shows the refutation at a point a
//! reader checks by hand — the simplest real point of the domain and of
//! the claim's parameter sets ([`trig_verdict::real_witness::instance`]),
//! where the sides, paired, agree although the negation says they differ.

use trig_symbolic::Sym;
use trig_verdict::evidence::{Evidence, Kind};

/// What the instance shows, as the report states it.
pub const TEXT: &str = "an instance at the simplest real point of the claim's set: each pair of values is equal there, where the negation says some pair differs";

/// A labelled expression: one side of an identity, or a value shown.
pub type Side = (String, Sym);

/// The evidence item of the instance of `sides` (each identity as its
/// two labelled sides), with its witness; `shown` (labelled: the
/// functions, the curve) are given at the same point beside it, for the
/// reader. `None` when no real point is known (outside a spec decision)
/// or a value is undefined there.
pub fn instance(sides: &[(Side, Side)], shown: &[Side]) -> Option<Evidence> {
    let exprs: Vec<(&str, &Sym)> = sides
        .iter()
        .flat_map(|((l, lhs), (r, rhs))| [(l.as_str(), lhs), (r.as_str(), rhs)])
        .chain(shown.iter().map(|(l, e)| (l.as_str(), e)))
        .collect();
    let mut witness = trig_verdict::real_witness::instance(&exprs)?;
    let beside = witness.values.split_off(2 * sides.len());
    let item = Evidence::new(Kind::Identity, TEXT).witnessed(Some(witness));
    Some(
        beside
            .into_iter()
            .fold(item, |item, v| item.with(v.label, v.value)),
    )
}
