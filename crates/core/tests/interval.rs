//! The inclusion property of [`Interval`]: every operation, and every family
//! of the catalog evaluated on intervals, encloses the exact value — checked
//! against exact rationals (field operations) and against an independent
//! 1000-bit MPFR evaluation (sin, cos, whole bases) with a margin of
//! 2⁻⁹⁰⁰, far below the widths tested (≥ 2⁻²⁰⁰ at 200 bits).

use proptest::prelude::*;
use rug::ops::Pow;
use rug::{Float, Rational};
use trig_core::certified::{enclose_basis, to_digits};
use trig_core::{Decimal, Family, Interval, Mpfr, Real, Ring};

/// A rational `n/d` with a numerator of up to 60 bits.
fn rational() -> impl Strategy<Value = Rational> {
    (any::<i64>(), 1..=1_000_000_007_i64).prop_map(|(n, d)| Rational::from((n >> 4, d)))
}

fn contains(i: &Interval, q: &Rational) -> bool {
    i.lo().to_rational().is_some_and(|lo| lo <= *q)
        && i.hi().to_rational().is_some_and(|hi| *q <= hi)
}

/// `x` (a 1000-bit reference) lies in `i` up to 2⁻⁹⁰⁰ relative.
fn encloses(i: &Interval, x: &Float) -> bool {
    let margin = Float::with_val(1000, x.clone().abs() + 1u32) >> 900u32;
    *i.lo() <= Float::with_val(1000, x + &margin) && *i.hi() >= Float::with_val(1000, x - &margin)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// `+ − × ÷` at a low precision enclose the exact rational result.
    #[test]
    fn field_operations_enclose_exact_results(a in rational(), b in rational(), bits in 2u32..80) {
        let (x, y) = (Interval::from_rational(bits, &a), Interval::from_rational(bits, &b));
        prop_assert!(contains(&(x.clone() + &y), &Rational::from(&a + &b)));
        prop_assert!(contains(&(x.clone() - &y), &Rational::from(&a - &b)));
        prop_assert!(contains(&(x.clone() * &y), &Rational::from(&a * &b)));
        prop_assert!(contains(&x.square(), &Rational::from(&a * &a)));
        prop_assert!(contains(&x.powi(7), &a.clone().pow(7u32)));
        if b != 0 {
            let q = x / &y;
            // at low precision the divisor may not be proved nonzero
            if q.fault().is_none() {
                prop_assert!(contains(&q, &Rational::from(&a / &b)));
            }
        }
    }

    /// `sin`, `cos` of an interval enclose the values at the exact point.
    #[test]
    fn sin_cos_enclose_the_exact_values(a in rational(), bits in 8u32..200) {
        let (s, c) = Interval::from_rational(bits, &a).sin_cos();
        let x = Float::with_val(1000, &a);
        let (rs, rc) = x.sin_cos(Float::new(1000));
        prop_assert!(encloses(&s, &rs), "sin {a}: [{}, {}] vs {rs}", s.lo(), s.hi());
        prop_assert!(encloses(&c, &rc));
    }

    /// Every family at a random exact point and parameters, evaluated on
    /// 200-bit intervals, encloses the 1000-bit MPFR value.
    #[test]
    fn families_enclose_their_1000_bit_values(x in 0u32..=1000, d in 0u32..=1000, e in 0u32..=1000) {
        for family in Family::ALL.into_iter().filter(Family::has_formulas) {
            let at = Rational::from((x, 1000)) * if family.info().variable == trig_core::Variable::Angle {
                Rational::from((157, 100))
            } else {
                Rational::from(1)
            };
            let p: Vec<Rational> = family.info().params.iter().zip([d, e]).map(|(spec, k)| {
                let lo = spec.range.lo.value().unwrap_or(Rational::from(0));
                let hi = spec.range.hi.value().unwrap_or(Rational::from(100));
                // strictly inside: (lo, hi) by k/1002 + 1/1002 steps
                lo.clone() + (hi - lo) * Rational::from((k + 1, 1002))
            }).collect();
            let enc = enclose_basis(&family, &at, &p, 200);
            let reference = family.eval_at(&Mpfr::from_rational(1000, &at), &p, true).unwrap();
            for (i, r) in enc.iter().zip(&reference) {
                prop_assert!(encloses(i, &r.0), "{family:?} at {at}: [{}, {}] vs {}", i.lo(), i.hi(), r.0);
            }
        }
    }
}

