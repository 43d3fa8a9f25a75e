//! Ring axioms hold exactly, and evaluation at rational points of the unit
//! circle is a ring homomorphism.

use proptest::prelude::*;
use rug::Rational;
use trig_symbolic::{Sym, SymError};

const VARS: [&str; 3] = ["m", "s", "c"];

/// A small polynomial in m, s, c: up to 4 terms, exponents ≤ 2,
/// coefficients n/d with |n| ≤ 4, 1 ≤ d ≤ 3.
fn poly() -> impl Strategy<Value = Sym> {
    prop::collection::vec(
        ((-4i64..=4, 1i64..=3), [0u32..=2, 0u32..=2, 0u32..=2]),
        1..=4,
    )
    .prop_map(|terms| {
        terms.into_iter().fold(Sym::int(0), |acc, ((n, d), exps)| {
            let mut t = Sym::rational(Rational::from((n, d)));
            for (name, e) in VARS.iter().zip(exps) {
                for _ in 0..e {
                    t = t * &Sym::var(name);
                }
            }
            acc + &t
        })
    })
}

/// A polynomial or a quotient of two polynomials.
fn element() -> impl Strategy<Value = Sym> {
    (poly(), poly(), any::<bool>()).prop_map(
        |(a, b, quotient)| {
            if quotient && !b.is_zero() { a / &b } else { a }
        },
    )
}

/// `m = q`, `(s, c) = (2k/(1+k²), (1−k²)/(1+k²))`.
fn point() -> impl Strategy<Value = (Rational, Rational, Rational)> {
    ((-9i64..=9, 1i64..=5), (-9i64..=9, 1i64..=5)).prop_map(|((a, b), (p, q))| {
        let k = Rational::from((p, q));
        let k2 = Rational::from(&k * &k);
        let den = Rational::from(1) + &k2;
        let s = 2 * k / &den;
        let c = (Rational::from(1) - k2) / &den;
        (Rational::from((a, b)), s, c)
    })
}

fn at(x: &Sym, (m, s, c): &(Rational, Rational, Rational)) -> Result<Rational, SymError> {
    x.eval_rational(&|n| match n {
        "m" => Some(m.clone()),
        "s" => Some(s.clone()),
        "c" => Some(c.clone()),
        _ => None,
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn ring_axioms(a in element(), b in element(), c in element()) {
        prop_assert!((a.clone() + &b).equals(&(b.clone() + &a)));
        prop_assert!((a.clone() * &b).equals(&(b.clone() * &a)));
        prop_assert!(((a.clone() + &b) + &c).equals(&(a.clone() + &(b.clone() + &c))));
        prop_assert!((a.clone() * &(b.clone() + &c)).equals(&(a.clone() * &b + &(a.clone() * &c))));
        prop_assert!((a.clone() - &a).is_zero());
        if !b.is_zero() {
            prop_assert!(((a.clone() / &b) * &b).equals(&a));
            prop_assert!(((a.clone() * &b) / &b).equals(&a));
        }
    }

    #[test]
    fn evaluation_is_a_homomorphism(a in element(), b in element(), p in point()) {
        if let (Ok(x), Ok(y)) = (at(&a, &p), at(&b, &p)) {
            prop_assert_eq!(at(&(a.clone() + &b), &p), Ok(Rational::from(&x + &y)));
            prop_assert_eq!(at(&(a.clone() - &b), &p), Ok(Rational::from(&x - &y)));
            prop_assert_eq!(at(&(a.clone() * &b), &p), Ok(Rational::from(&x * &y)));
            if y != 0 {
                prop_assert_eq!(at(&(a.clone() / &b), &p), Ok(x / y));
            }
        }
    }

    #[test]
    fn angle_derivative_is_a_derivation(a in poly(), b in element()) {
        let lhs = (a.clone() * &b).d_angle();
        let rhs = a.d_angle() * &b + &(a.clone() * &b.d_angle());
        prop_assert!(lhs.equals(&rhs));
    }
}
