//! Independent re-checks of the join solver in 256-bit MPFR: two segments
//! built with the derived formulas (random parameters, random first-segment
//! points) join with the claimed continuity when both are differentiated with
//! MPFR jets — not with the symbolic ring the formulas came from; a failing
//! printed formula (thesis (4.7)) leaves exactly the residual the audit
//! reports.

use proptest::prelude::*;
use rug::{Float, Rational};
use trig_core::{Family, Mpfr, Ring};
use trig_deriv::{End, JoinKind, JoinSetup, Wrt, curve_endpoint_derivatives, solve_join};
use trig_symbolic::Sym;

const PREC: u32 = 256;

fn mpfr(q: &Rational) -> Mpfr {
    Mpfr::from_rational(PREC, q)
}

/// Families with formulas, each with a parameter value inside its range.
fn families() -> Vec<(Family, Vec<Rational>)> {
    let q = |a: i64, b: i64| Rational::from((a, b));
    vec![
        (Family::ThesisCubic, vec![q(1, 3)]),
        (Family::Han, vec![q(-1, 2)]),
        (Family::MajeedQayyum, vec![q(3, 2)]),
        (Family::Usman, vec![q(1, 2)]),
        (Family::Seed002Quartic, vec![]),
        (Family::Eh, vec![q(1, 2), q(-1, 3)]),
        (Family::Bernstein3, vec![]),
        (Family::BSpline3, vec![]),
    ]
}

/// Orders 0…3 of one segment's curve at `end`, in MPFR jets.
fn jet_derivatives(
    family: Family,
    params: &[Mpfr],
    points: &[Mpfr],
    end: End,
    wrt: Wrt,
    h: &Mpfr,
) -> Vec<Mpfr> {
    curve_endpoint_derivatives::<Mpfr, 4>(family, params, points, None, end, wrt, h)
}

fn close(a: &Mpfr, b: &Mpfr) -> bool {
    let scale =
        a.0.clone()
            .abs()
            .max(&b.0.clone().abs())
            .max(&Float::with_val(PREC, 1));
    let diff = Float::with_val(PREC, &a.0 - &b.0).abs();
    diff <= scale * Float::with_val(PREC, Float::i_exp(1, -200))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn derived_joins_hold_in_mpfr_jets(
        family_index in 0usize..8,
        kind_index in 0usize..6,
        wrt_index in 0usize..3,
        coords in proptest::collection::vec(-50i64..50, 8),
        alpha in 1i64..20,
        beta in -20i64..20,
        h in (1i64..9, 1i64..9),
    ) {
        let (family, params) = families()[family_index].clone();
        let kind = JoinKind::ALL[kind_index];
        let wrt = [Wrt::Angle, Wrt::U, Wrt::X][wrt_index];
        let n = family.info().functions.len();
        // the second segment may take a different parameter: scale it by 1/2
        let second_params: Vec<Rational> = params.iter().map(|p| p.clone() / 2).collect();
        let sym = |q: &Rational| Sym::rational(q.clone());
        let (sp1, sp2): (Vec<Sym>, Vec<Sym>) = (params.iter().map(sym).collect(), second_params.iter().map(sym).collect());
        let first: Vec<Sym> = (0..n).map(|i| Sym::int(coords[i % 8] + i as i64)).collect();
        let second: Vec<Sym> = (0..n).map(|i| Sym::var(&format!("Q{i}"))).collect();
        let (h1, h2) = (Rational::from(h.0), Rational::from(h.1));
        let setup = JoinSetup {
            basis: family,
            first_params: &sp1,
            second_params: &sp2,
            wrt,
            h: (sym(&h1), sym(&h2)),
            factors: trig_deriv::default_factors(),
        };
        let Ok(join) = solve_join(&setup, kind, &first, &second) else {
            // inconsistent (e.g. C³ of the thesis basis with different m): the
            // solver said so; nothing to re-check
            return Ok(());
        };
        // free points: fixed numbers; forced points: the derived formulas
        let (a, b) = (Rational::from(alpha), Rational::from(beta));
        let assign = |name: &str| -> Option<Rational> {
            match name {
                "alpha" => Some(a.clone()),
                "beta" => Some(b.clone()),
                "pi" => None,
                _ => name.strip_prefix('Q').and_then(|i| i.parse::<i64>().ok()).map(|i| Rational::from(7 * i - 3)),
            }
        };
        let pi = mpfr(&Rational::from(1)).pi();
        let like = mpfr(&Rational::from(0));
        let to_mpfr = |e: &Sym| -> Mpfr {
            e.eval(&like, &|name| if name == "pi" { Some(pi.clone()) } else { assign(name).map(|q| mpfr(&q)) })
                .expect("every symbol bound, no zero denominator inside the ranges")
        };
        let q_points: Vec<Mpfr> = join.second_points(&second).iter().map(to_mpfr).collect();
        let p_points: Vec<Mpfr> = first.iter().map(to_mpfr).collect();
        let mp = |v: &[Rational]| v.iter().map(mpfr).collect::<Vec<_>>();
        let d1 = jet_derivatives(family, &mp(&params), &p_points, End::End, wrt, &mpfr(&h1));
        let d2 = jet_derivatives(family, &mp(&second_params), &q_points, End::Start, wrt, &mpfr(&h2));
        let (am, bm) = (mpfr(&a), mpfr(&b));
        for j in 0..=kind.order() {
            let target = match (kind, j) {
                (JoinKind::C(_), _) | (_, 0) => d1[j].clone(),
                (_, 1) => am.clone() * &d1[1],
                _ => am.clone() * &am * &d1[2] + &(bm.clone() * &d1[1]),
            };
            prop_assert!(close(&d2[j], &target), "{family:?} {kind} {wrt} order {j}: {} vs {}", d2[j], target);
        }
    }
}

/// The printed (4.7) leaves, at numbers, exactly the residual the audit
/// reports symbolically: `Q₂'(0) − Q₁'(1) = −2(m₁ + 2)·P₃` in the angle θ.
#[test]
fn printed_c1_formula_mismatch_equals_the_reported_residual() {
    let q = |a: i64, b: i64| Rational::from((a, b));
    let (m1, m2) = (q(1, 3), q(-1, 2));
    let p: Vec<Rational> = [3, -1, 4, 2].iter().map(|&x| q(x, 1)).collect();
    // (4.7) as printed: P5 = [(m2+2)P3 − (m1+2)P3 − (m2+2)P2]/(m1+2)
    let p5 = ((m2.clone() + 2) * &p[3] - (m1.clone() + 2) * &p[3] - (m2.clone() + 2) * &p[2])
        / (m1.clone() + 2);
    let second = [p[3].clone(), p5, q(5, 1), q(6, 1)];
    let mp = |v: &[Rational]| v.iter().map(mpfr).collect::<Vec<_>>();
    let one = mpfr(&q(1, 1));
    let d1 = jet_derivatives(
        Family::ThesisCubic,
        &mp(&[m2]),
        &mp(&p),
        End::End,
        Wrt::Angle,
        &one,
    );
    let d2 = jet_derivatives(
        Family::ThesisCubic,
        &mp(std::slice::from_ref(&m1)),
        &mp(&second),
        End::Start,
        Wrt::Angle,
        &one,
    );
    let mismatch = d2[1].clone() - &d1[1];
    let reported: Rational = -(m1 + 2u32) * 2u32 * &p[3];
    let reported = mpfr(&reported);
    assert!(close(&mismatch, &reported), "{mismatch} vs {reported}");
    assert!(!close(&mismatch, &mpfr(&q(0, 1))));
}
