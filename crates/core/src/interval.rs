//! Certified arithmetic: closed intervals `[lo, hi]` of MPFR numbers with
//! outward rounding, as a [`Ring`] and [`Real`].
//!
//! An [`Interval`] is a ball in the sense of Arb (Johansson, "Arb: efficient
//! arbitrary-precision midpoint-radius interval arithmetic", IEEE Trans.
//! Comput. 66 (2017)) stored by its ends instead of its midpoint and radius:
//! every operation returns an interval that contains every result of the
//! exact operation on the points of its operands (the *inclusion property*).
//! Lower ends are rounded down, upper ends up (MPFR's directed rounding is
//! exact to the last bit), so the property survives rounding, and the same
//! generic formulas — catalog families, spec bases through
//! [`crate::Basis::eval`], Taylor jets — evaluated on intervals built from
//! exact inputs ([`Interval::from_rational`]) enclose the exact value.
//!
//! * `a/b` where `b ∋ 0` has no enclosure: the result carries a [`Fault`],
//!   [`Fault::DivisionByZero`] when `b = [0, 0]` (the divisor is proved
//!   zero) and [`Fault::ZeroNotExcluded`] otherwise (the divisor could not
//!   be certified nonzero at this precision). Faults propagate through every
//!   later operation.
//! * An end that MPFR cannot represent (beyond its exponent range of
//!   ±2³⁰ bits) becomes `∓∞`: [`Real::is_finite`] is then false and the
//!   evaluation layer reports an overflow, never a division by zero.
//! * `sin`, `cos` use `|sin′|, |cos′| ≤ 1`: the value at the midpoint,
//!   rounded both ways, widened by the radius, clipped to `[−1, 1]`.
//! * Comparisons are certain or absent: `a < b` holds when `a.hi < b.lo`;
//!   overlapping intervals are unordered (`partial_cmp` is `None`).
//!
//! [`Interval::decimal`] prints only digits that are proved: the correctly
//! rounded `n`-digit decimal of the exact value, for the largest `n` at
//! which both ends round to the same decimal (rounding to nearest is
//! monotone, so every point between them does too).

use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::float::{Constant, Round};
use rug::{Float, Rational};

use crate::scalar::{Real, Ring};

/// Why an interval has no enclosure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Fault {
    /// A divisor that could not be certified nonzero at this precision (it
    /// contains zero but is not exactly zero).
    ZeroNotExcluded,
    /// A divisor proved to be exactly zero.
    DivisionByZero,
}

/// A closed interval of MPFR numbers (see the module docs).
#[derive(Clone, Debug)]
pub struct Interval {
    lo: Float,
    hi: Float,
    fault: Option<Fault>,
}

/// `op` rounded in direction `round` at `prec` bits; NaN (from `∞ − ∞`,
/// `0·∞`, `∞/∞` on overflowed ends) becomes the conservative infinity of
/// that direction.
fn directed(prec: u32, round: Round, op: impl FnOnce(Round) -> Float) -> Float {
    let mut x = op(round);
    if x.is_nan() {
        x = match round {
            Round::Down => Float::with_val(prec, rug::float::Special::NegInfinity),
            _ => Float::with_val(prec, rug::float::Special::Infinity),
        };
    }
    x
}

/// `a·b` rounded, with `0·∞ = 0` (an interval end at zero is exact).
fn mul_round(prec: u32, a: &Float, b: &Float, round: Round) -> Float {
    if a.is_zero() || b.is_zero() {
        return Float::new(prec);
    }
    directed(prec, round, |r| Float::with_val_round(prec, a * b, r).0)
}

fn div_round(prec: u32, a: &Float, b: &Float, round: Round) -> Float {
    if a.is_zero() {
        return Float::new(prec);
    }
    directed(prec, round, |r| Float::with_val_round(prec, a / b, r).0)
}

fn min(a: Float, b: Float) -> Float {
    if b < a { b } else { a }
}

fn max(a: Float, b: Float) -> Float {
    if b > a { b } else { a }
}

