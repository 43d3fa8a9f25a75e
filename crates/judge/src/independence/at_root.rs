//! The rank of a matrix of polynomials in one parameter at a real
//! algebraic value of it: Gaussian elimination in `Q[x]/(h)`, `h` a
//! squarefree polynomial with that value as a root.
//!
//! When a pivot is a zero divisor (`gcd(pivot, h) = g` nonconstant), `h`
//! splits as `g · h/g` and the elimination restarts with the factor that
//! keeps the root; otherwise every nonzero entry is invertible and the
//! rank found holds at every root of the final `h` (conjugates give the
//! same elimination), so at the value itself, exactly.

use rug::Rational;
use trig_certify::sturm::UPoly;

fn zero() -> UPoly {
    UPoly::new(vec![])
}

fn rem(a: &UPoly, h: &UPoly) -> UPoly {
    a.div_rem(h).1
}

/// The rank at the root.
#[derive(Debug, Clone)]
pub struct AtRoot {
    pub rank: usize,
    /// The squarefree factor of the given `h` that has the root, over
    /// which the rank was computed.
    pub h: UPoly,
    /// Where the rank drops: a dependence relation of the rows, its
    /// coefficients reduced modulo `h`.
    pub relation: Option<Vec<UPoly>>,
}

/// The rank of `rows` at the only root of the squarefree `h` in
/// `(lo, hi)`.
pub fn rank_at_root(rows: &[Vec<UPoly>], h: UPoly, lo: &Rational, hi: &Rational) -> AtRoot {
    let mut h = h;
    'restart: loop {
        let n = rows.len();
        let m = rows.first().map_or(0, Vec::len);
        let one = UPoly::new(vec![Rational::from(1)]);
        let mut a: Vec<Vec<UPoly>> = rows
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let mut v: Vec<UPoly> = r.iter().map(|x| rem(x, &h)).collect();
                v.extend((0..n).map(|j| if i == j { one.clone() } else { zero() }));
                v
            })
            .collect();
        let mut r = 0;
        for col in 0..m {
            let Some(p) = (r..n).find(|&i| !a[i][col].is_zero()) else {
                continue;
            };
            let (g, s) = a[p][col].ext_gcd(&h);
            if g.degree() > 0 {
                // a zero divisor: keep the factor with the root
                let other = h.div_rem(&g).0;
                h = if g.count_roots(lo, hi) > 0 { g } else { other };
                continue 'restart;
            }
            let inverse = s.mul(&UPoly::new(vec![Rational::from(1) / g.leading()]));
            a.swap(r, p);
            let pivot: Vec<UPoly> = a[r].iter().map(|x| rem(&x.mul(&inverse), &h)).collect();
            for (i, row) in a.iter_mut().enumerate() {
                if i == r || row[col].is_zero() {
                    continue;
                }
                let f = row[col].clone();
                for (x, y) in row.iter_mut().zip(&pivot).skip(col) {
                    *x = rem(&x.sub(&f.mul(y)), &h);
                }
            }
            a[r] = pivot;
            r += 1;
            if r == n {
                break;
            }
        }
        let relation = a.get(r).map(|row| row[m..].to_vec());
        return AtRoot {
            rank: r,
            h,
            relation,
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn u(c: &[i64]) -> UPoly {
        UPoly::new(c.iter().map(|&x| Rational::from(x)).collect())
    }

    #[test]
    fn the_rank_drops_at_the_root_of_two_and_not_at_its_neighbours() {
        // [[1, 0], [0, x² − 2]] at √2: rank 1; the relation is the second row
        let rows = vec![vec![u(&[1]), u(&[0])], vec![u(&[0]), u(&[-2, 0, 1])]];
        let (lo, hi) = (Rational::from(1), Rational::from(2));
        let at = rank_at_root(&rows, u(&[-2, 0, 1]), &lo, &hi);
        assert_eq!(at.rank, 1);
        let k = at.relation.expect("a relation");
        assert!(k[0].is_zero() && !k[1].is_zero());
        // with h = (x² − 2)(x − 5) a pivot x − 5 is a zero divisor: split
        let rows = vec![vec![u(&[-5, 1]), u(&[0])], vec![u(&[0]), u(&[-2, 0, 1])]];
        let h = u(&[-2, 0, 1]).mul(&u(&[-5, 1]));
        let at = rank_at_root(&rows, h, &lo, &hi);
        assert_eq!((at.rank, at.h.degree()), (1, 2));
        // at the root of x² − 3 the same matrix has full rank
        let at = rank_at_root(&rows, u(&[-3, 0, 1]), &lo, &hi);
        assert_eq!(at.rank, 2);
    }
}
