//! Real algebraic numbers: a root of a squarefree polynomial over ℚ with an
//! isolating interval, decided rational or irrational exactly.
//!
//! Rationality: if `r = a/b` (lowest terms) is a root of `P ∈ ℤ[x]` with
//! leading coefficient `L`, then `b | L`, so `L·r` is an integer. Once the
//! isolating interval is narrower than `1/|L|`, it contains at most one
//! candidate `k/L`; `P(k/L) = 0` decides. An irrational root keeps only
//! the factor of its polynomial without rational roots (each rational root
//! `r` found this way divides out as `x − r`); a polynomial of degree 2 or 3
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

    /// `a + b√k` (`k ≥ 1` an integer): a root of `(x − a)² − b²k`, the
    /// larger one for `b > 0`, the smaller for `b < 0` (`a` itself for
    /// `b = 0` or a square `k`).
    pub fn surd(a: &Rational, b: &Rational, k: u32) -> Algebraic {
        let shifted = UPoly::new(vec![-a.clone(), Rational::from(1)]);
        let poly = shifted
            .mul(&shifted)
            .sub(&UPoly::new(vec![Rational::from(b * b) * k]));
        let bound = poly.root_bound();
        let roots = poly.isolate(&-bound.clone(), &bound);
        let pick = if *b < 0 { roots.first() } else { roots.last() };
        let (lo, hi) = pick.cloned().unwrap_or_else(|| (a.clone(), a.clone()));
        Algebraic::new(&poly, lo, hi)
    }

    /// The exact order of two real algebraic numbers: equal when their
    /// polynomials have a common root in both isolating intervals (then it
    /// is the only root of each there), otherwise the intervals are
    /// narrowed until they are apart.
    pub fn cmp(&mut self, other: &mut Algebraic) -> std::cmp::Ordering {
        use std::cmp::Ordering;
        if let Some(q) = other.rational.clone() {
            return self.cmp_rational(&q);
        }
        if let Some(q) = self.rational.clone() {
            return other.cmp_rational(&q).reverse();
        }
        let common = self.poly.gcd(&other.poly);
        let (lo, hi) = (
            (&self.lo).max(&other.lo).clone(),
            (&self.hi).min(&other.hi).clone(),
        );
        if common.degree() > 0 && lo <= hi && common.count_roots(&lo, &hi) > 0 {
            return Ordering::Equal;
        }
        loop {
            if self.hi < other.lo {
                return Ordering::Less;
            }
            if other.hi < self.lo {
                return Ordering::Greater;
            }
            let (w1, w2) = (
                Rational::from(&self.hi - &self.lo) / 2u32,
                Rational::from(&other.hi - &other.lo) / 2u32,
            );
            self.refine(&w1);
            other.refine(&w2);
        }
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
            for r in self.rational_roots() {
                let (quotient, _) = self.poly.div_rem(&UPoly::new(vec![-r, Rational::from(1)]));
                self.poly = quotient.integer_primitive();
            }
            // no rational root is left: degree 2 or 3 is irreducible
            self.minimal = matches!(self.poly.degree(), 2 | 3);
        }
    }

    /// The rational roots of `poly` (each real root isolated and tested as
    /// above).
    fn rational_roots(&self) -> Vec<Rational> {
        let bound = self.poly.root_bound();
        let lead = self.poly.leading().clone().abs();
        self.poly
            .isolate(&-bound.clone(), &bound)
            .into_iter()
            .filter_map(|(lo, hi)| {
                let mut other = Algebraic {
                    poly: self.poly.clone(),
                    lo,
                    hi,
                    rational: None,
                    minimal: false,
                };
                if !other.is_point() {
                    other.refine(&(Rational::from(1) / (lead.clone() * 2u32)));
                }
                if other.is_point() {
                    return Some(other.lo);
                }
                let cand = (lead.clone() * &other.lo).ceil() / &lead;
                (cand <= other.hi && self.poly.sign_at(&cand) == 0).then_some(cand)
            })
            .collect()
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
    fn surds_are_ordered_exactly() {
        use std::cmp::Ordering::{Equal, Greater, Less};
        // 2 + 2√2 against the root of the boundary polynomial
        // 3λ⁶ − 10λ⁵ − 32λ⁴ + 32λ³ + 80λ² + 32λ in [4, 5]: the same number
        let mut printed = Algebraic::surd(&q(2, 1), &q(2, 1), 2);
        let c = |k: i64| q(k, 1);
        let boundary = UPoly::new(vec![c(0), c(32), c(80), c(32), c(-32), c(-10), c(3)]);
        let iv = boundary.isolate(&q(4, 1), &q(5, 1));
        let mut end = Algebraic::new(&boundary, iv[0].0.clone(), iv[0].1.clone());
        assert_eq!(printed.cmp(&mut end), Equal);
        assert_eq!(end.cmp(&mut printed), Equal);
        // 2 − 2√2 < 0 < (1 + √5)/2 < 2 = 2 + 0·√3; √2 + 1 against √3 + 1
        let mut below = Algebraic::surd(&q(2, 1), &q(-2, 1), 2);
        assert_eq!(below.cmp_rational(&q(0, 1)), Less);
        let mut golden = Algebraic::surd(&q(1, 2), &q(1, 2), 5);
        assert_eq!(golden.cmp(&mut below), Greater);
        let mut two = Algebraic::surd(&q(2, 1), &q(0, 1), 3);
        assert_eq!(two.rational, Some(q(2, 1)));
        assert_eq!(golden.cmp(&mut two), Less);
        let mut r2 = Algebraic::surd(&q(1, 1), &q(1, 1), 2);
        let mut r3 = Algebraic::surd(&q(1, 1), &q(1, 1), 3);
        assert_eq!(r2.cmp(&mut r3), Less);
        assert_eq!(r3.cmp(&mut r2), Greater);
        // a root close to but not equal to 2 + 2√2
        let near = UPoly::new(vec![q(-48_284_271, 10_000_000), q(1, 1)]);
        let mut n = Algebraic::new(&near, q(4, 1), q(5, 1));
        assert_eq!(printed.cmp(&mut n), Greater);
    }

    /// The boundary polynomial of `examples/squares-han.toml`'s upper end:
    /// `3λ⁶ − 10λ⁵ − 32λ⁴ + 32λ³ + 80λ² + 32λ = λ(λ − 2)(λ + 2)(3λ + 2)(λ² − 4λ − 4)`
    /// (SymPy): the rational roots divide out and `λ² − 4λ − 4` is minimal.
    #[test]
    fn rational_roots_divide_out_to_the_minimal_polynomial() {
        let c = |k: i64| q(k, 1);
        let p = UPoly::new(vec![c(0), c(32), c(80), c(32), c(-32), c(-10), c(3)]);
        let iv = p.isolate(&q(4, 1), &q(5, 1));
        assert_eq!(iv.len(), 1);
        let a = Algebraic::new(&p, iv[0].0.clone(), iv[0].1.clone());
        assert!(a.rational.is_none() && a.minimal);
        assert_eq!(a.poly_text("λ"), "λ^2 - 4*λ - 4");
        // x³ − 2 has no rational root: minimal as it is; with the factor x − 1, too
        let cube = UPoly::new(vec![c(-2), c(0), c(0), c(1)]);
        let with_one = cube.mul(&UPoly::new(vec![c(-1), c(1)]));
        let iv = with_one.isolate(&q(5, 4), &q(3, 2));
        let b = Algebraic::new(&with_one, iv[0].0.clone(), iv[0].1.clone());
        assert!(b.minimal && b.poly.degree() == 3, "{}", b.poly_text("x"));
        // degree 4 without rational roots: not called minimal
        let quartic = UPoly::new(vec![c(-2), c(0), c(0), c(0), c(1)]);
        let iv = quartic.isolate(&q(1, 1), &q(2, 1));
        let d = Algebraic::new(&quartic, iv[0].0.clone(), iv[0].1.clone());
        assert!(!d.minimal && d.poly.degree() == 4);
    }

    #[test]
    fn decimals_round_outward() {
        assert_eq!(decimal(&q(2, 3), 3, false), "0.666");
        assert_eq!(decimal(&q(2, 3), 3, true), "0.667");
        assert_eq!(decimal(&q(-2, 3), 2, false), "-0.67");
        assert_eq!(decimal(&q(5, 1), 2, true), "5.00");
    }
}
