//! Seed 004 (Dube & Mishra 2016), section V: the printed C⁰–C², G¹ and G²
//! joins of two EH curves `R1 = Σ bᵢ(t; λ1, μ1) Pᵢ` (at `t = 1`) and
//! `R2 = Σ bᵢ(t; λ2, μ2) Qᵢ` (at `t = 0`), stated for the join judge
//! ([`trig_judge::join`]). The EH curve ends at `P1` with tangent `P3`
//! (its terminal properties are shown with each claim), so the printed
//! `P3 = Q0` does not join the curves.
//!
//! The paper's `G¹` is printed as `P3 − P2 = ω(Q1 − Q0)`, that is
//! `R1'(1) = ω R2'(0)`, and its `G²` as `R1'' = ω² R2'' + β R2'`: in the
//! judge's orientation `R2' = α R1'`, `R2'' = α² R1'' + β' R1'` these are
//! `α = 1/ω`, `β' = −β/ω³`.

use trig_core::Family;
use trig_deriv::{End, JoinKind, Wrt, curve_endpoint_derivatives};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{IDENTITY, symbols};
use trig_judge::join::{Printed, PrintedJoin, audit};
use trig_verdict::evidence::{Assignment, Evidence, EvidenceList, Expr, Value, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "E15",
        check: e15,
    },
    Claim {
        id: "E16",
        check: e16,
    },
    Claim {
        id: "E17",
        check: e17,
    },
];

/// `[R, R', R'']` (in `t`) of `Σ b_i(t; λ, μ) X_i` at `end`.
fn eh_end(points: &[Sym], lambda: &Sym, mu: &Sym, end: End) -> Vec<Sym> {
    curve_endpoint_derivatives::<Sym, 3>(
        Family::Eh,
        &[lambda.clone(), mu.clone()],
        points,
        None,
        end,
        Wrt::Angle,
        &Sym::one(),
    )
}

/// The parameters `(λ1, μ1)`, `(λ2, μ2)` of the two curves, or one pair
/// for both.
fn params(same: bool) -> (Vec<Sym>, Vec<Sym>) {
    let first = vec![Sym::var("lambda1"), Sym::var("mu1")];
    let second = if same {
        first.clone()
    } else {
        vec![Sym::var("lambda2"), Sym::var("mu2")]
    };
    (first, second)
}

/// The printed join of two EH curves, with their terminal properties
/// stated first.
fn eh_join(kind: JoinKind, same: bool, printed: Vec<Printed>) -> PrintedJoin<Family> {
    let (first, second) = params(same);
    let (p, q) = (symbols("P", 4), symbols("Q", 4));
    let r1 = eh_end(&p, &first[0], &first[1], End::End);
    let r2 = eh_end(&q, &second[0], &second[1], End::Start);
    let mut join = PrintedJoin::new(Family::Eh, kind, (first, second), (p, q), printed);
    join.notes = vec![format!(
        "terminal properties from the bases: R1(1) = {}, R1'(1) = {}, R1''(1) = {}; R2(0) = {}, R2'(0) = {}, R2''(0) = {}",
        r1[0], r1[1], r1[2], r2[0], r2[1], r2[2]
    )];
    join
}

/// The paper's `G` factors in the judge's orientation: `α = 1/ω`, and for
/// `G²` `β' = −β/ω³`.
fn omega_factors() -> [Sym; 2] {
    let omega = Sym::var("omega");
    let beta = Sym::var("beta");
    [
        Sym::one() / &omega,
        -(beta / &(omega.clone() * &omega * &omega)),
    ]
}

fn e15() -> Verdict {
    let mut v = Verdict::not_checkable(
        "the printed formula is truncated: its last term −(2μ + 2λ + 6) carries no control point (a scalar added to points), and it does not say which curve's λ, μ it uses; the obvious reading is E15b",
    );
    let join = eh_join(JoinKind::C(2), false, Vec::new());
    v.evidence.extend(join.notes.clone());
    v.evidence.push(format!(
        "derived C² join (λ1, μ1 on R1; λ2, μ2 on R2): {}",
        join.derived_for(&[3])
    ));
    v
}

