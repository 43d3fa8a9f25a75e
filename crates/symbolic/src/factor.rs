//! Factorisation for display: `p = u · Π fᵢ^eᵢ` with a rational unit `u`
//! and primitive factors `fᵢ` of positive leading coefficient, so that a
//! residual reads `(m₂ + 2)·(m₁ − m₂)` rather than `m₁·m₂ − m₂² + 2·m₁ − 2·m₂`.
//!
//! The steps, each exact (the product of the factors is `p`, checked by the
//! tests), none a search:
//!
//! 1. the rational content and the sign ([`Poly::canonical`]);
//! 2. the monomial content (`m²·s·(…)` gives the factors `m`, `m`, `s`);
//! 3. the largest factor free of `s`, `c`: the gcd of the coefficients of
//!    `p` over the monomials in `s`, `c` (a free basis over the other
//!    variables, see [`crate::gcd`]); the rest stays one factor, since
//!    `ℚ[…][s, c]/(s² + c² − 1)` is not a unique factorisation domain;
//! 4. in `ℚ[x₁, …, x_k]` (a unique factorisation domain): the content with
//!    respect to each variable (the gcd of the coefficients in `x`, by the
//!    primitive remainder sequences of [`crate::gcd`]), recursively;
//! 5. the square-free decomposition of each primitive part (Yun/Musser:
//!    `gcd(f, ∂f/∂x)`);
//! 6. linear factors of univariate parts from their rational roots.
//!
//! This is not a complete factorisation into irreducibles (a product of two
//! factors in the same variables, each square-free and without rational
//! roots, stays one factor), which is all display needs. Steps 3–6 run only
//! for polynomials of at most [`FULL_LIMIT`] terms (gcds of large dense
//! polynomials are costly); larger ones get steps 1–2.

use std::collections::{BTreeMap, HashMap};
use std::sync::{Mutex, OnceLock, PoisonError};

use rug::Rational;
use rug::ops::Pow;

use crate::gcd::{coefficients_over, gcd_free, monomial_content, split_content};
use crate::poly::Poly;
use crate::sym::Sym;

/// Polynomials with more terms get only the content steps.
pub const FULL_LIMIT: usize = 300;

/// Rational roots are searched only when both end coefficients are at most
/// this large (the candidates are the quotients of their divisors).
const ROOT_COEFFICIENT_LIMIT: u64 = 1_000_000;

/// `unit · Π factorᵉ`: factors primitive with positive leading coefficient,
/// sorted (fewest terms first), each listed once.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Factored {
    pub unit: Rational,
    pub factors: Vec<(Poly, u32)>,
}

impl Factored {
    /// The product, multiplied out.
    pub fn expand(&self) -> Poly {
        self.factors
            .iter()
            .fold(Poly::constant(self.unit.clone()), |acc, (f, e)| {
                acc * &f.pow(*e)
            })
    }

    /// True when the factorisation shows nothing the expanded form does not:
    /// at most one factor, to the first power.
    pub fn is_trivial(&self) -> bool {
        match self.factors.as_slice() {
            [] => true,
            [(_, e)] => *e == 1,
            _ => false,
        }
    }
}

/// A quotient `num / den` with both sides factored: `unit · Π numᵉ / Π denᵉ`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FactoredQuotient {
    pub unit: Rational,
    pub num: Vec<(Poly, u32)>,
    pub den: Vec<(Poly, u32)>,
    /// True when the factored form shows nothing the plain form does not
    /// (the numerator is one factor, the denominator factors did not split).
    pub trivial: bool,
}

/// How many factorisations a process keeps: the audit of the five
/// documents asks for under 1000; past the bound the memo starts afresh, so
/// a long-running front end stays bounded.
pub const FACTOR_MEMO: usize = 2048;

/// `f` as the factorisation of `p` in `memo` (the one already there if
/// another thread was first), the memo emptied first when it holds `bound`.
fn remember(memo: &mut HashMap<Poly, Factored>, p: &Poly, f: Factored, bound: usize) -> Factored {
    if memo.len() >= bound && !memo.contains_key(p) {
        memo.clear();
    }
    memo.entry(p.clone()).or_insert(f).clone()
}

