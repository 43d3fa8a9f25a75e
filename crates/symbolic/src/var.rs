//! Variable names and the fixed variable order used for monomial order and
//! printing.
//!
//! The order is: the shape parameters in the order of [`PARAMETERS`], then
//! `pi`, then the trigonometric atoms `s`, `c`, then the polynomial variable
//! `t`, then every other name. Other names are compared naturally: by the
//! name without its trailing digits, then by the trailing digits as a number
//! (`P2` before `P10`), then by the whole name.

use std::cmp::Ordering;
use std::collections::HashMap;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::sync::{Mutex, OnceLock, PoisonError};

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
/// The name of the exponential atom `E = exp(κx)` of a basis's variable.
pub const EXP: &str = "E";

/// Position class of a name in the variable order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Class {
    Parameter(usize),
    Pi,
    /// `sin(X)` of a parameter expression `X` (paired with `cos(X)`).
    ParamSin,
    /// `cos(X)`.
    ParamCos,
    /// `sqrt(p)` of a prime `p` (`sqrt(p)² = p`): exact sines and cosines
    /// of multiples of π/12.
    Radical,
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
            _ if name.starts_with("sin(") && name.ends_with(')') => Class::ParamSin,
            _ if name.starts_with("cos(") && name.ends_with(')') => Class::ParamCos,
            _ if radicand(name).is_some() => Class::Radical,
            _ => PARAMETERS
                .iter()
                .position(|p| *p == name)
                .map_or(Class::Other, Class::Parameter),
        }
    }

    /// The position of the class in the variable order, as one number
    /// (the derived order of `Class`: parameters by index, then the other
    /// classes as declared).
    fn rank(self) -> u32 {
        let after = |k: u32| PARAMETERS.len() as u32 + k;
        match self {
            Class::Parameter(i) => i as u32,
            Class::Pi => after(0),
            Class::ParamSin => after(1),
            Class::ParamCos => after(2),
            Class::Radical => after(3),
            Class::Sin => after(4),
            Class::Cos => after(5),
            Class::T => after(6),
            Class::Other => after(7),
        }
    }

    /// True for the classes with several members, ordered by name.
    fn by_name(self) -> bool {
        matches!(
            self,
            Class::Other | Class::ParamSin | Class::ParamCos | Class::Radical
        )
    }
}

