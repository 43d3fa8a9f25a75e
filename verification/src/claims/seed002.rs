//! Seed 002 (Dube & Mishra 2017): the quartic trigonometric Bézier basis and
//! the rational curve.

use trig_core::{Family, Ring};
use trig_deriv::{End, Wrt, curve_endpoint_derivatives};
use trig_symbolic::Sym;

use crate::certify::evidence::nonnegative_on;
use crate::certify::nonneg::ParamBox;
use crate::claim::{Claim, Seed};
use crate::exact::{basis, combination, identities, identity, reflect, sum, symbols, symmetry};
use crate::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "D1",
        seed: Seed::S002,
        source: "property (b)",
        statement: "Σ_{i=0}^{5} b_i(t) = 0 (as printed)",
        check: d1,
    },
    Claim {
        id: "D1b",
        seed: Seed::S002,
        source: "property (b), reading",
        statement: "reading of D1: Σ_{i=0}^{5} b_i(t) = 1",
        check: d1b,
    },
    Claim {
        id: "D2",
        seed: Seed::S002,
        source: "property (a)",
        statement: "b_i(t) ≥ 0 on [0, π/2], i = 0…5",
        check: d2,
    },
    Claim {
        id: "D3",
        seed: Seed::S002,
        source: "property (c)",
        statement: "b_i(t) = b_{5−i}(π/2 − t), i = 0, 1, 2",
        check: d3,
    },
    Claim {
        id: "D5",
        seed: Seed::S002,
        source: "Theorem 2 (1)",
        statement: "R(0) = P0, R(π/2) = P5, R'(0) = 4(w1/w0)(P1 − P0), R'(π/2) = 4(w4/w5)(P5 − P4), R''(0) = [(32w1² − 8w0w1)(P0 − P1) − 12w0w2(P0 − P2)]/w0², R''(π/2) = [(32w4² − 8w4w5)(P5 − P4) − 12w3w5(P5 − P3)]/w5²",
        check: d5,
    },
    Claim {
        id: "D9",
        seed: Seed::S002,
        source: "Theorem 2 (2)",
        statement: "R(π/2 − t; P5, P4, P3, P2, P1, P0) = R(t; P0, …, P5) (weights as given)",
        check: d9,
    },
    Claim {
        id: "D9b",
        seed: Seed::S002,
        source: "Theorem 2 (2), reading",
        statement: "reading of D9 with the weights reversed with the points: R(π/2 − t; P5…P0; w5…w0) = R(t; P0…P5; w0…w5)",
        check: d9b,
    },
    Claim {
        id: "D10",
        seed: Seed::S002,
        source: "Theorem 2 (3), garbled print",
        statement: "reading of the garbled print: R(t; P_i + q) = R(t; P_i) + q and R(t; P_i T) = R(t; P_i) T",
        check: d10,
    },
    Claim {
        id: "D12",
        seed: Seed::S002,
        source: "Proposition 1, (5)",
        statement: "Σ_{i=0}^{3} Tb_i(t, α1, α2) = 1",
        check: d12,
    },
];

fn d1() -> Verdict {
    identity(
        "Σ b_i − 0",
        &sum(&basis(Family::Seed002Quartic)),
        &Sym::zero(),
    )
}

fn d1b() -> Verdict {
    identity(
        "Σ b_i − 1",
        &sum(&basis(Family::Seed002Quartic)),
        &Sym::one(),
    )
}

fn d3() -> Verdict {
    symmetry(Family::Seed002Quartic, 0..3)
}

