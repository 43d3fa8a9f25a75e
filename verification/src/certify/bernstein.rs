//! Exact tensor Bernstein polynomials on boxes and the subdivision test of
//! their sign.
//!
//! A polynomial `P(z, y)` of degrees `(n, m)` on `[0,1]²` is written
//! `Σ b_{kl} B^n_k(z) B^m_l(y)`. All `b_{kl} ≥ 0` proves `P ≥ 0` on the box;
//! corner coefficients are the values at the corners, so a negative corner is
//! an exact counterexample. Otherwise the box is split in half (de Casteljau,
//! exact) and both halves are tested, up to a depth limit.

use rug::Rational;

/// Power-basis coefficients `a[i][j]` of `Σ a_{ij} zⁱ yʲ`.
pub type Power = Vec<Vec<Rational>>;

/// Bernstein coefficients over a box `[z0, z1] × [y0, y1]` (in the
/// coordinates of the original `[0,1]²`).
#[derive(Debug, Clone)]
struct Patch {
    b: Vec<Vec<Rational>>,
    z: (Rational, Rational),
    y: (Rational, Rational),
    depth: u32,
}

/// Outcome of a sign test on `[0,1]²`.
#[derive(Debug, Clone, PartialEq)]
pub enum Sign {
    /// `P ≥ 0` everywhere; the number of boxes the proof used.
    NonNegative { boxes: usize },
    /// `P(z, y) < 0` at this exact point.
    Negative {
        z: Rational,
        y: Rational,
        value: Rational,
    },
    /// The depth limit was reached on this box without a decision.
    Undecided {
        z: (Rational, Rational),
        y: (Rational, Rational),
    },
}

fn binomial(n: usize, k: usize) -> Rational {
    Rational::from(rug::Integer::from(rug::Integer::binomial_u(
        n as u32, k as u32,
    )))
}

/// Bernstein coefficients on `[0,1]²` from power coefficients:
/// `b_{kl} = Σ_{i≤k} Σ_{j≤l} C(k,i)/C(n,i) · C(l,j)/C(m,j) · a_{ij}`.
pub fn to_bernstein(a: &Power) -> Vec<Vec<Rational>> {
    let n = a.len() - 1;
    let m = a[0].len() - 1;
    (0..=n)
        .map(|k| {
            (0..=m)
                .map(|l| {
                    let mut sum = Rational::new();
                    for (i, row) in a.iter().enumerate().take(k + 1) {
                        let fz = binomial(k, i) / binomial(n, i);
                        for (j, aij) in row.iter().enumerate().take(l + 1) {
                            if *aij != 0 {
                                sum += fz.clone() * (binomial(l, j) / binomial(m, j)) * aij;
                            }
                        }
                    }
                    sum
                })
                .collect()
        })
        .collect()
}

/// One de Casteljau split at 1/2 of a coefficient sequence.
fn split_seq(c: &[Rational]) -> (Vec<Rational>, Vec<Rational>) {
    let mut work = c.to_vec();
    let n = work.len();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![Rational::new(); n];
    for r in 0..n {
        left.push(work[0].clone());
        right[n - 1 - r] = work[n - 1 - r].clone();
        for i in 0..n - 1 - r {
            work[i] = (work[i].clone() + &work[i + 1]) / 2u32;
        }
    }
    (left, right)
}

fn mid(iv: &(Rational, Rational)) -> Rational {
    (iv.0.clone() + &iv.1) / 2u32
}

impl Patch {
    fn split(&self) -> (Patch, Patch) {
        let n = self.b.len();
        let m = self.b[0].len();
        // split the wider side (a degree-0 direction never needs splitting)
        let wider_z = self.z.1.clone() - &self.z.0 >= self.y.1.clone() - &self.y.0;
        let split_z = m == 1 || (n > 1 && wider_z);
        if split_z {
            let mut lo = vec![vec![Rational::new(); m]; n];
            let mut hi = lo.clone();
            for l in 0..m {
                let col: Vec<Rational> = self.b.iter().map(|row| row[l].clone()).collect();
                let (a, b) = split_seq(&col);
                for k in 0..n {
                    lo[k][l] = a[k].clone();
                    hi[k][l] = b[k].clone();
                }
            }
            let c = mid(&self.z);
            (
                Patch {
                    b: lo,
                    z: (self.z.0.clone(), c.clone()),
                    y: self.y.clone(),
                    depth: self.depth + 1,
                },
                Patch {
                    b: hi,
                    z: (c, self.z.1.clone()),
                    y: self.y.clone(),
                    depth: self.depth + 1,
                },
            )
        } else {
            let (lo, hi): (Vec<_>, Vec<_>) = self.b.iter().map(|row| split_seq(row)).unzip();
            let c = mid(&self.y);
            (
                Patch {
                    b: lo,
                    z: self.z.clone(),
                    y: (self.y.0.clone(), c.clone()),
                    depth: self.depth + 1,
                },
                Patch {
                    b: hi,
                    z: self.z.clone(),
                    y: (c, self.y.1.clone()),
                    depth: self.depth + 1,
                },
            )
        }
    }

