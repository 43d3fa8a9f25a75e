//! Total positivity of a rational matrix by Neville elimination: the
//! bidiagonal factorisation (Gasca & Peña, "Total positivity and Neville
//! elimination", Linear Algebra Appl. 165 (1992) 25–44; "A matricial
//! description of Neville elimination with applications to total
//! positivity", Linear Algebra Appl. 202 (1994) 33–53).
//!
//! Neville elimination makes zeros below each pivot by subtracting from
//! every row a multiple of the row just above it, bottom row first:
//! `rowᵢ ← rowᵢ − mᵢ·rowᵢ₋₁`. With `Eᵢ(m) = I + m·eᵢeᵢ₋₁ᵀ` (lower
//! bidiagonal, totally positive for `m ≥ 0`), `A = Π Eᵢ(mᵢ) · U` with `U`
//! in row echelon form; the same elimination of `Uᵀ` gives
//! `Uᵀ = Π Eⱼ(m'ⱼ) · V`. When no row exchange is needed, every multiplier
//! is `≥ 0` and `V` has at most one nonzero entry in each row and column,
//! all `> 0`, then `A = L · Vᵀ · L'ᵀ` is a product of totally positive
//! matrices, hence totally positive (Cauchy–Binet). Rows and columns of
//! zeros are left out, first and whenever the elimination makes one
//! (every minor through one is 0, so the rest decides). A sufficient
//! test, in `O(n²m)` exact operations: when it does not apply nothing is
//! concluded.

use rug::Rational;

/// The factorisation found: how many nonzero multipliers (all `> 0`) and
/// pivots (all `> 0`) it has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Bidiagonal {
    pub multipliers: usize,
    pub pivots: usize,
}

/// `a` without its rows and columns of zeros.
fn without_zero_lines(a: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let m = a.first().map_or(0, Vec::len);
    let cols: Vec<usize> = (0..m).filter(|&j| a.iter().any(|r| r[j] != 0)).collect();
    a.iter()
        .filter(|r| r.iter().any(|x| *x != 0))
        .map(|r| cols.iter().map(|&j| r[j].clone()).collect())
        .collect()
}

fn transpose(a: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let m = a.first().map_or(0, Vec::len);
    (0..m)
        .map(|j| a.iter().map(|r| r[j].clone()).collect())
        .collect()
}

/// Neville elimination of the rows of `a` to row echelon form, when no
/// row exchange is needed and every multiplier is `≥ 0`; with the number
/// of nonzero multipliers.
fn eliminate(mut a: Vec<Vec<Rational>>) -> Option<(Vec<Vec<Rational>>, usize)> {
    let m = a.first().map_or(0, Vec::len);
    let (mut r, mut count) = (0, 0);
    for col in 0..m {
        // a row of zeros is left out (it only adds zero minors): the
        // elimination goes on with the rows that remain
        a.retain(|row| row.iter().any(|x| *x != 0));
        let n = a.len();
        if r >= n {
            break;
        }
        if (r..n).all(|i| a[i][col] == 0) {
            continue;
        }
        if a[r][col] == 0 {
            return None;
        }
        for i in (r + 1..n).rev() {
            if a[i][col] == 0 {
                continue;
            }
            if a[i - 1][col] == 0 {
                return None;
            }
            let multiplier = Rational::from(&a[i][col] / &a[i - 1][col]);
            if multiplier < 0 {
                return None;
            }
            count += 1;
            let (top, bottom) = a.split_at_mut(i);
            for (x, p) in bottom[0].iter_mut().zip(&top[i - 1]).skip(col) {
                *x -= Rational::from(&multiplier * p);
            }
        }
        r += 1;
    }
    Some((a, count))
}

/// The bidiagonal factorisation of `a` with every factor `≥ 0`, when
/// Neville elimination finds one (see the module documentation): then `a`
/// is totally positive. `None` concludes nothing.
pub fn totally_positive(a: &[Vec<Rational>]) -> Option<Bidiagonal> {
    let (u, below) = eliminate(without_zero_lines(a))?;
    let (v, above) = eliminate(transpose(&without_zero_lines(&u)))?;
    let mut pivots = 0;
    for row in &v {
        let nonzero: Vec<&Rational> = row.iter().filter(|x| **x != 0).collect();
        match nonzero.as_slice() {
            [] => {}
            [p] if **p > 0 => pivots += 1,
            _ => return None,
        }
    }
    let m = v.first().map_or(0, Vec::len);
    if (0..m).any(|j| v.iter().filter(|r| r[j] != 0).count() > 1) {
        return None;
    }
    Some(Bidiagonal {
        multipliers: below + above,
        pivots,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::q;

    fn matrix(rows: &[&[i64]]) -> Vec<Vec<Rational>> {
        rows.iter()
            .map(|r| r.iter().map(|&x| q(x, 1)).collect())
            .collect()
    }

    #[test]
    fn totally_positive_matrices_factor_and_others_do_not() {
        // Pascal's matrix is totally positive
        let pascal = matrix(&[
            &[1, 1, 1, 1],
            &[1, 2, 3, 4],
            &[1, 3, 6, 10],
            &[1, 4, 10, 20],
        ]);
        let f = totally_positive(&pascal).expect("TP");
        assert_eq!(f.pivots, 4);
        // a negative 2 × 2 minor
        assert!(totally_positive(&matrix(&[&[1, 2], &[1, 1]])).is_none());
        // a negative entry
        assert!(totally_positive(&matrix(&[&[1, -1], &[0, 1]])).is_none());
        // rectangular, with a zero column and dependent rows: TP
        let wide = matrix(&[&[1, 1, 0, 0], &[0, 1, 0, 1], &[0, 1, 0, 1]]);
        assert!(totally_positive(&wide).is_some());
        // the identity (a Bernstein basis against itself)
        let id: Vec<Vec<Rational>> = (0..21)
            .map(|i| (0..21).map(|j| q(i64::from(i == j), 1)).collect())
            .collect();
        assert_eq!(totally_positive(&id).map(|f| f.pivots), Some(21));
    }

    #[test]
    fn a_factorisation_found_means_every_minor_is_nonnegative() {
        use crate::sturm::UPoly;
        use crate::total_positivity::minors;
        // small matrices with entries in {0, 1, 2} from a fixed sequence
        let mut seed: u64 = 12345;
        let (mut found, mut tp) = (0, 0);
        for k in 0..3000 {
            let a: Vec<Vec<Rational>> = (0..2 + k % 3)
                .map(|_| {
                    (0..4)
                        .map(|_| {
                            seed = seed
                                .wrapping_mul(6_364_136_223_846_793_005)
                                .wrapping_add(1_442_695_040_888_963_407);
                            q(((seed >> 33) % 3) as i64, 1)
                        })
                        .collect()
                })
                .collect();
            let polys: Vec<Vec<UPoly>> = a
                .iter()
                .map(|r| r.iter().map(|x| UPoly::new(vec![x.clone()])).collect())
                .collect();
            let all_nonnegative = minors(&polys)
                .unwrap()
                .iter()
                .all(|m| m.value.leading() >= 0);
            tp += usize::from(all_nonnegative);
            if totally_positive(&a).is_some() {
                found += 1;
                assert!(all_nonnegative, "{a:?}");
            }
        }
        println!("{found} factorisations among {tp} totally positive matrices");
        assert!(found > 0 && tp > 0, "{found} of {tp}");
    }
}
