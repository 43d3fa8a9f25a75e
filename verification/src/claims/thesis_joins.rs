//! Seed 001, the thesis: the endpoint lists of Chapter 4 and (4.30), the
//! curve join formulas (4.6)–(4.18), the revised range (−2, 1], and the
//! surface joins of Chapter 5 ((5.13)–(5.47), the cylinder of 5.4.3 and the
//! Appendix 1 listing).
//!
//! Conventions, as the text states them: the first curve `Q₁` has control
//! points `P₀…P₃`, the second `Q₂` has `P₄…P₇`; with different parameters the
//! text gives `m₁` to `Q₂` and `m₂` to `Q₁`. Surfaces `S₁(u, v; m₁, m₂)`,
//! `S₂(u, v; m₁*, m₂*)` join across `v` with, per the theorems, `m₁ = m₁*`;
//! with different parameters the proofs' equations (5.20)–(5.22) give the
//! cross-boundary parameter `m₁*` to `S₂` and `m₂` to `S₁`, as for curves
//! (see [`surface`]); the printed point formulas apply to every column.

use std::sync::OnceLock;

use rug::Rational;
use trig_core::Family;
use trig_deriv::{End, JoinKind, Wrt, curve_endpoint_derivatives, endpoint_derivatives};
use trig_symbolic::Sym;

use crate::claim::{Claim, shared, umbrella};
use trig_judge::exact::{identities, symbols};
use trig_judge::join::{Printed, PrintedJoin, audit};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

mod cylinder;

pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T10",
        check: t10,
    },
    Claim {
        id: "T11",
        check: t11,
    },
    Claim {
        id: "T12",
        check: t12,
    },
    Claim {
        id: "T13",
        check: t13,
    },
    Claim {
        id: "T14",
        check: t14,
    },
    Claim {
        id: "T15",
        check: t15,
    },
    Claim {
        id: "T16",
        check: t16,
    },
    Claim {
        id: "T17",
        check: t17,
    },
    Claim {
        id: "T18",
        check: t18,
    },
    Claim {
        id: "T19",
        check: t19,
    },
    Claim {
        id: "T26a",
        check: t26a,
    },
    Claim {
        id: "T26b",
        check: t26b,
    },
    Claim {
        id: "T26c",
        check: t26c,
    },
    Claim {
        id: "T26d",
        check: t26d,
    },
    Claim {
        id: "T26e",
        check: t26e,
    },
    Claim {
        id: "T26f",
        check: t26f,
    },
    Claim {
        id: "T26g",
        check: t26g,
    },
    Claim {
        id: "T26h",
        check: t26h,
    },
    Claim {
        id: "T26i",
        check: t26i,
    },
    Claim {
        id: "T26j",
        check: cylinder::t26j,
    },
    Claim {
        id: "T26k",
        check: cylinder::t26k,
    },
    Claim {
        id: "T26",
        check: t26,
    },
    Claim {
        id: "T39",
        check: t39,
    },
];

fn v(name: &str) -> Sym {
    Sym::var(name)
}

fn n(k: i64) -> Sym {
    Sym::int(k)
}

/// `a·m + b` for a parameter symbol.
fn lin(a: i64, m: &Sym, b: i64) -> Sym {
    n(a) * m + &n(b)
}

fn p(i: usize) -> Sym {
    v(&format!("P{i}"))
}

/// `P4 = P3` (4.4), printed with every join.
fn c0() -> Printed {
    Printed::new(0, vec![p(3)])
}

/// A thesis curve join: `(m, m)` for Condition 1, the text's `(m2, m1)`
/// (first curve `m2`, second `m1`) for Condition 2.
fn thesis_join(kind: JoinKind, same: bool, printed: Vec<Printed>) -> PrintedJoin<Family> {
    let (first, second) = if same {
        (v("m"), v("m"))
    } else {
        (v("m2"), v("m1"))
    };
    PrintedJoin::new(
        Family::ThesisCubic,
        kind,
        (vec![first], vec![second]),
        (symbols("P", 4), (4..8).map(p).collect()),
        printed,
    )
}

fn c1_same() -> Printed {
    Printed::new(1, vec![n(2) * &p(3), -p(2)])
}

fn c1_different() -> Printed {
    let (m1, m2) = (v("m1"), v("m2"));
    Printed::over(
        1,
        vec![
            lin(1, &m2, 2) * &p(3),
            -(lin(1, &m1, 2) * &p(3)),
            -(lin(1, &m2, 2) * &p(2)),
        ],
        lin(1, &m1, 2),
    )
}

fn c2_same() -> Printed {
    let m = v("m");
    Printed::new(
        2,
        vec![p(1), -(lin(4, &m, 4) * &p(2)), lin(4, &m, 4) * &p(3)],
    )
}

