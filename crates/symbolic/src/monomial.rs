//! Monomials: products of variables with positive exponents, ordered by the
//! graded lexicographic monomial order.
//!
//! A monomial `a` is greater than `b` when its total degree is larger, or,
//! at equal degree, when at the first variable (in the fixed variable order
//! of [`crate::var`]) where their exponents differ, `a` has the larger
//! exponent. This is a monomial order (compatible with multiplication), used
//! both for division and for printing (greatest term first). Since `s`
//! precedes `c`, `s²` is greater than `c²`, so the rewriting
//! `s² → 1 − c²` only produces smaller monomials.

use std::cmp::Ordering;
use std::fmt;

use crate::var::Var;

/// A product `x₁^e₁ ⋯ x_k^e_k` with variables sorted by the variable order
/// and exponents `≥ 1`; the empty product is `1`.
#[derive(Clone, Default, PartialEq, Eq, Hash)]
pub struct Monomial {
    factors: Vec<(Var, u32)>,
    /// The total degree, `Σ eᵢ` (kept: the order compares it first).
    degree: u64,
}

impl Monomial {
    fn from_factors(factors: Vec<(Var, u32)>) -> Monomial {
        let degree = factors.iter().map(|(_, e)| u64::from(*e)).sum();
        Monomial { factors, degree }
    }

    /// The monomial `1`.
    pub fn one() -> Monomial {
        Monomial::default()
    }

    /// `vᵉ` (`1` when `e = 0`).
    pub fn var(v: Var, e: u32) -> Monomial {
        if e == 0 {
            Monomial::one()
        } else {
            Monomial {
                factors: vec![(v, e)],
                degree: u64::from(e),
            }
        }
    }

    /// True for the empty product.
    pub fn is_one(&self) -> bool {
        self.factors.is_empty()
    }

    /// Total degree.
    pub fn degree(&self) -> u64 {
        self.degree
    }

    /// The exponent of the variable `name` (0 when absent).
    pub fn exponent(&self, name: &str) -> u32 {
        self.factors
            .iter()
            .find(|(v, _)| v.name() == name)
            .map_or(0, |(_, e)| *e)
    }

    /// The exponent of the variable `v` (0 when absent).
    pub fn exponent_of(&self, v: Var) -> u32 {
        self.factors
            .iter()
            .find(|(w, _)| *w == v)
            .map_or(0, |(_, e)| *e)
    }

    /// The variables with their exponents, in the variable order.
    pub fn factors(&self) -> impl Iterator<Item = (&Var, u32)> {
        self.factors.iter().map(|(v, e)| (v, *e))
    }

