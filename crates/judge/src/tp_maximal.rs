//! "Normalized totally positive exactly for λ in the printed range": the
//! maximal set of total positivity of a one-parameter basis, against the
//! printed range.
//!
//! Total positivity on the range is decided as for any range
//! ([`crate::total_positivity`]). Nonnegativity is necessary for total
//! positivity (the `1 × 1` minors), so where the printed range is exactly
//! the maximal nonnegativity set, it is exactly the maximal set of total
//! positivity too (**exact**). Otherwise, beyond each end of the range: a
//! rational value where the certificate proves total positivity refutes
//! maximality (exact witness); a value where a collocation minor is
//! negative bounds the end (a **bracket**, called so: `not-checkable`).

use rug::Rational;
use trig_certify::ParamBox;
use trig_certify::total_positivity::{certify, refute};
use trig_core::{End, ParamRange};

use super::nonnegative::{nonnegative_claim, pieces};
use super::total_positivity::normalized_totally_positive;
use crate::exact::ExactBasis;
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How the maximal set is decided, as the report states it.
pub const METHOD: &str = "total positivity on the printed range by the totally positive factorisation; nonnegativity, necessary for it, exactly on the range (the maximal nonnegativity interval) makes the range exactly maximal; beyond an end, a value where the certificate proves total positivity refutes maximality, a negative collocation minor bounds the end (a bracket)";

/// The distances beyond an end that are tried: 1, 1/4, …, 1/256.
const STEPS: u32 = 5;

/// Decides "normalized totally positive exactly for the range" (the
/// claim's range, else the declared one) for a one-parameter basis.
pub fn maximal_totally_positive<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    let params = basis.parameters();
    let [p] = params.as_slice() else {
        return Verdict::not_checkable(format!(
            "the maximal set of total positivity is decided for one parameter ({} here)",
            params.len()
        ));
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
    let Ok((trig, fs, _)) = pieces(basis) else {
        return Verdict::not_checkable(
            "the factorisation needs functions polynomial in sin, cos or the variable",
        );
    };
    let mut evidence: Vec<Evidence> = vec![Evidence::note(format!(
        "normalized totally positive on the printed range {} ∈ {printed} (proved, see the claim without maximal); the range is not exactly the maximal nonnegativity interval, so its ends are decided by total positivity itself",
        p.symbol
    ))];
    let mut bracketed = false;
    for (end, outward) in [(&printed.lo, -1), (&printed.hi, 1)] {
        let e = match (end, printed.pi) {
            (End::Unbounded, _) => continue,
            (_, true) => {
                evidence.push(Evidence::note(
                    "an end in multiples of π is not compared (rational values only)",
                ));
                bracketed = true;
                continue;
            }
            (End::Closed(e) | End::Open(e), false) => e.clone(),
        };
        // an open end itself, then values at 1, 1/4, … beyond it
        let mut tries: Vec<Rational> = Vec::new();
        if matches!(end, End::Open(_)) {
            tries.push(e.clone());
        }
        tries.extend((0..STEPS).map(|k| e.clone() + Rational::from((outward, 1u32 << (2 * k)))));
        let mut refuted: Option<Rational> = None;
        for q in tries {
            // a refutation is cheap; the certificate at a value only where
            // none is found
            if refute(&fs, trig, Some((p.name.as_str(), &q))).is_some() {
                refuted = Some(q);
                continue;
            }
            let at = ParamBox::point(q.clone());
            let proved =
                certify(&fs, trig, Some((p.name.as_str(), &at))).is_ok_and(|c| c.set.covers);
            if proved {
                evidence.push(Evidence::note(format!(
                    "at {} = {q}, outside the printed range, the basis is totally positive too (the certificate at that value, exact): the printed range is not the maximal set",
                    p.symbol
                )));
                return Verdict::new(Status::Fails, METHOD, evidence);
            }
        }
        match refuted {
            Some(q) => evidence.push(Evidence::note(format!(
                "beyond the end {e}: not totally positive at {} = {q} (a negative collocation minor, exact), but not proved on the whole gap: the maximal set ends between {e} and {q} (a bracket)",
                p.symbol
            ))),
            None => evidence.push(Evidence::note(format!(
                "beyond the end {e}: neither proved nor refuted at the values tried"
            ))),
        }
        bracketed = true;
    }
    if !bracketed {
        return Verdict::new(Status::Holds, METHOD, evidence);
    }
    evidence.push(Evidence::note(format!(
        "the maximal set is not decided exactly ({TOTALLY_POSITIVE_SHORT}); the Wronskian criterion that could close the gap is not implemented"
    )));
    Verdict::new(Status::NotCheckable, METHOD, evidence)
}

/// A short name of the certificate's method for the notes.
const TOTALLY_POSITIVE_SHORT: &str =
    "the totally positive factorisation is sufficient, not necessary";
