//! The names of one computation as a namespace: the user's names (shape
//! parameters, their printed symbols) and the symbols the tool introduces
//! (control points `Pᵢ`, `Qᵢ`, weights `wᵢ`, interval lengths `h₁`, `h₂`, the
//! `G¹`/`G²` factors `α`, `β`, the copies `p₁`, `p₂` of a parameter on two
//! segments) never read alike.
//!
//! The exact ring keys variables by name, so two symbols with one name are
//! one symbol: a `G¹` factor called `gamma` beside a parameter `gamma` would
//! silently merge. A [`Names`] is seeded with every user name of the
//! computation; every tool symbol is drawn from it, which hands out only
//! names whose *reading* (the Unicode form a reader sees: Greek names as
//! letters, trailing digits as subscripts, so `w1`, `w₁` read alike) is
//! free, trying the usual letter first (`α, β`, then `γ, δ`, …) and
//! reserving what it hands out. A name the user must write as given (the
//! control points of a printed claim, `λ1` for the first segment's `λ`) is
//! reserved as is, or refused with the name it would read as.
//!
//! The ring's own atoms (`s`, `c`, `t`, `E`, `pi`, `sin(…)`, `sqrt(…)`) are
//! outside every namespace: user names are identifiers that cannot take
//! them (spec files refuse them).

use std::fmt;

use crate::print::unicode_name;
use crate::sym::Sym;

/// Letters of the control points of two segments, preferred first.
const POINT_PAIRS: [[char; 2]; 4] = [['P', 'Q'], ['R', 'S'], ['U', 'V'], ['A', 'B']];
/// Letters of the weights of a rational curve, preferred first.
const WEIGHT_LETTERS: &str = "wvy";
/// Letters of interval lengths, preferred first.
const LENGTH_LETTERS: &str = "hlk";
/// Letters tried when the preferred ones are taken (none of them reads as
/// an atom, the variable or another kind of tool symbol).
const FALLBACK: &str = "dfgjnopqrDFGJKLMNOY";

/// Pairs for the `G¹`/`G²` factors, preferred first.
const FACTOR_PAIRS: [[&str; 2]; 8] = [
    ["alpha", "beta"],
    ["gamma", "delta"],
    ["kappa", "nu"],
    ["rho", "sigma"],
    ["phi", "psi"],
    ["chi", "tau"],
    ["epsilon", "omega"],
    ["xi", "zeta"],
];

/// A name that reads like one already in the namespace.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NameClash {
    pub name: String,
    pub what: String,
    pub other: String,
    pub other_what: String,
}

impl fmt::Display for NameClash {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "`{}` ({}) reads as `{}` ({}) in printed formulas",
            self.name, self.what, self.other, self.other_what
        )
    }
}

impl std::error::Error for NameClash {}

/// How a name reads in printed formulas: its Unicode form (`lambda1` →
/// `λ₁`, `w₁` stays `w₁`).
pub fn reading(name: &str) -> String {
    unicode_name(name.trim())
}

/// The names of one computation (see the [module documentation](self)).
#[derive(Debug, Clone, Default)]
pub struct Names {
    /// `(reading, name, what)` of every reserved name.
    taken: Vec<(String, String, String)>,
}

impl Names {
    /// An empty namespace.
    pub fn new() -> Names {
        Names::default()
    }

