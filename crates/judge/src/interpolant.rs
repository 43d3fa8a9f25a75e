//! The interpolant judge: a printed data table (a table file, read by
//! `trig_interp::DataSet::parse`) interpolated by a scheme of `trig-interp`
//! (C¹, C², G¹, G², with the table's per-interval parameters), and whether
//! the curve stays `≥ 0` on its whole interval.
//!
//! Positivity is decided piece by piece by a certified minimum: the
//! control points enclosed with `π` in a rational interval, the piece in
//! the Weierstrass variable `z = tan(θ/2)`, exact Bernstein subdivision for
//! the lower bound and the exact value at a rational point for the upper
//! bound ([`trig_interp::certified_minimum`] with [`prove`]). A piece
//! certified negative carries a witness: an exact point where the exact
//! piece (`π` symbolic) is below 0 ([`crate::interpolant_point`]).
//!
//! The schemes are built on `trig-interp`'s basis ([`trig_interp::BASIS`]);
//! a claim about another basis is `not-checkable`, saying so. A scheme
//! whose print has a corrected variant (C², G²) is decided as printed (the
//! curve the document computes), the corrected one reported beside it.

use rug::Rational;
use trig_certify::ParamBox;
use trig_certify::algebraic::decimal;
use trig_certify::nonneg::{Certificate, certify};
use trig_core::Described;
use trig_interp::{
    DataSet, Interval, PieceMinimum, Proof, Scheme, Spline, Variant, build, certified_minimum,
};
use trig_symbolic::Sym;
use trig_verdict::evidence::{Evidence, Relation};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::exact::ExactBasis;
use crate::interpolant_point::piece_witness;
use crate::memo::Memo;

/// How positivity is certified, as the report states it.
pub const CERTIFIED: &str = "certified minimum per piece: control points enclosed for π ∈ [3.14159265358979323846264338327, …328], Weierstrass z = tan(θ/2) + exact Bernstein subdivision lower bound, exact value at a rational point as upper bound";

/// Proves `f(θ) ≥ 0` on `[0, π/2]` (no shape parameter), or finds where it
/// is negative: the prover `trig_interp::certified_minimum` takes (Weierstrass
/// substitution and exact Bernstein subdivision, [`certify`]), for the
/// judge and the `interp` command alike.
pub fn prove(f: &Sym) -> Proof {
    match certify(
        f,
        true,
        None,
        &ParamBox::closed(Rational::new(), Rational::new()),
    ) {
        Certificate::NonNegative { .. } => Proof::NonNegative,
        Certificate::Counterexample { z, .. } => Proof::Negative { z },
        Certificate::Pole(why) | Certificate::Undecided(why) => Proof::Undecided(why),
    }
}

/// The exact interpolant (`π` a symbol) of `data` by `scheme`/`variant`.
pub fn exact_spline(
    data: &DataSet,
    scheme: Scheme,
    variant: Variant,
) -> Result<Spline<Sym>, String> {
    build(data, scheme, variant, &Sym::zero()).map_err(|e| e.to_string())
}

/// Describes one piece's certified minimum.
pub fn describe(name: &str, variant: Variant, m: &PieceMinimum) -> String {
    let bracket = match &m.lower {
        Some(l) => format!("[{}, {}]", decimal(l, 6, false), decimal(&m.upper, 6, true)),
        None => format!(
            "(undecided: {}) ≤ {}",
            m.undecided.as_deref().unwrap_or("?"),
            decimal(&m.upper, 6, true)
        ),
    };
    format!(
        "{name} ({variant}), piece {}: min P ∈ {bracket} at x ≈ {:.6} (z = tan(θ/2) = {})",
        m.piece + 1,
        m.x,
        m.z
    )
}

/// The certified minima of the interpolant of `data` by `scheme`/`variant`,
/// as a verdict: holds when every piece is certified `≥ 0`, fails when one
/// is certified negative (with its witness).
///
/// Decided once per process for the same table, scheme and reading (an
/// umbrella and the claims about the same curve ask again); the key is
/// every value read from the table.
pub fn positivity(data: &DataSet, scheme: Scheme, variant: Variant) -> Verdict {
    static DECIDED: Memo<Verdict> = Memo::new();
    let key = format!("{data:?} {scheme:?} {variant:?}");
    DECIDED.get_or_compute(key, || decide_positivity(data, scheme, variant))
}