#[test]
fn division_by_a_divisor_containing_zero_is_a_fault_not_a_value() {
    let z = Interval::from_ends(
        64,
        &Float::with_val(64, -1e-30),
        &Float::with_val(64, 1e-30),
    );
    let one = z.int(1);
    let q = one.clone() / &z;
    assert_eq!(q.fault(), Some(trig_core::Fault::ZeroNotExcluded));
    assert!(!q.is_finite());
    let zero = z.int(0);
    assert_eq!(
        (one / &zero).fault(),
        Some(trig_core::Fault::DivisionByZero)
    );
    // faults propagate
    assert!((q + &z).fault().is_some());
}

#[test]
fn comparisons_are_certain_or_absent() {
    let a = Interval::from_rational(64, &Rational::from((1, 3)));
    let b = Interval::from_rational(64, &Rational::from((1, 2)));
    assert!(a < b);
    assert!(b > a);
    assert!(a <= b);
    assert!(
        a.partial_cmp(&a.clone()).is_none(),
        "1/3 is not a 64-bit point"
    );
    let h = b.clone();
    assert!(b == h && b <= h && b >= h);
}

/// `(1 + s + c)^512` at `s = 0`, `c = 1` is exactly 2⁵¹²; its expansion
/// cancels catastrophically, so a fixed precision is not a certificate —
/// raising the precision until the digits are proved is.
#[test]
fn catastrophic_cancellation_is_caught_and_overcome() {
    // Σ_k C(512, k) (−1)^k 3^(512−k) 1^k... evaluated as the expanded
    // alternating sum (1+2)^512 − ... : (3 − 1)^512 = 2^512 by the binomial theorem
    let expanded = |bits: u32| {
        let x = Interval::from_rational(bits, &Rational::from(0));
        let mut sum = x.int(0);
        let mut binom = rug::Integer::from(1);
        for k in 0..=512u32 {
            let term = Rational::from(binom.clone() * rug::Integer::from(3).pow(512 - k));
            let t = x.rational(&term);
            sum = if k % 2 == 0 { sum + &t } else { sum - &t };
            binom = binom * (512 - k) / (k + 1);
        }
        Ok(vec![sum])
    };
    // at 256 bits the enclosure is honest: no digit is proved
    let low = expanded(256).unwrap();
    assert_eq!(low[0].decimal(80).digits(), 0, "{}", low[0].decimal(80));
    let e = to_digits(40, "sum", expanded).unwrap();
    let two_512 = Float::with_val(600, 1u32) << 512u32;
    assert!(encloses(&e.values[0], &two_512));
    let Decimal::Digits { text, .. } = e.values[0].decimal(40) else {
        panic!("digits")
    };
    assert_eq!(text, "1.340780792994259709957402499820584612748e154");
}

#[test]
fn exp_and_sqrt_enclose_the_exact_values() {
    use trig_core::{Interval, Real, Ring};
    let x = Interval::from_rational(64, &rug::Rational::from((1, 3)));
    let e = x.exp();
    let exact = rug::Float::with_val(256, rug::Float::with_val(256, 1) / 3u32).exp();
    assert!(*e.lo() <= exact && exact <= *e.hi());
    let two = x.int(2);
    let r = two.try_sqrt().unwrap();
    let s2 = rug::Float::with_val(256, 2).sqrt();
    assert!(*r.lo() <= s2 && s2 <= *r.hi());
    assert!(x.int(-1).try_sqrt().is_none());
}