    /// A namespace holding the parameters `(name, printed symbol)`.
    pub fn of_parameters<'a>(params: impl IntoIterator<Item = (&'a str, &'a str)>) -> Names {
        let mut names = Names::new();
        for (name, symbol) in params {
            names.user(name, "a parameter");
            if symbol != name {
                names.user(symbol, &format!("the symbol of the parameter `{name}`"));
            }
        }
        names
    }

    /// Reserves a user name (user names may read alike: they are checked
    /// where they are declared).
    pub fn user(&mut self, name: &str, what: &str) {
        self.taken
            .push((reading(name), name.to_string(), what.to_string()));
    }

    /// The reserved name reading as `name`, with what it is.
    fn holder(&self, name: &str) -> Option<&(String, String, String)> {
        let r = reading(name);
        self.taken.iter().find(|(t, _, _)| *t == r)
    }

    /// True when `name` reads like no reserved name.
    pub fn is_free(&self, name: &str) -> bool {
        self.holder(name).is_none()
    }

    /// Reserves `name` as given (a name the user writes, e.g. `P0` of a
    /// printed claim, `lambda1` for the first segment's `λ`): its symbol,
    /// or the clash.
    pub fn fixed(&mut self, name: &str, what: &str) -> Result<Sym, NameClash> {
        if let Some((_, other, other_what)) = self.holder(name) {
            return Err(NameClash {
                name: name.to_string(),
                what: what.to_string(),
                other: other.clone(),
                other_what: other_what.clone(),
            });
        }
        self.user(name, what);
        Ok(Sym::var(name))
    }

    /// The first candidate (a group of names) whose names are all free,
    /// after which `stem_` with more underscores (the namespace is finite).
    fn first_free(
        &self,
        candidates: impl Iterator<Item = Vec<String>>,
        stem: impl Fn(&str) -> Vec<String>,
    ) -> Vec<String> {
        let mut candidates = candidates;
        candidates
            .find(|names| names.iter().all(|n| self.is_free(n)))
            .unwrap_or_else(|| {
                (1..)
                    .map(|k| stem(&"_".repeat(k)))
                    .find(|names| names.iter().all(|n| self.is_free(n)))
                    .expect("finitely many names are taken")
            })
    }

    /// Letters: `preferred`, then [`FALLBACK`].
    fn letters(preferred: &str) -> impl Iterator<Item = char> + '_ {
        preferred.chars().chain(FALLBACK.chars())
    }

    /// Symbols `L{i}` for `i` in `indices` with the first letter `L` of
    /// `preferred` (then of [`FALLBACK`]) for which all are free.
    fn indexed(
        &mut self,
        preferred: &str,
        indices: std::ops::Range<usize>,
        what: &str,
    ) -> Vec<Sym> {
        let named = |l: &str| indices.clone().map(|i| format!("{l}{i}")).collect();
        let first = preferred.chars().next().unwrap_or('x');
        let chosen = self.first_free(
            Self::letters(preferred).map(|l| named(&l.to_string())),
            |u| named(&format!("{first}{u}")),
        );
        chosen.iter().map(|n| self.take(n, what)).collect()
    }

    /// Control points `P0…P{n−1}` and `Q0…Q{n−1}` of two segments (the next
    /// pair of letters, `R`, `S`, …, when a name is taken).
    pub fn points(&mut self, n: usize) -> [Vec<Sym>; 2] {
        let named = |l: &str| (0..n).map(|i| format!("{l}{i}")).collect::<Vec<_>>();
        let both = |a: &str, b: &str| [named(a), named(b)].concat();
        let pairs = POINT_PAIRS
            .iter()
            .map(|[a, b]| both(&a.to_string(), &b.to_string()))
            .chain(
                FALLBACK
                    .chars()
                    .zip(FALLBACK.chars().skip(1))
                    .map(|(a, b)| both(&a.to_string(), &b.to_string())),
            );
        let chosen = self.first_free(pairs, |u| both(&format!("P{u}"), &format!("Q{u}")));
        let (first, second) = chosen.split_at(n);
        [
            first
                .iter()
                .map(|p| self.take(p, "a control point"))
                .collect(),
            second
                .iter()
                .map(|q| self.take(q, "a control point of the second segment"))
                .collect(),
        ]
    }

    /// Weights `w0…w{n−1}` of a rational curve (`v…` when one is taken).
    pub fn weights(&mut self, n: usize) -> Vec<Sym> {
        self.indexed(WEIGHT_LETTERS, 0..n, "a weight")
    }

    /// Interval lengths `h1`, `h2` of two segments (`l1`, `l2`, … when one
    /// is taken).
    pub fn lengths(&mut self) -> [Sym; 2] {
        let v = self.indexed(LENGTH_LETTERS, 1..3, "an interval length");
        [v[0].clone(), v[1].clone()]
    }

    /// The interval length `h` of one segment (`l`, … when taken).
    pub fn length(&mut self) -> Sym {
        let chosen = self.first_free(
            Self::letters(LENGTH_LETTERS).map(|l| vec![l.to_string()]),
            |u| vec![format!("h{u}")],
        );
        self.take(&chosen[0], "the interval length")
    }

    /// The `G¹`/`G²` factors: `α`, `β`, or the first pair of
    /// `FACTOR_PAIRS` that reads like no reserved name.
    pub fn factors(&mut self) -> [Sym; 2] {
        let pair = self.first_free(
            FACTOR_PAIRS
                .iter()
                .map(|[a, b]| vec![a.to_string(), b.to_string()]),
            |u| vec![format!("alpha{u}"), format!("beta{u}")],
        );
        [
            self.take(&pair[0], "the first G factor"),
            self.take(&pair[1], "the second G factor"),
        ]
    }

    fn take(&mut self, name: &str, what: &str) -> Sym {
        self.user(name, what);
        Sym::var(name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_read_alike_through_greek_and_subscripts() {
        assert_eq!(reading("lambda1"), "λ₁");
        assert_eq!(reading("λ₁"), "λ₁");
        assert_eq!(reading("w1"), reading("w₁"));
        assert_eq!(reading("gamma"), reading("γ"));
        assert_ne!(reading("P1"), reading("P11"));
    }

    #[test]
    fn tool_symbols_avoid_every_user_name() {
        // a parameter alpha moves the factors to γ, δ; one called gamma too
        // moves them on (they used to merge with it)
        let mut n = Names::of_parameters([("alpha", "α"), ("gamma", "gamma")]);
        let [a, b] = n.factors();
        assert_eq!(
            (a.to_string(), b.to_string()),
            ("kappa".into(), "nu".into())
        );
        // a printed symbol reserves its reading
        let mut n = Names::of_parameters([("a", "γ"), ("b", "α")]);
        assert_eq!(n.factors()[0].to_string(), "kappa");
        // weights w0…w3 beside parameters w1, w2 take the next letter
        let mut n = Names::of_parameters([("w1", "w₁"), ("w2", "w₂")]);
        let w = n.weights(4);
        assert_eq!(w[1].to_string(), "v1");
        // and the tool's own symbols do not collide either
        let [p, q] = n.points(4);
        assert_eq!(
            (p[0].to_string(), q[3].to_string()),
            ("P0".into(), "Q3".into())
        );
        let [r, _] = n.points(2);
        assert_eq!(r[1].to_string(), "R1");
        let mut n = Names::of_parameters([("h1", "h1"), ("l", "l")]);
        assert_eq!(n.lengths()[1].to_string(), "l2");
        assert_eq!(n.length().to_string(), "h");
        assert_eq!(n.length().to_string(), "k");
    }

    #[test]
    fn fixed_names_are_reserved_or_refused() {
        let mut n = Names::of_parameters([("m", "m"), ("m1", "m1")]);
        let clash = n
            .fixed("m1", "the first segment's copy of `m`")
            .unwrap_err();
        assert!(
            clash.to_string().contains("reads as `m1` (a parameter)"),
            "{clash}"
        );
        assert_eq!(
            n.fixed("m2", "m on the second segment").unwrap(),
            Sym::var("m2")
        );
        assert!(n.fixed("m2", "again").is_err());
    }
}