    /// `self · other`.
    pub fn mul(&self, other: &Monomial) -> Monomial {
        let (a, b) = (&self.factors, &other.factors);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                Ordering::Less => {
                    out.push(a[i]);
                    i += 1;
                }
                Ordering::Greater => {
                    out.push(b[j]);
                    j += 1;
                }
                Ordering::Equal => {
                    out.push((a[i].0, a[i].1 + b[j].1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Monomial {
            factors: out,
            degree: self.degree + other.degree,
        }
    }

    /// `self / other` when `other` divides `self`.
    pub fn checked_div(&self, other: &Monomial) -> Option<Monomial> {
        let mut out = Vec::with_capacity(self.factors.len());
        let mut rest = other.factors.iter().peekable();
        for (v, e) in &self.factors {
            let d = match rest.peek() {
                Some((w, f)) if w == v => {
                    rest.next();
                    *f
                }
                _ => 0,
            };
            match e.cmp(&d) {
                Ordering::Less => return None,
                Ordering::Equal => {}
                Ordering::Greater => out.push((*v, e - d)),
            }
        }
        if rest.next().is_some() {
            return None;
        }
        Some(Monomial {
            factors: out,
            degree: self.degree - other.degree,
        })
    }

    /// The greatest common divisor (minimum exponents).
    pub fn gcd(&self, other: &Monomial) -> Monomial {
        let factors = self
            .factors
            .iter()
            .filter_map(|(v, e)| {
                let f = other.exponent_of(*v);
                (f > 0).then(|| (*v, (*e).min(f)))
            })
            .collect();
        Monomial::from_factors(factors)
    }

    /// `(inside, outside)`: the factors whose variable satisfies `keep`, and
    /// the others (`self = inside · outside`).
    pub fn partition(&self, keep: impl Fn(&Var) -> bool) -> (Monomial, Monomial) {
        let (inside, outside) = self.factors.iter().cloned().partition(|(v, _)| keep(v));
        (
            Monomial::from_factors(inside),
            Monomial::from_factors(outside),
        )
    }

    /// The monomial without the variable `name`, and the exponent it had.
    pub fn split(&self, name: &str) -> (Monomial, u32) {
        match Var::find(name) {
            Some(v) => self.split_off(v),
            None => (self.clone(), 0),
        }
    }

    /// The monomial without the variable `v`, and the exponent it had.
    pub fn split_off(&self, v: Var) -> (Monomial, u32) {
        let mut e = 0;
        let factors = self
            .factors
            .iter()
            .filter(|(w, k)| {
                let hit = *w == v;
                if hit {
                    e = *k;
                }
                !hit
            })
            .cloned()
            .collect();
        (
            Monomial {
                factors,
                degree: self.degree - u64::from(e),
            },
            e,
        )
    }
}

/// Lexicographic comparison of exponent vectors (earlier variables weigh
/// more).
fn lex(a: &[(Var, u32)], b: &[(Var, u32)]) -> Ordering {
    for pair in a.iter().zip(b) {
        let ((va, ea), (vb, eb)) = pair;
        match va.cmp(vb) {
            // `a` has the earlier variable, which `b` lacks.
            Ordering::Less => return Ordering::Greater,
            Ordering::Greater => return Ordering::Less,
            Ordering::Equal if ea != eb => return ea.cmp(eb),
            Ordering::Equal => {}
        }
    }
    a.len().cmp(&b.len())
}

impl Ord for Monomial {
    fn cmp(&self, other: &Self) -> Ordering {
        self.degree
            .cmp(&other.degree)
            .then_with(|| lex(&self.factors, &other.factors))
    }
}

impl PartialOrd for Monomial {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl fmt::Debug for Monomial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_one() {
            return f.write_str("1");
        }
        let parts: Vec<String> = self
            .factors
            .iter()
            .map(|(v, e)| {
                if *e == 1 {
                    v.to_string()
                } else {
                    format!("{v}^{e}")
                }
            })
            .collect();
        f.write_str(&parts.join("*"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mono(parts: &[(&str, u32)]) -> Monomial {
        parts.iter().fold(Monomial::one(), |m, (n, e)| {
            m.mul(&Monomial::var(Var::new(n), *e))
        })
    }

    #[test]
    fn graded_lex_order() {
        let m2 = mono(&[("m", 2)]);
        let ms = mono(&[("m", 1), ("s", 1)]);
        let s2 = mono(&[("s", 2)]);
        let c2 = mono(&[("c", 2)]);
        let m = mono(&[("m", 1)]);
        assert!(m2 > ms && ms > s2 && s2 > c2 && c2 > m && m > Monomial::one());
        assert!(mono(&[("s", 1), ("c", 1)]) > c2);
    }

    #[test]
    fn multiply_divide_split() {
        let a = mono(&[("m", 1), ("c", 2)]);
        let b = mono(&[("s", 1), ("c", 1)]);
        let p = a.mul(&b);
        assert_eq!(format!("{p:?}"), "m*s*c^3");
        assert_eq!(p.checked_div(&b), Some(a.clone()));
        assert_eq!(a.checked_div(&b), None);
        assert_eq!(p.split("c"), (mono(&[("m", 1), ("s", 1)]), 3));
        assert_eq!(p.exponent("s"), 1);
        assert_eq!(p.degree(), 5);
        assert_eq!(
            p.gcd(&mono(&[("m", 2), ("c", 1), ("t", 1)])),
            mono(&[("m", 1), ("c", 1)])
        );
    }
}
