//! Every minor of a matrix whose entries are polynomials — in one
//! parameter ([`UPoly`]) or in several ([`Poly`]) — by Laplace expansion
//! along the last row of each minor from the minors one order lower, and
//! the degree elevation of a Bernstein coefficient matrix, written once for
//! both kinds of entry.

use std::collections::HashMap;

use rug::Rational;
use trig_symbolic::Poly;

use crate::sturm::UPoly;

/// The operations on a matrix entry that minors and degree elevation need.
pub trait Entry: Clone {
    fn zero() -> Self;
    fn is_zero(&self) -> bool;
    fn times(&self, other: &Self) -> Self;
    fn plus(&self, other: &Self) -> Self;
    fn minus(&self, other: &Self) -> Self;
    fn scaled(&self, q: &Rational) -> Self;
}

impl Entry for UPoly {
    fn zero() -> Self {
        UPoly::new(vec![])
    }
    fn is_zero(&self) -> bool {
        UPoly::is_zero(self)
    }
    fn times(&self, other: &Self) -> Self {
        self.mul(other)
    }
    fn plus(&self, other: &Self) -> Self {
        self.add(other)
    }
    fn minus(&self, other: &Self) -> Self {
        self.sub(other)
    }
    fn scaled(&self, q: &Rational) -> Self {
        self.mul(&UPoly::new(vec![q.clone()]))
    }
}

impl Entry for Rational {
    fn zero() -> Self {
        Rational::new()
    }
    fn is_zero(&self) -> bool {
        *self == 0
    }
    fn times(&self, other: &Self) -> Self {
        Rational::from(self * other)
    }
    fn plus(&self, other: &Self) -> Self {
        Rational::from(self + other)
    }
    fn minus(&self, other: &Self) -> Self {
        Rational::from(self - other)
    }
    fn scaled(&self, q: &Rational) -> Self {
        Rational::from(self * q)
    }
}

impl Entry for Poly {
    fn zero() -> Self {
        Poly::zero()
    }
    fn is_zero(&self) -> bool {
        Poly::is_zero(self)
    }
    fn times(&self, other: &Self) -> Self {
        self.clone() * other
    }
    fn plus(&self, other: &Self) -> Self {
        self.clone() + other
    }
    fn minus(&self, other: &Self) -> Self {
        self.clone() - other
    }
    fn scaled(&self, q: &Rational) -> Self {
        self.scale(q)
    }
}

/// Most rows and columns of a matrix whose minors are enumerated (index
/// sets are bit masks of one word).
pub const MAX_SIDE: usize = 31;

/// Most minor positions `Σₖ C(rows, k)·C(cols, k) = C(rows + cols, rows) − 1`
/// the enumeration of all minors visits (a 10 × 10 matrix has 184 755).
pub const MAX_MINORS: u64 = 1_000_000;

/// A matrix too large for the enumeration of its minors.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "the coefficient matrix is {rows} × {cols}: {} minor positions, beyond the limit of the enumeration of all minors (at most {MAX_SIDE} rows and columns and {MAX_MINORS} minors)",
    minors.map_or_else(|| "more than 2^64".to_string(), |m| m.to_string())
)]
pub struct TooLarge {
    pub rows: usize,
    pub cols: usize,
    /// `C(rows + cols, rows) − 1`, when it fits a word.
    pub minors: Option<u64>,
}

/// `C(n, k)`, when it fits a word.
pub fn binomial(n: usize, k: usize) -> Option<u64> {
    let k = k.min(n - k);
    (0..k).try_fold(1u64, |acc, i| {
        let next = u128::from(acc) * (n - i) as u128 / (i + 1) as u128;
        u64::try_from(next).ok()
    })
}

/// The enumeration of the minors of a `rows × cols` matrix is within the
/// limits.
pub fn within_limits(rows: usize, cols: usize) -> Result<(), TooLarge> {
    let minors = binomial(rows + cols, rows).map(|c| c - 1);
    if rows > MAX_SIDE || cols > MAX_SIDE || minors.is_none_or(|m| m > MAX_MINORS) {
        return Err(TooLarge { rows, cols, minors });
    }
    Ok(())
}

/// One minor: its row and column indices and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct MinorOf<E> {
    pub rows: Vec<usize>,
    pub cols: Vec<usize>,
    pub value: E,
}

/// The sets of `k ≥ 1` indices out of `n ≤ 31`, as bit masks, in
/// increasing order (Gosper's next subset of the same size).
fn subsets(n: usize, k: usize) -> Vec<u32> {
    let mut out = Vec::new();
    if k == 0 || k > n {
        return out;
    }
    let end = 1u64 << n;
    let mut m: u64 = (1 << k) - 1;
    while m < end {
        out.push(m as u32);
        let low = m & m.wrapping_neg();
        let ripple = m + low;
        m = (((ripple ^ m) >> 2) / low) | ripple;
    }
    out
}

fn indices(mask: u32) -> Vec<usize> {
    (0..32).filter(|i| mask & (1 << i) != 0).collect()
}

