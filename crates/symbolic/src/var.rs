//! Variable names and the fixed variable order used for monomial order and
//! printing.
//!
//! The order is: the shape parameters in the order of [`PARAMETERS`], then
//! `pi`, then the trigonometric atoms `s`, `c`, then the polynomial variable
//! `t`, then every other name. Other names are compared naturally: by the
//! name without its trailing digits, then by the trailing digits as a number
//! (`P2` before `P10`), then by the whole name.

use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::Arc;

/// Shape parameters, earliest first in the variable order.
pub const PARAMETERS: [&str; 9] = [
    "m", "beta", "lambda", "mu", "eta", "alpha", "zeta", "xi", "omega",
];

/// The name of `sin θ`.
pub const SIN: &str = "s";
/// The name of `cos θ`.
pub const COS: &str = "c";
/// The name of the polynomial variable.
pub const T: &str = "t";
/// The name of the symbol π.
pub const PI: &str = "pi";

/// Position class of a name in the variable order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Class {
    Parameter(usize),
    Pi,
    Sin,
    Cos,
    T,
    Other,
}

impl Class {
    fn of(name: &str) -> Class {
        match name {
            PI => Class::Pi,
            SIN => Class::Sin,
            COS => Class::Cos,
            T => Class::T,
            _ => PARAMETERS
                .iter()
                .position(|p| *p == name)
                .map_or(Class::Other, Class::Parameter),
        }
    }
}

/// A named variable. Equality and hashing are by name; the order is the
/// fixed variable order described in the [module documentation](self).
#[derive(Clone)]
pub struct Var {
    class: Class,
    name: Arc<str>,
}

impl Var {
    /// The variable called `name` (any string).
    pub fn new(name: &str) -> Var {
        Var {
            class: Class::of(name),
            name: Arc::from(name),
        }
    }

    /// The name.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// True for `s` and `c`, whose degrees are not preserved by the
    /// reduction modulo `s² + c² − 1`.
    pub fn is_trig(&self) -> bool {
        matches!(self.class, Class::Sin | Class::Cos)
    }
}

/// Splits a name into the part before its trailing digits and the digits.
pub(crate) fn split_digits(name: &str) -> (&str, &str) {
    let cut = name.trim_end_matches(|ch: char| ch.is_ascii_digit()).len();
    name.split_at(cut)
}

/// Natural order of two names: prefix, then trailing number, then name.
fn natural(a: &str, b: &str) -> Ordering {
    let (pa, da) = split_digits(a);
    let (pb, db) = split_digits(b);
    let (na, nb) = (da.trim_start_matches('0'), db.trim_start_matches('0'));
    pa.cmp(pb)
        .then_with(|| na.len().cmp(&nb.len()))
        .then_with(|| na.cmp(nb))
        .then_with(|| a.cmp(b))
}

impl PartialEq for Var {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

impl Eq for Var {}

impl Hash for Var {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.name.hash(state);
    }
}

impl Ord for Var {
    fn cmp(&self, other: &Self) -> Ordering {
        self.class.cmp(&other.class).then_with(|| {
            if self.class == Class::Other {
                natural(&self.name, &other.name)
            } else {
                Ordering::Equal
            }
        })
    }
}

impl PartialOrd for Var {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Debug for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sorted(names: &[&str]) -> Vec<String> {
        let mut v: Vec<Var> = names.iter().map(|n| Var::new(n)).collect();
        v.sort();
        v.iter().map(|x| x.name().to_string()).collect()
    }

    #[test]
    fn fixed_order() {
        assert_eq!(
            sorted(&[
                "t", "P10", "c", "w0", "s", "pi", "zeta", "P2", "beta", "m", "h1"
            ]),
            [
                "m", "beta", "zeta", "pi", "s", "c", "t", "P2", "P10", "h1", "w0"
            ]
        );
    }

    #[test]
    fn equality_is_by_name() {
        assert_eq!(Var::new("x01"), Var::new("x01"));
        assert_ne!(Var::new("x01"), Var::new("x1"));
        assert_ne!(Var::new("x01").cmp(&Var::new("x1")), Ordering::Equal);
    }
}