fn d5() -> Verdict {
    let p: Vec<Sym> = symbols("P", 6);
    let w: Vec<Sym> = symbols("w", 6);
    let at = |end| {
        curve_endpoint_derivatives::<Sym, 3>(
            Family::Seed002Quartic,
            &[],
            &p,
            Some(&w),
            end,
            Wrt::Angle,
            &Sym::one(),
        )
    };
    let (r0, r1) = (at(End::Start), at(End::End));
    let n = |k: i64| Sym::int(k);
    let printed_r2_0 = ((n(32) * &w[1].square() - &(n(8) * &w[0] * &w[1]))
        * &(p[0].clone() - &p[1])
        - &(n(12) * &w[0] * &w[2] * &(p[0].clone() - &p[2])))
        / &w[0].square();
    let printed_r2_1 = ((n(32) * &w[4].square() - &(n(8) * &w[4] * &w[5]))
        * &(p[5].clone() - &p[4])
        - &(n(12) * &w[3] * &w[5] * &(p[5].clone() - &p[3])))
        / &w[5].square();
    identities(vec![
        ("R(0) − P0".into(), r0[0].clone(), p[0].clone()),
        ("R(π/2) − P5".into(), r1[0].clone(), p[5].clone()),
        (
            "R'(0) − 4(w1/w0)(P1 − P0)".into(),
            r0[1].clone(),
            n(4) * &w[1] / &w[0] * &(p[1].clone() - &p[0]),
        ),
        (
            "R'(π/2) − 4(w4/w5)(P5 − P4)".into(),
            r1[1].clone(),
            n(4) * &w[4] / &w[5] * &(p[5].clone() - &p[4]),
        ),
        ("R''(0) − printed".into(), r0[2].clone(), printed_r2_0),
        ("R''(π/2) − printed".into(), r1[2].clone(), printed_r2_1),
    ])
}

fn d12() -> Verdict {
    Verdict::not_checkable(
        "the functions Tb_i(t, α1, α2) of (5) are unreadable in our copy (the printed fraction is garbled: \"T_0(tα1,α2) = 1/Σ_{i=0, i=1, i=1, i=0 …}\"), so their sum cannot be formed",
    )
}

fn d2() -> Verdict {
    let zero = rug::Rational::new();
    nonnegative_on(
        Family::Seed002Quartic,
        &basis(Family::Seed002Quartic),
        None,
        &ParamBox::Interval(zero.clone(), zero),
    )
}

/// `Σ w_i b_i P_i / Σ w_i b_i` at the symbolic atoms.
fn rational_curve(points: &[Sym], weights: &[Sym]) -> Sym {
    let b = basis(Family::Seed002Quartic);
    let wb: Vec<Sym> = b
        .iter()
        .zip(weights)
        .map(|(bi, wi)| bi.clone() * wi)
        .collect();
    combination(&wb, points) / &sum(&wb)
}

fn d9_with(reverse_weights: bool) -> Verdict {
    let p: Vec<Sym> = symbols("P", 6);
    let w: Vec<Sym> = symbols("w", 6);
    let rp: Vec<Sym> = p.iter().rev().cloned().collect();
    let rw: Vec<Sym> = if reverse_weights {
        w.iter().rev().cloned().collect()
    } else {
        w.clone()
    };
    identities(vec![(
        "R(π/2 − t; reversed) − R(t)".into(),
        reflect(&rational_curve(&rp, &rw), true),
        rational_curve(&p, &w),
    )])
}

fn d9() -> Verdict {
    d9_with(false)
}

fn d9b() -> Verdict {
    d9_with(true)
}

fn d10() -> Verdict {
    let p: Vec<Sym> = symbols("P", 6);
    let w: Vec<Sym> = symbols("w", 6);
    let (q, k) = (Sym::var("q"), Sym::var("k"));
    let shifted: Vec<Sym> = p.iter().map(|x| x.clone() + &q).collect();
    let scaled: Vec<Sym> = p.iter().map(|x| x.clone() * &k).collect();
    let mut v = identities(vec![
        (
            "R(P_i + q) − (R(P_i) + q)".into(),
            rational_curve(&shifted, &w),
            rational_curve(&p, &w) + &q,
        ),
        (
            "R(k P_i) − k R(P_i) (a linear map acts coordinatewise)".into(),
            rational_curve(&scaled, &w),
            rational_curve(&p, &w) * &k,
        ),
    ]);
    v.evidence.push("the printed equations are unreadable in our copy (\"R_2^π − t, P, …\"); this is the obvious reading".into());
    v
}
