//! Exact univariate polynomials over ℚ and their real roots.
//!
//! Sturm's theorem: for a polynomial `p` with Sturm sequence
//! `p₀ = p, p₁ = p', p_{k+1} = −rem(p_{k−1}, p_k)`, the number of distinct
//! real roots in `(a, b]` is `V(a) − V(b)`, `V(x)` the number of sign changes
//! of `(p₀(x), p₁(x), …)` (zeros skipped). Roots are isolated by exact
//! bisection in rational arithmetic; nothing is rounded.

use rug::Rational;
use trig_symbolic::Poly;

/// `Σ aᵢ xⁱ` with rational coefficients, lowest degree first, no trailing
/// zeros (the zero polynomial is empty).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UPoly(Vec<Rational>);

impl UPoly {
    /// From coefficients, lowest degree first.
    pub fn new(mut coeffs: Vec<Rational>) -> UPoly {
        while coeffs.last().is_some_and(|c| *c == 0) {
            coeffs.pop();
        }
        UPoly(coeffs)
    }

    /// A symbolic polynomial in the single variable `var`, or `None` when
    /// another variable occurs.
    pub fn from_poly(p: &Poly, var: &str) -> Option<UPoly> {
        let mut coeffs = vec![Rational::new(); p.degree_in(var) as usize + 1];
        for (mono, q) in p.terms() {
            let e = mono.exponent(var);
            if u64::from(e) != mono.degree() {
                return None;
            }
            coeffs[e as usize] += q.to_rational();
        }
        Some(UPoly::new(coeffs))
    }

    /// The coefficients, lowest degree first.
    pub fn coeffs(&self) -> &[Rational] {
        &self.0
    }

    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// Degree (0 for constants and for zero).
    pub fn degree(&self) -> usize {
        self.0.len().saturating_sub(1)
    }

    /// Exact value at `x` (Horner).
    pub fn eval(&self, x: &Rational) -> Rational {
        self.0
            .iter()
            .rev()
            .fold(Rational::new(), |acc, a| acc * x + a)
    }

    /// Sign of the value at `x`: −1, 0 or 1.
    pub fn sign_at(&self, x: &Rational) -> i32 {
        self.eval(x).cmp0() as i32
    }

    /// The leading coefficient (zero for the zero polynomial).
    pub fn leading(&self) -> Rational {
        self.0.last().cloned().unwrap_or_default()
    }

    /// The product.
    pub fn mul(&self, other: &UPoly) -> UPoly {
        if self.is_zero() || other.is_zero() {
            return UPoly::new(vec![]);
        }
        let mut c = vec![Rational::new(); self.0.len() + other.0.len() - 1];
        for (i, x) in self.0.iter().enumerate() {
            for (j, y) in other.0.iter().enumerate() {
                c[i + j] += x.clone() * y;
            }
        }
        UPoly::new(c)
    }

    /// The same roots with coprime integer coefficients and a positive
    /// leading coefficient.
    pub fn integer_primitive(&self) -> UPoly {
        let mut num = rug::Integer::new();
        let mut den = rug::Integer::from(1);
        for q in &self.0 {
            num.gcd_mut(q.numer());
            den.lcm_mut(q.denom());
        }
        if num == 0 {
            return self.clone();
        }
        let mut g = Rational::from((num, den));
        if self.leading() < 0 {
            g = -g;
        }
        UPoly::new(self.0.iter().map(|a| a.clone() / &g).collect())
    }

    /// Cauchy's bound: every root `r` has `|r| < 1 + max |aᵢ/aₙ|`.
    pub fn root_bound(&self) -> Rational {
        let lead = self.leading().abs();
        let max = self.0[..self.0.len().saturating_sub(1)]
            .iter()
            .map(|a| a.clone().abs() / &lead)
            .max()
            .unwrap_or_default();
        max + 1u32
    }

    /// The polynomial in `var`, highest power first, e.g. `x^2 - 4*x - 4`.
    pub fn display(&self, var: &str) -> String {
        let mut out = String::new();
        for (i, a) in self.0.iter().enumerate().rev() {
            if *a == 0 {
                continue;
            }
            let sign = if *a < 0 { "-" } else { "+" };
            let abs = a.clone().abs();
            let coef = match (i, abs == 1) {
                (0, _) => abs.to_string(),
                (_, true) => String::new(),
                _ => format!("{abs}*"),
            };
            let power = match i {
                0 => String::new(),
                1 => var.to_string(),
                _ => format!("{var}^{i}"),
            };
            if out.is_empty() {
                out = format!("{}{coef}{power}", if *a < 0 { "-" } else { "" });
            } else {
                out = format!("{out} {sign} {coef}{power}");
            }
        }
        if out.is_empty() { "0".into() } else { out }
    }

