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

/// Most rows and columns whose minors are enumerated (subsets are bit
/// masks of a `u32`).
pub const MAX_SIDE: usize = 31;

/// Most nonzero minors kept: past it the enumeration stops with
/// [`TooLarge`] instead of exhausting memory (`C(2n, n)` grows fast).
pub const MAX_MINORS: usize = 200_000;

/// Why the minors of a matrix were not enumerated.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TooLarge {
    #[error(
        "the matrix is {rows} × {cols}; minors are enumerated for at most {MAX_SIDE} rows and columns"
    )]
    Side { rows: usize, cols: usize },
    #[error("the matrix has more than {MAX_MINORS} nonzero minors")]
    Count,
}

/// One minor: its row and column indices and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct MinorOf<E> {
    pub rows: Vec<usize>,
    pub cols: Vec<usize>,
    pub value: E,
}

/// The sets of `k` indices out of `n`, as bit masks, in lexicographic order.
fn subsets(n: usize, k: usize) -> Vec<u32> {
    (0u32..(1 << n))
        .filter(|m| m.count_ones() as usize == k)
        .collect()
}

fn indices(mask: u32) -> Vec<usize> {
    (0..32).filter(|i| mask & (1 << i) != 0).collect()
}

/// Every nonzero minor of `m` (any order).
pub fn all_minors<E: Entry>(m: &[Vec<E>]) -> Result<Vec<MinorOf<E>>, TooLarge> {
    let rows = m.len();
    let cols = m.first().map_or(0, Vec::len);
    if rows > MAX_SIDE || cols > MAX_SIDE {
        return Err(TooLarge::Side { rows, cols });
    }
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
                    if out.len() >= MAX_MINORS {
                        return Err(TooLarge::Count);
                    }
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
            TooLarge::Side { rows: 2, cols: 32 }
        );
    }

    #[test]
    fn elevation_keeps_the_polynomial() {
        // 1 = B⁰₀ → (1, 1) in degree 1
        let rows = vec![vec![UPoly::new(vec![q(1)])]];
        let up = elevate_rows(&rows, 0);
        assert_eq!(up[0], vec![UPoly::new(vec![q(1)]), UPoly::new(vec![q(1)])]);
    }
}
