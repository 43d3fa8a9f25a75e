//! The coefficients of a [`crate::Poly`]: rational numbers, stored inline
//! while numerator and denominator fit in a machine word and as GMP
//! rationals beyond.
//!
//! Almost every coefficient the audit meets is a small fraction (binomials,
//! `1/2`, `3/4`, …). A GMP rational costs two heap allocations to create,
//! copy and free; the inline form costs none, and its arithmetic is word
//! arithmetic with a widening to 128 bits, checked: a result that does not
//! fit is formed as a GMP rational, never wrapped.
//!
//! Every value has exactly one form: `Small(n, d)` with `d ≥ 1`,
//! `gcd(|n|, d) = 1` and `n ≠ i64::MIN` (so `−n` fits) whenever the reduced
//! value fits, `Big` otherwise. Equality and hashing are therefore
//! structural, and the order is the order of the rationals.

use std::cmp::Ordering;
use std::fmt;

use rug::{Integer, Rational};

/// A rational number (see the module documentation for its two forms).
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Coef(Form);

#[derive(Clone, PartialEq, Eq, Hash)]
enum Form {
    /// `n/d`: `d ≥ 1`, `gcd(|n|, d) = 1`, `n ≠ i64::MIN`.
    Small(i64, u64),
    /// A value whose reduced numerator or denominator does not fit `Small`.
    Big(Rational),
}

impl Coef {
    /// `0`.
    pub const ZERO: Coef = Coef(Form::Small(0, 1));

    /// `1`.
    pub const ONE: Coef = Coef(Form::Small(1, 1));

    /// The integer `n`.
    pub fn int(n: i64) -> Coef {
        Coef::from_reduced(i128::from(n), 1)
    }

    /// True for `0`.
    pub fn is_zero(&self) -> bool {
        matches!(self.0, Form::Small(0, _))
    }

    /// `−1`, `0` or `1`.
    pub fn signum(&self) -> i32 {
        match &self.0 {
            Form::Small(n, _) => n.signum() as i32,
            Form::Big(q) => q.cmp0() as i32,
        }
    }

    /// True when the value is an integer.
    pub fn is_integer(&self) -> bool {
        match &self.0 {
            Form::Small(_, d) => *d == 1,
            Form::Big(q) => *q.denom() == 1,
        }
    }

    /// The value as a GMP rational.
    pub fn to_rational(&self) -> Rational {
        match &self.0 {
            Form::Small(n, d) => Rational::from((*n, *d)),
            Form::Big(q) => q.clone(),
        }
    }

    /// The numerator (of the reduced fraction).
    pub fn numer(&self) -> Integer {
        match &self.0 {
            Form::Small(n, _) => Integer::from(*n),
            Form::Big(q) => q.numer().clone(),
        }
    }

    /// The denominator (of the reduced fraction, positive).
    pub fn denom(&self) -> Integer {
        match &self.0 {
            Form::Small(_, d) => Integer::from(*d),
            Form::Big(q) => q.denom().clone(),
        }
    }

    /// The most significant bits of the numerator or the denominator.
    pub fn significant_bits(&self) -> u32 {
        match &self.0 {
            Form::Small(n, d) => {
                (u64::BITS - n.unsigned_abs().leading_zeros()).max(u64::BITS - d.leading_zeros())
            }
            Form::Big(q) => q
                .numer()
                .significant_bits()
                .max(q.denom().significant_bits()),
        }
    }

    /// `(n, d)` when the value is stored inline.
    pub(crate) fn small(&self) -> Option<(i64, u64)> {
        match self.0 {
            Form::Small(n, d) => Some((n, d)),
            Form::Big(_) => None,
        }
    }

    /// `n/d` reduced (`d ≠ 0`).
    fn from_parts(n: i128, d: u128) -> Coef {
        debug_assert!(d != 0);
        // in words when both fit (the usual case), else through GMP
        let (Ok(m), Ok(d)) = (u64::try_from(n.unsigned_abs()), u64::try_from(d)) else {
            return Coef::from(Rational::from((Integer::from(n), Integer::from(d))));
        };
        let g = gcd64(m, d);
        let m = i128::from(m / g);
        Coef::from_reduced(if n < 0 { -m } else { m }, u128::from(d / g))
    }

    /// `n/d` already in lowest terms (`d ≠ 0`).
    fn from_reduced(n: i128, d: u128) -> Coef {
        match (i64::try_from(n), u64::try_from(d)) {
            (Ok(n), Ok(d)) if n != i64::MIN => Coef(Form::Small(n, d)),
            _ => Coef(Form::Big(Rational::from((
                Integer::from(n),
                Integer::from(d),
            )))),
        }
    }

