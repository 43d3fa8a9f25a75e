//! Proved decimal digits of an [`Interval`].
//!
//! A digit is printed only when it is proved. For an enclosure `[lo, hi]`
//! of an exact value `x`, write `Rₙ(y)` for `y` rounded to nearest at `n`
//! significant decimal digits. `Rₙ` is monotone, so `Rₙ(lo) = Rₙ(hi)`
//! implies `Rₙ(x) = Rₙ(lo)`: the printed `n` digits are the correctly
//! rounded value of `x`. [`Interval::decimal`] prints the largest such `n`
//! (at most a requested maximum). An enclosure that contains zero has no
//! significant digit; it prints as `0 ± b` with `|x| ≤ b`. One that has
//! neither prints as the enclosure `[lo, hi]`, rounded outward.

use std::fmt;

use rug::float::Round;
use rug::ops::Pow;
use rug::{Float, Integer, Rational};

use crate::interval::{Fault, Interval};

/// What an enclosure proves about the decimal expansion of its value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Decimal {
    /// The value correctly rounded to `digits` significant digits, every one
    /// proved; `exact` when the text is the value itself.
    Digits {
        text: String,
        digits: usize,
        exact: bool,
    },
    /// An enclosure of zero: `|x| ≤ bound` (no significant digit proved).
    Small { bound: String },
    /// No digit proved: `lo ≤ x ≤ hi`, ends rounded outward to 3 digits.
    Range { lo: String, hi: String },
    /// No enclosure (a division by a divisor not proved nonzero).
    Undefined(Fault),
}

impl Decimal {
    /// Number of proved significant digits (`usize::MAX` for an exact value).
    pub fn digits(&self) -> usize {
        match self {
            Decimal::Digits { exact: true, .. } => usize::MAX,
            Decimal::Digits { digits, .. } => *digits,
            _ => 0,
        }
    }
}

impl fmt::Display for Decimal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Decimal::Digits { text, .. } => f.write_str(text),
            Decimal::Small { bound } => write!(f, "0 ± {bound}"),
            Decimal::Range { lo, hi } => write!(f, "[{lo}, {hi}]"),
            Decimal::Undefined(Fault::DivisionByZero) => {
                f.write_str("undefined (division by zero)")
            }
            Decimal::Undefined(Fault::ZeroNotExcluded) => {
                f.write_str("undefined (a denominator is not certified nonzero)")
            }
        }
    }
}

/// Decimal digits a `prec`-bit number carries: `⌈prec·log₁₀2⌉ + 1`.
pub fn max_digits(prec: u32) -> usize {
    (f64::from(prec) * std::f64::consts::LOG10_2).ceil() as usize + 1
}

/// `x` rounded in direction `round` to `digits` significant digits, as text.
fn text(x: &Float, digits: usize, round: Round) -> String {
    x.to_string_radix_round(10, Some(digits.max(1)), round)
}

/// An upper bound of `|q|` with two significant digits (`1.3e-17`).
pub fn bound_text(q: &Rational) -> String {
    let up = Float::with_val_round(64, q.clone().abs(), Round::Up).0;
    text(&up, 2, Round::Up)
}

/// The number of significant digits of the exact decimal expansion of the
/// binary number `x ≠ 0`, when it is at most `max`.
fn exact_digits(x: &Float, max: usize) -> Option<usize> {
    let (mut m, mut exp) = x.to_integer_exp()?;
    m.abs_mut();
    if m == 0 {
        return None;
    }
    let twos = m.find_one(0).unwrap_or(0);
    m >>= twos;
    exp = exp.checked_add(i32::try_from(twos).ok()?)?;
    let budget = max as f64 + 2.0;
    let bits = f64::from(m.significant_bits());
    let n: Integer = if exp >= 0 {
        if (bits + f64::from(exp)) * std::f64::consts::LOG10_2 > budget + 40.0 {
            return None;
        }
        m << exp.unsigned_abs()
    } else {
        let k = exp.unsigned_abs();
        if f64::from(k) * 5f64.log10() > budget {
            return None;
        }
        m * Integer::from(5).pow(k)
    };
    let digits = n.to_string();
    let significant = digits.trim_end_matches('0').len();
    (significant <= max).then_some(significant)
}

