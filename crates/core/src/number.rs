//! Exact numbers as a user writes them: integers, decimals (`0.6` is
//! `3/5`), fractions, exponents, and rational multiples of π for points.

use rug::Rational;
use rug::ops::Pow;

use crate::domain::Affine;
use crate::echo::echo;
use crate::error::{CoreError, Result};

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
}
