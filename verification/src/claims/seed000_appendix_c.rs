//! Seed 000, Theorems 3, 4, 7 (M4, M4b, M8) decided by the exact
//! knot-jump computation of [`trig_deriv::continuity`]; the non-uniform knot
//! vector the seed's Rust claims share.

use std::sync::OnceLock;

use trig_core::Family;
use trig_symbolic::Sym;

use super::seed000_appendix_print::zeta;
use crate::claim::{Claim, shared};
use trig_deriv::continuity::{
    self, KnotContinuity, curve_jumps, nonuniform_bspline, uniform_bspline,
};
use trig_judge::continuity::{METHOD, at_least, describe, knot_witness};
use trig_judge::exact::symbols;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "M4",
        check: m4,
    },
    Claim {
        id: "M4b",
        check: m4b,
    },
    Claim {
        id: "M8",
        check: m8,
    },
];

/// A non-uniform knot vector with distinct integer knots and unequal
/// spacings (q = 1, 2, 1, 3, 1, 2, 3, …).
pub(super) fn nonuniform_knots() -> Vec<Sym> {
    [
        0, 1, 3, 4, 7, 8, 10, 13, 14, 16, 19, 20, 22, 25, 26, 29, 30, 32, 35, 36, 38,
    ]
    .map(Sym::int)
    .to_vec()
}

/// The basis function examined on [`nonuniform_knots`].
pub(super) const NONUNIFORM_J: i64 = 8;

/// The claim "C⁵ for ξ ≠ 1": it fails when some knot is below C⁵ for
/// generic ξ (then every ξ outside the finitely many exceptions is a
/// counterexample); the exceptional values where C⁵ holds are listed.
fn c5_except_one(label: &str, knots: &[KnotContinuity]) -> Verdict {
    let mut evidence = trig_verdict::evidence::EvidenceList::from(vec![format!(
        "{label}: C^5 claimed for every ξ ≠ 1"
    )]);
    for k in knots.iter().filter(|k| !k.smoothness.is_at_least(5)) {
        let good: Vec<String> = k
            .exceptions
            .iter()
            .filter(|e| e.smoothness.is_at_least(5))
            .map(|e| e.value.to_string())
            .collect();
        evidence.push(
            trig_verdict::evidence::Evidence::note(format!(
                "knot {}: {} for every ξ except ξ ∈ {{{}}}, where it is C^5",
                k.knot,
                k.smoothness,
                good.join(", ")
            ))
            .witnessed(knot_witness(k)),
        );
    }
    let ok = knots.iter().all(|k| k.smoothness.is_at_least(5));
    Verdict::new(
        if ok { Status::Holds } else { Status::Fails },
        METHOD,
        evidence,
    )
}

fn uniform_basis() -> Vec<KnotContinuity> {
    let pieces = uniform_bspline(&Family::Seed000Uniform, &[zeta()]);
    continuity::continuity(&pieces, true, Some("zeta"))
}

/// The interior knots of the uniform curve `Σ F_i P_i` over `spans` unit
/// spans (control points `P0…` as symbols), optionally rational with
/// weights `w0…`: at knot `k` the end of span `k − 1` meets the start of
/// span `k` (only these one-sided derivatives are computed).
pub(super) fn uniform_curve(rational: bool, spans: usize) -> Vec<KnotContinuity> {
    let p = symbols("P", spans + 3);
    let w = symbols("w", spans + 3);
    (1..spans)
        .map(|knot| {
            let (left, right) = (knot - 1..knot + 3, knot..knot + 4);
            let jumps = curve_jumps(
                Family::Seed000Uniform,
                &[zeta()],
                (&p[left.clone()], &p[right.clone()]),
                rational.then(|| (&w[left], &w[right])),
            );
            continuity::classify(knot, jumps, Some("zeta"))
        })
        .collect()
}

