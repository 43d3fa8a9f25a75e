//! "Normalized totally positive exactly for λ in the printed range": the
//! maximal set of total positivity of a one-parameter basis, against the
//! printed range.
//!
//! Total positivity on the range is decided as for any range
//! ([`crate::total_positivity`]). Nonnegativity is necessary for total
//! positivity (the `1 × 1` minors), so where the printed range is exactly
//! the maximal nonnegativity set, it is exactly the maximal set of total
//! positivity too (**exact**). Otherwise each end of the range is
//! compared with the exact end of a set of necessary conditions decided by
//! the range engine (nonnegativity and, for a basis interpolating its ends,
//! `b₀` non-increasing and `bₙ` non-decreasing — variation diminishing):
//! an end where they stop holding is exact (the squared Han basis:
//! totally positive exactly on `[−1, 1]`, nonnegative up to `2 + 2√2`).
//! An end where the domain `[0, α]` shrinks to a point is exact (no basis
//! beyond). Beyond any other end, a value where the certificate (or, for
//! bases it does not take, Karlin's Wronskian criterion,
//! [`crate::tp_wronskian`]) proves total positivity refutes maximality, and
//! a value where a collocation minor (or a consecutive Wronskian) is
//! negative bounds the end (a **bracket**, called so: `not-checkable`).

use rug::Rational;
use trig_core::{End, ParamRange};

use trig_certify::range::{EndPoint, MaximalRange, maximal_range};

use super::certificate::show_outside;
use super::nonnegative::{nonnegative_claim, pieces};
use super::total_positivity::normalized_totally_positive;
use super::tp_conditions::{METHOD, necessary_functions, totally_positive_at};
use super::tp_maximal_box::maximal_totally_positive_box;
use super::tp_wronskian::continuous;
use crate::exact::ExactBasis;
use crate::exact::basis_of;
use trig_certify::analytic_end::Problem;
use trig_certify::branch::Axis;
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The distances beyond an end that are tried: 1, 1/4, …, 1/256.
const STEPS: u32 = 5;