    /// `a + b`.
    pub fn add(&self, other: &Coef) -> Coef {
        if let (Form::Small(a, b), Form::Small(c, d)) = (&self.0, &other.0) {
            if *b == 1 && *d == 1 {
                // integers: no gcd
                return Coef::from_reduced(i128::from(*a) + i128::from(*c), 1);
            }
            let (a, b, c, d) = (i128::from(*a), *b, i128::from(*c), *d);
            if b == d {
                // |a + c| < 2⁶⁴
                return Coef::from_parts(a + c, u128::from(b));
            }
            // |a·d|, |c·b| < 2⁶³·2⁶⁴ = 2¹²⁷: each product fits, the sum may not
            if let Some(n) = (a * i128::from(d)).checked_add(c * i128::from(b)) {
                return Coef::from_parts(n, u128::from(b) * u128::from(d));
            }
        }
        Coef::from(self.to_rational() + other.to_rational())
    }

    /// `a − b`.
    pub fn sub(&self, other: &Coef) -> Coef {
        self.add(&other.neg())
    }

    /// `a·b`.
    pub fn mul(&self, other: &Coef) -> Coef {
        if let (Form::Small(a, b), Form::Small(c, d)) = (&self.0, &other.0) {
            if *a == 0 || *c == 0 {
                return Coef::ZERO;
            }
            // cross-cancel first: the product of reduced fractions
            // (a/g₁)(c/g₂) / ((b/g₂)(d/g₁)) is reduced; g₁ divides a ≠ 0 and
            // g₂ divides c ≠ 0, so both fit i64
            let g1 = if *d == 1 {
                1
            } else {
                gcd64(a.unsigned_abs(), *d)
            };
            let g2 = if *b == 1 {
                1
            } else {
                gcd64(c.unsigned_abs(), *b)
            };
            let n = i128::from(a / g1 as i64) * i128::from(c / g2 as i64);
            let den = u128::from(b / g2) * u128::from(d / g1);
            return Coef::from_reduced(n, den);
        }
        Coef::from(self.to_rational() * other.to_rational())
    }

    /// `a/b`, or `None` when `b = 0`.
    pub fn checked_div(&self, other: &Coef) -> Option<Coef> {
        other.recip().map(|r| self.mul(&r))
    }

    /// `1/a`, or `None` when `a = 0`.
    pub fn recip(&self) -> Option<Coef> {
        match &self.0 {
            Form::Small(0, _) => None,
            Form::Small(n, d) => {
                let sign = i128::from(n.signum());
                Some(Coef::from_parts(
                    sign * *d as i128,
                    u128::from(n.unsigned_abs()),
                ))
            }
            Form::Big(q) => Some(Coef::from(q.clone().recip())),
        }
    }

    /// `aⁿ`.
    pub fn pow(&self, n: u32) -> Coef {
        crate::power::by_squaring(self, n, Coef::ONE, Coef::mul)
    }

    /// `−a`.
    pub fn neg(&self) -> Coef {
        match &self.0 {
            // n ≠ i64::MIN, so −n fits
            Form::Small(n, d) => Coef(Form::Small(-n, *d)),
            Form::Big(q) => Coef(Form::Big(-q.clone())),
        }
    }

    /// `|a|`.
    pub fn abs(&self) -> Coef {
        if self.signum() < 0 {
            self.neg()
        } else {
            self.clone()
        }
    }
}

/// `gcd(a, b)` (`gcd(0, b) = b`), binary.
fn gcd64(a: u64, b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    let (mut a, mut b) = (a >> a.trailing_zeros(), b);
    while b != 0 {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
    }
    a << shift
}

/// `q`'s inline form, when it has one.
fn inline(q: &Rational) -> Option<Form> {
    match (q.numer().to_i64(), q.denom().to_u64()) {
        (Some(n), Some(d)) if n != i64::MIN => Some(Form::Small(n, d)),
        _ => None,
    }
}

impl From<Rational> for Coef {
    fn from(q: Rational) -> Coef {
        Coef(inline(&q).unwrap_or(Form::Big(q)))
    }
}

impl From<&Rational> for Coef {
    fn from(q: &Rational) -> Coef {
        Coef(inline(q).unwrap_or_else(|| Form::Big(q.clone())))
    }
}

impl From<&Integer> for Coef {
    fn from(n: &Integer) -> Coef {
        match n.to_i64() {
            Some(n) => Coef::from_reduced(i128::from(n), 1),
            None => Coef(Form::Big(Rational::from(n))),
        }
    }
}

impl Ord for Coef {
    fn cmp(&self, other: &Coef) -> Ordering {
        match (&self.0, &other.0) {
            // a/b against c/d as a·d against c·b: each product < 2¹²⁷
            (Form::Small(a, b), Form::Small(c, d)) => {
                (i128::from(*a) * i128::from(*d)).cmp(&(i128::from(*c) * i128::from(*b)))
            }
            (Form::Big(p), Form::Big(q)) => p.cmp(q),
            _ => self.to_rational().cmp(&other.to_rational()),
        }
    }
}

