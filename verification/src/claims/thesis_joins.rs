//! Seed 001, the thesis: the endpoint lists of Chapter 4 and (4.30), the
//! cylinder of 5.4.3 and the Appendix 1 listing, and the umbrella T26 over
//! the surface joins (the curve and surface join formulas (4.6)–(4.18),
//! (5.13)–(5.47) and the revised range (−2, 1] are data: the thesis's
//! document file).
//!
//! Conventions, as the text states them: the first curve `Q₁` has control
//! points `P₀…P₃`, the second `Q₂` has `P₄…P₇`; with different parameters the
//! text gives `m₁` to `Q₂` and `m₂` to `Q₁`.

use rug::Rational;
use trig_core::Family;
use trig_deriv::{End, Wrt, curve_endpoint_derivatives, endpoint_derivatives};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{identities, symbols};
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
        id: "T26j",
        check: cylinder::t26j,
    },
    Claim {
        id: "T26k",
        check: cylinder::t26k,
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
