//! The domain of the variable and the sets of parameter values, as the
//! certifier sees them: everything is mapped onto unit coordinates.
//!
//! * The angle `θ ∈ [0, π/2]` becomes `z = tan(θ/2) ∈ [0, 1]` by the
//!   Weierstrass substitution `s = 2z/(1+z²)`, `c = (1−z²)/(1+z²)`; a
//!   polynomial variable `t ∈ [0, 1]` is `z` itself. Rational `z` give
//!   rational points `(s, c)` on the circle, so witnesses stay exact.
//! * A parameter set `[a, b]` is `p = a + (b − a)y`; a half-line `[a, ∞)` is
//!   `p = a + y/(1 − y)` (the face `y = 1` is the point at infinity and is
//!   excluded); `(−∞, b]` is `p = b − y/(1 − y)`; the whole line is
//!   `p = (2y − 1)/(y(1 − y))`. Open ends exclude their face.

use std::fmt;

use rug::Rational;
use trig_core::{End, ParamRange};
use trig_symbolic::Sym;

use crate::bernstein::Excluded;

/// One end of a parameter set.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Bound {
    Closed(Rational),
    Open(Rational),
    Infinite,
}

impl Bound {
    /// The finite value, open or closed.
    pub fn value(&self) -> Option<&Rational> {
        match self {
            Bound::Closed(v) | Bound::Open(v) => Some(v),
            Bound::Infinite => None,
        }
    }

    fn is_open(&self) -> bool {
        matches!(self, Bound::Open(_))
    }
}

/// A set of parameter values: an interval, possibly open or unbounded at
/// either end.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParamBox {
    pub lo: Bound,
    pub hi: Bound,
}

impl ParamBox {
    /// A published range as a parameter set of the Bernstein engine
    /// (rational ends). A range in multiples of π has none: the interval
    /// engine takes it ([`crate::branch::Axis::from_range`]); here its
    /// ends are rounded outward to rationals (`π < 3.1416`), for
    /// containment proofs only.
    pub fn from_range(r: &ParamRange) -> ParamBox {
        let pi = if r.pi {
            Rational::from((31_416, 10_000))
        } else {
            Rational::from(1)
        };
        let bound = |e: &End| match e {
            End::Closed(q) => Bound::Closed(Rational::from(q * &pi)),
            End::Open(q) => Bound::Open(Rational::from(q * &pi)),
            End::Unbounded => Bound::Infinite,
        };
        ParamBox {
            lo: bound(&r.lo),
            hi: bound(&r.hi),
        }
    }

    /// `[a, b]`.
    pub fn closed(a: Rational, b: Rational) -> ParamBox {
        ParamBox {
            lo: Bound::Closed(a),
            hi: Bound::Closed(b),
        }
    }

    /// The single value `{p}`.
    pub fn point(p: Rational) -> ParamBox {
        ParamBox::closed(p.clone(), p)
    }

    /// `[a, ∞)`.
    pub fn from_closed(a: Rational) -> ParamBox {
        ParamBox {
            lo: Bound::Closed(a),
            hi: Bound::Infinite,
        }
    }

    /// `(−∞, b]`.
    pub fn up_to(b: Rational) -> ParamBox {
        ParamBox {
            lo: Bound::Infinite,
            hi: Bound::Closed(b),
        }
    }

    /// True when `p` lies in the set.
    pub fn contains(&self, p: &Rational) -> bool {
        let above = match &self.lo {
            Bound::Closed(a) => p >= a,
            Bound::Open(a) => p > a,
            Bound::Infinite => true,
        };
        let below = match &self.hi {
            Bound::Closed(b) => p <= b,
            Bound::Open(b) => p < b,
            Bound::Infinite => true,
        };
        above && below
    }

    /// The parameter as a function of its unit coordinate `y ∈ [0, 1]`.
    pub fn unit_map(&self, y: &Sym) -> Result<Sym, String> {
        let frac = || y.clone() / &(Sym::one() - y);
        Ok(match (self.lo.value(), self.hi.value()) {
            (Some(a), Some(b)) if a > b || (a == b && (self.lo.is_open() || self.hi.is_open())) => {
                return Err(format!("the parameter set {self} is empty"));
            }
            (Some(a), Some(b)) => Sym::rational(a.clone()) + &(Sym::rational(b.clone() - a) * y),
            (Some(a), None) => Sym::rational(a.clone()) + &frac(),
            (None, Some(b)) => Sym::rational(b.clone()) - &frac(),
            (None, None) => (Sym::int(2) * y - &Sym::one()) / &(y.clone() * &(Sym::one() - y)),
        })
    }

