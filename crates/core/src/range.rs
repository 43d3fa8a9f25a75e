//! Published parameter ranges with exact ends — rational, or rational
//! multiples of π: `[-2, 1]`, `(1/2, 2]`, `[0, inf)`, `(-inf, +inf)`,
//! `(0, pi)`. Decimals are read exactly (`0.3` is `3/10`). The range of
//! every described basis's parameter ([`crate::Parameter`]), catalog
//! family or spec file.

use std::fmt;

use crate::domain::Affine;
use crate::number::parse_exact;
use crate::precision::affine_sign;
use rug::Rational;

/// One end of a range.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum End {
    Closed(Rational),
    Open(Rational),
    Unbounded,
}

impl End {
    /// The finite value, if any.
    pub fn value(&self) -> Option<&Rational> {
        match self {
            End::Closed(q) | End::Open(q) => Some(q),
            End::Unbounded => None,
        }
    }
}

/// A parameter range `lo … hi`; with `pi`, the finite ends are the
/// printed rational multiples of π (`(0, pi)` for C-curves).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParamRange {
    pub lo: End,
    pub hi: End,
    pub pi: bool,
}

/// `q` for an end printed `q*pi`, `pi*q`, `pi/r`, `q*pi/r` or `pi`
/// (`None` when there is no π).
fn pi_multiple(s: &str) -> Result<Option<Rational>, String> {
    let compact: String = s.chars().filter(|c| !c.is_whitespace()).collect();
    let compact = compact.replace('π', "pi");
    if !compact.contains("pi") {
        return Ok(None);
    }
    let (before, after) = compact.split_once("pi").expect("contains pi");
    let coef = match before.trim_end_matches('*') {
        "" => Rational::from(1),
        "-" => Rational::from(-1),
        c => parse_exact(c).map_err(|e| e.to_string())?,
    };
    let rest = after.trim_start_matches('*');
    let value = match rest.strip_prefix('/') {
        Some(d) => {
            let d = parse_exact(d).map_err(|e| e.to_string())?;
            if d == 0 {
                return Err(format!("`{s}`: division by zero"));
            }
            coef / d
        }
        None if rest.is_empty() => coef,
        None => coef * parse_exact(rest).map_err(|e| e.to_string())?,
    };
    Ok(Some(value))
}

/// The sign of `x − q·π`, decided with π enclosed at rising precision
/// (`x = qπ` only for `x = q = 0`: π is irrational).
fn compare_pi(x: &Rational, q: &Rational) -> std::cmp::Ordering {
    use rug::float::{Constant, Round};
    if *q == 0 {
        return x.cmp0();
    }
    let mut bits = 64;
    loop {
        let lo = rug::Float::with_val_round(bits, Constant::Pi, Round::Down).0;
        let hi = rug::Float::with_val_round(bits, Constant::Pi, Round::Up).0;
        let (a, b) = (
            q * lo.to_rational().expect("finite"),
            q * hi.to_rational().expect("finite"),
        );
        let (a, b) = if a < b { (a, b) } else { (b, a) };
        if *x < a {
            return std::cmp::Ordering::Less;
        }
        if *x > b {
            return std::cmp::Ordering::Greater;
        }
        bits *= 2;
    }
}