impl Poly {
    /// The display factorisation (see the [module documentation](self)).
    ///
    /// Computed once per process for each polynomial: the same denominators
    /// and residuals are shown again and again. The key is the polynomial
    /// itself (every term); at most [`FACTOR_MEMO`] are kept.
    pub fn factor(&self) -> Factored {
        static FACTORED: OnceLock<Mutex<HashMap<Poly, Factored>>> = OnceLock::new();
        let memo = FACTORED.get_or_init(Default::default);
        let lock = || memo.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(f) = lock().get(self) {
            return f.clone();
        }
        let f = self.factor_once();
        remember(&mut lock(), self, f, FACTOR_MEMO)
    }

    fn factor_once(&self) -> Factored {
        let mut acc = Accumulator {
            unit: Rational::from(1),
            ..Accumulator::default()
        };
        if self.is_zero() {
            acc.unit = Rational::new();
            return acc.finish();
        }
        acc.push(self, 1);
        acc.finish()
    }
}

impl Sym {
    /// The numerator factored over the denominator, each denominator factor
    /// factored too (see [`Poly::factor`]).
    pub fn factored(&self) -> FactoredQuotient {
        let num = self.numerator().factor();
        let trivial = num.is_trivial();
        let mut unit = num.unit;
        let mut den: BTreeMap<Poly, u32> = BTreeMap::new();
        for (f, e) in self.denominator() {
            let g = f.factor();
            unit /= g.unit.clone().pow(*e);
            for (h, k) in g.factors {
                *den.entry(h).or_insert(0) += k * e;
            }
        }
        let split = den.len() != self.denominator().len()
            || den
                .iter()
                .any(|(f, e)| self.denominator().get(f) != Some(e));
        FactoredQuotient {
            unit,
            num: num.factors,
            den: sorted(den),
            trivial: trivial && !split,
        }
    }
}

fn sorted(map: BTreeMap<Poly, u32>) -> Vec<(Poly, u32)> {
    let mut v: Vec<(Poly, u32)> = map.into_iter().collect();
    v.sort_by(|(a, _), (b, _)| {
        let lead = |p: &Poly| p.leading_term().map(|(m, _)| m.clone());
        a.len()
            .cmp(&b.len())
            .then_with(|| lead(b).cmp(&lead(a)))
            .then_with(|| a.cmp(b))
    });
    v
}

/// Collects factors with their multiplicities; the unit absorbs every
/// constant and sign.
#[derive(Default)]
struct Accumulator {
    unit: Rational,
    factors: BTreeMap<Poly, u32>,
}

impl Accumulator {
    fn finish(self) -> Factored {
        Factored {
            unit: self.unit,
            factors: sorted(self.factors),
        }
    }

    /// Records `pᵉ` as one factor (made canonical).
    fn record(&mut self, p: &Poly, e: u32) {
        let (u, f) = p.canonical();
        self.unit *= u.clone().pow(e);
        if f.as_constant().is_none() {
            *self.factors.entry(f).or_insert(0) += e;
        }
    }

    /// Factors `pᵉ` (steps 1–3) and records the factors.
    fn push(&mut self, p: &Poly, e: u32) {
        let (u, p) = p.canonical();
        self.unit *= u.clone().pow(e);
        if p.as_constant().is_some() {
            return;
        }
        let p = self.take_monomials(&p, e);
        if p.as_constant().is_some() {
            return;
        }
        if p.len() > FULL_LIMIT {
            self.record(&p, e);
            return;
        }
        if !p.is_trig() {
            self.split(&p, e);
            return;
        }
        let free = trig_free_part(&p);
        match free {
            Some(g) => match p.exact_div(&g) {
                Some(rest) => {
                    self.split(&g, e);
                    self.record(&rest, e);
                }
                None => self.record(&p, e),
            },
            None => self.record(&p, e),
        }
    }

    /// Removes the monomial content of `p` as single-variable factors.
    fn take_monomials(&mut self, p: &Poly, e: u32) -> Poly {
        let mono = monomial_content(p);
        if mono.is_one() {
            return p.clone();
        }
        for (v, k) in mono.factors() {
            *self.factors.entry(Poly::var(v.name())).or_insert(0) += k * e;
        }
        let m = Poly::term(mono, Rational::from(1));
        p.exact_div(&m).expect("the monomial content divides")
    }

