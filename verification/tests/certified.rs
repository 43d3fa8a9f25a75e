//! Independent re-checks of the certified-inequality machinery in 256-bit
//! MPFR: points inside a certified region evaluate ≥ 0; every counterexample
//! it reports evaluates < 0 when recomputed from the catalog's numeric path.

use proptest::prelude::*;
use rug::{Float, Rational};
use trig_certify::ParamBox;
use trig_certify::nonneg::{Certificate, certify};
use trig_core::{Family, Mpfr, Real, Ring, Variable};
use trig_judge::exact::basis;

const PREC: u32 = 256;

/// The family's functions at the angle `θ = 2·atan(z)` (or `t = z`), through
/// `Family::eval_at` in MPFR — not through the symbolic ring.
fn numeric_at(family: Family, p: &[Rational], z: &Rational) -> Vec<Mpfr> {
    let z = Float::with_val(PREC, z);
    let theta = Mpfr(Float::with_val(PREC, z.clone().atan() * 2u32));
    let x = match family.info().variable {
        Variable::UnitAngle => theta.clone() / &(theta.pi() * &theta.ratio(1, 2)),
        Variable::Angle => theta,
        Variable::Polynomial => Mpfr(Float::with_val(PREC, &z)),
    };
    family.eval_at(&x, p, true).expect("finite")
}

/// Every counterexample found over a parameter box re-evaluates negative.
fn counterexamples_recheck(family: Family, bx: ParamBox) -> usize {
    let param = family.info().params[0].name;
    let trig = family.info().variable.is_trigonometric();
    let mut found = 0;
    for (i, f) in basis(family).iter().enumerate() {
        if let Certificate::Counterexample { p, z, value } = certify(f, trig, Some(param), &bx) {
            assert!(value < 0);
            let v = &numeric_at(family, std::slice::from_ref(&p), &z)[i];
            assert!(
                v.to_f64() < 0.0,
                "{family:?} f{i} at {param} = {p}, z = {z}: {v}"
            );
            found += 1;
        }
    }
    found
}

#[test]
fn counterexamples_are_negative_in_mpfr() {
    let q = |a: i64, b: i64| Rational::from((a, b));
    // outside the thesis range, inside seed 000's published one, outside Usman's
    let mut n = counterexamples_recheck(Family::ThesisCubic, ParamBox::closed(q(1, 1), q(2, 1)));
    n += counterexamples_recheck(
        Family::ThesisCubic,
        ParamBox::closed(q(-3, 1), q(-2, 1) - q(1, 1000)),
    );
    n += counterexamples_recheck(Family::Seed000Uniform, ParamBox::closed(q(0, 1), q(4, 1)));
    n += counterexamples_recheck(
        Family::Usman,
        ParamBox::closed(q(2, 1) + q(1, 100), q(3, 1)),
    );
    assert!(n >= 4, "the boxes do contain negative values ({n} found)");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The thesis cubic is certified ≥ 0 on m ∈ [−2, 1]; random points there
    /// are ≥ 0 in MPFR up to rounding (values are O(1), 256-bit evaluation:
    /// error far below 2⁻²⁴⁰).
    #[test]
    fn certified_region_is_nonnegative_in_mpfr(m in -2.0..=1.0f64, z in 0.0..=1.0f64) {
        let p = [Rational::from_f64(m).unwrap()];
        for f in basis(Family::ThesisCubic) {
            let cert = certify(&f, true, Some("m"), &ParamBox::closed(Rational::from(-2), Rational::from(1)));
            prop_assert!(matches!(cert, Certificate::NonNegative { .. }), "{:?}", cert);
        }
        for v in numeric_at(Family::ThesisCubic, &p, &Rational::from_f64(z).unwrap()) {
            prop_assert!(v.to_f64() >= -1e-70, "{v}");
        }
    }
}
