//! The scalar layers every formula is written against.
//!
//! Two small traits, in the style of `simba`:
//!
//! * [`Ring`]: exact field operations (`+ − × ÷`, negation) on values and on
//!   references, plus constants *obtained from an existing value* (`x.int(2)`,
//!   `x.ratio(1, 2)`, `x.pi()`), so that a backend with a context — MPFR's
//!   precision, the symbolic ring's variable table — builds constants in that
//!   context. f64, [`crate::Mpfr`], Taylor jets and the exact symbolic ring all
//!   implement it; every basis of the catalog is written once against it.
//! * [`Real`]: a [`Ring`] that can also evaluate `sin`, `cos` and be compared,
//!   i.e. a numeric backend (f64, MPFR, jets over them).
//!
//! The traits are `Clone`, not `Copy` (so MPFR fits). The operators are
//! supertraits with an owned left operand and an owned or borrowed right
//! operand (`a.clone() * &b`): those bounds are implied wherever `T: Ring` is
//! written, unlike bounds on `&T`, which Rust would make every generic
//! function repeat.

use std::fmt::Debug;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Operators `+ − × ÷` between owned values and with a borrowed right operand.
pub trait RingOps<Rhs = Self, Output = Self>:
    Add<Rhs, Output = Output>
    + Sub<Rhs, Output = Output>
    + Mul<Rhs, Output = Output>
    + Div<Rhs, Output = Output>
{
}

impl<T, Rhs, Output> RingOps<Rhs, Output> for T where
    T: Add<Rhs, Output = Output>
        + Sub<Rhs, Output = Output>
        + Mul<Rhs, Output = Output>
        + Div<Rhs, Output = Output>
{
}

/// A commutative field (up to rounding) in which the catalog's formulas are
/// evaluated.
///
/// Division by zero is the caller's concern: exact backends report it through
/// their own checked operations, floating backends produce IEEE values that
/// the evaluation layer turns into typed errors.
pub trait Ring:
    Clone + Debug + RingOps + for<'a> RingOps<&'a Self> + Neg<Output = Self> + Sized
{
    /// The integer `n` in the context of `self`.
    fn int(&self, n: i64) -> Self;

    /// The exact rational `num/den` in the context of `self` (`den ≠ 0`).
    fn ratio(&self, num: i64, den: i64) -> Self;

    /// An exact rational in the context of `self`.
    fn rational(&self, q: &rug::Rational) -> Self;

    /// π in the context of `self` (a symbol in the exact ring).
    fn pi(&self) -> Self;

    /// True when `self` is zero: exactly in exact backends, `== 0` in
    /// floating ones, and for a jet when its value (constant term) is zero,
    /// i.e. when dividing by it is undefined.
    fn is_zero(&self) -> bool;

    /// True when `self` is known to be the ring's zero itself, so that
    /// `self·x = 0` for every `x` (an evaluation may then skip a product
    /// with it). Unlike [`Ring::is_zero`], never true for a jet whose
    /// value alone is zero. `false` (not known) unless a backend says so.
    fn is_exact_zero(&self) -> bool {
        false
    }

    /// `(sin self, cos self)` when the backend can form them: numerically
    /// (f64, MPFR, jets over them), or, in the exact ring, as the paired
    /// symbols `sin(p)`, `cos(p)` of a rational multiple of one parameter.
    /// `None` when it cannot (the caller reports it).
    fn try_sin_cos(&self) -> Option<(Self, Self)> {
        None
    }

    /// `exp self` when the backend can form it (as [`Ring::try_sin_cos`]).
    fn try_exp(&self) -> Option<Self> {
        None
    }

    /// `√self` when the backend can form it: numerically for `self ≥ 0`,
    /// exactly in the exact ring for rationals whose square-free part is a
    /// product of the primes 2, 3, 5, 7 (the atoms `sqrt(p)`).
    fn try_sqrt(&self) -> Option<Self> {
        None
    }

    /// `self²`.
    fn square(&self) -> Self {
        self.clone() * self
    }

    /// `selfⁿ` by repeated squaring.
    fn powi(&self, n: u32) -> Self {
        let mut result = self.int(1);
        let mut base = self.clone();
        let mut e = n;
        while e > 0 {
            if e & 1 == 1 {
                result = result * &base;
            }
            e >>= 1;
            if e > 0 {
                base = base.square();
            }
        }
        result
    }
}

/// A numeric [`Ring`]: trigonometric functions, comparison, conversion.
pub trait Real: Ring + PartialOrd {
    /// `(sin self, cos self)`.
    fn sin_cos(&self) -> (Self, Self);

    /// `exp self`.
    fn exp(&self) -> Self;

    /// Nearest f64 (for display and cross-checks only).
    fn to_f64(&self) -> f64;

    /// True when the value is neither NaN nor infinite.
    fn is_finite(&self) -> bool;

    /// The exact value as a rational, for backends whose values are exact
    /// binary numbers (f64, MPFR); `None` otherwise (enclosures, jets).
    fn to_rational(&self) -> Option<rug::Rational> {
        None
    }

    /// `sin self`.
    fn sin(&self) -> Self {
        self.sin_cos().0
    }

    /// `cos self`.
    fn cos(&self) -> Self {
        self.sin_cos().1
    }
}