impl Interval {
    /// The exact rational `q` enclosed at `prec` bits: `[q↓, q↑]` (a single
    /// point when `q` is a `prec`-bit binary number).
    pub fn from_rational(prec: u32, q: &Rational) -> Self {
        Interval {
            lo: Float::with_val_round(prec, q, Round::Down).0,
            hi: Float::with_val_round(prec, q, Round::Up).0,
            fault: None,
        }
    }

    /// The interval `[lo, hi]` (ends in either order) at `prec` bits,
    /// rounded outward.
    pub fn from_ends(prec: u32, lo: &Float, hi: &Float) -> Self {
        let (lo, hi) = if hi < lo { (hi, lo) } else { (lo, hi) };
        Interval {
            lo: Float::with_val_round(prec, lo, Round::Down).0,
            hi: Float::with_val_round(prec, hi, Round::Up).0,
            fault: None,
        }
    }

    fn faulty(prec: u32, fault: Fault) -> Self {
        let nan = Float::with_val(prec, rug::float::Special::Nan);
        Interval {
            lo: nan.clone(),
            hi: nan,
            fault: Some(fault),
        }
    }

    /// Working precision in bits (of the wider end).
    pub fn prec(&self) -> u32 {
        self.lo.prec().max(self.hi.prec())
    }

    /// Lower end.
    pub fn lo(&self) -> &Float {
        &self.lo
    }

    /// Upper end.
    pub fn hi(&self) -> &Float {
        &self.hi
    }

    /// Why there is no enclosure, if there is none.
    pub fn fault(&self) -> Option<Fault> {
        self.fault
    }

    /// True when the interval contains zero (or has no enclosure).
    pub fn contains_zero(&self) -> bool {
        self.fault.is_some() || (self.lo <= 0 && self.hi >= 0)
    }

    /// True when the interval is one exact number.
    pub fn is_point(&self) -> bool {
        self.fault.is_none() && self.lo == self.hi
    }

    /// An upper bound of `hi − lo` (∞ without an enclosure).
    pub fn width(&self) -> Float {
        if self.fault.is_some() {
            return Float::with_val(53, rug::float::Special::Infinity);
        }
        let prec = self.prec();
        directed(prec, Round::Up, |r| {
            Float::with_val_round(prec, &self.hi - &self.lo, r).0
        })
    }

    /// An upper bound of `max |x|` over the interval.
    pub fn mag(&self) -> Float {
        let (a, b) = (self.lo.clone().abs(), self.hi.clone().abs());
        max(a, b)
    }

    /// An upper bound of the distance from `x` to the farthest point of the
    /// interval: `max(|x − lo|, |x − hi|)`, exact inputs, rounded up.
    pub fn distance_bound(&self, x: &Rational) -> Option<Rational> {
        let (lo, hi) = (self.lo.to_rational()?, self.hi.to_rational()?);
        let a = Rational::from(x - &lo).abs();
        let b = Rational::from(x - &hi).abs();
        Some(if a > b { a } else { b })
    }

    fn combine(&self, other: &Self) -> Option<Fault> {
        self.fault.max(other.fault)
    }

    fn with_fault(prec: u32, a: &Self, b: &Self) -> Option<Self> {
        a.combine(b).map(|f| Self::faulty(prec, f))
    }
}

macro_rules! owned_rhs {
    ($Trait:ident, $method:ident) => {
        impl $Trait<Interval> for Interval {
            type Output = Interval;
            fn $method(self, rhs: Interval) -> Interval {
                self.$method(&rhs)
            }
        }
    };
}

impl Add<&Interval> for Interval {
    type Output = Interval;
    fn add(self, rhs: &Interval) -> Interval {
        let prec = self.prec().max(rhs.prec());
        if let Some(f) = Interval::with_fault(prec, &self, rhs) {
            return f;
        }
        Interval {
            lo: directed(prec, Round::Down, |r| {
                Float::with_val_round(prec, &self.lo + &rhs.lo, r).0
            }),
            hi: directed(prec, Round::Up, |r| {
                Float::with_val_round(prec, &self.hi + &rhs.hi, r).0
            }),
            fault: None,
        }
    }
}

