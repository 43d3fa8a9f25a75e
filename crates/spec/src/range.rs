//! Published parameter ranges with exact rational ends: `[-2, 1]`,
//! `(1/2, 2]`, `[0, inf)`, `(-inf, +inf)`. Decimals are read exactly
//! (`0.3` is `3/10`).

use std::fmt;

use rug::Rational;
use trig_core::parse_exact;

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

/// A parameter range `lo … hi`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SpecRange {
    pub lo: End,
    pub hi: End,
}

impl SpecRange {
    /// Reads a range; the message says what was expected.
    pub fn parse(text: &str) -> Result<SpecRange, String> {
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
            let q = parse_exact(&s).map_err(|e| format!("`{text}`: {e}"))?;
            Ok(if open { End::Open(q) } else { End::Closed(q) })
        };
        let range = SpecRange {
            lo: end(a, open_lo, true)?,
            hi: end(b, open_hi, false)?,
        };
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
        self.to_box().contains(x)
    }

    /// The range as a parameter set of the certifier.
    pub fn to_box(&self) -> trig_certify::ParamBox {
        let bound = |e: &End| match e {
            End::Closed(q) => trig_certify::Bound::Closed(q.clone()),
            End::Open(q) => trig_certify::Bound::Open(q.clone()),
            End::Unbounded => trig_certify::Bound::Infinite,
        };
        trig_certify::ParamBox {
            lo: bound(&self.lo),
            hi: bound(&self.hi),
        }
    }

    /// A value inside: the midpoint, one beyond a single finite end, or 0.
    pub fn interior_point(&self) -> Rational {
        match (self.lo.value(), self.hi.value()) {
            (Some(a), Some(b)) => (a.clone() + b) / 2u32,
            (Some(a), None) => a.clone() + 1u32,
            (None, Some(b)) => b.clone() - 1u32,
            (None, None) => Rational::new(),
        }
    }
}

/// Printed as `trig_core::Range` prints: `[-2, 1]`, `(1/2, 2]`, `[0, +inf)`.
impl fmt::Display for SpecRange {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.lo {
            End::Closed(q) => write!(f, "[{q}")?,
            End::Open(q) => write!(f, "({q}")?,
            End::Unbounded => f.write_str("(-inf")?,
        }
        f.write_str(", ")?;
        match &self.hi {
            End::Closed(q) => write!(f, "{q}]"),
            End::Open(q) => write!(f, "{q})"),
            End::Unbounded => f.write_str("+inf)"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_read_exactly_and_print_like_the_catalog() {
        let r = SpecRange::parse("(1/2, 2]").unwrap();
        assert_eq!(
            r.to_string(),
            trig_core::Family::MajeedQayyum.info().params[0]
                .range
                .to_string()
        );
        assert!(!r.contains(&Rational::from((1, 2))) && r.contains(&Rational::from(2)));
        let d = SpecRange::parse("[0.3, 0.5]").unwrap();
        assert_eq!(d.lo, End::Closed(Rational::from((3, 10))));
        assert_eq!(
            SpecRange::parse("[0, inf)").unwrap().to_string(),
            "[0, +inf)"
        );
        assert_eq!(SpecRange::parse("[−2, 1]").unwrap().to_string(), "[-2, 1]");
    }

    #[test]
    fn bad_ranges_are_refused_with_a_reason() {
        assert!(
            SpecRange::parse("[1, -2]")
                .unwrap_err()
                .contains("reversed")
        );
        assert!(SpecRange::parse("(1, 1]").unwrap_err().contains("reversed"));
        assert!(
            SpecRange::parse("1, 2")
                .unwrap_err()
                .contains("expected a range")
        );
        assert!(SpecRange::parse("[0, inf]").unwrap_err().contains("open"));
        assert!(SpecRange::parse("[inf, 0)").is_err());
        assert!(SpecRange::parse("[a, 2]").is_err());
    }
}
