//! Local control, joins of piecewise curves and the interpolation of the
//! second list of `shared/claims.md`: which segments a shape parameter of
//! seed 002's segments enters (D19, decided by the local-control judge),
//! how consecutive segments join (E24, by the continuity judge), which
//! control points a refinement moves (T65), how a piecewise curve
//! interpolates (D17), and the printed G² condition (T51). Each states what
//! is printed and computes the verdict.

use trig_core::{Family, Ring};
use trig_deriv::continuity::{Piece, continuity, curve_piece};
use trig_symbolic::Sym;

use super::local_control_joins::{d17, seed002_segment};
use crate::claim::Claim;
use trig_judge::continuity::at_least;
use trig_judge::exact::{IDENTITY, identities, symbols};
use trig_judge::local_control::{Entry, compare};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// In report order (after each document's first-list claims).
pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "D17",
        check: d17,
    },
    Claim {
        id: "D19",
        check: d19,
    },
    Claim {
        id: "E24",
        check: e24,
    },
];

/// D19: segment `Q_i(t, α_i, α_{i+1})` of (6) uses `α_i` as its first
/// parameter and `Q_{i−1}` as its second; every other segment has neither.
fn d19() -> Verdict {
    let q = seed002_segment();
    let entries = [
        Entry {
            offset: 0,
            weights: vec![("∂Q_i/∂α_i = ∂Q/∂α1".into(), q.diff("alpha1"))],
        },
        Entry {
            offset: -1,
            weights: vec![("∂Q_{i−1}/∂α_i = ∂Q/∂α2".into(), q.diff("alpha2"))],
        },
    ];
    let mut v = compare("α_j", &entries, &[-1, 0]);
    v.evidence.insert(
        0,
        Evidence::note(
            "segment i of (6) is Q_i(t, α_i, α_{i+1}) = Q(t, α1, α2) of (4) on V_{i−1} … V_{i+2}: the rational curve (2) with P0…P5 solved from the end conditions (3) (reading D6b; the printed Tb_i of (5) is unreadable, see D12); so α_j is α1 of Q_j, α2 of Q_{j−1}, and in no other segment; the witness is a point where the derivative is nonzero",
        ),
    );
    v
}

/// E24: two consecutive segments of (3), `R_i` on `P_{i−3} … P_i` and
/// `R_{i+1}` on `P_{i−2} … P_{i+1}` (local symbols `P0 … P4`), joined at
/// their common knot: derivatives in `t` (unit intervals), then in `u`
/// (`d/du = (1/Δt_i) d/dt` on segment `i`).
fn e24() -> Verdict {
    let f = Family::Eh;
    let params = trig_judge::exact::params(f);
    let p = symbols("P", 5);
    let (dt0, dt1) = (Sym::var("dt_i"), Sym::var("dt_i1"));
    let left = curve_piece(f, &params, &p[0..4], None);
    let right = curve_piece(f, &params, &p[1..5], None);
    let in_u = |piece: &Piece, dt: &Sym| {
        let scale = |d: &[Sym]| -> Vec<Sym> {
            d.iter()
                .enumerate()
                .map(|(r, x)| x.clone() / &dt.powi(r as u32))
                .collect()
        };
        Piece {
            start: scale(&piece.start),
            end: scale(&piece.end),
        }
    };
    let label = "R_i, R_{i+1} of (2) (local P0 … P4 = P_{i−3} … P_{i+1})";
    let t = at_least(
        &format!("{label}, derivatives in t"),
        &continuity(&[left.clone(), right.clone()], false, None),
        1,
        None,
    );
    let u_pieces = [in_u(&left, &dt0), in_u(&right, &dt1)];
    let u_knots = continuity(&u_pieces, false, None);
    let jump = u_pieces[1].start[1].clone() - &u_pieces[0].end[1];
    let expected = (Sym::one() / &dt1 - &(Sym::one() / &dt0)) * &p[3];
    let values = identities(vec![
        ("R_i(1) = P_{i−2}".into(), left.end[0].clone(), p[1].clone()),
        (
            "R_{i+1}(0) = P_{i−2}".into(),
            right.start[0].clone(),
            p[1].clone(),
        ),
    ]);
    let u_jump = identities(vec![
        (
            "jump of R' in u = (1/Δt_{i+1} − 1/Δt_i)·P_i".into(),
            jump.clone(),
            expected,
        ),
        (
            "the jump of R' in u at Δt_{i+1} = Δt_i".into(),
            jump.subs("dt_i1", &dt0),
            Sym::zero(),
        ),
    ]);
    let mut u_evidence = at_least(&format!("{label}, derivatives in u"), &u_knots, 0, None);
    u_evidence.evidence.extend(u_jump.evidence.into_vec());
    u_evidence.status = Status::conjunction([u_evidence.status, u_jump.status]);
    Verdict::all(
        format!("{}; {IDENTITY}", trig_judge::continuity::METHOD),
        vec![
            ("C⁰: R_i(1) = P_{i−2} = R_{i+1}(0)".into(), values),
            ("R' matches in t (C¹ in t)".into(), t),
            (
                "in u: C⁰, and C¹ only when Δt_i = Δt_{i+1} (P_i ≠ 0)".into(),
                u_evidence,
            ),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The computed sets of segments (the "enters exactly" lines).
    fn entered(v: &Verdict) -> Vec<String> {
        v.evidence
            .iter()
            .filter(|e| e.text.contains("enters exactly"))
            .map(|e| e.text.clone())
            .collect()
    }

    #[test]
    fn the_local_claims_compute_their_segments() {
        assert_eq!(
            entered(&d19()),
            ["α_j enters exactly: j−1, j (printed: j−1, j)"]
        );
        let m20 = &crate::run(None, Some("M20")).expect("the document files")[0].verdict;
        let m = entered(m20);
        assert_eq!(m.len(), 2);
        assert!(m.iter().all(|l| l.contains("exactly: j, j+1, j+2, j+3 (")));
        let t48 = &crate::run(None, Some("T48")).expect("the document files")[0].verdict;
        assert_eq!(entered(t48), ["m_j enters exactly: j (printed: j)"]);
        let e = e24();
        assert_eq!(e.status, Status::Holds);
        assert!(e.evidence.iter().any(|i| {
            i.line()
                .contains("derivatives in u: achieved for all parameter values: exactly C^0")
        }));
    }

    #[test]
    fn every_claim_of_this_file_decides() {
        for c in CLAIMS {
            let v = (c.check)();
            assert_ne!(v.status, Status::NotCheckable, "{}: {:?}", c.id, v.evidence);
        }
    }
}