    /// The parameter value at unit coordinate `y`; `None` at infinity.
    pub fn at_unit(&self, y: &Rational) -> Option<Rational> {
        let frac = || -> Option<Rational> {
            let d = Rational::from(1) - y;
            (d != 0).then(|| y.clone() / d)
        };
        match (self.lo.value(), self.hi.value()) {
            (Some(a), Some(b)) => Some(a.clone() + (b.clone() - a) * y),
            (Some(a), None) => Some(a.clone() + frac()?),
            (None, Some(b)) => Some(b.clone() - frac()?),
            (None, None) => {
                let d = y.clone() * (Rational::from(1) - y);
                (d != 0).then(|| (Rational::from(2) * y - 1u32) / d)
            }
        }
    }

    /// The faces of the unit coordinate that are not in the set.
    pub fn excluded(&self) -> Excluded {
        match (&self.lo, &self.hi) {
            (lo, Bound::Infinite) if lo.value().is_some() => Excluded {
                lo: lo.is_open(),
                hi: true,
            },
            (Bound::Infinite, hi) if hi.value().is_some() => Excluded {
                lo: hi.is_open(),
                hi: true,
            },
            (Bound::Infinite, Bound::Infinite) => Excluded { lo: true, hi: true },
            (lo, hi) => Excluded {
                lo: lo.is_open(),
                hi: hi.is_open(),
            },
        }
    }

    /// A point of the set (its lower end, or the nearest finite one).
    pub fn some_point(&self) -> Option<Rational> {
        self.at_unit(&Rational::from((1, 2)))
    }
}

impl fmt::Display for ParamBox {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let lo = match &self.lo {
            Bound::Closed(a) => format!("[{a}"),
            Bound::Open(a) => format!("({a}"),
            Bound::Infinite => "(−∞".into(),
        };
        let hi = match &self.hi {
            Bound::Closed(b) => format!("{b}]"),
            Bound::Open(b) => format!("{b})"),
            Bound::Infinite => "∞)".into(),
        };
        write!(f, "{lo}, {hi}")
    }
}

/// The name of the unit coordinate of parameter `k`.
pub fn unit_var(k: usize) -> String {
    format!("__y{k}")
}

/// `2z/(1+z²)`, `(1−z²)/(1+z²)`.
fn weierstrass() -> (Sym, Sym) {
    let z = Sym::var("z");
    let d = Sym::one() + &(z.clone() * &z);
    let s = Sym::int(2) * &z / &d;
    let c = (Sym::one() - &(z.clone() * &z)) / &d;
    (s, c)
}

/// `f` in `z` (and the parameters): Weierstrass for trigonometric
/// functions, `t = z` for polynomial ones.
pub fn in_z(f: &Sym, trigonometric: bool) -> Sym {
    if trigonometric {
        let (s, c) = weierstrass();
        f.subs("s", &s).subs("c", &c)
    } else {
        f.subs("t", &Sym::var("z"))
    }
}

/// `(s, c) = (2z/(1+z²), (1−z²)/(1+z²))` at a rational `z`, printed.
pub fn describe_z(z: &Rational, trigonometric: bool) -> String {
    if !trigonometric {
        return format!("t = {z}");
    }
    let d = Rational::from(1) + z.clone() * z;
    let s = Rational::from(2) * z / d.clone();
    let c = (Rational::from(1) - z.clone() * z) / d;
    format!(
        "z = tan(θ/2) = {z} (θ ≈ {:.6}, s = {s}, c = {c})",
        2.0 * z.to_f64().atan()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_maps_and_their_inverses_agree() {
        let half = Rational::from((1, 2));
        let sets = [
            ParamBox::closed(Rational::from(-2), Rational::from(1)),
            ParamBox::from_closed(Rational::from(3)),
            ParamBox::up_to(Rational::from(3)),
            ParamBox {
                lo: Bound::Infinite,
                hi: Bound::Infinite,
            },
        ];
        for bx in &sets {
            let at = bx.at_unit(&half).unwrap();
            let sym = bx.unit_map(&Sym::rational(half.clone())).unwrap();
            assert_eq!(sym.as_rational().unwrap(), at, "{bx}");
            assert!(bx.contains(&at));
        }
        assert_eq!(sets[1].at_unit(&Rational::from(1)), None);
        assert!(
            ParamBox {
                lo: Bound::Open(Rational::from(1)),
                hi: Bound::Closed(Rational::from(1))
            }
            .unit_map(&Sym::var("y"))
            .is_err()
        );
    }
}