/// Decides "normalized totally positive exactly for the range" (the
/// claim's range, else the declared one) for a one-parameter basis.
pub fn maximal_totally_positive<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    let params = basis.parameters();
    let p = match params.as_slice() {
        [] => {
            return Verdict::not_checkable(
                "the basis has no parameter: there is no set of parameters to be maximal",
            );
        }
        [p] => p,
        _ => return maximal_totally_positive_box(basis),
    };
    let printed = range.unwrap_or(&p.range).clone();
    let inside = normalized_totally_positive(basis, Some(&printed));
    if inside.status != Status::Holds {
        return inside;
    }
    let nonnegative = nonnegative_claim(basis, Some(&printed), true);
    if nonnegative.status == Status::Holds {
        let mut v = Verdict::all(
            METHOD,
            vec![
                ("total positivity on the range".into(), inside),
                (
                    "nonnegativity exactly on the range (necessary for total positivity)".into(),
                    nonnegative,
                ),
            ],
        );
        v.evidence.push(Evidence::note(format!(
            "so {} ∈ {printed} is exactly the maximal set of normalized total positivity",
            p.symbol
        )));
        return v;
    }
    // the factorisation where the functions are polynomial in sin, cos or
    // the variable; the Wronskian criterion at single values otherwise
    let polynomial = pieces(basis).ok();
    let mut evidence: Vec<Evidence> = vec![Evidence::note(format!(
        "normalized totally positive on the printed range {} ∈ {printed} (proved, see the claim without maximal); the range is not exactly the maximal nonnegativity interval, so its ends are decided by total positivity itself",
        p.symbol
    ))];
    let necessary = match &polynomial {
        Some(_) => necessary_set(basis, &p.name, &printed),
        None => (None, None),
    };
    if let Some(note) = &necessary.1 {
        evidence.push(Evidence::note(note.clone()));
    }
    let unit = if printed.pi { "·π" } else { "" };
    let mut bracketed = false;
    for (end, outward) in [(&printed.lo, -1), (&printed.hi, 1)] {
        let e = match (end, printed.pi, &polynomial) {
            (End::Unbounded, _, _) => continue,
            (_, true, Some(_)) => {
                evidence.push(Evidence::note(
                    "an end in multiples of π is not compared (rational values only)",
                ));
                bracketed = true;
                continue;
            }
            (End::Closed(e) | End::Open(e), _, _) => e.clone(),
        };
        let necessary_end = if outward < 0 {
            necessary.0.as_ref().map(|r| &r.lo)
        } else {
            necessary.0.as_ref().map(|r| &r.hi)
        };
        if let (
            Some(EndPoint::Exact {
                value,
                closed,
                outside,
                ..
            }),
            Some((trig, _, _)),
        ) = (necessary_end, &polynomial)
        {
            if value.rational.as_ref() == Some(&e) && *closed == matches!(end, End::Closed(_)) {
                evidence.push(Evidence::note(format!(
                    "the end {e} is exact: just beyond it a necessary condition of normalized total positivity fails ({}; exact end of that condition's set, found by its boundary polynomials)",
                    show_outside(outside, &p.symbol, *trig)
                )));
                continue;
            }
        }
        // where the domain shrinks to a point there is no basis beyond
        let functions = basis_of(basis);
        let domain = basis.domain();
        if Problem::new(&functions, &domain, printed.pi).empty_domain_at() == Some(e.clone()) {
            evidence.push(Evidence::note(format!(
                "the end {e}{unit} is exact: the domain shrinks to a point there, and there is no basis beyond it"
            )));
            continue;
        }
        // an open end where the functions are continuous: totally positive
        // there too, as a limit from inside the printed range
        if matches!(end, End::Open(_)) {
            let point = [Axis {
                lo: e.clone(),
                hi: e.clone(),
                lo_open: false,
                hi_open: false,
                pi: printed.pi,
            }];
            if continuous(&functions, &domain, &point).is_ok() {
                evidence.push(Evidence::note(format!(
                    "at the open end {} = {e}{unit} the basis is totally positive too: every denominator is nonzero there, so each collocation minor is a limit of minors ≥ 0 from inside the printed range; the printed range is not the maximal set",
                    p.symbol
                )));
                return Verdict::new(Status::Fails, METHOD, evidence);
            }
        }
        // an open end itself, then values at 1, 1/4, … beyond it
        let mut tries: Vec<Rational> = Vec::new();
        if matches!(end, End::Open(_)) {
            tries.push(e.clone());
        }
        tries.extend((0..STEPS).map(|k| e.clone() + Rational::from((outward, 1u32 << (2 * k)))));
        let mut refuted: Option<Rational> = None;
        for q in tries {
            match totally_positive_at(basis, polynomial.as_ref(), &[(&p.name, &q)], &[printed.pi]) {
                Some(false) => refuted = Some(q),
                Some(true) => {
                    evidence.push(Evidence::note(format!(
                        "at {} = {q}{unit}, outside the printed range, the basis is totally positive too (proved at that value): the printed range is not the maximal set",
                        p.symbol
                    )));
                    return Verdict::new(Status::Fails, METHOD, evidence);
                }
                None => {}
            }
        }
        match refuted {
            Some(q) => evidence.push(Evidence::note(format!(
                "beyond the end {e}{unit}: not totally positive at {} = {q}{unit} (refuted there), but not proved on the whole gap: the maximal set ends between {e}{unit} and {q}{unit} (a bracket)",
                p.symbol
            ))),
            None => evidence.push(Evidence::note(format!(
                "beyond the end {e}{unit}: neither proved nor refuted at the values tried"
            ))),
        }
        bracketed = true;
    }
    if !bracketed {
        return Verdict::new(Status::Holds, METHOD, evidence);
    }
    evidence.push(Evidence::note(format!(
        "the maximal set is not decided exactly ({TOTALLY_POSITIVE_SHORT})"
    )));
    Verdict::new(Status::NotCheckable, METHOD, evidence)
}

/// A short name of the certificate's method for the notes.
const TOTALLY_POSITIVE_SHORT: &str =
    "the totally positive factorisation is sufficient, not necessary";

/// The maximal interval, around a point of the printed range, of the
/// necessary conditions of normalized total positivity
/// ([`necessary_functions`]), with a note saying which were used.
fn necessary_set<B: ExactBasis>(
    basis: &B,
    param: &str,
    printed: &ParamRange,
) -> (Option<MaximalRange>, Option<String>) {
    if printed.pi {
        return (None, None);
    }
    let Some(necessary) = necessary_functions(basis) else {
        return (None, None);
    };
    let names: Vec<&str> = necessary.names.iter().map(String::as_str).collect();
    let start = printed.interior_point();
    let r = maximal_range(&necessary.functions, &names, necessary.trig, param, &start);
    (Some(r), Some(necessary.note))
}