impl PartialOrd for Coef {
    fn partial_cmp(&self, other: &Coef) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq<i32> for Coef {
    fn eq(&self, other: &i32) -> bool {
        matches!(self.0, Form::Small(n, 1) if n == i64::from(*other))
    }
}

impl PartialOrd<i32> for Coef {
    fn partial_cmp(&self, other: &i32) -> Option<Ordering> {
        Some(match &self.0 {
            Form::Small(n, d) => i128::from(*n).cmp(&(i128::from(*other) * i128::from(*d))),
            Form::Big(q) => q.partial_cmp(other)?,
        })
    }
}

impl fmt::Display for Coef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Form::Small(n, 1) => write!(f, "{n}"),
            Form::Small(n, d) => write!(f, "{n}/{d}"),
            Form::Big(q) => write!(f, "{q}"),
        }
    }
}

impl fmt::Debug for Coef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Numerators and denominators around the edges of the inline form.
    fn edge_i64() -> impl Strategy<Value = i64> {
        prop_oneof![
            -50i64..50,
            any::<i64>(),
            Just(i64::MIN),
            Just(i64::MIN + 1),
            Just(i64::MAX),
            Just(i64::MAX - 1),
            (1u32..63).prop_map(|k| 1i64 << k),
            (1u32..63).prop_map(|k| -(1i64 << k)),
        ]
    }

    fn edge_u64() -> impl Strategy<Value = u64> {
        prop_oneof![
            1u64..50,
            1u64..,
            Just(u64::MAX),
            Just(u64::MAX - 1),
            Just(1u64 << 63),
            (1u32..64).prop_map(|k| 1u64 << k),
        ]
    }

    fn rational() -> impl Strategy<Value = Rational> {
        prop_oneof![
            4 => (edge_i64(), edge_u64()).prop_map(|(n, d)| Rational::from((n, d))),
            1 => (edge_i64(), edge_i64(), edge_u64()).prop_map(|(a, b, d)| {
                Rational::from((Integer::from(a) * b, Integer::from(d)))
            }),
        ]
    }

    /// The one form of a value: inline exactly when it fits.
    fn canonical(c: &Coef) -> bool {
        let q = c.to_rational();
        let fits =
            q.numer().to_i64().is_some_and(|n| n != i64::MIN) && q.denom().to_u64().is_some();
        fits == c.small().is_some()
    }

    proptest! {
        #[test]
        fn agrees_with_gmp(p in rational(), q in rational()) {
            let (a, b) = (Coef::from(&p), Coef::from(&q));
            prop_assert!(canonical(&a) && canonical(&b));
            for (got, want) in [
                (a.add(&b), Rational::from(&p + &q)),
                (a.sub(&b), Rational::from(&p - &q)),
                (a.mul(&b), Rational::from(&p * &q)),
                (a.neg(), Rational::from(-&p)),
                (a.abs(), Rational::from(p.abs_ref())),
            ] {
                prop_assert!(canonical(&got));
                prop_assert_eq!(got.to_rational(), want.clone());
                prop_assert_eq!(got, Coef::from(want));
            }
            for n in [0, 1, 2, 5] {
                prop_assert_eq!(a.pow(n).to_rational(), rug::ops::Pow::pow(p.clone(), n));
            }
            match a.checked_div(&b) {
                None => prop_assert_eq!(q.cmp0(), Ordering::Equal),
                Some(r) => {
                    prop_assert!(canonical(&r));
                    prop_assert_eq!(r.to_rational(), Rational::from(&p / &q));
                }
            }
            prop_assert_eq!(a.cmp(&b), p.cmp(&q));
            prop_assert_eq!(a == b, p == q);
            prop_assert_eq!(a.signum(), p.cmp0() as i32);
            prop_assert_eq!(a.is_integer(), *p.denom() == 1);
            prop_assert_eq!(a.to_string(), p.to_string());
            prop_assert_eq!(
                a.significant_bits(),
                p.numer().significant_bits().max(p.denom().significant_bits())
            );
            for k in [-2, 0, 1, 3] {
                prop_assert_eq!(a.partial_cmp(&k), p.partial_cmp(&k));
                prop_assert_eq!(a == k, p == k);
            }
        }
    }

    #[test]
    fn the_edges_of_the_inline_form() {
        // i64::MIN is kept out of the inline form, so negation never overflows
        let min = Coef::int(i64::MIN);
        assert!(min.small().is_none());
        assert_eq!(min.neg().to_rational(), -Rational::from(i64::MIN));
        let max = Coef::int(i64::MAX);
        assert_eq!(
            max.add(&Coef::ONE).to_rational(),
            Rational::from(i64::MAX) + 1
        );
        // back to inline once the value fits again
        assert_eq!(max.add(&Coef::ONE).sub(&Coef::ONE), max);
        let tiny = Coef::from(Rational::from((1, u64::MAX)));
        assert_eq!(
            tiny.mul(&tiny).to_rational(),
            Rational::from((1, u64::MAX)).square()
        );
        assert_eq!(
            tiny.recip().unwrap().to_rational(),
            Rational::from(u64::MAX)
        );
        assert!(Coef::ZERO.recip().is_none());
    }
}