impl Interval {
    /// The proved decimal digits, at most `max` of them (see the module docs).
    pub fn decimal(&self, max: usize) -> Decimal {
        let max = max.max(1);
        if let Some(f) = self.fault() {
            return Decimal::Undefined(f);
        }
        let (lo, hi) = (self.lo(), self.hi());
        if !lo.is_finite() || !hi.is_finite() {
            return Decimal::Range {
                lo: text(lo, 3, Round::Down),
                hi: text(hi, 3, Round::Up),
            };
        }
        if self.is_point() {
            if lo.is_zero() {
                return Decimal::Digits {
                    text: "0".into(),
                    digits: 1,
                    exact: true,
                };
            }
            if let Some(n) = exact_digits(lo, max) {
                return Decimal::Digits {
                    text: text(lo, n, Round::Nearest),
                    digits: n,
                    exact: true,
                };
            }
        }
        if self.contains_zero() {
            let bound = self.mag();
            return Decimal::Small {
                bound: text(&bound, 2, Round::Up),
            };
        }
        // At most one digit more than log₁₀(|x|/width) can agree.
        let width = self.width();
        let start = if width.is_zero() {
            max
        } else {
            let ratio = Float::with_val(64, self.mag() / &width).log10();
            let n = ratio.to_f64().floor() + 2.0;
            if n.is_finite() && n >= 1.0 {
                (n as usize).min(max)
            } else {
                1
            }
        };
        for n in (1..=start).rev() {
            let (a, b) = (text(lo, n, Round::Nearest), text(hi, n, Round::Nearest));
            if a == b {
                return Decimal::Digits {
                    text: a,
                    digits: n,
                    exact: false,
                };
            }
        }
        Decimal::Range {
            lo: text(lo, 3, Round::Down),
            hi: text(hi, 3, Round::Up),
        }
    }
}

impl fmt::Display for Interval {
    /// The proved decimal digits (see [`Interval::decimal`]), at most as
    /// many as the precision carries.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.decimal(max_digits(self.prec())).to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    #[test]
    fn exact_points_print_their_exact_expansion() {
        let x = Interval::from_rational(64, &q(1, 4));
        assert_eq!(x.decimal(30).to_string(), "2.5e-1");
        assert_eq!(x.decimal(30).digits(), usize::MAX);
        let one = Interval::from_rational(64, &q(1, 1));
        assert_eq!(one.decimal(30).to_string(), "1");
        let zero = Interval::from_rational(64, &q(0, 1));
        assert_eq!(zero.decimal(30).to_string(), "0");
    }

    #[test]
    fn one_third_prints_only_proved_digits() {
        let x = Interval::from_rational(64, &q(1, 3));
        let d = x.decimal(100);
        let Decimal::Digits { text, digits, .. } = &d else {
            panic!("{d:?}")
        };
        // 64 bits carry about 19 digits; every printed one is a 3
        assert!((17..=20).contains(digits), "{digits}");
        let mantissa = text.split('e').next().expect("mantissa");
        assert!(
            mantissa.trim_start_matches("3.").chars().all(|c| c == '3'),
            "{text}"
        );
        assert_eq!(x.decimal(5).to_string(), "3.3333e-1");
    }

    #[test]
    fn carries_across_a_digit_boundary_are_handled() {
        // [0.12999999, 0.13000001]: 7 digits agree (1.300000e-1), 8 do not
        let x = Interval::from_ends(
            128,
            &Float::with_val(128, 0.12999999),
            &Float::with_val(128, 0.13000001),
        );
        let d = x.decimal(30);
        assert_eq!(d.digits(), 7, "{d:?}");
        assert_eq!(d.to_string(), "1.300000e-1");
    }

    #[test]
    fn zero_enclosures_and_wide_ones_say_what_is_proved() {
        let x = Interval::from_ends(
            64,
            &Float::with_val(64, -1e-20),
            &Float::with_val(64, 3e-21),
        );
        assert_eq!(x.decimal(10).to_string(), "0 ± 1.0e-20");
        let y = Interval::from_ends(64, &Float::with_val(64, 1.2), &Float::with_val(64, 1.8));
        assert_eq!(y.decimal(10).to_string(), "[1.19, 1.81]");
    }

    #[test]
    fn bounds_round_up() {
        assert_eq!(bound_text(&q(-1, 3)), "3.4e-1");
    }
}
