//! Exact tensor Bernstein polynomials on boxes and the subdivision test of
//! their sign, in any number of variables.
//!
//! A polynomial `P(x₁, …, x_d)` of degrees `(n₁, …, n_d)` on `[0,1]^d` is
//! written `Σ b_α B^{n₁}_{α₁}(x₁)⋯B^{n_d}_{α_d}(x_d)`. All `b_α ≥ 0` proves
//! `P ≥ 0` on the box; corner coefficients are the values at the corners, so
//! a negative corner is an exact counterexample. Otherwise the box is split
//! in half along its widest side of positive degree (de Casteljau, exact)
//! and both halves are tested, up to a depth limit. The two-variable API
//! (`z` and one parameter coordinate `y`) is a thin layer over this.

use rug::Rational;

/// Power-basis coefficients `a[i][j]` of `Σ a_{ij} zⁱ yʲ`.
pub type Power = Vec<Vec<Rational>>;

/// Coefficients of a polynomial in `d` variables, indexed by exponent (or
/// Bernstein index) tuples `α` with `αₖ ≤ degrees[k]`, stored flat with the
/// last variable fastest.
#[derive(Debug, Clone, PartialEq)]
pub struct Tensor {
    pub degrees: Vec<usize>,
    pub coeffs: Vec<Rational>,
}

impl Tensor {
    /// The zero polynomial of the given degrees.
    pub fn zeros(degrees: Vec<usize>) -> Tensor {
        let len = degrees.iter().map(|d| d + 1).product();
        Tensor {
            degrees,
            coeffs: vec![Rational::new(); len],
        }
    }

    /// Distance in the flat array between consecutive indices of `axis`.
    fn stride(&self, axis: usize) -> usize {
        self.degrees[axis + 1..].iter().map(|d| d + 1).product()
    }

    /// The flat position of the index tuple `alpha`.
    pub fn position(&self, alpha: &[usize]) -> usize {
        alpha
            .iter()
            .enumerate()
            .map(|(k, a)| a * self.stride(k))
            .sum()
    }

    /// Adds `q` to the coefficient of `alpha`.
    pub fn add(&mut self, alpha: &[usize], q: &Rational) {
        let i = self.position(alpha);
        self.coeffs[i] += q;
    }

    /// Start positions of every fiber along `axis` (all indices but `axis`
    /// free, `axis` index 0).
    fn fiber_starts(&self, axis: usize) -> Vec<usize> {
        let stride = self.stride(axis);
        let block = stride * (self.degrees[axis] + 1);
        (0..self.coeffs.len())
            .filter(|i| i % block < stride)
            .collect()
    }