    /// A corner with a negative value, if any (corner coefficients are values).
    fn negative_corner(&self, strict: bool) -> Option<(Rational, Rational, Rational)> {
        let (n, m) = (self.b.len() - 1, self.b[0].len() - 1);
        [(0, 0), (n, 0), (0, m), (n, m)]
            .into_iter()
            .find_map(|(k, l)| {
                let v = &self.b[k][l];
                (*v < 0 || (strict && *v == 0)).then(|| {
                    let z = if k == 0 {
                        self.z.0.clone()
                    } else {
                        self.z.1.clone()
                    };
                    let y = if l == 0 {
                        self.y.0.clone()
                    } else {
                        self.y.1.clone()
                    };
                    (z, y, v.clone())
                })
            })
    }
}

/// Decides the sign of `P` (power coefficients on `[0,1]²`) by subdivision
/// up to `max_depth` halvings: `P ≥ 0`, or `P > 0` when `strict` (then a
/// corner value `≤ 0` is the counterexample).
pub fn sign_on_unit_box(a: &Power, max_depth: u32, strict: bool) -> Sign {
    let one = || (Rational::new(), Rational::from(1));
    let mut stack = vec![Patch {
        b: to_bernstein(a),
        z: one(),
        y: one(),
        depth: 0,
    }];
    let mut boxes = 0;
    while let Some(p) = stack.pop() {
        if p.b
            .iter()
            .flatten()
            .all(|x| if strict { *x > 0 } else { *x >= 0 })
        {
            boxes += 1;
            continue;
        }
        if let Some((z, y, value)) = p.negative_corner(strict) {
            return Sign::Negative { z, y, value };
        }
        if p.depth >= max_depth {
            return Sign::Undecided { z: p.z, y: p.y };
        }
        let (l, r) = p.split();
        stack.push(r);
        stack.push(l);
    }
    Sign::NonNegative { boxes }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    #[test]
    fn a_nonnegative_polynomial_is_certified_and_a_negative_one_refuted() {
        // (z − 1/2)² + (y − 1/2)² + 1/100 > 0: the coefficients on the whole
        // square are not all ≥ 0 (b₁₁ = −1/2 + 1/100 + …), subdivision proves it
        let r = |a, b| Rational::from((a, b));
        let sq = vec![
            vec![r(51, 100), q(-1), q(1)],
            vec![q(-1), q(0), q(0)],
            vec![q(1), q(0), q(0)],
        ];
        assert!(to_bernstein(&sq).iter().flatten().any(|x| *x < 0));
        assert!(matches!(
            sign_on_unit_box(&sq, 20, false),
            Sign::NonNegative { .. }
        ));
        // z − 1/2 is negative at z = 0
        let lin = vec![vec![Rational::from((-1, 2))], vec![q(1)]];
        match sign_on_unit_box(&lin, 20, false) {
            Sign::Negative { z, value, .. } => {
                assert_eq!(z, 0);
                assert_eq!(value, Rational::from((-1, 2)));
            }
            other => panic!("{other:?}"),
        }
        // (z − 1/2)² − 1/1000 dips below zero only inside: found by subdivision
        let dip = vec![
            vec![Rational::from((1, 4)) - Rational::from((1, 1000))],
            vec![q(-1)],
            vec![q(1)],
        ];
        assert!(matches!(
            sign_on_unit_box(&dip, 30, false),
            Sign::Negative { .. }
        ));
    }

    #[test]
    fn bernstein_coefficients_of_one_are_all_one() {
        let one = vec![vec![q(1), q(0)], vec![q(0), q(0)]];
        assert!(to_bernstein(&one).iter().flatten().all(|x| *x == 1));
    }
}