/// A named variable. Equality and hashing are by name; the order is the
/// fixed variable order described in the [module documentation](self).
///
/// Names are interned: every variable with the same name points to one
/// shared, immutable record (kept for the life of the process — a program
/// uses a bounded set of names), so a `Var` is a `Copy` pointer, equality
/// is a pointer comparison, and the order compares keys computed once per
/// name instead of the names.
#[derive(Clone, Copy)]
pub struct Var(&'static Interned);

/// The record behind a [`Var`]: its name and its precomputed order key.
struct Interned {
    name: &'static str,
    class: Class,
    /// `class.rank()`, computed once.
    rank: u32,
    /// For names of a class ordered by name ([`Class::by_name`]) whose key
    /// decides [`natural`] order:
    /// the first 8 bytes of the name without its trailing digits (big
    /// endian, zero padded) and the trailing number. `None` for a longer
    /// prefix, a prefix containing a NUL byte, or more than 19 digits.
    key: Option<(u64, u64)>,
    /// The name as printed in each of the printer's styles, formed on first
    /// use ([`Var::printed`]).
    printed: [OnceLock<&'static str>; PRINT_STYLES],
}

/// How many printed forms a variable keeps ([`Var::printed`]).
pub(crate) const PRINT_STYLES: usize = 4;

impl Interned {
    fn new(name: &'static str) -> Interned {
        let class = Class::of(name);
        let (prefix, digits) = split_digits(name);
        let key = (class.by_name()
            && prefix.len() <= 8
            && !prefix.as_bytes().contains(&0)
            && digits.len() <= 19)
            .then(|| {
                let mut head = [0u8; 8];
                head[..prefix.len()].copy_from_slice(prefix.as_bytes());
                (u64::from_be_bytes(head), digits.parse::<u64>().unwrap_or(0))
            });
        Interned {
            name,
            class,
            rank: class.rank(),
            key,
            printed: Default::default(),
        }
    }
}

/// Every name seen so far.
fn table() -> &'static Mutex<HashMap<&'static str, &'static Interned>> {
    static TABLE: OnceLock<Mutex<HashMap<&'static str, &'static Interned>>> = OnceLock::new();
    TABLE.get_or_init(Default::default)
}

impl Var {
    /// The variable called `name` (any string).
    pub fn new(name: &str) -> Var {
        let mut table = table().lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(record) = table.get(name) {
            return Var(record);
        }
        let name: &'static str = Box::leak(name.into());
        let record: &'static Interned = Box::leak(Box::new(Interned::new(name)));
        table.insert(name, record);
        Var(record)
    }

    /// The variable called `name` when it has been formed before (a name
    /// never formed occurs in no polynomial); unlike [`Var::new`], nothing
    /// is recorded.
    pub fn find(name: &str) -> Option<Var> {
        let table = table().lock().unwrap_or_else(PoisonError::into_inner);
        table.get(name).map(|record| Var(record))
    }

    /// `sin θ`, the variable [`SIN`].
    pub fn sin() -> Var {
        static SIN_VAR: OnceLock<Var> = OnceLock::new();
        *SIN_VAR.get_or_init(|| Var::new(SIN))
    }

    /// `cos θ`, the variable [`COS`].
    pub fn cos() -> Var {
        static COS_VAR: OnceLock<Var> = OnceLock::new();
        *COS_VAR.get_or_init(|| Var::new(COS))
    }

    /// The name.
    pub fn name(&self) -> &'static str {
        self.0.name
    }

    /// The name as printed in style number `style` (`< PRINT_STYLES`),
    /// formed by `print` once for the life of the process, like the record.
    pub(crate) fn printed(&self, style: usize, print: impl FnOnce() -> String) -> &'static str {
        self.0.printed[style].get_or_init(|| Box::leak(print().into_boxed_str()))
    }

    /// True for the paired atoms `s`, `c` and `sin(X)`, `cos(X)`, whose
    /// degrees are not preserved by the reduction modulo `s² + c² − 1`.
    pub fn is_trig(&self) -> bool {
        matches!(
            self.0.class,
            Class::Sin | Class::Cos | Class::ParamSin | Class::ParamCos | Class::Radical
        )
    }

    /// For a sine atom (`s`, `sin(X)`), its cosine partner (`c`, `cos(X)`):
    /// the normal form rewrites `sin² = 1 − cos²`.
    pub fn cosine_partner(&self) -> Option<Var> {
        match self.0.class {
            Class::Sin => Some(Var::cos()),
            Class::ParamSin => Some(Var::new(&format!("cos{}", &self.name()[3..]))),
            _ => None,
        }
    }

    /// True for a sine atom (`s`, `sin(X)`).
    pub fn is_sine(&self) -> bool {
        self.cosine_partner().is_some()
    }

    /// True for the atoms the normal form reduces by a square rule
    /// ([`Var::square`]): sine atoms and radicals. Their degrees are not
    /// preserved by multiplication, and division clears them by conjugates.
    pub fn is_reduced(&self) -> bool {
        matches!(self.0.class, Class::Sin | Class::ParamSin | Class::Radical)
    }

    /// `v²` in lower terms when the normal form rewrites it: `1 − c²` for a
    /// sine atom with cosine partner `c`, `p` for `sqrt(p)`.
    pub fn square(&self) -> Option<(Option<Var>, rug::Integer)> {
        match self.0.class {
            Class::Radical => radicand(self.name()).map(|p| (None, rug::Integer::from(p))),
            _ => self
                .cosine_partner()
                .map(|c| (Some(c), rug::Integer::from(1))),
        }
    }
}

/// `p` for the name `sqrt(p)` of a radical atom (`p` = 2, 3, 5, 7).
fn radicand(name: &str) -> Option<u32> {
    let p = name
        .strip_prefix("sqrt(")?
        .strip_suffix(')')?
        .parse::<u32>()
        .ok()?;
    [2, 3, 5, 7].contains(&p).then_some(p)
}