    /// The derivative.
    pub fn derivative(&self) -> UPoly {
        UPoly::new(
            self.0
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, a)| a.clone() * Rational::from(i as u64))
                .collect(),
        )
    }

    /// Quotient and remainder of the division by a nonzero `d`.
    ///
    /// # Panics
    /// If `d` is zero.
    pub fn div_rem(&self, d: &UPoly) -> (UPoly, UPoly) {
        let lead = d.0.last().expect("division by the zero polynomial");
        let mut r = self.0.clone();
        if r.len() < d.0.len() {
            return (UPoly::new(vec![]), self.clone());
        }
        let mut q = vec![Rational::new(); r.len() - d.0.len() + 1];
        for k in (0..q.len()).rev() {
            let c = r[k + d.0.len() - 1].clone() / lead;
            if c != 0 {
                for (j, dj) in d.0.iter().enumerate() {
                    r[k + j] -= c.clone() * dj;
                }
            }
            q[k] = c;
        }
        r.truncate(d.0.len() - 1);
        (UPoly::new(q), UPoly::new(r))
    }

    /// The monic greatest common divisor.
    pub fn gcd(&self, other: &UPoly) -> UPoly {
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            let r = a.div_rem(&b).1;
            a = b;
            b = r;
        }
        a.monic()
    }

    /// `(g, s)` with `g = gcd(self, h)` (not made monic) and
    /// `s·self ≡ g (mod h)`, for `self ≢ 0 (mod h)`: the inverse of `self`
    /// modulo `h` is `s/g` when `g` is a constant.
    pub fn ext_gcd(&self, h: &UPoly) -> (UPoly, UPoly) {
        let (mut r0, mut r1) = (h.clone(), self.div_rem(h).1);
        let (mut s0, mut s1) = (UPoly::new(vec![]), UPoly::new(vec![Rational::from(1)]));
        while !r1.is_zero() {
            let (q, r) = r0.div_rem(&r1);
            let s = s0.sub(&q.mul(&s1));
            (r0, r1) = (r1, r);
            (s0, s1) = (s1, s);
        }
        (r0, s0)
    }

    fn monic(&self) -> UPoly {
        match self.0.last() {
            Some(l) => UPoly::new(self.0.iter().map(|a| a.clone() / l).collect()),
            None => self.clone(),
        }
    }

    /// The squarefree part `p / gcd(p, p')`: the same distinct roots, each
    /// simple.
    pub fn squarefree(&self) -> UPoly {
        let g = self.gcd(&self.derivative());
        self.div_rem(&g).0
    }

    /// The square-free decomposition (Yun): `(fᵢ, i)` with `p = c·∏ fᵢⁱ`,
    /// each `fᵢ` square-free and the `fᵢ` pairwise coprime, so a root of
    /// `p` is a root of exactly one `fᵢ`; constant factors left out.
    pub fn squarefree_factors(&self) -> Vec<(UPoly, u32)> {
        let mut out = Vec::new();
        if self.degree() == 0 {
            return out;
        }
        let d = self.derivative();
        let a = self.gcd(&d);
        let mut b = self.div_rem(&a).0;
        let mut c = d.div_rem(&a).0;
        let mut i = 1;
        loop {
            let next = c.sub(&b.derivative());
            let g = b.gcd(&next);
            if g.degree() > 0 {
                out.push((g.clone(), i));
            }
            b = b.div_rem(&g).0;
            if b.degree() == 0 {
                break;
            }
            c = next.div_rem(&g).0;
            i += 1;
        }
        out
    }

    /// `self + other`.
    pub fn add(&self, other: &UPoly) -> UPoly {
        self.zip_with(other, |a, b| a + b)
    }

    /// `self − other`.
    pub fn sub(&self, other: &UPoly) -> UPoly {
        self.zip_with(other, |a, b| a - b)
    }

    /// Coefficientwise `f(aₖ, bₖ)`, missing coefficients read as zero.
    fn zip_with(&self, other: &UPoly, f: impl Fn(Rational, Rational) -> Rational) -> UPoly {
        let n = self.0.len().max(other.0.len());
        let get = |v: &[Rational], k: usize| v.get(k).cloned().unwrap_or_default();
        UPoly::new(
            (0..n)
                .map(|k| f(get(&self.0, k), get(&other.0, k)))
                .collect(),
        )
    }

    /// The Sturm sequence `p, p', −rem(p, p'), …`.
    pub fn sturm_sequence(&self) -> Vec<UPoly> {
        let mut seq = vec![self.clone(), self.derivative()];
        while !seq[seq.len() - 1].is_zero() {
            let n = seq.len();
            let r = seq[n - 2].div_rem(&seq[n - 1]).1;
            seq.push(UPoly::new(r.0.into_iter().map(|a| -a).collect()));
        }
        seq.pop();
        seq
    }

    /// The number of distinct real roots in the half-open `(a, b]`.
    pub fn count_roots(&self, a: &Rational, b: &Rational) -> usize {
        let seq = self.sturm_sequence();
        variations(&seq, a).saturating_sub(variations(&seq, b))
    }

    /// Isolating intervals of the distinct roots in the open `(a, b)`, in
    /// increasing order: either `lo = hi`, the root itself, or `lo < r < hi`
    /// with neither end a root. Hence a point between two intervals (or an
    /// endpoint shared by two of them) is never a root.
    pub fn isolate(&self, a: &Rational, b: &Rational) -> Vec<(Rational, Rational)> {
        let p = self.squarefree();
        let mut raw = Vec::new();
        bisect(&p, a.clone(), b.clone(), &mut raw);
        raw.into_iter()
            .filter(|(_, hi)| !(hi == b && p.sign_at(b) == 0))
            .map(|(lo, hi)| tighten(&p, lo, hi))
            .collect()
    }
}