impl Sub<&Interval> for Interval {
    type Output = Interval;
    fn sub(self, rhs: &Interval) -> Interval {
        let prec = self.prec().max(rhs.prec());
        if let Some(f) = Interval::with_fault(prec, &self, rhs) {
            return f;
        }
        Interval {
            lo: directed(prec, Round::Down, |r| {
                Float::with_val_round(prec, &self.lo - &rhs.hi, r).0
            }),
            hi: directed(prec, Round::Up, |r| {
                Float::with_val_round(prec, &self.hi - &rhs.lo, r).0
            }),
            fault: None,
        }
    }
}

/// The smallest lower and largest upper rounding of `op` over the four
/// pairs of ends.
fn corners(
    prec: u32,
    a: &Interval,
    b: &Interval,
    op: fn(u32, &Float, &Float, Round) -> Float,
) -> Interval {
    let pairs = [
        (&a.lo, &b.lo),
        (&a.lo, &b.hi),
        (&a.hi, &b.lo),
        (&a.hi, &b.hi),
    ];
    let lo = pairs
        .iter()
        .map(|(x, y)| op(prec, x, y, Round::Down))
        .reduce(min)
        .expect("four corners");
    let hi = pairs
        .iter()
        .map(|(x, y)| op(prec, x, y, Round::Up))
        .reduce(max)
        .expect("four corners");
    Interval {
        lo,
        hi,
        fault: None,
    }
}

impl Mul<&Interval> for Interval {
    type Output = Interval;
    fn mul(self, rhs: &Interval) -> Interval {
        let prec = self.prec().max(rhs.prec());
        if let Some(f) = Interval::with_fault(prec, &self, rhs) {
            return f;
        }
        corners(prec, &self, rhs, mul_round)
    }
}

impl Div<&Interval> for Interval {
    type Output = Interval;
    fn div(self, rhs: &Interval) -> Interval {
        let prec = self.prec().max(rhs.prec());
        if let Some(f) = Interval::with_fault(prec, &self, rhs) {
            return f;
        }
        if rhs.lo.is_zero() && rhs.hi.is_zero() {
            return Interval::faulty(prec, Fault::DivisionByZero);
        }
        if rhs.contains_zero() {
            return Interval::faulty(prec, Fault::ZeroNotExcluded);
        }
        corners(prec, &self, rhs, div_round)
    }
}

owned_rhs!(Add, add);
owned_rhs!(Sub, sub);
owned_rhs!(Mul, mul);
owned_rhs!(Div, div);

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
            fault: self.fault,
        }
    }
}

impl PartialEq for Interval {
    /// Equal when both are the same exact number.
    fn eq(&self, other: &Self) -> bool {
        self.is_point() && other.is_point() && self.lo == other.lo
    }
}

impl PartialOrd for Interval {
    /// Certain order only: `Less` when every point of `self` is below every
    /// point of `other`; `None` when they overlap (unless both are the same
    /// exact number).
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        if self.fault.is_some() || other.fault.is_some() {
            return None;
        }
        if self == other {
            Some(Ordering::Equal)
        } else if self.hi < other.lo {
            Some(Ordering::Less)
        } else if self.lo > other.hi {
            Some(Ordering::Greater)
        } else {
            None
        }
    }

    // `a <= b` is certain when `a.hi ≤ b.lo` (touching ends included).
    fn le(&self, other: &Self) -> bool {
        self.fault.is_none() && other.fault.is_none() && self.hi <= other.lo
    }

    fn ge(&self, other: &Self) -> bool {
        other.le(self)
    }
}

impl Ring for Interval {
    fn int(&self, n: i64) -> Self {
        Interval::from_rational(self.prec(), &Rational::from(n))
    }

    fn ratio(&self, num: i64, den: i64) -> Self {
        Interval::from_rational(self.prec(), &Rational::from((num, den)))
    }

    fn rational(&self, q: &Rational) -> Self {
        Interval::from_rational(self.prec(), q)
    }

    fn pi(&self) -> Self {
        let prec = self.prec();
        Interval {
            lo: Float::with_val_round(prec, Constant::Pi, Round::Down).0,
            hi: Float::with_val_round(prec, Constant::Pi, Round::Up).0,
            fault: None,
        }
    }