/// The names of `vars`, as a sorted set.
pub(crate) fn names(vars: Vec<Var>) -> std::collections::BTreeSet<String> {
    vars.into_iter().map(|v| v.name().to_string()).collect()
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
        // one record per name
        std::ptr::eq(self.0, other.0)
    }
}

impl Eq for Var {}

impl Hash for Var {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.name.hash(state);
    }
}

impl Ord for Var {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        let (a, b) = (self.0, other.0);
        if std::ptr::eq(a, b) {
            return Ordering::Equal;
        }
        // classes with one member compare equal; the others by name
        match a.rank.cmp(&b.rank) {
            Ordering::Equal if a.class.by_name() => match (a.key, b.key) {
                // Equal keys mean equal prefixes and trailing numbers,
                // i.e. names that differ only in leading zeros:
                // `natural` then compares the names.
                (Some(ka), Some(kb)) => ka.cmp(&kb).then_with(|| a.name.cmp(b.name)),
                _ => natural(a.name, b.name),
            },
            order => order,
        }
    }
}

impl PartialOrd for Var {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Debug for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
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
    fn the_rank_orders_as_the_classes_do() {
        let names = [
            "m", "omega", "pi", "sin(a)", "cos(a)", "sqrt(2)", "s", "c", "t", "w0",
        ];
        let classes: Vec<Class> = names.iter().map(|n| Class::of(n)).collect();
        for a in &classes {
            for b in &classes {
                assert_eq!(a.rank().cmp(&b.rank()), a.cmp(b), "{a:?} against {b:?}");
            }
        }
        assert!(names.iter().all(|n| {
            let v = Var::new(n);
            v.is_reduced() == (v.is_sine() || Class::of(n) == Class::Radical)
        }));
    }

    #[test]
    fn parameter_trig_atoms_pair_up() {
        let s = Var::new("sin(alpha/2)");
        assert!(s.is_trig() && s.is_sine());
        assert_eq!(s.cosine_partner().unwrap().name(), "cos(alpha/2)");
        assert!(Var::new("cos(alpha/2)").is_trig() && !Var::new("cos(alpha/2)").is_sine());
        assert_eq!(Var::new("s").cosine_partner().unwrap().name(), "c");
        assert!(!Var::new(EXP).is_trig());
        assert_eq!(
            sorted(&["s", "sin(alpha)", "pi", "alpha", "E"]),
            ["alpha", "pi", "sin(alpha)", "s", "E"]
        );
    }

    #[test]
    fn the_interned_key_orders_as_the_names_do() {
        let names = [
            "P",
            "P0",
            "P00",
            "P1",
            "P01",
            "P2",
            "P10",
            "P010",
            "Q",
            "a",
            "ab",
            "abcdefgh",
            "abcdefgh1",
            "abcdefghi",
            "abcdefghi2",
            "abcdefgh\u{0}",
            "x99999999999999999999",
            "x100000000000000000000",
            "x18446744073709551615",
            "x18446744073709551616",
            "h1",
            "w0",
            "m1",
            "m",
            "pi",
            "s",
            "c",
            "t",
            "sin(alpha)",
            "sin(alpha/2)",
            "cos(alpha)",
            "sqrt(2)",
            "sqrt(3)",
            "E",
        ];
        for a in names {
            for b in names {
                let (va, vb) = (Var::new(a), Var::new(b));
                let want = Class::of(a).cmp(&Class::of(b)).then_with(|| {
                    if Class::of(a).by_name() {
                        natural(a, b)
                    } else {
                        Ordering::Equal
                    }
                });
                assert_eq!(va.cmp(&vb), want, "{a} vs {b}");
                assert_eq!(va == vb, a == b);
            }
        }
        assert_eq!(Var::sin(), Var::new(SIN));
        assert_eq!(Var::cos().name(), COS);
    }

    #[test]
    fn equality_is_by_name() {
        assert_eq!(Var::new("x01"), Var::new("x01"));
        assert_ne!(Var::new("x01"), Var::new("x1"));
        assert_ne!(Var::new("x01").cmp(&Var::new("x1")), Ordering::Equal);
    }
}