fn m4() -> Verdict {
    let basis = uniform_basis();
    let curve = uniform_curve(false, 3);
    let mut parts = vec![
        (
            "Theorem 3, C^3, uniform knots (Appendix A basis F_j = l_k/(6ζ²−6ζ+10) on unit knots 0…4)".to_string(),
            at_least("basis F_j", &basis, 3, Some("zeta")),
        ),
        (
            "Theorems 3/4, C^5 (\"for ξ ≠ 1\"), uniform basis".to_string(),
            c5_except_one("basis F_j", &basis),
        ),
        (
            "Theorem 4, C^3, uniform curve Σ F_i P_i (three spans, symbolic P0…P5)".to_string(),
            at_least("curve", &curve, 3, Some("zeta")),
        ),
        (
            "Theorem 4, C^5 for ξ ≠ 1, uniform curve".to_string(),
            c5_except_one("curve", &curve),
        ),
    ];
    parts.push((
        format!(
            "Theorem 3, non-uniform knots with the printed coefficients (2)–(3), F_{NONUNIFORM_J} on knots {}",
            nonuniform_knots().iter().map(|k| k.to_string()).collect::<Vec<_>>().join(", ")
        ),
        match nonuniform_bspline(&nonuniform_knots(), &zeta(), NONUNIFORM_J) {
            Ok(pieces) => at_least(
                "non-uniform F_j",
                &continuity::continuity(&pieces, true, Some("zeta")),
                3,
                Some("zeta"),
            ),
            Err(e) => Verdict::not_checkable(format!("the construction is undefined: {e}")),
        },
    ));
    Verdict::all(METHOD, parts)
}

/// Knot vectors with one knot of multiplicity `k` inside the support of
/// `F_j`, `j` = [`NONUNIFORM_J`].
fn multiple_knots(k: usize) -> Vec<Sym> {
    let mut knots = nonuniform_knots();
    let at = NONUNIFORM_J as usize + 2;
    for i in 1..k {
        knots[at + i] = knots[at].clone();
    }
    // keep the knots after the repeated one increasing
    knots
}

fn m4b() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        let mut parts = Vec::new();
        for k in 2..=4 {
            let knots = multiple_knots(k);
            let label = format!(
                "multiplicity {k} (claimed C^{}), printed coefficients (2)–(3), knots {}",
                3 - k as i64,
                knots
                    .iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            );
            let v = match nonuniform_bspline(&knots, &zeta(), NONUNIFORM_J) {
                Ok(pieces) => {
                    let cont = continuity::continuity(&pieces, true, Some("zeta"));
                    let want = 3 - k as i64;
                    let ok = cont.iter().all(|c| c.smoothness.rank() >= want);
                    Verdict::new(
                        if ok { Status::Holds } else { Status::Fails },
                        METHOD,
                        cont.iter().map(|c| {
                            let item = describe(c, Some("zeta"));
                            if c.smoothness.rank() >= want {
                                item
                            } else {
                                item.witnessed(knot_witness(c))
                            }
                        }),
                    )
                }
                Err(e) => Verdict::not_checkable(format!(
                    "the printed construction (2)–(3) is undefined at coincident knots: {e}"
                )),
            };
            parts.push((label, v));
        }
        let uniform = Verdict::not_checkable(
            "the uniform construction (Appendix A) has unit knot spacing only: it has no knots of multiplicity k > 1",
        );
        parts.push(("uniform reading".into(), uniform));
        let all = Verdict::all(METHOD, parts.clone());
        if parts.iter().all(|(_, v)| v.status == Status::NotCheckable) {
            Verdict::new(Status::NotCheckable, "none possible", all.evidence)
        } else {
            all
        }
    })
}

fn m8() -> Verdict {
    let curve = uniform_curve(true, 2);
    Verdict::all(
        METHOD,
        vec![
            (
                "C^3, uniform rational curve Σ w_i F_i P_i / Σ w_i F_i (two spans, symbolic P0…P4, w0…w4)".to_string(),
                at_least("rational curve", &curve, 3, Some("zeta")),
            ),
            ("C^{3−k} at knots of multiplicity k (as M4b)".to_string(), m4b()),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_deriv::continuity::Smoothness;

    #[test]
    fn uniform_seed000_basis_is_c3_at_its_ends_and_smooth_inside() {
        let knots = uniform_basis();
        assert_eq!(knots[0].smoothness, Smoothness::Exactly(3));
        assert_eq!(knots[4].smoothness, Smoothness::Exactly(3));
        for k in &knots[1..4] {
            assert_eq!(k.smoothness, Smoothness::AtLeast(6));
        }
        let values: Vec<String> = knots[0]
            .exceptions
            .iter()
            .map(|e| e.value.to_string())
            .collect();
        assert_eq!(values, ["0", "1"]);
        assert!(
            knots[0]
                .exceptions
                .iter()
                .all(|e| e.smoothness == Smoothness::Exactly(5))
        );
    }
}