    /// Proved zero: the single point 0.
    fn is_zero(&self) -> bool {
        self.fault.is_none() && self.lo.is_zero() && self.hi.is_zero()
    }

    fn try_sin_cos(&self) -> Option<(Self, Self)> {
        Some(Real::sin_cos(self))
    }

    fn try_exp(&self) -> Option<Self> {
        Some(Real::exp(self))
    }

    /// `[√lo↓, √hi↑]` for `lo ≥ 0`.
    fn try_sqrt(&self) -> Option<Self> {
        if self.fault.is_some() || self.lo < 0 {
            return None;
        }
        let prec = self.prec();
        Some(Interval {
            lo: Float::with_val_round(prec, self.lo.sqrt_ref(), Round::Down).0,
            hi: directed(prec, Round::Up, |r| {
                Float::with_val_round(prec, self.hi.sqrt_ref(), r).0
            }),
            fault: None,
        })
    }

    /// `x²` without the dependency of `x·x`: `[0, max(lo², hi²)]` when the
    /// interval contains zero.
    fn square(&self) -> Self {
        if self.fault.is_some() || !self.contains_zero() {
            return self.clone() * self;
        }
        let prec = self.prec();
        let m = self.mag();
        Interval {
            lo: Float::new(prec),
            hi: mul_round(prec, &m, &m, Round::Up),
            fault: None,
        }
    }
}

impl Real for Interval {
    fn sin_cos(&self) -> (Self, Self) {
        let prec = self.prec();
        if self.fault.is_some() {
            return (self.clone(), self.clone());
        }
        let unit =
            || Interval::from_ends(prec, &Float::with_val(prec, -1), &Float::with_val(prec, 1));
        if !self.is_finite() {
            return (unit(), unit());
        }
        // midpoint m (rounded), radius r ≥ max(hi − m, m − lo)
        let m = Float::with_val(prec, &self.lo + &self.hi) / 2u32;
        let r = max(
            directed(prec, Round::Up, |rd| {
                Float::with_val_round(prec, &self.hi - &m, rd).0
            }),
            directed(prec, Round::Up, |rd| {
                Float::with_val_round(prec, &m - &self.lo, rd).0
            }),
        );
        let widen = |down: Float, up: Float| {
            let lo = directed(prec, Round::Down, |rd| {
                Float::with_val_round(prec, &down - &r, rd).0
            });
            let hi = directed(prec, Round::Up, |rd| {
                Float::with_val_round(prec, &up + &r, rd).0
            });
            let one = Float::with_val(prec, 1);
            let minus_one = Float::with_val(prec, -1);
            Interval {
                lo: max(lo, minus_one),
                hi: min(hi, one),
                fault: None,
            }
        };
        let s = widen(
            Float::with_val_round(prec, m.sin_ref(), Round::Down).0,
            Float::with_val_round(prec, m.sin_ref(), Round::Up).0,
        );
        let c = widen(
            Float::with_val_round(prec, m.cos_ref(), Round::Down).0,
            Float::with_val_round(prec, m.cos_ref(), Round::Up).0,
        );
        (s, c)
    }

    /// `exp` is increasing: `[exp(lo)↓, exp(hi)↑]` (an overflowed upper
    /// end is `+∞`, so [`Real::is_finite`] reports it).
    fn exp(&self) -> Self {
        if self.fault.is_some() {
            return self.clone();
        }
        let prec = self.prec();
        Interval {
            lo: directed(prec, Round::Down, |r| {
                Float::with_val_round(prec, self.lo.exp_ref(), r).0
            }),
            hi: directed(prec, Round::Up, |r| {
                Float::with_val_round(prec, self.hi.exp_ref(), r).0
            }),
            fault: None,
        }
    }

    /// The midpoint, rounded to f64 (for display and cross-checks only).
    fn to_f64(&self) -> f64 {
        if self.fault.is_some() {
            return f64::NAN;
        }
        Float::with_val(self.prec() + 1, &self.lo + &self.hi).to_f64() / 2.0
    }

    /// True when the interval is an enclosure with finite ends.
    fn is_finite(&self) -> bool {
        self.fault.is_none() && self.lo.is_finite() && self.hi.is_finite()
    }
}