impl ParamRange {
    /// Reads a range; the message says what was expected.
    pub fn parse(text: &str) -> Result<ParamRange, String> {
        let expected = "expected a range such as [-2, 1], (1/2, 2] or [0, inf)";
        let t = text.trim();
        let (open_lo, rest) = match t.chars().next() {
            Some('[') => (false, &t[1..]),
            Some('(') => (true, &t[1..]),
            _ => return Err(format!("`{text}`: {expected}")),
        };
        let (open_hi, body) = match rest.chars().last() {
            Some(']') => (false, &rest[..rest.len() - 1]),
            Some(')') => (true, &rest[..rest.len() - 1]),
            _ => return Err(format!("`{text}`: {expected}")),
        };
        let (a, b) = body
            .split_once(',')
            .ok_or_else(|| format!("`{text}`: {expected}"))?;
        let end = |s: &str, open: bool, below: bool| -> Result<End, String> {
            let s = s.trim().replace('−', "-");
            let inf = ["inf", "∞", "infinity"];
            let bare = s.trim_start_matches(['+', '-']);
            if inf.contains(&bare) {
                let negative = s.starts_with('-');
                if negative != below {
                    return Err(format!(
                        "`{text}`: {} cannot be {}",
                        if below {
                            "the lower end"
                        } else {
                            "the upper end"
                        },
                        if negative { "-inf" } else { "+inf" }
                    ));
                }
                if !open {
                    return Err(format!("`{text}`: an infinite end must be open"));
                }
                return Ok(End::Unbounded);
            }
            let q = match pi_multiple(&s).map_err(|e| format!("`{text}`: {e}"))? {
                Some(q) => q,
                None => parse_exact(&s).map_err(|e| format!("`{text}`: {e}"))?,
            };
            Ok(if open { End::Open(q) } else { End::Closed(q) })
        };
        let with_pi = |s: &str| matches!(pi_multiple(s), Ok(Some(_)));
        let nonzero = |e: &End| e.value().is_some_and(|q| *q != 0);
        let (lo, hi) = (end(a, open_lo, true)?, end(b, open_hi, false)?);
        let pi = with_pi(a) || with_pi(b);
        if pi && ((!with_pi(a) && nonzero(&lo)) || (!with_pi(b) && nonzero(&hi))) {
            return Err(format!(
                "`{text}`: give both finite ends as multiples of pi, or neither (e.g. (0, pi), [pi/6, pi/2])"
            ));
        }
        let range = ParamRange { lo, hi, pi };
        if let (Some(lo), Some(hi)) = (range.lo.value(), range.hi.value()) {
            let both_closed = matches!((&range.lo, &range.hi), (End::Closed(_), End::Closed(_)));
            if lo > hi || (lo == hi && !both_closed) {
                return Err(format!(
                    "`{text}`: the ends are reversed or the range is empty ({lo} is not below {hi}); expected lower end first"
                ));
            }
        }
        Ok(range)
    }

    /// True when `x` lies in the range.
    pub fn contains(&self, x: &Rational) -> bool {
        use std::cmp::Ordering::{Equal, Greater, Less};
        let above = match &self.lo {
            End::Closed(q) => matches!(self.compare(x, q), Greater | Equal),
            End::Open(q) => self.compare(x, q) == Greater,
            End::Unbounded => true,
        };
        let below = match &self.hi {
            End::Closed(q) => matches!(self.compare(x, q), Less | Equal),
            End::Open(q) => self.compare(x, q) == Less,
            End::Unbounded => true,
        };
        above && below
    }

    /// Whether the exact value `x = q₀ + q_π·π` (a parameter value as
    /// [`crate::parse_point`] reads it) lies in the range: the sign of
    /// `x − end` decided exactly when no π is left, else by certified
    /// enclosures of π ([`crate::precision::affine_sign`]; `q₀ + q·π ≠ 0`
    /// for `q ≠ 0`, π being irrational).
    pub fn contains_value(&self, x: &Affine) -> crate::Result<bool> {
        use std::cmp::Ordering::{Equal, Greater, Less};
        let minus = |q: &Rational| {
            let mut d = x.clone();
            if self.pi {
                d.pi -= q;
            } else {
                d.constant -= q;
            }
            affine_sign(&d)
        };
        let above = match &self.lo {
            End::Closed(q) => matches!(minus(q)?, Greater | Equal),
            End::Open(q) => minus(q)? == Greater,
            End::Unbounded => true,
        };
        let below = match &self.hi {
            End::Closed(q) => matches!(minus(q)?, Less | Equal),
            End::Open(q) => minus(q)? == Less,
            End::Unbounded => true,
        };
        Ok(above && below)
    }

    /// The sign of `x − end` for an end `q` (`q·π` in a range in
    /// multiples of π).
    fn compare(&self, x: &Rational, q: &Rational) -> std::cmp::Ordering {
        if self.pi { compare_pi(x, q) } else { x.cmp(q) }
    }

    /// A value inside: the midpoint, one beyond a single finite end, or 0
    /// (for multiples of π, the midpoint times 3.14159 < π).
    pub fn interior_point(&self) -> Rational {
        let unit = if self.pi {
            Rational::from((314_159, 100_000))
        } else {
            Rational::from(1)
        };
        unit * match (self.lo.value(), self.hi.value()) {
            (Some(a), Some(b)) => (a.clone() + b) / 2u32,
            (Some(a), None) => a.clone() + 1u32,
            (None, Some(b)) => b.clone() - 1u32,
            (None, None) => Rational::new(),
        }
    }
}

impl ParamRange {
    /// The value `q` of an end as the range prints it: `q`, or for a range
    /// in multiples of π `pi`, `pi/2`, `3*pi/4`.
    pub fn end_text(&self, q: &Rational) -> String {
        if !self.pi || *q == 0 {
            q.to_string()
        } else if *q == 1 {
            "pi".into()
        } else if *q.numer() == 1 {
            format!("pi/{}", q.denom())
        } else if *q.denom() == 1 {
            format!("{}*pi", q.numer())
        } else {
            format!("{}*pi/{}", q.numer(), q.denom())
        }
    }
}

