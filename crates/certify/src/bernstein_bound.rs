//! The range of a polynomial on the unit box `[−1, 1]ⁿ` from its tensor
//! Bernstein coefficients: the polynomial lies between their least and
//! greatest (Farouki & Rajan, "On the numerical condition of polynomials in
//! Bernstein form", CAGD 4 (1987)), an overestimation that shrinks
//! quadratically with the box — where summing `|coefficient|` per monomial
//! only shrinks linearly (a monotone `c₀ + c₁u + c₂u²` with `c₁ ≈ c₀` gets a
//! negative lower bound that way).
//!
//! Along each variable the coefficients `aⱼ` (in `u ∈ [−1, 1]`) become
//! `bᵢ = Σⱼ Mᵢⱼ aⱼ` with `M = B·S`: `S` substitutes `u = 2v − 1`
//! (`S_{mj} = C(j, m)·2ᵐ·(−1)^{j−m}`) and `B` is the power-to-Bernstein
//! map on `[0, 1]` (`B_{im} = C(i, m)/C(d, m)`). The arithmetic is f64
//! interval arithmetic with outward rounding (`rounding::up`,
//! `rounding::down`), so the bound is rigorous.

use rug::Rational;
use rug::float::Round;

use crate::rounding::{down, up};

/// A closed f64 interval with outward rounding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    pub lo: f64,
    pub hi: f64,
}

impl Span {
    /// The point `x` (exact).
    pub fn point(x: f64) -> Span {
        Span { lo: x, hi: x }
    }

    /// The rational `q`, rounded outward.
    pub fn rational(q: &Rational) -> Span {
        let end = |round: Round| {
            rug::Float::with_val_round(128, q, round)
                .0
                .to_f64_round(round)
        };
        Span {
            lo: end(Round::Down),
            hi: end(Round::Up),
        }
    }

    /// The MPFR number `x`, rounded outward to f64.
    pub fn float(x: &rug::Float) -> Span {
        Span {
            lo: x.to_f64_round(Round::Down),
            hi: x.to_f64_round(Round::Up),
        }
    }

    fn add(self, o: Span) -> Span {
        Span {
            lo: down(self.lo + o.lo),
            hi: up(self.hi + o.hi),
        }
    }

    fn mul(self, o: Span) -> Span {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return Span {
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            };
        }
        Span {
            lo: down(p.iter().copied().fold(f64::INFINITY, f64::min)),
            hi: up(p.iter().copied().fold(f64::NEG_INFINITY, f64::max)),
        }
    }
}

fn binomial(n: u32, k: u32) -> Rational {
    (0..k).fold(Rational::from(1), |acc, j| {
        acc * Rational::from(n - j) / Rational::from(j + 1)
    })
}

/// The `(d+1)×(d+1)` matrix from power coefficients in `u ∈ [−1, 1]` to
/// Bernstein coefficients of degree `d`.
pub fn conversion(d: u32) -> Vec<Vec<Span>> {
    let n = d as usize + 1;
    // S[m][j] = C(j, m) 2^m (−1)^(j−m), j ≥ m
    let s = |m: u32, j: u32| -> Rational {
        if j < m {
            return Rational::new();
        }
        let sign = if (j - m) % 2 == 0 { 1 } else { -1 };
        binomial(j, m) * Rational::from(1u64 << m) * sign
    };
    (0..n as u32)
        .map(|i| {
            (0..n as u32)
                .map(|j| {
                    let exact = (0..=i).fold(Rational::new(), |acc, m| {
                        acc + binomial(i, m) / binomial(d, m) * s(m, j)
                    });
                    Span::rational(&exact)
                })
                .collect()
        })
        .collect()
}

/// The range of `Σ cₖ u^{eₖ}` on `[−1, 1]ⁿ` (`exps[k]` the exponents of
/// coefficient `coefs[k]`, every total degree `≤ d`), from the Bernstein
/// coefficients of the tensor degree `(d, …, d)`.
pub fn range(coefs: &[Span], exps: &[Vec<u32>], vars: usize, d: u32, m: &[Vec<Span>]) -> Span {
    let n = d as usize + 1;
    let size = n.pow(vars as u32);
    let mut t = vec![Span::point(0.0); size];
    for (c, e) in coefs.iter().zip(exps) {
        let at = e.iter().fold(0usize, |acc, k| acc * n + *k as usize);
        t[at] = t[at].add(*c);
    }
    // convert along each axis: the stride of axis k is n^(vars − 1 − k)
    let mut line = vec![Span::point(0.0); n];
    for k in 0..vars {
        let stride = n.pow((vars - 1 - k) as u32);
        for base in 0..size {
            if (base / stride) % n != 0 {
                continue;
            }
            for (j, x) in line.iter_mut().enumerate() {
                *x = t[base + j * stride];
            }
            for (i, row) in m.iter().enumerate() {
                t[base + i * stride] = row
                    .iter()
                    .zip(&line)
                    .fold(Span::point(0.0), |acc, (a, x)| acc.add(a.mul(*x)));
            }
        }
    }
    t.iter().fold(
        Span {
            lo: f64::INFINITY,
            hi: f64::NEG_INFINITY,
        },
        |acc, s| Span {
            lo: acc.lo.min(s.lo),
            hi: acc.hi.max(s.hi),
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn monotone_quadratics_get_their_true_minimum() {
        // 1 − u + u²/3 on [−1, 1]: minimum 1/3 at u = 1 (monotone there)
        let m = conversion(2);
        let exps = vec![vec![0], vec![1], vec![2]];
        let c = [Span::point(1.0), Span::point(-1.0), Span::point(1.0 / 3.0)];
        let r = range(&c, &exps, 1, 2, &m);
        assert!(r.lo > 0.0 && r.lo <= 1.0 / 3.0, "{r:?}");
        assert!(r.hi >= 7.0 / 3.0 - 1e-12, "{r:?}");
        // u² has Bernstein coefficients 1, −1, 1 on [−1, 1]: range ⊂ [−1, 1]
        let c = [Span::point(0.0), Span::point(0.0), Span::point(1.0)];
        let r = range(&c, &exps, 1, 2, &m);
        assert!(r.lo >= -1.0 - 1e-12 && r.hi >= 1.0);
    }

    #[test]
    fn two_variables() {
        // u0·u1 on [−1, 1]²: exactly [−1, 1]
        let m = conversion(2);
        let exps = vec![vec![0, 0], vec![1, 1]];
        let c = [Span::point(0.0), Span::point(1.0)];
        let r = range(&c, &exps, 2, 2, &m);
        assert!(
            (r.lo + 1.0).abs() < 1e-12 && (r.hi - 1.0).abs() < 1e-12,
            "{r:?}"
        );
    }
}
