//! Seed 000: independent 256-bit MPFR re-checks of the audit's
//! counterexamples and of the exact knot jumps.

use proptest::prelude::*;
use rug::Rational;
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_core::{Family, Mpfr, Real, Ring};
use trig_deriv::continuity::{self, Smoothness};
use trig_deriv::family_derivatives;
use trig_judge::numeric::{PREC, differ};
use trig_symbolic::Sym;
use trig_verification::run;

fn mp(q: &Rational) -> Mpfr {
    Mpfr::from_rational(PREC, q)
}

/// Derivatives of orders 0–6 in u (angle derivatives times (π/2)^k) of the
/// family's functions at angle 0, in MPFR.
fn at_start_in_u(family: Family, zeta: &Rational) -> Vec<Vec<Mpfr>> {
    let zero = mp(&Rational::new());
    let half_pi = zero.pi() * &zero.ratio(1, 2);
    family_derivatives::<Mpfr, 7>(family, &zero, &[mp(zeta)])
        .into_iter()
        .map(|row| {
            let mut f = zero.int(1);
            row.into_iter()
                .map(|d| {
                    let v = d * &f;
                    f = f.clone() * &half_pi;
                    v
                })
                .collect()
        })
        .collect()
}

#[test]
fn printed_a3_differs_from_the_fourth_derivative_in_mpfr() {
    // ζ = 2, S = 3, a_j = 1: F^iv(n_j^+) = (π/2)^4 (6S − 6) = 12 (π/2)^4; printed (π/2)^4 (6 + 6S) = 24 (π/2)^4
    let d = at_start_in_u(Family::Seed000Blending, &Rational::from(2));
    let x = d[3][4].clone();
    let q4 = {
        let h = x.pi() * &x.ratio(1, 2);
        h.clone() * &h * &h * &h
    };
    assert!(differ(&x, &(q4.clone() * &x.int(24))));
    assert!(!differ(&x, &(q4 * &x.int(12))));
}

/// An exact witness value as the report prints it (`plain`: rationals and
/// `sqrt(2)`), in MPFR.
fn reported(plain: &str) -> Mpfr {
    let text = plain.replace("sqrt(2)", "r");
    let sym = trig_specfile::Expression::parse(&text, trig_specfile::Grammar::Spec, &["r"])
        .and_then(|e| e.to_sym())
        .expect("an exact value");
    let like = mp(&Rational::new());
    sym.eval(&like, &|n: &str| {
        (n == "r").then(|| Mpfr(mp(&Rational::from(2)).0.sqrt()))
    })
    .expect("a value")
}

#[test]
fn partition_of_unity_counterexample_recomputes_in_mpfr() {
    let m3 = run(Some("000"), Some("M3"))
        .expect("the document files")
        .remove(0)
        .verdict;
    let knots: Vec<Mpfr> = [
        0, 1, 3, 4, 7, 8, 10, 13, 14, 16, 19, 20, 22, 25, 26, 29, 30, 32, 35, 36, 38,
    ]
    .iter()
    .map(|&k| mp(&Rational::from(k)))
    .collect();
    // each non-uniform span's witness: ζ and t exact, Σ F − 1 recomputed
    // from the printed formulas in MPFR
    let witnesses: Vec<_> = m3
        .evidence
        .iter()
        .filter_map(|e| e.witness.as_ref())
        .collect();
    assert_eq!(witnesses.len(), 2, "{:?}", m3.evidence);
    for (w, j) in witnesses.into_iter().zip([8, 10]) {
        let value = |name: &str| {
            w.point
                .iter()
                .find(|a| a.name == name)
                .map(|a| a.value.clone())
                .expect("the witness point")
        };
        assert_eq!((value("ζ").as_str(), value("t").as_str()), ("0", "1/4·π"));
        let f = NonUniform::new(knots.clone(), mp(&Rational::new()));
        let x = mp(&Rational::new());
        let (s, c) = (x.pi() * &x.ratio(1, 4)).sin_cos();
        let seg = f.segment(j, &s, &c).unwrap();
        let total = seg[1..].iter().fold(seg[0].clone(), |a, x| a + x);
        let reported = reported(&w.values[0].value.plain);
        assert!(
            !differ(&total, &reported),
            "span {j}: {total:?} {reported:?}"
        );
        assert!(differ(&total, &s.int(1)));
    }
}

#[test]
fn printed_nonuniform_basis_jumps_in_value_in_mpfr() {
    let knots: Vec<Mpfr> = [
        0, 1, 3, 4, 7, 8, 10, 13, 14, 16, 19, 20, 22, 25, 26, 29, 30, 32, 35, 36, 38,
    ]
    .iter()
    .map(|&k| mp(&Rational::from(k)))
    .collect();
    let f = NonUniform::new(knots, mp(&Rational::from(2)));
    let (zero, one) = (mp(&Rational::new()), mp(&Rational::from(1)));
    // F_8 at n_9: end of piece 0 (t = π/2) versus start of piece 1 (t = 0)
    let left = f.bspline_piece(8, 0, &one, &zero).unwrap();
    let right = f.bspline_piece(8, 1, &zero, &one).unwrap();
    assert!(differ(&left, &right));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// At the first knot of the uniform basis function the exact jumps equal
    /// the MPFR derivatives of F3 = l3/D at t = 0 (the left side is 0), to
    /// 2⁻²⁰⁰ (256-bit evaluation of short expressions); the order-4 jump is
    /// nonzero unless ζ ∈ {0, 1}.
    #[test]
    fn uniform_knot_jumps_agree_with_mpfr(p in -40i64..40, q in 1i64..9) {
        let zeta = Rational::from((p, q));
        let pieces = continuity::uniform_bspline(&Family::Seed000Uniform, &[Sym::rational(zeta.clone())]);
        let knot0 = continuity::continuity(&pieces, true, None).remove(0);
        let mpfr = at_start_in_u(Family::Seed000Uniform, &zeta);
        let like = mp(&Rational::new());
        for (order, jump) in knot0.jumps.iter().enumerate() {
            let exact = jump.eval(&like, &|n: &str| (n == "pi").then(|| like.pi())).unwrap();
            prop_assert!(!differ(&exact, &mpfr[3][order]), "order {}", order);
        }
        let special = zeta == 0 || zeta == 1;
        let want = if special { Smoothness::Exactly(5) } else { Smoothness::Exactly(3) };
        prop_assert_eq!(knot0.smoothness, want);
    }
}

#[test]
fn printed_appendix_d_third_derivative_differs_in_mpfr() {
    // ζ = 2 (S = 3), F_0 = d_j l0 with d_j = 1, S0 = 1, all other coefficients 0:
    // T'''(n_j^+) = l0'''(0) in u; printed (π/2)³(5 + 2S) = 11 (π/2)³,
    // Appendix C's factor (π/2)³(2S − 5) = (π/2)³.
    let d = at_start_in_u(Family::Seed000Blending, &Rational::from(2));
    let x = d[0][3].clone();
    let q3 = {
        let h = x.pi() * &x.ratio(1, 2);
        h.clone() * &h * &h
    };
    assert!(differ(&x, &(q3.clone() * &x.int(11))));
    assert!(!differ(&x, &q3));
    let m9 = run(Some("000"), Some("M9"))
        .expect("the document files")
        .remove(0)
        .verdict;
    assert!(
        m9.evidence
            .iter()
            .any(|e| e.line().starts_with("T_j'''(n_j^+)") && e.contains("fails"))
    );
}
