//! Exact rational intervals as a [`Ring`]: the schemes' control points
//! contain `1/π`, so building a spline over [`Interval`] (with `π` in
//! `[PI_LO, PI_HI]`) gives rational enclosures of every control point, which
//! the certified minimum needs. An operation that is undefined on the
//! enclosure (division by an interval containing 0) gives the undefined
//! interval, which propagates and is reported by [`Interval::bounds`].

use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::Rational;
use trig_core::Ring;

/// `π > 3.14159265358979323846264338327` (30 significant digits).
pub fn pi_lo() -> Rational {
    Rational::from_str_radix(
        "314159265358979323846264338327/100000000000000000000000000000",
        10,
    )
    .expect("literal")
}

/// `π < 3.14159265358979323846264338328`.
pub fn pi_hi() -> Rational {
    Rational::from_str_radix(
        "314159265358979323846264338328/100000000000000000000000000000",
        10,
    )
    .expect("literal")
}

/// `[lo, hi]` with rational ends, or undefined.
#[derive(Debug, Clone, PartialEq)]
pub struct Interval(Option<(Rational, Rational)>);

impl Interval {
    /// The point interval `[q, q]`.
    pub fn point(q: Rational) -> Interval {
        Interval(Some((q.clone(), q)))
    }

    /// `[lo, hi]` (ends ordered).
    pub fn new(a: Rational, b: Rational) -> Interval {
        if a <= b {
            Interval(Some((a, b)))
        } else {
            Interval(Some((b, a)))
        }
    }

    /// The ends, or `None` when an operation was undefined.
    pub fn bounds(&self) -> Option<(&Rational, &Rational)> {
        self.0.as_ref().map(|(a, b)| (a, b))
    }

    fn map2(
        &self,
        other: &Interval,
        f: impl Fn(&Rational, &Rational, &Rational, &Rational) -> Interval,
    ) -> Interval {
        match (&self.0, &other.0) {
            (Some((a, b)), Some((c, d))) => f(a, b, c, d),
            _ => Interval(None),
        }
    }

    fn hull(values: [Rational; 4]) -> Interval {
        let lo = values
            .iter()
            .min_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
        let hi = values
            .iter()
            .max_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
        match (lo, hi) {
            (Some(lo), Some(hi)) => Interval(Some((lo.clone(), hi.clone()))),
            _ => Interval(None),
        }
    }

    fn contains_zero(&self) -> bool {
        match &self.0 {
            Some((a, b)) => *a <= 0 && *b >= 0,
            None => true,
        }
    }
}

fn add(x: &Interval, y: &Interval) -> Interval {
    x.map2(y, |a, b, c, d| {
        Interval(Some((a.clone() + c, b.clone() + d)))
    })
}

fn sub(x: &Interval, y: &Interval) -> Interval {
    x.map2(y, |a, b, c, d| {
        Interval(Some((a.clone() - d, b.clone() - c)))
    })
}

fn mul(x: &Interval, y: &Interval) -> Interval {
    x.map2(y, |a, b, c, d| {
        Interval::hull([a.clone() * c, a.clone() * d, b.clone() * c, b.clone() * d])
    })
}

fn div(x: &Interval, y: &Interval) -> Interval {
    if y.contains_zero() {
        return Interval(None);
    }
    x.map2(y, |a, b, c, d| {
        Interval::hull([a.clone() / c, a.clone() / d, b.clone() / c, b.clone() / d])
    })
}

macro_rules! binary_op {
    ($Trait:ident, $method:ident, $f:ident) => {
        impl $Trait<&Interval> for Interval {
            type Output = Interval;
            fn $method(self, rhs: &Interval) -> Interval {
                $f(&self, rhs)
            }
        }
        impl $Trait<Interval> for Interval {
            type Output = Interval;
            fn $method(self, rhs: Interval) -> Interval {
                $f(&self, &rhs)
            }
        }
    };
}

binary_op!(Add, add, add);
binary_op!(Sub, sub, sub);
binary_op!(Mul, mul, mul);
binary_op!(Div, div, div);

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval(self.0.map(|(a, b)| (-b, -a)))
    }
}

impl Ring for Interval {
    fn int(&self, n: i64) -> Interval {
        Interval::point(Rational::from(n))
    }

    fn ratio(&self, num: i64, den: i64) -> Interval {
        Interval::point(Rational::from((num, den)))
    }

    fn rational(&self, q: &Rational) -> Interval {
        Interval::point(q.clone())
    }

    fn pi(&self) -> Interval {
        Interval::new(pi_lo(), pi_hi())
    }

    /// True when 0 is in the enclosure (division by it is undefined).
    fn is_zero(&self) -> bool {
        self.contains_zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pi_is_enclosed_and_operations_enclose() {
        let lo = pi_lo().to_f64();
        assert!(lo <= std::f64::consts::PI && pi_hi().to_f64() >= std::f64::consts::PI);
        let x = Interval::new(Rational::from(-1), Rational::from(2));
        let y = Interval::point(Rational::from(3));
        assert_eq!(
            x.clone() * &y,
            Interval::new(Rational::from(-3), Rational::from(6))
        );
        assert_eq!(
            x.clone() - &x,
            Interval::new(Rational::from(-3), Rational::from(3))
        );
        assert_eq!((y.clone() / &x).bounds(), None);
        assert!(x.is_zero() && !y.is_zero());
        let inv = y.int(1) / &y.pi();
        let (a, b) = inv.bounds().unwrap();
        assert!(a < b && a.to_f64() <= 1.0 / std::f64::consts::PI);
    }
}
