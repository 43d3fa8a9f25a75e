//! Shape parameters, their published ranges, and exact parameter values.

use std::fmt;

use rug::Rational;

use crate::domain::Affine;
use crate::echo::echo;
use crate::error::{CoreError, Result};
use crate::number::parse_point;
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
/// last pair of a name wins) into exact values in the order of `params`:
/// a rational or a rational multiple of π (`alpha=pi/2`, read as
/// [`parse_point`] reads a point, no parameter left in it). Checks names
/// and, unless `allow_outside`, the published ranges — exactly, or for a
/// multiple of π against a rational end by certified enclosures of π;
/// `id` names the basis in errors.
pub fn read_params(
    id: &str,
    params: &[Parameter],
    pairs: &[(String, String)],
    allow_outside: bool,
) -> Result<Vec<Affine>> {
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
            let value = parse_point(text)?;
            if !allow_outside && !spec.range.contains_value(&value)? {
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

#[cfg(test)]
mod tests {
    use super::*;

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