    /// Steps 4–6 for `pᵉ`, `p` free of `s`, `c`.
    fn split(&mut self, p: &Poly, e: u32) {
        let (u, p) = p.canonical();
        self.unit *= u.clone().pow(e);
        if p.as_constant().is_some() {
            return;
        }
        let p = self.take_monomials(&p, e);
        if p.as_constant().is_some() {
            return;
        }
        let vars = p.variables();
        for x in &vars {
            let (content, primitive) = split_content(&p, x);
            if content.as_constant().is_none() {
                self.split(&content, e);
                self.split(&primitive, e);
                return;
            }
        }
        for x in &vars {
            if p.degree_in(x) < 2 {
                continue;
            }
            let parts = square_free(&p, x);
            if parts.len() > 1 || parts.iter().any(|(_, k)| *k > 1) {
                for (z, k) in parts {
                    self.split(&z, e * k);
                }
                return;
            }
        }
        if vars.len() == 1
            && let Some(x) = vars.first()
            && p.degree_in(x) >= 2
            && let Some((linear, rest)) = rational_root(&p, x)
        {
            self.record(&linear, e);
            self.split(&rest, e);
            return;
        }
        self.record(&p, e);
    }
}

/// The largest factor of `p` free of `s`, `c` (nonconstant), if any.
fn trig_free_part(p: &Poly) -> Option<Poly> {
    let keep: std::collections::BTreeSet<String> = p
        .variables()
        .into_iter()
        .filter(|v| v != crate::var::SIN && v != crate::var::COS)
        .collect();
    if keep.is_empty() {
        return None;
    }
    let mut coefficients: Vec<Poly> = coefficients_over(p, &keep).into_values().collect();
    coefficients.sort_by_key(Poly::len);
    let mut g = Poly::zero();
    for c in &coefficients {
        g = gcd_free(&g, c);
        if g.as_constant().is_some() {
            return None;
        }
    }
    Some(g)
}

/// The square-free decomposition of `p` (primitive, free of `s`, `c`) with
/// respect to `x` (Musser's algorithm): `p = Π zᵢⁱ`, the `zᵢ` square-free and
/// pairwise coprime. Returns `[(p, 1)]` when `p` is square-free in `x` (or
/// when a division is not exact, which would be a defect: nothing is lost).
fn square_free(p: &Poly, x: &str) -> Vec<(Poly, u32)> {
    let trivial = vec![(p.clone(), 1)];
    let mut c = gcd_free(p, &p.diff(x));
    if c.as_constant().is_some() {
        return trivial;
    }
    let Some(mut w) = p.exact_div(&c) else {
        return trivial;
    };
    let mut out = Vec::new();
    let mut i = 1;
    while c.as_constant().is_none() {
        let y = gcd_free(&w, &c);
        let (Some(z), Some(next_c)) = (w.exact_div(&y), c.exact_div(&y)) else {
            return trivial;
        };
        if z.as_constant().is_none() {
            out.push((z, i));
        }
        i += 1;
        w = y;
        c = next_c;
    }
    if w.as_constant().is_none() {
        out.push((w, i));
    }
    out
}