fn c2_different() -> Printed {
    let (m1, m2) = (v("m1"), v("m2"));
    let half = Sym::rational(Rational::from((1, 2)));
    Printed::new(
        2,
        vec![
            p(1),
            half.clone() * &lin(4, &m2, 2) * &p(3),
            -(half.clone() * &lin(4, &m2, 4) * &p(2)),
            -(half.clone() * &lin(4, &m1, 2) * &p(3)),
            -(half * &lin(4, &m1, 4) * &p(5)),
        ],
    )
}

fn g1_same() -> Printed {
    let a = v("alpha");
    Printed::new(1, vec![a.clone() * &p(3), -(a * &p(2)), p(3)])
}

fn g1_different() -> Printed {
    let (m1, m2, a) = (v("m1"), v("m2"), v("alpha"));
    Printed::over(
        1,
        vec![
            a.clone() * &lin(1, &m2, 2) * &p(3),
            -(a * &lin(1, &m2, 2) * &p(2)),
            lin(1, &m1, 2) * &p(3),
        ],
        lin(1, &m1, 2),
    )
}

fn g2_same() -> Printed {
    let (m, a, b) = (v("m"), v("alpha"), v("beta"));
    let a2 = a.clone() * &a;
    let half = Sym::rational(Rational::from((1, 2)));
    let p3 = n(2) * &a2 * &m
        + &a2
        + &(half.clone() * &b * &m)
        + &b
        + &n(1)
        + &(n(2) * &m * &a)
        + &(n(2) * &a);
    let p2 =
        n(2) * &m * &a + &(n(2) * &a) + &(n(2) * &a2 * &m) + &(n(2) * &a2) + &(half * &b * &m) + &b;
    Printed::new(2, vec![p3 * &p(3), -(p2 * &p(2)), a2 * &p(1)])
}

/// The bracket `α²[2P1 − (4m2+4)P2 + (4m2+2)P3 + β(m2+2)P3 − (m2+2)P2]/2`
/// of (4.18), (5.43), (5.47), term by term.
fn g2_bracket() -> Vec<Sym> {
    let (m2, a, b) = (v("m2"), v("alpha"), v("beta"));
    let k = a.clone() * &a * &Sym::rational(Rational::from((1, 2)));
    vec![
        k.clone() * &n(2) * &p(1),
        -(k.clone() * &lin(4, &m2, 4) * &p(2)),
        k.clone() * &lin(4, &m2, 2) * &p(3),
        k.clone() * &b * &lin(1, &m2, 2) * &p(3),
        -(k * &lin(1, &m2, 2) * &p(2)),
    ]
}

/// (4.18) and (5.47): `{(4m1+4)P3 − (4m1+2)P3 + bracket}/2`.
fn g2_different() -> Printed {
    let m1 = v("m1");
    let half = Sym::rational(Rational::from((1, 2)));
    let mut terms = vec![
        half.clone() * &lin(4, &m1, 4) * &p(3),
        -(half * &lin(4, &m1, 2) * &p(3)),
    ];
    terms.extend(g2_bracket());
    Printed::new(2, terms)
}

fn t12() -> Verdict {
    audit(&thesis_join(JoinKind::C(1), true, vec![c0(), c1_same()]))
}

fn t13() -> Verdict {
    audit(&thesis_join(
        JoinKind::C(1),
        false,
        vec![c0(), c1_different()],
    ))
}

fn t14() -> Verdict {
    audit(&thesis_join(JoinKind::C(2), true, vec![c0(), c2_same()]))
}

fn t15() -> Verdict {
    audit(&thesis_join(
        JoinKind::C(2),
        false,
        vec![c0(), c2_different()],
    ))
}

fn t16() -> Verdict {
    audit(&thesis_join(JoinKind::G1, true, vec![c0(), g1_same()]))
}

fn t17() -> Verdict {
    audit(&thesis_join(
        JoinKind::G1,
        false,
        vec![c0(), g1_different()],
    ))
}

fn t18() -> Verdict {
    audit(&thesis_join(JoinKind::G2, true, vec![c0(), g2_same()]))
}

fn t19() -> Verdict {
    audit(&thesis_join(
        JoinKind::G2,
        false,
        vec![c0(), g2_different()],
    ))
}

