//! "Normalized totally positive exactly for the parameters in the printed
//! box": the maximal set of total positivity with two or more parameters.
//!
//! Total positivity on the box is decided as for any box
//! ([`crate::total_positivity`]). With two parameters, the region where
//! the necessary conditions hold (every function `≥ 0`; `b₀`
//! non-increasing and `bₙ` non-decreasing for a basis interpolating its
//! ends — [`crate::tp_maximal`]) is compared with the box by the region
//! judge ([`crate::region::maximal`]: containment, then each face against
//! the exact boundary curves): where the box is exactly that region, it is
//! exactly the maximal set of total positivity (**exact**; the squares of
//! Han's quadratic in `λ²`, `μ²`: totally positive exactly on `[−1, 1]²`,
//! nonnegative on a larger set). Otherwise, beyond the middle of each face
//! (pushed out by `1, 1/4, …, 1/256`): a parameter vector where total
//! positivity is proved refutes maximality; refutations alone bound the set
//! (a **bracket**, called so: `not-checkable`).

use rug::Rational;
use trig_certify::ParamBox;
use trig_certify::branch::Axis as BranchAxis;
use trig_certify::region::{CellKind, Region};
use trig_certify::tp_box::BoxOutcome;
use trig_core::{End, Parameter};

use super::nonnegative::pieces;
use super::region::{self, Axis};
use super::total_positivity::normalized_totally_positive;
use super::tp_conditions::{METHOD, necessary_functions, totally_positive_at};
use super::tp_wronskian::continuous;
use crate::exact::{ExactBasis, basis_of};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The distances beyond a face that are tried: 1, 1/4, …, 1/256.
const STEPS: u32 = 5;

/// Decides "normalized totally positive exactly on the box of the
/// parameters' ranges" (the claim's ranges substituted before).
pub fn maximal_totally_positive_box<B: ExactBasis>(basis: &B) -> Verdict {
    let params = basis.parameters();
    let inside = normalized_totally_positive(basis, None);
    if inside.status != Status::Holds {
        return inside;
    }
    let on_box = params
        .iter()
        .map(|p| format!("{} ∈ {}", p.symbol, p.range))
        .collect::<Vec<_>>()
        .join(", ");
    if let (2, Some(necessary)) = (params.len(), necessary_functions(basis)) {
        let axes = [axis(&params[0]), axis(&params[1])];
        let names: Vec<&str> = necessary.names.iter().map(String::as_str).collect();
        let region = region::maximal(&necessary.functions, &names, necessary.trig, axes);
        if region.status == Status::Holds {
            let mut v = Verdict::all(
                METHOD,
                vec![
                    ("total positivity on the box".into(), inside),
                    (
                        "the necessary conditions hold exactly on the box".into(),
                        region,
                    ),
                ],
            );
            v.evidence.insert(0, Evidence::note(necessary.note));
            v.evidence.push(Evidence::note(format!(
                "so {on_box} is exactly the maximal set of normalized total positivity"
            )));
            return v;
        }
    }
    let polynomial = pieces(basis).ok();
    let mut evidence = vec![Evidence::note(format!(
        "normalized totally positive on the printed box {on_box} (proved, see the claim without maximal); the box is not known to be exactly the region of the necessary conditions, so each face is decided by total positivity beyond it"
    ))];
    let pis: Vec<bool> = params.iter().map(|p| p.range.pi).collect();
    let mut bracketed = false;
    for (i, p) in params.iter().enumerate() {
        for (end, outward) in [(p.range.lo.value(), -1), (p.range.hi.value(), 1)] {
            let Some(e) = end else { continue };
            let open = if outward < 0 {
                matches!(p.range.lo, End::Open(_))
            } else {
                matches!(p.range.hi, End::Open(_))
            };
            if open && continuous_on_face(basis, &params, i, e) {
                evidence.push(Evidence::note(format!(
                    "on the open face {} = {e} the basis is totally positive too: every denominator is nonzero there, so each collocation minor is a limit of minors ≥ 0 from inside the printed box; the box is not the maximal set",
                    p.symbol
                )));
                return Verdict::new(Status::Fails, METHOD, evidence);
            }
            let mut refuted: Option<Rational> = None;
            for k in 0..STEPS {
                let q = e.clone() + Rational::from((outward, 1u32 << (2 * k)));
                let point: Vec<Rational> = params
                    .iter()
                    .enumerate()
                    .map(|(j, r)| {
                        if j == i {
                            q.clone()
                        } else {
                            r.range.interior_point()
                        }
                    })
                    .collect();
                let at: Vec<(&str, &Rational)> =
                    params.iter().map(|r| r.name.as_str()).zip(&point).collect();
                match totally_positive_at(basis, polynomial.as_ref(), &at, &pis) {
                    Some(true) => {
                        evidence.push(Evidence::note(format!(
                            "at {}, outside the printed box, the basis is totally positive too (proved at that point): the box is not the maximal set",
                            equalities(&params, &point)
                        )));
                        return Verdict::new(Status::Fails, METHOD, evidence);
                    }
                    Some(false) => refuted = Some(q),
                    None => {}
                }
            }
            evidence.push(Evidence::note(match refuted {
                Some(q) => format!(
                    "beyond the face {} = {e}: not totally positive at {} = {q} (the other parameters inside, refuted there), but not proved on the whole gap (a bracket)",
                    p.symbol, p.symbol
                ),
                None => format!(
                    "beyond the face {} = {e}: neither proved nor refuted at the points tried",
                    p.symbol
                ),
            }));
            bracketed = true;
        }
    }
    if !bracketed {
        return Verdict::new(Status::Holds, METHOD, evidence);
    }
    evidence.push(Evidence::note(
        "the maximal set is not decided exactly: beyond the faces, total positivity is refuted at single points only",
    ));
    Verdict::new(Status::NotCheckable, METHOD, evidence)
}