fn e16() -> Verdict {
    let p = symbols("P", 4);
    let omega = Sym::var("omega");
    let printed = vec![
        Printed::new(0, vec![p[3].clone()]),
        Printed::new(1, vec![p[3].clone(), (p[3].clone() - &p[2]) / &omega]),
    ];
    let mut join = eh_join(JoinKind::G1, false, printed);
    join.factors = omega_factors();
    join.notes
        .push("printed orientation R1'(1) = ω R2'(0), ω > 0: the judge's factor α = 1/ω".into());
    audit(&join)
}

/// Whatever the unreadable relation between |P1Q2| and |P2Q1| is, a
/// configuration with `Q2 − P1 = Q1 − P2` (equal and parallel segments)
/// satisfies every reflexive relation; the printed G⁰/G¹ conditions then
/// leave a gap at the join.
fn e17() -> Verdict {
    let mut join = eh_join(JoinKind::G2, false, Vec::new());
    join.factors = omega_factors();
    let (p, q) = (symbols("P", 4), symbols("Q", 4));
    let (r1, r2) = (
        eh_end(&p, &Sym::var("lambda1"), &Sym::var("mu1"), End::End),
        eh_end(&q, &Sym::var("lambda2"), &Sym::var("mu2"), End::Start),
    );
    let omega = Sym::var("omega");
    let n = Sym::int;
    let pts: Vec<(&str, Sym)> = vec![
        ("P0", n(0)),
        ("P1", n(1)),
        ("P2", n(2)),
        ("P3", n(3)),
        ("omega", n(1)),
        ("Q0", n(3)),
        ("Q1", n(4)),
        ("Q2", n(3)),
        ("Q3", n(0)),
        ("lambda1", n(0)),
        ("mu1", n(0)),
        ("lambda2", n(0)),
        ("mu2", n(0)),
    ];
    let at = |e: &Sym| {
        pts.iter()
            .fold(e.clone(), |acc, (name, v)| acc.subs(name, v))
    };
    let printed_hold = [
        ("Q0 − P3", q[0].clone() - &p[3]),
        (
            "P3 − P2 − ω(Q1 − Q0)",
            p[3].clone() - &p[2] - &(omega.clone() * &(q[1].clone() - &q[0])),
        ),
        (
            "(Q2 − P1) − (Q1 − P2)",
            q[2].clone() - &p[1] - &(q[1].clone() - &p[2]),
        ),
    ];
    let all_zero = printed_hold.iter().all(|(_, e)| at(e).is_zero());
    let gap = at(&(r2[0].clone() - &r1[0]));
    let evidence = EvidenceList::from(vec![
        Evidence::note(join.notes[0].clone()),
        "the relation between |P1Q2| and |P2Q1| is unreadable (\"|P1Q2| □ |P2Q1|\"); the counterexample below has Q2 − P1 = Q1 − P2, so it satisfies every reflexive relation between the two segments (equal length, parallel, ≤, ≥)".into(),
        Evidence::note(format!(
            "one coordinate, λ1 = μ1 = λ2 = μ2 = 0, ω = 1: P = (0, 1, 2, 3), Q = (3, 4, 3, 0); printed conditions satisfied exactly: {all_zero}"
        )),
        Evidence::note(format!(
            "R2(0) − R1(1) = {gap} (exact): the curves do not even meet (G⁰ fails)"
        ))
        .witnessed(Some(Witness {
            point: pts
                .iter()
                .map(|(name, v)| Assignment::exact(name, v))
                .collect(),
            note: Some("one coordinate; the printed conditions hold exactly there".into()),
            values: vec![
                Value::new("R1(1)", Expr::new(&at(&r1[0]))).of(&r1[0]),
                Value::new("R2(0)", Expr::new(&at(&r2[0]))).of(&r2[0]),
            ],
            exact: true,
            stated: None,
        })),
    ]);
    let status = if all_zero && !gap.is_zero() {
        Status::Fails
    } else {
        Status::NotCheckable
    };
    Verdict::new(status, IDENTITY, evidence).with_correction(format!(
        "derived G² (R1' = ωR2', R1'' = ω²R2'' + βR2' at the join): {}",
        join.derived_for(&[3])
    ))
}