/// A rational root `a/b` of the univariate `p` (integer coefficients):
/// the linear factor `b·x − a` and the quotient.
fn rational_root(p: &Poly, x: &str) -> Option<(Poly, Poly)> {
    let coefficients = p.coefficients_in(x);
    let small = |c: &Poly| {
        c.as_constant()
            .and_then(|q| q.numer().clone().abs().to_u64())
            .is_some_and(|n| n != 0 && n <= ROOT_COEFFICIENT_LIMIT)
    };
    if !small(coefficients.first()?) || !small(coefficients.last()?) {
        return None;
    }
    let (roots, _) = crate::roots::rational_roots(p, x);
    let root = roots.first()?;
    let linear = Poly::constant(Rational::from(root.denom().clone())) * &Poly::var(x)
        - &Poly::constant(Rational::from(root.numer().clone()));
    let rest = p.exact_div(&linear)?;
    Some((linear, rest))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn v(n: &str) -> Poly {
        Poly::var(n)
    }

    #[test]
    fn the_memo_stays_within_its_bound() {
        let mut memo = HashMap::new();
        for k in 0..10 {
            let p = v("m") + &Poly::int(k);
            let f = remember(&mut memo, &p, p.factor_once(), 4);
            assert_eq!(f, p.factor_once());
            assert!(memo.len() <= 4, "{} entries", memo.len());
        }
        // a polynomial already kept is found, not a reason to start afresh
        let kept = memo.keys().next().unwrap().clone();
        let before = memo.len();
        remember(&mut memo, &kept, kept.factor_once(), before);
        assert_eq!(memo.len(), before);
    }

    fn n(k: i64) -> Poly {
        Poly::int(k)
    }

    fn shown(p: &Poly) -> Vec<(String, u32)> {
        let f = p.factor();
        assert_eq!(f.expand(), *p, "the factors multiply back");
        f.factors.iter().map(|(g, e)| (g.to_string(), *e)).collect()
    }

    #[test]
    fn contents_in_each_variable_split_a_join_residual() {
        // m₁m₂ − m₂² + 2m₁ − 2m₂ = (m₁ − m₂)(m₂ + 2)
        let (m1, m2) = (v("m1"), v("m2"));
        let p = &(&(&(&m1 * &m2) - &(&m2 * &m2)) + &(&n(2) * &m1)) - &(&n(2) * &m2);
        assert_eq!(shown(&p), [("m1 - m2".into(), 1), ("m2 + 2".into(), 1)]);
        assert_eq!(p.factor().unit, 1);
    }

    #[test]
    fn repeated_factors_rational_roots_and_units() {
        let m = v("m");
        // −6(m + 2)²(2m − 1) m³
        let p = &(&(&n(-6) * &(&m + &n(2)).pow(2)) * &(&(&n(2) * &m) - &n(1))) * &m.pow(3);
        let f = p.factor();
        assert_eq!(f.expand(), p);
        assert_eq!(f.unit, -6);
        let mut got: Vec<(String, u32)> =
            f.factors.iter().map(|(g, e)| (g.to_string(), *e)).collect();
        got.sort();
        assert_eq!(
            got,
            [
                ("2*m - 1".to_string(), 1),
                ("m".to_string(), 3),
                ("m + 2".to_string(), 2)
            ]
        );
        // square-free: the linear factors come from the rational roots 1/2, −3
        let q = &(&(&(&n(2) * &m) - &n(1)) * &(&m + &n(3))) * &(&m.pow(2) + &n(1));
        let mut got: Vec<String> = q
            .factor()
            .factors
            .iter()
            .map(|(g, _)| g.to_string())
            .collect();
        got.sort();
        assert_eq!(got, ["2*m - 1", "m + 3", "m^2 + 1"]);
    }

    #[test]
    fn trigonometric_parts_keep_their_parameter_factors() {
        let (m, s, c) = (v("m"), v("s"), v("c"));
        // (m + 2)·(s·c − c²)·λ: s·c − c² = c(s − c)
        let p = &(&(&m + &n(2)) * &(&(&s * &c) - &c.pow(2))) * &v("lambda");
        let got = shown(&p);
        assert!(got.contains(&("m + 2".into(), 1)), "{got:?}");
        assert!(got.contains(&("c".into(), 1)), "{got:?}");
        assert!(got.contains(&("lambda".into(), 1)), "{got:?}");
        assert!(got.contains(&("s - c".into(), 1)), "{got:?}");
    }

    #[test]
    fn quotients_factor_both_sides() {
        let (m1, m2) = (Sym::var("m1"), Sym::var("m2"));
        let two = Sym::int(2);
        let x = (m1.clone() - &m2) * &(m2.clone() + &two) * &Sym::int(3)
            / &((m1.clone() + &two) * &Sym::int(4));
        let f = x.factored();
        assert_eq!(f.unit, Rational::from((3, 4)));
        assert_eq!(f.num.len(), 2);
        assert_eq!(f.den.len(), 1);
        assert!(!f.trivial);
        assert!(Sym::var("m").factored().trivial);
    }

    #[test]
    fn large_polynomials_get_only_the_content_steps() {
        let x = v("x");
        let p = (0..=FULL_LIMIT as u32).fold(Poly::zero(), |acc, k| acc + &(x.pow(k) * &v("y")));
        let f = p.factor();
        assert_eq!(f.expand(), p);
        assert_eq!(f.factors.len(), 2); // y · (big)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Whatever the input, the factors multiply back to it exactly.
        #[test]
        fn factors_multiply_back(
            a in proptest::collection::vec((-3i64..=3, 0u32..=2, 0u32..=2, 0u32..=1), 1..6),
            b in proptest::collection::vec((-3i64..=3, 0u32..=2, 0u32..=2, 0u32..=1), 1..4),
        ) {
            let build = |t: &[(i64, u32, u32, u32)]| t.iter().fold(Poly::zero(), |acc, (k, i, j, l)| {
                acc + &(&(&(n(*k) * &v("m").pow(*i)) * &v("beta").pow(*j)) * &v("c").pow(*l))
            });
            let p = &build(&a) * &build(&b);
            prop_assert_eq!(p.factor().expand(), p);
        }
    }
}