/// Every denominator of the basis nonzero on the closed face `pᵢ = e` of
/// the box (the other ranges closed, bounded ones only).
fn continuous_on_face<B: ExactBasis>(
    basis: &B,
    params: &[Parameter],
    i: usize,
    e: &Rational,
) -> bool {
    let axes: Option<Vec<BranchAxis>> = params
        .iter()
        .enumerate()
        .map(|(j, r)| {
            let (lo, hi) = if j == i {
                (e.clone(), e.clone())
            } else {
                (r.range.lo.value()?.clone(), r.range.hi.value()?.clone())
            };
            Some(BranchAxis {
                lo,
                hi,
                lo_open: false,
                hi_open: false,
                pi: r.range.pi,
            })
        })
        .collect();
    axes.is_some_and(|axes| continuous(&basis_of(basis), &basis.domain(), &axes).is_ok())
}

/// A parameter as an axis of the region judge.
fn axis(p: &Parameter) -> Axis<'_> {
    Axis {
        name: &p.name,
        symbol: &p.symbol,
        set: ParamBox::from_range(&p.range),
        source: &p.source,
    }
}

/// `λ = 1, μ = 1/2`.
fn equalities(params: &[Parameter], point: &[Rational]) -> String {
    params
        .iter()
        .zip(point)
        .map(|(p, v)| format!("{} = {v}", p.symbol))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The window around the printed box of a two-parameter basis, classified
/// for total positivity (`plot region --property total-positivity`): a
/// cell is **inside** where the factorisation's minors are certified `≥ 0`
/// on the whole cell ([`trig_certify::tp_box`]), **outside** where a
/// necessary condition (a function `≥ 0`; `b₀` non-increasing, `bₙ`
/// non-decreasing) is certified to fail at one point of the domain for
/// every parameter of the cell, the **edge** otherwise. The edge lies on
/// the necessary conditions' boundary curves or inside the certificate's
/// gap.
pub fn totally_positive_region<B: ExactBasis>(
    basis: &B,
    axes: &[Axis<'_>; 2],
) -> Result<Region, String> {
    let (trig, fs, _) = pieces(basis)?;
    let necessary = necessary_functions(basis)
        .ok_or("the necessary conditions need functions polynomial in sin, cos or the variable")?;
    let names: Vec<&str> = necessary.names.iter().map(String::as_str).collect();
    let params = [axes[0].name, axes[1].name];
    Ok(region::classify_window_by(
        &necessary.functions,
        &names,
        trig,
        axes,
        |lo, hi| match trig_certify::region::classify(&necessary.functions, trig, params, lo, hi) {
            outside @ CellKind::Outside { .. } => outside,
            _ => {
                let cell = [
                    (params[0], ParamBox::closed(lo[0].clone(), hi[0].clone())),
                    (params[1], ParamBox::closed(lo[1].clone(), hi[1].clone())),
                ];
                match trig_certify::tp_box::certify(&fs, trig, &cell) {
                    Ok(c) if matches!(c.outcome, BoxOutcome::Covers { .. }) => CellKind::Inside,
                    _ => CellKind::Boundary,
                }
            }
        },
    ))
}