/// Bisection: `(a, b]` with several roots is split at its midpoint until
/// each piece `(lo, hi]` holds exactly one.
fn bisect(p: &UPoly, a: Rational, b: Rational, out: &mut Vec<(Rational, Rational)>) {
    match p.count_roots(&a, &b) {
        0 => {}
        1 => out.push((a, b)),
        _ => {
            let m = (a.clone() + &b) / 2u32;
            bisect(p, a, m.clone(), out);
            bisect(p, m, b, out);
        }
    }
}

/// From `(lo, hi]` with one root to the invariant of [`UPoly::isolate`].
fn tighten(p: &UPoly, mut lo: Rational, mut hi: Rational) -> (Rational, Rational) {
    if p.sign_at(&hi) == 0 {
        return (hi.clone(), hi);
    }
    while p.sign_at(&lo) == 0 {
        let m = (lo.clone() + &hi) / 2u32;
        if p.sign_at(&m) == 0 {
            return (m.clone(), m);
        }
        if p.count_roots(&m, &hi) == 1 {
            lo = m;
        } else {
            hi = m;
        }
    }
    (lo, hi)
}

/// Sign changes of the sequence evaluated at `x` (zeros skipped).
fn variations(seq: &[UPoly], x: &Rational) -> usize {
    let signs: Vec<i32> = seq
        .iter()
        .map(|p| p.sign_at(x))
        .filter(|s| *s != 0)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    /// `Π (x − rᵢ)`.
    fn from_roots(roots: &[Rational]) -> UPoly {
        roots.iter().fold(UPoly::new(vec![q(1, 1)]), |acc, r| {
            let lin = UPoly::new(vec![-r.clone(), q(1, 1)]);
            acc.mul(&lin)
        })
    }

    /// `x⁴(x² − 2)⁷(2x⁴ − 4x² + 1)` (the half-angle basis's elimination
    /// polynomial) splits into `x` (4), `x² − 2` (7), `x⁴ − 2x² + 1/2` (1).
    #[test]
    fn squarefree_factors_separate_the_multiplicities() {
        let x2m2 = UPoly::new(vec![q(-2, 1), q(0, 1), q(1, 1)]);
        let quartic = UPoly::new(vec![q(1, 1), q(0, 1), q(-4, 1), q(0, 1), q(2, 1)]);
        let x = UPoly::new(vec![q(0, 1), q(1, 1)]);
        let pow = |p: &UPoly, n: u32| (0..n).fold(UPoly::new(vec![q(1, 1)]), |a, _| a.mul(p));
        let p = pow(&x, 4)
            .mul(&pow(&x2m2, 7))
            .mul(&quartic)
            .mul(&UPoly::new(vec![q(-3, 1)]));
        let factors = p.squarefree_factors();
        let monic = |p: &UPoly| p.monic();
        assert_eq!(
            factors,
            vec![(monic(&quartic), 1), (x, 4), (x2m2, 7)],
            "{factors:?}"
        );
        assert!(UPoly::new(vec![q(5, 1)]).squarefree_factors().is_empty());
    }

    #[test]
    fn sturm_counts_distinct_roots_and_ignores_multiplicity() {
        let p = from_roots(&[q(1, 3), q(1, 3), q(1, 2), q(2, 1)]);
        assert_eq!(p.count_roots(&q(0, 1), &q(1, 1)), 2);
        assert_eq!(p.count_roots(&q(0, 1), &q(3, 1)), 3);
        assert_eq!(p.count_roots(&q(1, 2), &q(1, 1)), 0, "(a, b] excludes a");
        // x² + 1 has no real root
        assert_eq!(
            UPoly::new(vec![q(1, 1), q(0, 1), q(1, 1)]).count_roots(&q(-9, 1), &q(9, 1)),
            0
        );
        assert_eq!(p.squarefree().degree(), 3);
    }

    #[test]
    fn roots_are_isolated_including_exact_midpoints() {
        let p = from_roots(&[q(1, 2), q(1, 4), q(7, 10), q(1, 1)]);
        let iv = p.isolate(&q(0, 1), &q(1, 1));
        assert_eq!(iv.len(), 3, "{iv:?}");
        for ((lo, hi), r) in iv.iter().zip([q(1, 4), q(1, 2), q(7, 10)]) {
            assert!(*lo <= r && r <= *hi, "{lo} {hi} {r}");
        }
        assert!(iv.windows(2).all(|w| w[0].1 <= w[1].0));
    }
}