    /// Applies `f` to every fiber along `axis`, in place.
    fn map_fibers(&mut self, axis: usize, f: impl Fn(&[Rational]) -> Vec<Rational>) {
        let (stride, n) = (self.stride(axis), self.degrees[axis] + 1);
        for start in self.fiber_starts(axis) {
            let fiber: Vec<Rational> = (0..n)
                .map(|k| self.coeffs[start + k * stride].clone())
                .collect();
            for (k, v) in f(&fiber).into_iter().enumerate() {
                self.coeffs[start + k * stride] = v;
            }
        }
    }
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

/// Outcome of a sign test on `[0,1]^d`.
#[derive(Debug, Clone, PartialEq)]
pub enum SignNd {
    /// `P ≥ 0` (or `> 0`) everywhere; the number of boxes the proof used.
    NonNegative { boxes: usize },
    /// `P < 0` (or `≤ 0` when strict) at this exact corner point.
    Negative {
        point: Vec<Rational>,
        value: Rational,
    },
    /// The depth limit was reached on this box without a decision.
    Undecided { cell: Vec<(Rational, Rational)> },
}

fn binomial(n: usize, k: usize) -> Rational {
    Rational::from(rug::Integer::from(rug::Integer::binomial_u(
        n as u32, k as u32,
    )))
}

/// One variable: `b_k = Σ_{i≤k} C(k,i)/C(n,i) · a_i`.
fn power_to_bernstein(a: &[Rational]) -> Vec<Rational> {
    let n = a.len() - 1;
    (0..=n)
        .map(|k| {
            let mut sum = Rational::new();
            for (i, ai) in a.iter().enumerate().take(k + 1) {
                if *ai != 0 {
                    sum += binomial(k, i) / binomial(n, i) * ai;
                }
            }
            sum
        })
        .collect()
}

/// Tensor Bernstein coefficients on `[0,1]^d` from power coefficients (the
/// change of basis is separable: one variable at a time).
pub fn tensor_to_bernstein(a: &Tensor) -> Tensor {
    let mut b = a.clone();
    for axis in 0..b.degrees.len() {
        b.map_fibers(axis, power_to_bernstein);
    }
    b
}

/// Bernstein coefficients on `[0,1]²` from power coefficients:
/// `b_{kl} = Σ_{i≤k} Σ_{j≤l} C(k,i)/C(n,i) · C(l,j)/C(m,j) · a_{ij}`.
pub fn to_bernstein(a: &Power) -> Vec<Vec<Rational>> {
    let b = tensor_to_bernstein(&from_power(a));
    let m = b.degrees[1] + 1;
    b.coeffs.chunks(m).map(<[Rational]>::to_vec).collect()
}

fn from_power(a: &Power) -> Tensor {
    Tensor {
        degrees: vec![a.len() - 1, a[0].len() - 1],
        coeffs: a.iter().flatten().cloned().collect(),
    }
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

/// Bernstein coefficients over a sub-box of `[0,1]^d`.
#[derive(Debug, Clone)]
struct Patch {
    b: Tensor,
    cell: Vec<(Rational, Rational)>,
    depth: u32,
}

impl Patch {
    /// Splits along the widest side among the variables of positive degree
    /// (the first such on ties).
    fn split(&self) -> (Patch, Patch) {
        let width = |k: usize| self.cell[k].1.clone() - &self.cell[k].0;
        let axis = (0..self.cell.len())
            .filter(|k| self.b.degrees[*k] > 0)
            .fold(None, |best: Option<usize>, k| match best {
                Some(j) if width(j) >= width(k) => Some(j),
                _ => Some(k),
            })
            .unwrap_or(0);
        let (mut lo, mut hi) = (self.b.clone(), self.b.clone());
        let (stride, n) = (self.b.stride(axis), self.b.degrees[axis] + 1);
        for start in self.b.fiber_starts(axis) {
            let fiber: Vec<Rational> = (0..n)
                .map(|k| self.b.coeffs[start + k * stride].clone())
                .collect();
            let (l, r) = split_seq(&fiber);
            for k in 0..n {
                lo.coeffs[start + k * stride] = l[k].clone();
                hi.coeffs[start + k * stride] = r[k].clone();
            }
        }
        let (a, c) = self.cell[axis].clone();
        let m = (a.clone() + &c) / 2u32;
        let mut lcell = self.cell.clone();
        lcell[axis] = (a, m.clone());
        let mut hcell = self.cell.clone();
        hcell[axis] = (m, c);
        (
            Patch {
                b: lo,
                cell: lcell,
                depth: self.depth + 1,
            },
            Patch {
                b: hi,
                cell: hcell,
                depth: self.depth + 1,
            },
        )
    }

    /// A corner with a negative (or, when strict, nonpositive) value.
    fn bad_corner(&self, strict: bool) -> Option<(Vec<Rational>, Rational)> {
        let d = self.cell.len();
        (0..1usize << d).find_map(|mask| {
            let alpha: Vec<usize> = (0..d)
                .map(|k| {
                    if mask >> k & 1 == 1 {
                        self.b.degrees[k]
                    } else {
                        0
                    }
                })
                .collect();
            // a corner of a degree-0 direction is counted once
            if (0..d).any(|k| mask >> k & 1 == 1 && self.b.degrees[k] == 0) {
                return None;
            }
            let v = &self.b.coeffs[self.b.position(&alpha)];
            (*v < 0 || (strict && *v == 0)).then(|| {
                let point = (0..d)
                    .map(|k| {
                        if alpha[k] == 0 {
                            self.cell[k].0.clone()
                        } else {
                            self.cell[k].1.clone()
                        }
                    })
                    .collect();
                (point, v.clone())
            })
        })
    }
}

/// Decides the sign of `P` (power coefficients on `[0,1]^d`) by subdivision
/// up to `max_depth` halvings: `P ≥ 0`, or `P > 0` when `strict` (then a
/// corner value `≤ 0` is the counterexample).
pub fn sign_on_unit_cube(a: &Tensor, max_depth: u32, strict: bool) -> SignNd {
    let unit = (Rational::new(), Rational::from(1));
    let mut stack = vec![Patch {
        b: tensor_to_bernstein(a),
        cell: vec![unit; a.degrees.len()],
        depth: 0,
    }];
    let mut boxes = 0;
    while let Some(p) = stack.pop() {
        if p.b
            .coeffs
            .iter()
            .all(|x| if strict { *x > 0 } else { *x >= 0 })
        {
            boxes += 1;
            continue;
        }
        if let Some((point, value)) = p.bad_corner(strict) {
            return SignNd::Negative { point, value };
        }
        if p.depth >= max_depth {
            return SignNd::Undecided { cell: p.cell };
        }
        let (l, r) = p.split();
        stack.push(r);
        stack.push(l);
    }
    SignNd::NonNegative { boxes }
}

/// Decides the sign of `P` (power coefficients on `[0,1]²`) by subdivision
/// up to `max_depth` halvings: `P ≥ 0`, or `P > 0` when `strict` (then a
/// corner value `≤ 0` is the counterexample).
pub fn sign_on_unit_box(a: &Power, max_depth: u32, strict: bool) -> Sign {
    match sign_on_unit_cube(&from_power(a), max_depth, strict) {
        SignNd::NonNegative { boxes } => Sign::NonNegative { boxes },
        SignNd::Negative { point, value } => Sign::Negative {
            z: point[0].clone(),
            y: point[1].clone(),
            value,
        },
        SignNd::Undecided { cell } => Sign::Undecided {
            z: cell[0].clone(),
            y: cell[1].clone(),
        },
    }
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

    #[test]
    fn three_variables_certify_and_refute() {
        // x + y + z − 1/10 on [0,1]³: negative at the origin corner
        let r = |a, b| Rational::from((a, b));
        let mut t = Tensor::zeros(vec![1, 1, 1]);
        t.coeffs[0] = r(-1, 10);
        t.add(&[1, 0, 0], &q(1));
        t.add(&[0, 1, 0], &q(1));
        t.add(&[0, 0, 1], &q(1));
        match sign_on_unit_cube(&t, 30, false) {
            SignNd::Negative { point, value } => {
                assert_eq!(point, vec![q(0), q(0), q(0)]);
                assert_eq!(value, r(-1, 10));
            }
            other => panic!("{other:?}"),
        }
        // (x − y)² + z·(1 − z)/10 + 1/1000 > 0: needs subdivision near x = y
        let mut s = Tensor::zeros(vec![2, 2, 2]);
        s.add(&[2, 0, 0], &q(1));
        s.add(&[0, 2, 0], &q(1));
        s.add(&[1, 1, 0], &q(-2));
        s.add(&[0, 0, 1], &r(1, 10));
        s.add(&[0, 0, 2], &r(-1, 10));
        s.coeffs[0] = r(1, 1000);
        assert!(tensor_to_bernstein(&s).coeffs.iter().any(|x| *x < 0));
        assert!(matches!(
            sign_on_unit_cube(&s, 40, false),
            SignNd::NonNegative { boxes } if boxes > 1
        ));
    }
}
