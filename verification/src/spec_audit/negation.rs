//! A claim stated as the negation of its check ("is not C⁴", "the
//! functions are not normalised", "cannot trace a conic"): it holds where
//! the check fails and fails where the check holds. A failing negation of
//! an identity carries a witness: the identity's sides at the simplest
//! real point of the claim's set ([`trig_judge::instance`]), equal where
//! the claim says they differ.

use trig_judge::instance::Side;
use trig_specfile::{Check, Spec, SpecClaim};
use trig_symbolic::Sym;
use trig_verdict::evidence::Evidence;
use trig_verdict::real_witness::with_real_points;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The negation of a check's verdict: holds where the check fails (its
/// counterexample proves the negation) and fails where it holds (its proof
/// refutes it, with `instance` — computed only then, and only when the
/// proof shows no witness of its own); a check that holds only after a
/// correction of its print leaves the negation undecided, and an
/// undecided check stays undecided.
pub(super) fn negation(v: Verdict, instance: impl FnOnce() -> Option<Evidence>) -> Verdict {
    let (status, line) = match v.status {
        Status::Fails => (
            Status::Holds,
            "the claim is the negation of the check, which fails: the counterexample below proves the claim",
        ),
        Status::Holds => (
            Status::Fails,
            "the claim is the negation of the check, which holds: the proof below refutes the claim",
        ),
        Status::HoldsAfterCorrection => (
            Status::NotCheckable,
            "the claim is the negation of the check, whose print fails but holds after the correction below: which of the two the negation is about is not decided",
        ),
        Status::NotCheckable => (
            Status::NotCheckable,
            "the claim is the negation of the check, which is not decided",
        ),
    };
    let shown = v.evidence.iter().any(|e| e.witness.is_some());
    let mut out = Verdict::new(status, v.method.clone(), vec![line.to_string()]);
    out.evidence.extend(v.evidence);
    if status == Status::Fails && !shown {
        out.evidence.extend(instance());
    }
    out
}

/// The instance of the claim's check at the simplest real point of its
/// set (its values substituted, its ranges in place of the declared
/// ones): for the identity checks (`unity`, `conic`, `identity`), each
/// identity's two sides; `None` for the others (their proof is over a
/// set: no point refutes the negation) and where no point is found.
pub(super) fn instance(spec: &Spec, claim: &SpecClaim) -> Option<Evidence> {
    if !claim.given.exact.is_empty() {
        return None;
    }
    let at = |fixed: &Spec, check: &Check| {
        with_real_points(super::real_points(fixed), || {
            let (sides, shown) = sides(fixed, check)?;
            trig_judge::instance::instance(&sides, &shown)
        })
    };
    if claim.given.is_empty() {
        return at(spec, &claim.check);
    }
    let (fixed, check) = claim.given.apply(spec, &claim.check).ok()?;
    at(&fixed, &check)
}

/// Identities as their two sides, and the values shown beside them.
type Identities = (Vec<(Side, Side)>, Vec<Side>);

/// The identities a check proves, each as its two labelled sides, and
/// what the reader is shown beside them at the same point (the functions
/// whose sum is 1, the curve on the conic).
fn sides(spec: &Spec, check: &Check) -> Option<Identities> {
    let functions = trig_judge::exact::basis_of(spec);
    let names = spec.functions.iter().map(|f| f.name.clone());
    match check {
        Check::Unity => {
            let label = trig_judge::unity::sum_label(&names.clone().collect::<Vec<_>>());
            let sum = label.strip_suffix(" − 1").unwrap_or(&label).to_string();
            Some((
                vec![(
                    (sum, trig_judge::exact::sum(&functions)),
                    ("1".into(), Sym::one()),
                )],
                names.zip(functions).collect(),
            ))
        }
        Check::Conic {
            points,
            equation,
            equation_text,
            quantifier: None,
            ..
        } => {
            let along = |pick: fn(&(Sym, Sym)) -> &Sym| {
                trig_judge::exact::combination(
                    &functions,
                    &points.iter().map(|p| pick(p).clone()).collect::<Vec<_>>(),
                )
            };
            Some((
                vec![(
                    (
                        trig_judge::span::conic_label(equation_text),
                        trig_judge::span::conic_residual(spec, points, equation),
                    ),
                    ("0".into(), Sym::zero()),
                )],
                vec![
                    ("X of Σ bᵢPᵢ".into(), along(|p| &p.0)),
                    ("Y of Σ bᵢPᵢ".into(), along(|p| &p.1)),
                ],
            ))
        }
        Check::Identity {
            identities,
            curves,
            lets,
            change,
            ..
        } => {
            let sides =
                trig_judge::identity::sides(spec, identities, curves, lets, change.as_ref())
                    .ok()?;
            Some((
                sides
                    .into_iter()
                    .map(|(label, lhs, rhs)| {
                        (
                            (format!("{label}, left side"), lhs),
                            (format!("{label}, right side"), rhs),
                        )
                    })
                    .collect(),
                Vec::new(),
            ))
        }
        _ => None,
    }
}