/// Printed as `[-2, 1]`, `(1/2, 2]`, `[0, +inf)`, `(0, pi)`.
impl fmt::Display for ParamRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = |q: &Rational| self.end_text(q);
        match &self.lo {
            End::Closed(q) => write!(f, "[{}", v(q))?,
            End::Open(q) => write!(f, "({}", v(q))?,
            End::Unbounded => f.write_str("(-inf")?,
        }
        f.write_str(", ")?;
        match &self.hi {
            End::Closed(q) => write!(f, "{}]", v(q)),
            End::Open(q) => write!(f, "{})", v(q)),
            End::Unbounded => f.write_str("+inf)"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_read_exactly_and_print_like_the_catalog() {
        let r = ParamRange::parse("(1/2, 2]").unwrap();
        assert_eq!(
            r.to_string(),
            crate::Family::MajeedQayyum.info().params[0]
                .range
                .to_string()
        );
        assert!(!r.contains(&Rational::from((1, 2))) && r.contains(&Rational::from(2)));
        let d = ParamRange::parse("[0.3, 0.5]").unwrap();
        assert_eq!(d.lo, End::Closed(Rational::from((3, 10))));
        assert_eq!(
            ParamRange::parse("[0, inf)").unwrap().to_string(),
            "[0, +inf)"
        );
        assert_eq!(ParamRange::parse("[−2, 1]").unwrap().to_string(), "[-2, 1]");
    }

    #[test]
    fn bad_ranges_are_refused_with_a_reason() {
        // a multiple of π over zero (it panicked in the division)
        assert!(
            ParamRange::parse("[0, pi/0]")
                .unwrap_err()
                .contains("division by zero")
        );
        assert!(
            ParamRange::parse("[1, -2]")
                .unwrap_err()
                .contains("reversed")
        );
        assert!(
            ParamRange::parse("(1, 1]")
                .unwrap_err()
                .contains("reversed")
        );
        assert!(
            ParamRange::parse("1, 2")
                .unwrap_err()
                .contains("expected a range")
        );
        assert!(ParamRange::parse("[0, inf]").unwrap_err().contains("open"));
        assert!(ParamRange::parse("[inf, 0)").is_err());
        assert!(ParamRange::parse("[a, 2]").is_err());
        assert!(
            ParamRange::parse("[1, pi]")
                .unwrap_err()
                .contains("multiples of pi")
        );
    }

    #[test]
    fn ranges_in_multiples_of_pi() {
        let r = ParamRange::parse("(0, pi)").unwrap();
        assert!(r.pi && r.to_string() == "(0, pi)");
        assert!(r.contains(&Rational::from((314_159, 100_000))));
        assert!(!r.contains(&Rational::from((314_160, 100_000))));
        assert!(!r.contains(&Rational::new()));
        let s = ParamRange::parse("[pi/6, 3*pi/4]").unwrap();
        assert_eq!(s.to_string(), "[pi/6, 3*pi/4]");
        assert!(s.contains(&s.interior_point()));
        assert_eq!(
            ParamRange::parse("[-pi/2, 2π]").unwrap().to_string(),
            "[-1*pi/2, 2*pi]"
        );
    }

    /// Parameter values that are multiples of π, against ranges in
    /// multiples of π (exact: `π/2 < π`, the open end `π` excluded) and
    /// against rational ends (by enclosures of π: `π/2 ∈ [1, 1.5708]`,
    /// `π/2 ∉ [1, 1.5707]`, `π ∉ [−2, 3.14159]`).
    #[test]
    fn multiples_of_pi_are_placed_against_both_kinds_of_range() {
        let at = |text: &str| crate::parse_point(text).unwrap();
        let inside = |range: &str, x: &str| {
            ParamRange::parse(range)
                .unwrap()
                .contains_value(&at(x))
                .unwrap()
        };
        assert!(inside("(0, pi)", "pi/2"));
        assert!(!inside("(0, pi)", "pi"));
        assert!(inside("(0, pi]", "pi"));
        assert!(!inside("(0, pi)", "7*pi"));
        assert!(!inside("(0, pi)", "0*pi"));
        assert!(inside("(0, pi)", "3.1415926"));
        assert!(!inside("(0, pi)", "3.1415927"));
        assert!(inside("[1, 1.5708]", "pi/2"));
        assert!(!inside("[1, 1.5707]", "pi/2"));
        assert!(!inside("[-2, 3.14159]", "pi"));
        assert!(inside("[-2, 3.1416]", "-pi/2"));
        assert!(inside("[1/2, 2]", "3/4"));
    }
}
