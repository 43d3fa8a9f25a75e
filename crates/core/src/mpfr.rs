//! Arbitrary-precision binary floating point (MPFR through `rug`) as a
//! [`Ring`] and [`Real`].
//!
//! An [`Mpfr`] carries its own precision in bits. The result of a binary
//! operation has the larger precision of its operands, and constants built
//! from a value (`x.int(2)`, `x.ratio(1, 2)`, `x.pi()`) take the precision of
//! `x`, so a whole evaluation runs at the precision of its inputs. Every
//! elementary operation is correctly rounded by MPFR.

use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use rug::Float;
use rug::float::Constant;

use crate::scalar::{Real, Ring};

/// Whether GMP and MPFR are the system's libraries (feature `system-gmp`)
/// rather than built from source by `gmp-mpfr-sys`: a build made with the
/// other setting compiles every crate above them again.
pub const SYSTEM_LIBS: bool = cfg!(feature = "system-gmp");

/// An MPFR number with its precision.
#[derive(Clone, Debug, PartialEq)]
pub struct Mpfr(pub Float);

impl Mpfr {
    /// The exact rational `q` rounded to `prec` bits.
    pub fn from_rational(prec: u32, q: &rug::Rational) -> Self {
        Mpfr(Float::with_val(prec, q))
    }

    /// `x` (an f64, exact) at `prec` bits.
    pub fn from_f64(prec: u32, x: f64) -> Self {
        Mpfr(Float::with_val(prec, x))
    }

    /// Precision in bits.
    pub fn prec(&self) -> u32 {
        self.0.prec()
    }

    /// Decimal digits, enough to round-trip at this precision.
    pub fn to_decimal(&self) -> String {
        let digits = (f64::from(self.prec()) * std::f64::consts::LOG10_2).ceil() as usize + 1;
        self.0.to_string_radix(10, Some(digits))
    }
}

impl fmt::Display for Mpfr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_decimal())
    }
}

impl PartialOrd for Mpfr {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.0.partial_cmp(&other.0)
    }
}

/// `a op b` at the larger precision of the operands, correctly rounded.
/// When the left operand is owned and at least as precise, the result is
/// computed in its storage (`a op= b`, the same rounding) instead of a new
/// allocation: formulas written with owned left operands allocate only for
/// their clones.
macro_rules! binary_op {
    ($Trait:ident, $method:ident, $assign:ident) => {
        impl $Trait<&Mpfr> for Mpfr {
            type Output = Mpfr;
            fn $method(mut self, rhs: &Mpfr) -> Mpfr {
                if self.prec() >= rhs.prec() {
                    self.0.$assign(&rhs.0);
                    self
                } else {
                    Mpfr(Float::with_val(rhs.prec(), (&self.0).$method(&rhs.0)))
                }
            }
        }
        impl $Trait<Mpfr> for Mpfr {
            type Output = Mpfr;
            fn $method(self, rhs: Mpfr) -> Mpfr {
                self.$method(&rhs)
            }
        }
    };
}

binary_op!(Add, add, add_assign);
binary_op!(Sub, sub, sub_assign);
binary_op!(Mul, mul, mul_assign);
binary_op!(Div, div, div_assign);

impl Neg for Mpfr {
    type Output = Mpfr;
    fn neg(self) -> Mpfr {
        Mpfr(-self.0)
    }
}

impl Ring for Mpfr {
    fn int(&self, n: i64) -> Self {
        Mpfr(Float::with_val(self.prec(), n))
    }

    fn ratio(&self, num: i64, den: i64) -> Self {
        Mpfr(Float::with_val(
            self.prec(),
            rug::Rational::from((num, den)),
        ))
    }

    fn rational(&self, q: &rug::Rational) -> Self {
        Mpfr(Float::with_val(self.prec(), q))
    }

    fn pi(&self) -> Self {
        Mpfr(Float::with_val(self.prec(), Constant::Pi))
    }

    fn is_zero(&self) -> bool {
        self.0.is_zero()
    }

    fn try_sin_cos(&self) -> Option<(Self, Self)> {
        Some(Real::sin_cos(self))
    }

    fn try_exp(&self) -> Option<Self> {
        Some(Real::exp(self))
    }

    fn try_sqrt(&self) -> Option<Self> {
        (!self.0.is_sign_negative() || self.0.is_zero()).then(|| Mpfr(self.0.clone().sqrt()))
    }
}

impl Real for Mpfr {
    fn sin_cos(&self) -> (Self, Self) {
        let prec = self.prec();
        let (s, c) = self.0.clone().sin_cos(Float::new(prec));
        (Mpfr(s), Mpfr(c))
    }

    fn exp(&self) -> Self {
        Mpfr(self.0.clone().exp())
    }

    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }

    fn is_finite(&self) -> bool {
        self.0.is_finite()
    }

    fn to_rational(&self) -> Option<rug::Rational> {
        self.0.to_rational()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_take_the_precision_of_the_value() {
        let x = Mpfr::from_f64(256, 0.5);
        assert_eq!(x.int(2).prec(), 256);
        assert_eq!(x.pi().prec(), 256);
        let third = x.ratio(1, 3);
        // 1/3 is built exactly then rounded once: 3·(1/3) − 1 is a single ulp at most.
        let err = (third * &x.int(3) - &x.int(1)).to_f64().abs();
        assert!(err < 1e-75, "{err}");
    }

    #[test]
    fn operations_round_once_at_the_larger_precision() {
        let third = |prec| Mpfr::from_rational(prec, &rug::Rational::from((1, 3)));
        let (a, b) = (third(64), third(256));
        for (got, want) in [
            (a.clone() * &b, Float::with_val(256, &a.0 * &b.0)),
            (b.clone() * &a, Float::with_val(256, &b.0 * &a.0)),
            (b.clone() - &a, Float::with_val(256, &b.0 - &a.0)),
            (a.clone() / &b, Float::with_val(256, &a.0 / &b.0)),
            (b.clone() + &b, Float::with_val(256, &b.0 + &b.0)),
        ] {
            assert_eq!(got.prec(), 256);
            assert_eq!(got.0, want);
        }
    }

    #[test]
    fn sin_cos_at_256_bits_satisfy_pythagoras_to_256_bits() {
        let x = Mpfr::from_rational(256, &rug::Rational::from((7, 10)));
        let (s, c) = x.sin_cos();
        let one = s.square() + &c.square();
        let err = (one - &x.int(1)).to_f64().abs();
        assert!(err < 1e-75, "{err}");
        // and differ from f64 in the 17th digit at most
        assert!((s.to_f64() - 0.7_f64.sin()).abs() < 1e-16);
    }
}
