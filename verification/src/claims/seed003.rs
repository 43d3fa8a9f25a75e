//! Seed 003: the C³ trigonometric B-spline paper whose formulas are missing
//! from our copy.

use trig_core::Family;
use trig_deriv::{Wrt, knot_derivatives};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::IDENTITY;
use trig_verdict::evidence::EvidenceList;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "S1",
        check: s1,
    },
    Claim {
        id: "S2",
        check: s2,
    },
];

fn s1() -> Verdict {
    Verdict::not_checkable(
        "the basis formulas of seed 003 are missing from our copy (catalog entry `seed003` has no formulas); every claim of the paper depends on them. To decide them, type the paper's four segment functions and its claims into a spec file (format in docs/spec.md: variable = \"unit-angle\", parameter alpha with range \"[0.3, 0.5]\", checks unity, nonnegative, symmetry, endpoint-values, continuity with order = 3) and run `trig-audit audit --spec FILE`.",
    )
}

fn s2() -> Verdict {
    let knots = knot_derivatives::<Sym, 5>(Family::BSpline3, &[], Wrt::U, &Sym::one());
    let mut evidence = EvidenceList::default();
    let mut c2 = true;
    let mut c3 = true;
    for k in &knots[1..4] {
        let (l, r) = (
            k.left.as_ref().expect("interior"),
            k.right.as_ref().expect("interior"),
        );
        let jumps: Vec<Sym> = l.iter().zip(r).map(|(a, b)| b.clone() - a).collect();
        c2 &= jumps[..3].iter().all(Sym::is_zero);
        c3 &= jumps[3].is_zero();
        evidence.push(format!(
            "knot n{}: jumps of orders 0–4 (right − left) = {}",
            k.knot,
            jumps
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    let status = if c2 && !c3 {
        Status::Holds
    } else {
        Status::Fails
    };
    evidence.insert(0, "uniform cubic B-spline basis function (catalog `bspline3`), exact one-sided derivatives at its interior knots");
    Verdict::new(status, IDENTITY, evidence)
}