fn decide_positivity(data: &DataSet, scheme: Scheme, variant: Variant) -> Verdict {
    let name = &data.table.name;
    let result = build(data, scheme, variant, &Interval::point(Rational::new()))
        .and_then(|s| certified_minimum(&s, &prove));
    let minima = match result {
        Err(e) => return Verdict::not_checkable(e.to_string()),
        Ok(minima) => minima,
    };
    let status = if minima.iter().all(PieceMinimum::nonnegative) {
        Status::Holds
    } else if minima.iter().any(PieceMinimum::negative) {
        Status::Fails
    } else {
        Status::NotCheckable
    };
    // the exact interpolant (π symbolic), for the witnesses' formulas
    let exact = minima
        .iter()
        .any(PieceMinimum::negative)
        .then(|| exact_spline(data, scheme, variant));
    let evidence = minima.iter().map(|m| {
        let item = Evidence::note(describe(name, variant, m));
        if !m.negative() {
            return item;
        }
        // a simple point near the certified minimum where P is exactly negative
        let witness = exact
            .as_ref()
            .and_then(|e| e.as_ref().ok())
            .and_then(|spline| {
                piece_witness(
                    spline,
                    m.piece,
                    &m.z,
                    Relation::AtLeast,
                    ("0", &Rational::new()),
                )
            });
        item.witnessed(witness)
    });
    Verdict::new(status, CERTIFIED, evidence)
}

/// "The interpolant of `data` by `scheme` stays `≥ 0` on its whole
/// interval", about `basis`: decided on the printed scheme (the curve the
/// document computes and plots), with the corrected scheme of a print that
/// has one reported beside it for comparison.
pub fn nonnegative<B: ExactBasis>(basis: &B, data: &DataSet, scheme: Scheme) -> Verdict {
    if let Some(why) = other_basis(basis) {
        return Verdict::not_checkable(why);
    }
    let mut v = positivity(data, scheme, Variant::Printed);
    if let Some(correction) = scheme.correction() {
        let corrected = positivity(data, scheme, Variant::Corrected);
        v.evidence.push(format!(
            "decided on the printed scheme (what the thesis computes and plots); the corrected scheme ({correction}) on the same table, for comparison: {}",
            corrected.status
        ));
        v.evidence.extend(corrected.evidence);
    }
    v
}

/// Why the schemes do not apply to `basis`: it is not exactly the basis
/// they are built on.
pub(crate) fn other_basis<B: ExactBasis>(basis: &B) -> Option<String> {
    let theirs = trig_interp::BASIS.exact_functions();
    let ours = basis.exact_functions();
    let same = ours.len() == theirs.len()
        && ours
            .iter()
            .zip(&theirs)
            .all(|(a, b)| (a.clone() - b).is_zero());
    (!same).then(|| {
        format!(
            "the interpolation schemes are built on the basis {} ({}); the claim's basis {} is not exactly that basis",
            trig_interp::BASIS.id(),
            trig_interp::BASIS.citation(),
            basis.id()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    fn table(name: &str) -> DataSet {
        DataSet::named(name).unwrap()
    }

    #[test]
    fn a_negative_piece_fails_with_a_witness_and_a_positive_curve_holds() {
        let v = nonnegative(&Family::ThesisCubic, &table("thesis-table-4.6"), Scheme::G1);
        assert_eq!(v.status, Status::Fails);
        assert!(v.evidence.iter().any(|e| e.witness.is_some()));
        let v = nonnegative(&Family::ThesisCubic, &table("thesis-table-4.1"), Scheme::C1);
        assert_eq!(v.status, Status::Holds);
        // a value of the table changed: the curve's minimum follows the data
        let mut low = table("thesis-table-4.1");
        low.f[1] = Rational::from(-1);
        let v = nonnegative(&Family::ThesisCubic, &low, Scheme::C1);
        assert_eq!(v.status, Status::Fails);
    }

    #[test]
    fn a_corrected_scheme_is_reported_beside_the_printed_one() {
        let v = nonnegative(&Family::ThesisCubic, &table("thesis-table-4.2"), Scheme::C2);
        assert!(
            v.evidence
                .iter()
                .any(|e| e.text.contains("(corrected), piece 2")),
            "{:?}",
            v.evidence
        );
    }

    #[test]
    fn another_basis_is_not_checkable() {
        let v = nonnegative(&Family::Bernstein3, &table("thesis-table-4.1"), Scheme::C1);
        assert_eq!(v.status, Status::NotCheckable);
        assert!(
            v.evidence[0].text.contains("not exactly that basis"),
            "{:?}",
            v.evidence
        );
    }
}
