//! Shape parameters, their published ranges, and exact parameter values.

use std::fmt;

use rug::Rational;
use rug::ops::Pow;

use crate::domain::Affine;
use crate::echo::echo;
use crate::error::{CoreError, Result};
use crate::range::{End, ParamRange};

/// One end of a parameter range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// The end is included: `[a` or `b]`.
    Closed(i64, i64),
    /// The end is excluded: `(a` or `b)`.
    Open(i64, i64),
    /// No end: `−∞` or `+∞`.
    Unbounded,
}

impl Bound {
    /// The end as an exact rational, if there is one.
    pub fn value(&self) -> Option<Rational> {
        match *self {
            Bound::Closed(n, d) | Bound::Open(n, d) => Some(Rational::from((n, d))),
            Bound::Unbounded => None,
        }
    }
}

/// A catalog family's published range such as `[−2, 1]` or `(1/2, 2]`,
/// in a form that can be a constant; [`Range::to_param_range`] gives the
/// value every consumer reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Range {
    pub lo: Bound,
    pub hi: Bound,
}

impl Range {
    /// `[lo, hi]`.
    pub const fn closed(lo: (i64, i64), hi: (i64, i64)) -> Self {
        Range {
            lo: Bound::Closed(lo.0, lo.1),
            hi: Bound::Closed(hi.0, hi.1),
        }
    }

    /// Every real number.
    pub const ALL: Range = Range {
        lo: Bound::Unbounded,
        hi: Bound::Unbounded,
    };

    /// True when `x` lies in the range.
    pub fn contains(&self, x: &Rational) -> bool {
        self.to_param_range().contains(x)
    }

    /// The range as a value ([`ParamRange`]): the form every consumer reads.
    pub fn to_param_range(&self) -> ParamRange {
        let end = |b: &Bound| match b {
            Bound::Closed(..) => End::Closed(b.value().expect("closed bound")),
            Bound::Open(..) => End::Open(b.value().expect("open bound")),
            Bound::Unbounded => End::Unbounded,
        };
        ParamRange {
            lo: end(&self.lo),
            hi: end(&self.hi),
            pi: false,
        }
    }
}

impl fmt::Display for Range {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.to_param_range().fmt(f)
    }
}

/// A shape parameter of a family.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamSpec {
    /// ASCII name used on the command line (`m`, `beta`, `lambda`, …).
    pub name: &'static str,
    /// The symbol the source prints (`m`, `β`, `λ`, …).
    pub symbol: &'static str,
    /// The published range.
    pub range: Range,
    /// Where the range is stated.
    pub range_source: &'static str,
}

impl ParamSpec {
    /// The parameter as every described basis states it.
    pub fn parameter(&self) -> Parameter {
        Parameter {
            name: self.name.to_string(),
            symbol: self.symbol.to_string(),
            range: self.range.to_param_range(),
            source: self.range_source.to_string(),
        }
    }
}

/// A shape parameter of a basis (catalog family or spec file).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Parameter {
    /// ASCII name: the symbol in the exact ring, `--param NAME=…`.
    pub name: String,
    /// The symbol the source prints (`m`, `β`, `λ`, …).
    pub symbol: String,
    /// The published range.
    pub range: ParamRange,
    /// Where the range is stated.
    pub source: String,
}