/// A surface join across `v` (the "u-direction" joins of 5.3.1). Condition
/// 1: every parameter `m`. Condition 2 follows the proofs' own equations
/// (5.20)–(5.22), (5.30)–(5.32), (5.38)–(5.39), (5.45): the cross-boundary
/// factor is `(m₁* + 2)` for `S₂` and `(m₂ + 2)` for `S₁` — `m₁` (= `m₁*`)
/// for the second patch and `m₂` for the first, as in the curve case (4.7),
/// (4.10) — and the `u`-direction basis has `m₁ = m₁*` on both patches. Read
/// literally, (5.11) would give both patches the `v`-parameter `m₂ = m₂*`;
/// the printed formulas, which contain `m₁` and `m₂`, are also decided under
/// that reading, in the angle convention, and the result stated.
fn surface(kind: JoinKind, same: bool, printed: Vec<Printed>) -> Verdict {
    if same {
        let join = thesis_join(kind, true, printed);
        return audit(&join);
    }
    let join = thesis_join(kind, false, printed);
    let mut verdict = audit(&join);
    let literal = PrintedJoin {
        first_params: vec![v("m2")],
        second_params: vec![v("m2")],
        ..join.clone()
    };
    let holds = trig_judge::join::holds_as_printed(&literal);
    verdict.evidence.push(format!(
        "decided with the proofs' convention (5.20)–(5.22): cross-boundary parameter m₁ (= m₁*) for S₂ and m₂ for S₁; read literally, (5.11) gives both patches the cross-boundary parameter m₂ = m₂*, and under that reading the printed formula {} in the angle convention",
        if holds { "holds" } else { "fails" }
    ));
    verdict
}

fn t26a() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::C(1), true, vec![c0(), c1_same()])
    })
}

fn t26b() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::C(1), false, vec![c0(), c1_different()])
    })
}

fn t26c() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::G1, true, vec![c0(), g1_same()])
    })
}

fn t26d() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::G1, false, vec![c0(), g1_different()])
    })
}

fn t26e() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::C(2), true, vec![c0(), c1_same(), c2_same()])
    })
}

fn t26f() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(
            JoinKind::C(2),
            false,
            vec![c0(), c1_different(), c2_different()],
        )
    })
}

fn t26g() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::G2, true, vec![c0(), g1_same(), g2_same()])
    })
}

fn t26h() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(
            JoinKind::G2,
            false,
            vec![c0(), g1_different(), Printed::new(2, g2_bracket())],
        )
    })
}

fn t26i() -> Verdict {
    static VERDICT: OnceLock<Verdict> = OnceLock::new();
    shared(&VERDICT, || {
        surface(JoinKind::G2, false, vec![c0(), g2_different()])
    })
}

fn t26() -> Verdict {
    let parts = [
        ("T26a", t26a as fn() -> Verdict),
        ("T26b", t26b),
        ("T26c", t26c),
        ("T26d", t26d),
        ("T26e", t26e),
        ("T26f", t26f),
        ("T26g", t26g),
        ("T26h", t26h),
        ("T26i", t26i),
        ("T26j", cylinder::t26j),
        ("T26k", cylinder::t26k),
    ];
    umbrella(
        parts
            .iter()
            .map(|(id, check)| (id.to_string(), check()))
            .collect(),
    )
}

/// Printed endpoint derivatives against computed ones, in the angle θ.
fn t10() -> Verdict {
    let mut parts = Vec::new();
    for (label, q1, q2) in [
        ("Condition 1", v("m"), v("m")),
        ("Condition 2", v("m2"), v("m1")),
    ] {
        let at = |params: &Sym, points: Vec<Sym>, end| {
            curve_endpoint_derivatives::<Sym, 3>(
                Family::ThesisCubic,
                std::slice::from_ref(params),
                &points,
                None,
                end,
                Wrt::Angle,
                &Sym::one(),
            )
        };
        let d2 = at(&q2, (4..8).map(p).collect(), End::Start);
        let d1 = at(&q1, symbols("P", 4), End::End);
        let printed = [
            ("Q2(0)", d2[0].clone(), p(4)),
            ("Q1(1)", d1[0].clone(), p(3)),
            (
                "Q2'(0)",
                d2[1].clone(),
                lin(1, &q2, 2) * &p(5) - &(lin(1, &q2, 2) * &p(4)),
            ),
            (
                "Q1'(1)",
                d1[1].clone(),
                lin(1, &q1, 2) * &p(3) - &(lin(1, &q1, 2) * &p(2)),
            ),
            (
                "Q2''(0)",
                d2[2].clone(),
                n(2) * &p(6) - &(lin(4, &q2, 4) * &p(5)) + &(lin(4, &q2, 2) * &p(4)),
            ),
            (
                "Q1''(1)",
                d1[2].clone(),
                n(2) * &p(1) - &(lin(4, &q1, 4) * &p(2)) + &(lin(4, &q1, 2) * &p(3)),
            ),
        ];
        parts.extend(
            printed
                .into_iter()
                .map(|(name, computed, printed)| (format!("{label}, {name}"), computed, printed)),
        );
    }
    identities(parts)
}

