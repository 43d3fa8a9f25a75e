//! Property tests of the range engine against closed forms derived by hand.
//!
//! Family: `f(t; p) = 1 + g(p)·t(1 − t)` on `t ∈ [0, 1]` with
//! `g(p) = a p² + b p + c`. Since `t(1 − t) ∈ [0, 1/4]`, `f ≥ 0` for all `t`
//! exactly when `g(p) ≥ −4`: the ends of the maximal interval around a
//! start with `g > −4` are roots of `a p² + b p + c + 4`. Each exact end
//! found is re-verified independently: it is such a root (to 10⁻⁹, far
//! above f64 rounding at these magnitudes), the closed form is ≥ 0 just
//! inside and < 0 just outside (at distance 10⁻⁶, where `|g + 4|` is at
//! least `|g'(e)|·10⁻⁶ − |a|·10⁻¹²`, far above rounding for `g'(e) ≠ 0`).
//! Every printed witness is re-evaluated from the closed form.

use proptest::prelude::*;
use rug::Rational;
use trig_certify::range::{EndPoint, Outside, maximal_range};
use trig_symbolic::Sym;

fn family(a: i64, b: i64, c: i64) -> Sym {
    let (t, p) = (Sym::var("t"), Sym::var("p"));
    let g = Sym::int(a) * &p * &p + &(Sym::int(b) * &p) + &Sym::int(c);
    Sym::one() + &(g * &t * &(Sym::one() - &t))
}

fn g(a: i64, b: i64, c: i64, p: f64) -> f64 {
    a as f64 * p * p + b as f64 * p + c as f64
}

fn check_end(a: i64, b: i64, c: i64, end: &EndPoint, dir: f64) -> Result<(), TestCaseError> {
    match end {
        EndPoint::Exact { value, outside, .. } => {
            let e = value.to_f64();
            let slope = (2.0 * a as f64 * e + b as f64).abs();
            prop_assert!(
                (g(a, b, c, e) + 4.0).abs() < 1e-9 * (1.0 + e * e),
                "not a root: {e}"
            );
            if slope > 1e-3 {
                prop_assert!(g(a, b, c, e - dir * 1e-6) >= -4.0, "inside fails at {e}");
                prop_assert!(g(a, b, c, e + dir * 1e-6) < -4.0, "outside holds at {e}");
            }
            if let Outside::Counterexample(p, t, v) = outside {
                // re-evaluate the witness exactly from the closed form
                let gp = Rational::from(a) * p.clone() * p + Rational::from(b) * p + c;
                let exact = Rational::from(1) + gp * t.clone() * (Rational::from(1) - t);
                prop_assert_eq!(&exact, v);
                prop_assert!(exact < 0);
            }
            Ok(())
        }
        EndPoint::Unbounded => {
            // g ≥ −4 beyond the start in this direction: a ≥ 0 and no root there
            prop_assert!(
                a > 0 || (a == 0 && (b as f64) * dir >= 0.0),
                "unbounded with a={a} b={b}"
            );
            Ok(())
        }
        other => Err(TestCaseError::fail(format!("undecided end {other:?}"))),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn exact_ends_are_the_roots_of_the_closed_form(a in -3i64..=3, b in -6i64..=6, c in -3i64..=3) {
        // start at p = 0 where g = c ≥ −3 > −4
        let r = maximal_range(&[family(a, b, c)], &["f"], false, "p", &Rational::new());
        prop_assert!(r.start_outside.is_none());
        check_end(a, b, c, &r.lo, -1.0)?;
        check_end(a, b, c, &r.hi, 1.0)?;
    }
}

#[test]
fn an_end_a_billion_away_is_found_exactly() {
    // 1 − p·t/10⁹ ≥ 0 on t ∈ [0, 1] ⇔ p ≤ 10⁹
    let f = Sym::one() - &(Sym::var("p") * &Sym::var("t") / &Sym::int(1_000_000_000));
    let r = maximal_range(&[f], &["f"], false, "p", &Rational::new());
    match &r.hi {
        EndPoint::Exact {
            value,
            closed: true,
            ..
        } => {
            assert_eq!(value.rational, Some(Rational::from(1_000_000_000)));
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(r.lo, EndPoint::Unbounded);
}