/// Reads `name=value` pairs (a parameter's name or printed symbol; the
/// last pair of a name wins) into exact values in the order of `params`,
/// checking names and, unless `allow_outside`, the published ranges; `id`
/// names the basis in errors.
pub fn read_params(
    id: &str,
    params: &[Parameter],
    pairs: &[(String, String)],
    allow_outside: bool,
) -> Result<Vec<Rational>> {
    for (name, _) in pairs {
        if !params.iter().any(|p| &p.name == name || &p.symbol == name) {
            let expected = if params.is_empty() {
                "none".to_string()
            } else {
                params
                    .iter()
                    .map(|p| p.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            return Err(CoreError::UnknownParameter {
                family: id.into(),
                name: name.clone(),
                expected,
            });
        }
    }
    params
        .iter()
        .map(|spec| {
            let (_, text) = pairs
                .iter()
                .rev()
                .find(|(n, _)| *n == spec.name || *n == spec.symbol)
                .ok_or_else(|| CoreError::MissingParameter {
                    family: id.into(),
                    name: spec.name.clone(),
                })?;
            let value = parse_exact(text)?;
            if !allow_outside && !spec.range.contains(&value) {
                return Err(CoreError::OutOfRange {
                    family: id.into(),
                    name: spec.name.clone(),
                    value: echo(text),
                    range: spec.range.to_string(),
                });
            }
            Ok(value)
        })
        .collect()
}

/// Longest number accepted, in characters (the cost model: exact inputs stay
/// small enough for every later step).
pub const MAX_NUMBER_LEN: usize = 10_000;

/// Reads a number exactly: an integer, a decimal (`0.6` is `3/5`), a
/// fraction (`-1/2`), or a decimal with exponent (`1e-3`, `|exponent| ≤
/// 10,000`), at most [`MAX_NUMBER_LEN`] characters.
pub fn parse_exact(input: &str) -> Result<Rational> {
    if input.len() > MAX_NUMBER_LEN {
        return Err(CoreError::Limit {
            what: format!("number `{}`", echo(input)),
            limit: format!("{MAX_NUMBER_LEN} characters"),
        });
    }
    let malformed = || CoreError::Malformed {
        input: echo(input),
        expected: "a number (integer, decimal such as 0.6, or fraction such as 1/2)".into(),
    };
    let text = input.trim();
    let lower = text.to_ascii_lowercase();
    if lower.contains("nan") || lower.contains("inf") {
        return Err(CoreError::NotFinite {
            what: format!("`{}`", echo(input)),
        });
    }
    if let Some((num, den)) = text.split_once('/') {
        let num: Rational = parse_decimal(num.trim()).ok_or_else(malformed)?;
        let den: Rational = parse_decimal(den.trim()).ok_or_else(malformed)?;
        if den == 0 {
            return Err(CoreError::DivisionByZero {
                quantity: format!("`{}`", echo(input)),
            });
        }
        return Ok(num / den);
    }
    parse_decimal(text).ok_or_else(malformed)
}

/// Reads a point exactly: a number as [`parse_exact`] reads it, or a
/// rational multiple of π — `pi`, `-pi/2`, `pi/4`, `3*pi/8`, `3pi/8`,
/// `0.5*pi` (`π` is accepted for `pi`). The result is `q₀` or `q·π`.
pub fn parse_point(input: &str) -> Result<Affine> {
    let text = input.trim();
    let lower = text.to_ascii_lowercase().replace('π', "pi");
    let Some((left, right)) = lower.split_once("pi") else {
        return parse_exact(input).map(Affine::rational);
    };
    let malformed = || CoreError::Malformed {
        input: echo(input),
        expected: "a number, or a rational multiple of pi such as pi/4, -pi/2 or 3*pi/8".into(),
    };
    let left = left.trim();
    let left = left.strip_suffix('*').map_or(left, str::trim);
    let factor = match left {
        "" | "+" => Rational::from(1),
        "-" => Rational::from(-1),
        number => parse_exact(number).map_err(|_| malformed())?,
    };
    let right = right.trim();
    let divisor = match right.strip_prefix('/') {
        None if right.is_empty() => Rational::from(1),
        None => return Err(malformed()),
        Some(d) if d.contains('/') => return Err(malformed()),
        Some(d) => parse_exact(d).map_err(|_| malformed())?,
    };
    if divisor == 0 {
        return Err(CoreError::DivisionByZero {
            quantity: format!("`{}`", echo(input)),
        });
    }
    Ok(Affine::pi_times(factor / divisor))
}

fn parse_decimal(text: &str) -> Option<Rational> {
    let (mantissa, exponent) = match text.find(['e', 'E']) {
        Some(i) => (&text[..i], text[i + 1..].parse::<i32>().ok()?),
        None => (text, 0),
    };
    let (negative, digits) = match mantissa.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, mantissa.strip_prefix('+').unwrap_or(mantissa)),
    };
    let (int_part, frac_part) = digits.split_once('.').unwrap_or((digits, ""));
    if int_part.is_empty() && frac_part.is_empty() {
        return None;
    }
    if !int_part
        .chars()
        .chain(frac_part.chars())
        .all(|c| c.is_ascii_digit())
    {
        return None;
    }
    if exponent.unsigned_abs() > 10_000 {
        return None;
    }
    let all_digits = format!("{int_part}{frac_part}");
    let int = rug::Integer::from_str_radix(&all_digits, 10).ok()?;
    let scale = exponent - i32::try_from(frac_part.len()).ok()?;
    let ten = Rational::from(10);
    let factor = if scale >= 0 {
        ten.pow(scale as u32)
    } else {
        Rational::from(1) / ten.pow((-scale) as u32)
    };
    let value = Rational::from(int) * factor;
    Some(if negative { -value } else { value })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_are_rationals_or_rational_multiples_of_pi() {
        let pi = |n: i32, d: i32| Affine::pi_times(Rational::from((n, d)));
        assert_eq!(
            parse_point("0.25").unwrap(),
            Affine::rational(Rational::from((1, 4)))
        );
        for (text, want) in [
            ("pi", pi(1, 1)),
            ("-pi", pi(-1, 1)),
            ("pi/4", pi(1, 4)),
            (" -pi / 2 ", pi(-1, 2)),
            ("3*pi/8", pi(3, 8)),
            ("3pi/8", pi(3, 8)),
            ("0.5*pi", pi(1, 2)),
            ("3/4*pi", pi(3, 4)),
            ("π/3", pi(1, 3)),
        ] {
            assert_eq!(parse_point(text).unwrap(), want, "{text}");
        }
        for bad in ["pi/0", "pi*2", "pix", "2pi/3/4", "x*pi", "pi/"] {
            assert!(parse_point(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn decimals_are_read_exactly() {
        assert_eq!(parse_exact("0.6").unwrap(), Rational::from((3, 5)));
        assert_eq!(parse_exact("-1/2").unwrap(), Rational::from((-1, 2)));
        assert_eq!(parse_exact("2.5e-1").unwrap(), Rational::from((1, 4)));
        assert_eq!(parse_exact("-2").unwrap(), Rational::from(-2));
        assert!(parse_exact("abc").is_err());
        assert!(parse_exact("").is_err());
        assert!(parse_exact("1/0").is_err());
        assert!(matches!(
            parse_exact("NaN"),
            Err(CoreError::NotFinite { .. })
        ));
    }

    #[test]
    fn ranges_respect_open_and_closed_ends() {
        let r = Range {
            lo: Bound::Open(1, 2),
            hi: Bound::Closed(2, 1),
        };
        assert!(!r.contains(&Rational::from((1, 2))));
        assert!(r.contains(&Rational::from(2)));
        assert!(!r.contains(&Rational::from((201, 100))));
        assert_eq!(r.to_string(), "(1/2, 2]");
    }
}
