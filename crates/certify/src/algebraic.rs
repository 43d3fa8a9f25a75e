//! Real algebraic numbers: a root of a squarefree polynomial over ℚ with an
//! isolating interval, decided rational or irrational exactly.
//!
//! Rationality: if `r = a/b` (lowest terms) is a root of `P ∈ ℤ[x]` with
//! leading coefficient `L`, then `b | L`, so `L·r` is an integer. Once the
//! isolating interval is narrower than `1/|L|`, it contains at most one
//! candidate `k/L`; `P(k/L) = 0` decides. A polynomial of degree 2 or 3
//! without rational roots is irreducible, so it is then the minimal
//! polynomial.

use std::fmt;

use rug::{Integer, Rational};

use crate::sturm::UPoly;

/// A real root of `poly` in `[lo, hi]` (`lo = hi` exactly when the root is
/// that rational; otherwise `poly` has exactly one root in `(lo, hi)` and
/// none at the ends).
#[derive(Debug, Clone, PartialEq)]
pub struct Algebraic {
    /// Squarefree, integer coefficients, positive leading coefficient.
    pub poly: UPoly,
    pub lo: Rational,
    pub hi: Rational,
    /// The root when it is rational (then `lo = hi` is it).
    pub rational: Option<Rational>,
    /// True when `poly` is proved to be the minimal polynomial.
    pub minimal: bool,
}

impl Algebraic {
    /// The root of `poly` isolated in `[lo, hi]` (the invariant of
    /// [`UPoly::isolate`]), decided rational or not.
    pub fn new(poly: &UPoly, lo: Rational, hi: Rational) -> Algebraic {
        let mut a = Algebraic {
            poly: poly.squarefree().integer_primitive(),
            lo,
            hi,
            rational: None,
            minimal: false,
        };
        a.decide_rationality();
        a
    }

    /// True when the isolating interval is a point (the root itself).
    fn is_point(&self) -> bool {
        self.lo == self.hi
    }

    fn decide_rationality(&mut self) {
        if !self.is_point() {
            let lead = self.poly.leading().clone().abs();
            self.refine(&(Rational::from(1) / (lead.clone() * 2u32)));
            if !self.is_point() {
                let k = (lead.clone() * &self.lo).ceil();
                let cand = k / &lead;
                if cand <= self.hi && self.poly.sign_at(&cand) == 0 {
                    self.lo = cand.clone();
                    self.hi = cand;
                }
            }
        }
        if self.is_point() {
            self.rational = Some(self.lo.clone());
            self.poly = UPoly::new(vec![-self.lo.clone(), Rational::from(1)]).integer_primitive();
            self.minimal = true;
        } else {
            self.minimal =
                self.poly.degree() == 2 || (self.poly.degree() == 3 && self.no_rational_root());
        }
    }

    /// No root of `poly` is rational (each real root tested as above).
    fn no_rational_root(&self) -> bool {
        let bound = self.poly.root_bound();
        self.poly
            .isolate(&-bound.clone(), &bound)
            .into_iter()
            .all(|(lo, hi)| {
                let mut other = Algebraic {
                    poly: self.poly.clone(),
                    lo,
                    hi,
                    rational: None,
                    minimal: false,
                };
                if other.is_point() {
                    return false;
                }
                let lead = self.poly.leading().clone().abs();
                other.refine(&(Rational::from(1) / (lead.clone() * 2u32)));
                if other.is_point() {
                    return false;
                }
                let cand = (lead.clone() * &other.lo).ceil() / &lead;
                !(cand <= other.hi && self.poly.sign_at(&cand) == 0)
            })
    }

    /// Bisects the isolating interval until it is narrower than `width`
    /// (or the root is hit exactly).
    pub fn refine(&mut self, width: &Rational) {
        let lo_sign = self.poly.sign_at(&self.lo);
        while !self.is_point() && Rational::from(&self.hi - &self.lo) >= *width {
            let mid = Rational::from(&self.lo + &self.hi) / 2u32;
            match self.poly.sign_at(&mid) {
                0 => {
                    self.lo = mid.clone();
                    self.hi = mid;
                }
                s if s == lo_sign => self.lo = mid,
                _ => self.hi = mid,
            }
        }
    }