/// The sets of `k ≥ 1` indices out of `n ≤ 31`, each increasing, in the
/// order of [`subsets`] (the columns of the maximal minors, say).
pub fn index_sets(n: usize, k: usize) -> Vec<Vec<usize>> {
    subsets(n, k).into_iter().map(indices).collect()
}

/// Every nonzero minor of `m` (any order), by Laplace expansion along the
/// last row of each minor from the minors one order lower; an error beyond
/// the limits of the enumeration ([`MAX_SIDE`], [`MAX_MINORS`]).
pub fn all_minors<E: Entry>(m: &[Vec<E>]) -> Result<Vec<MinorOf<E>>, TooLarge> {
    let rows = m.len();
    let cols = m.first().map_or(0, Vec::len);
    within_limits(rows, cols)?;
    let mut out = Vec::new();
    let mut previous: HashMap<(u32, u32), E> = HashMap::new();
    for k in 1..=rows.min(cols) {
        let mut level = HashMap::new();
        for r in subsets(rows, k) {
            let ri = indices(r);
            let last = ri[k - 1];
            let rest = r & !(1 << last);
            for c in subsets(cols, k) {
                let ci = indices(c);
                let value = if k == 1 {
                    m[last][ci[0]].clone()
                } else {
                    ci.iter().enumerate().fold(E::zero(), |acc, (t, &j)| {
                        let Some(sub) = previous.get(&(rest, c & !(1 << j))) else {
                            return acc;
                        };
                        let term = m[last][j].times(sub);
                        if (k - 1 + t) % 2 == 0 {
                            acc.plus(&term)
                        } else {
                            acc.minus(&term)
                        }
                    })
                };
                if !value.is_zero() {
                    out.push(MinorOf {
                        rows: ri.clone(),
                        cols: ci,
                        value: value.clone(),
                    });
                    level.insert((r, c), value);
                }
            }
        }
        previous = level;
    }
    Ok(out)
}

/// The Bernstein coefficients of degree `d ≥ deg` of `Σ aᵢ zⁱ`:
/// `b_k = Σ_{i ≤ k} C(k, i)/C(d, i)·aᵢ` (entries of any kind: the change of
/// basis is linear).
pub fn power_to_bernstein<E: Entry>(a: &[E], d: usize) -> Vec<E> {
    let ratio = |k: usize, i: usize| -> Rational {
        let c = |n: usize, k: usize| {
            Rational::from(rug::Integer::from(rug::Integer::binomial_u(
                n as u32, k as u32,
            )))
        };
        c(k, i) / c(d, i)
    };
    (0..=d)
        .map(|k| {
            a.iter()
                .enumerate()
                .take(k + 1)
                .filter(|(_, ai)| !ai.is_zero())
                .fold(E::zero(), |acc, (i, ai)| acc.plus(&ai.scaled(&ratio(k, i))))
        })
        .collect()
}

/// One degree elevation of Bernstein coefficient rows of degree `d`:
/// `c'_k = k/(d+1)·c_{k−1} + (1 − k/(d+1))·c_k`.
pub fn elevate_rows<E: Entry>(rows: &[Vec<E>], d: usize) -> Vec<Vec<E>> {
    let d1 = d + 1;
    rows.iter()
        .map(|row| {
            (0..=d1)
                .map(|k| {
                    let left = match k {
                        0 => E::zero(),
                        _ => row[k - 1].scaled(&Rational::from((k as u32, d1 as u32))),
                    };
                    let right = match row.get(k) {
                        Some(c) => c.scaled(&Rational::from(((d1 - k) as u32, d1 as u32))),
                        None => E::zero(),
                    };
                    left.plus(&right)
                })
                .collect()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn minors_of_polynomials_in_two_parameters() {
        // [[a, 1], [1, b]]: minors a, 1, 1, b and ab − 1
        let (a, b) = (Poly::var("a"), Poly::var("b"));
        let m = vec![vec![a.clone(), Poly::one()], vec![Poly::one(), b.clone()]];
        let ms = all_minors(&m).expect("small");
        assert_eq!(ms.len(), 5);
        assert_eq!(ms[4].value, a * &b - &Poly::one());
    }

    #[test]
    fn a_matrix_too_large_is_an_error_not_a_panic() {
        let m = vec![vec![UPoly::new(vec![q(1)]); 32]; 2];
        assert_eq!(
            all_minors(&m).unwrap_err(),
            TooLarge {
                rows: 2,
                cols: 32,
                minors: Some(560)
            }
        );
    }

    #[test]
    fn subsets_come_in_increasing_order_of_their_masks() {
        for (n, k) in [(5, 2), (6, 3), (4, 4), (7, 1)] {
            let slow: Vec<u32> = (0u32..(1 << n))
                .filter(|m| m.count_ones() as usize == k)
                .collect();
            assert_eq!(subsets(n, k), slow, "{n}, {k}");
        }
    }

    #[test]
    fn elevation_keeps_the_polynomial() {
        // 1 = B⁰₀ → (1, 1) in degree 1
        let rows = vec![vec![UPoly::new(vec![q(1)])]];
        let up = elevate_rows(&rows, 0);
        assert_eq!(up[0], vec![UPoly::new(vec![q(1)]), UPoly::new(vec![q(1)])]);
    }
}