/// (4.30): derivatives with respect to u of each function, and the curve.
fn t11() -> Verdict {
    let m = v("m");
    let pi = Sym::pi();
    let pi2 = pi.clone() * &pi;
    let half = Sym::rational(Rational::from((1, 2)));
    let first = -pi.clone() - &(m.clone() * &pi * &half); // −π − mπ/2
    let second_end = pi2.clone() * &half + &(m.clone() * &pi2); // π²/2 + mπ²
    let second_mid = -pi2.clone() - &(m.clone() * &pi2); // −π² − mπ²
    let at = |end| {
        endpoint_derivatives::<Sym, 3>(
            Family::ThesisCubic,
            std::slice::from_ref(&m),
            end,
            Wrt::U,
            &Sym::one(),
        )
    };
    let (d0, d1) = (at(End::Start), at(End::End));
    let zero = Sym::zero();
    let half_pi2 = pi2 * &half;
    let printed_start = [
        [first.clone(), second_end.clone()],
        [-first.clone(), second_mid.clone()],
        [zero.clone(), half_pi2.clone()],
        [zero.clone(), zero.clone()],
    ];
    let printed_end = [
        [zero.clone(), zero.clone()],
        [zero.clone(), half_pi2],
        [first.clone(), second_mid],
        [-first, second_end],
    ];
    let mut parts = Vec::new();
    for (end, d, printed) in [("0", &d0, &printed_start), ("1", &d1, &printed_end)] {
        for k in 0..4 {
            for (order, primes) in [(1, "'"), (2, "''")] {
                parts.push((
                    format!("b{k}{primes}({end})"),
                    d[k][order].clone(),
                    printed[k][order - 1].clone(),
                ));
            }
        }
    }
    // the curve block of (4.30) is Σ V_k b_k^{(j)}: the same printed values
    let vs = symbols("V", 4);
    for (end, d, printed) in [("0", &d0, &printed_start), ("1", &d1, &printed_end)] {
        for (order, primes) in [(1, "'"), (2, "''")] {
            let computed = trig_judge::exact::sum(
                &(0..4)
                    .map(|k| d[k][order].clone() * &vs[k])
                    .collect::<Vec<_>>(),
            );
            let printed_sum = trig_judge::exact::sum(
                &(0..4)
                    .map(|k| printed[k][order - 1].clone() * &vs[k])
                    .collect::<Vec<_>>(),
            );
            parts.push((format!("P{primes}({end})"), computed, printed_sum));
        }
    }
    identities(parts)
}

/// The pivots of every join of the thesis basis vanish exactly at `m = −2`.
fn t39() -> Verdict {
    let mut evidence = Vec::new();
    let mut singular = std::collections::BTreeSet::new();
    for kind in JoinKind::ALL {
        for same in [true, false] {
            let join = thesis_join(kind, same, vec![]);
            let setup = trig_deriv::JoinSetup {
                basis: join.basis,
                first_params: &join.first_params,
                second_params: &join.second_params,
                wrt: Wrt::Angle,
                h: (Sym::one(), Sym::one()),
                factors: trig_deriv::default_factors(),
            };
            match trig_deriv::solve_join(&setup, kind, &join.first, &join.second) {
                Ok(solved) => {
                    let conditions: Vec<String> = solved
                        .forced
                        .iter()
                        .flat_map(|f| trig_deriv::vanishing(&f.pivot))
                        .collect();
                    singular.extend(conditions.iter().cloned());
                    evidence.push(format!(
                        "{kind} ({}): pivots vanish where {}",
                        if same { "same m" } else { "different m" },
                        if conditions.is_empty() {
                            "never".to_string()
                        } else {
                            conditions.join(", ")
                        }
                    ));
                }
                Err(e) => evidence.push(format!("{kind}: {e}")),
            }
        }
    }
    // each shape parameter at −2, described by the same function
    let expected: std::collections::BTreeSet<String> = ["m", "m1", "m2"]
        .iter()
        .flat_map(|name| trig_deriv::vanishing(&(v(name) + &n(2))))
        .collect();
    let only_minus_two = singular.is_subset(&expected);
    let status = if only_minus_two && !singular.is_empty() {
        Status::Holds
    } else {
        Status::Fails
    };
    evidence.push(format!(
        "singular set over all joins: {}",
        singular.into_iter().collect::<Vec<_>>().join(", ")
    ));
    Verdict::new(
        status,
        "pivots of the exact join solution (Gauss–Jordan over Q(m, α, β)) and where they vanish",
        evidence,
    )
}