    /// Compares with a rational: `Less` when the root is below `q`.
    pub fn cmp_rational(&mut self, q: &Rational) -> std::cmp::Ordering {
        use std::cmp::Ordering;
        loop {
            if self.hi < *q {
                return Ordering::Less;
            }
            if self.lo > *q {
                return Ordering::Greater;
            }
            if self.is_point() {
                return self.lo.cmp(q);
            }
            if self.poly.sign_at(q) == 0 {
                return Ordering::Equal;
            }
            let half = Rational::from(&self.hi - &self.lo) / 2u32;
            self.refine(&half);
        }
    }

    /// An f64 approximation (the midpoint of the isolating interval).
    pub fn to_f64(&self) -> f64 {
        (Rational::from(&self.lo + &self.hi) / 2u32).to_f64()
    }

    /// The polynomial in `var`, e.g. `λ² − 4λ − 4`.
    pub fn poly_text(&self, var: &str) -> String {
        self.poly.display(var)
    }

    /// `rational`, or `root of P in [lo, hi]` with decimal ends rounded
    /// outward (`digits` after the point; refine first for more).
    pub fn describe(&self, var: &str, digits: usize) -> String {
        if let Some(q) = &self.rational {
            return q.to_string();
        }
        let kind = if self.minimal {
            "minimal polynomial"
        } else {
            "a root of the squarefree"
        };
        format!(
            "the root of {} = 0 in [{}, {}] ({kind}{})",
            self.poly_text(var),
            decimal(&self.lo, digits, false),
            decimal(&self.hi, digits, true),
            if self.minimal {
                String::new()
            } else {
                format!(
                    " polynomial of degree {}; irreducibility not checked",
                    self.poly.degree()
                )
            }
        )
    }
}

impl fmt::Display for Algebraic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.describe("x", 12))
    }
}

/// `q` to `digits` decimals, rounded down (or up when `up`).
pub fn decimal(q: &Rational, digits: usize, up: bool) -> String {
    let scale = Integer::from(Integer::u_pow_u(10, digits as u32));
    let scaled = Rational::from(q * &scale);
    let n = if up { scaled.ceil() } else { scaled.floor() };
    let n = n.numer().clone();
    let negative = n < 0;
    let text = n.abs().to_string();
    let text = format!("{text:0>width$}", width = digits + 1);
    let (int, frac) = text.split_at(text.len() - digits);
    format!("{}{int}.{frac}", if negative { "-" } else { "" })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn irrational_and_rational_roots_are_told_apart() {
        // λ² − 4λ − 4: roots 2 ± 2√2
        let p = UPoly::new(vec![q(-4, 1), q(-4, 1), q(1, 1)]);
        let iv = p.isolate(&q(0, 1), &q(10, 1));
        assert_eq!(iv.len(), 1);
        let mut a = Algebraic::new(&p, iv[0].0.clone(), iv[0].1.clone());
        assert!(a.rational.is_none() && a.minimal);
        a.refine(&q(1, 1_000_000_000_000));
        let text = a.describe("λ", 11);
        assert!(
            text.contains("λ^2 - 4*λ - 4 = 0 in [4.82842712474, 4.82842712475]"),
            "{text}"
        );
        assert_eq!(a.cmp_rational(&q(4828, 1000)), std::cmp::Ordering::Greater);
        // (3λ − 2)(λ² + 1): the rational root 2/3 is found though isolated
        // by an interval
        let r = UPoly::new(vec![q(-2, 1), q(3, 1), q(-2, 1), q(3, 1)]);
        let a = Algebraic::new(&r, q(1, 2), q(1, 1));
        assert_eq!(a.rational, Some(q(2, 3)));
        assert_eq!(a.describe("m", 5), "2/3");
        // x³ − 2 has no rational root: minimal polynomial
        let c = UPoly::new(vec![q(-2, 1), q(0, 1), q(0, 1), q(1, 1)]);
        let a = Algebraic::new(&c, q(1, 1), q(2, 1));
        assert!(a.rational.is_none() && a.minimal);
    }

    #[test]
    fn decimals_round_outward() {
        assert_eq!(decimal(&q(2, 3), 3, false), "0.666");
        assert_eq!(decimal(&q(2, 3), 3, true), "0.667");
        assert_eq!(decimal(&q(-2, 3), 2, false), "-0.67");
        assert_eq!(decimal(&q(5, 1), 2, true), "5.00");
    }
}
