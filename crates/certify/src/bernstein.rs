//! Exact tensor Bernstein polynomials on boxes and the subdivision test of
//! their sign, in any number of variables.
//!
//! A polynomial `P(x₁, …, x_d)` of degrees `(n₁, …, n_d)` on `[0,1]^d` is
//! written `Σ b_α B^{n₁}_{α₁}(x₁)⋯B^{n_d}_{α_d}(x_d)`. All `b_α ≥ 0` proves
//! `P ≥ 0` on the box; corner coefficients are the values at the corners, so
//! a negative corner is an exact counterexample. Otherwise the box is split
//! in half along its widest side of positive degree (de Casteljau, exact)
//! and both halves are tested, up to a depth limit.
//!
//! Faces of the cube can be *excluded* ([`Excluded`]): the face `y = 1` of a
//! half-line `p = a + y/(1 − y)` is the point at infinity, the face of an
//! open range end is not in the set. A corner on an excluded face is never
//! a counterexample, and strict positivity is proved on the cube minus its
//! excluded faces: with all `b_α ≥ 0`, `P > 0` there as soon as `b_α > 0`
//! for every `α` whose index on each excluded face's axis is the one whose
//! Bernstein polynomial is positive off that face (`B₀ = (1 − y)ⁿ > 0` for
//! `y < 1`, `Bₙ = yⁿ > 0` for `y > 0`).

use rug::{Integer, Rational};

/// Coefficients of a polynomial in `d` variables, indexed by exponent (or
/// Bernstein index) tuples `α` with `αₖ ≤ degrees[k]`, stored flat with the
/// last variable fastest: rationals, or the integer numerators of a
/// subdivision over their common denominator.
#[derive(Debug, Clone, PartialEq)]
pub struct Tensor<C = Rational> {
    pub degrees: Vec<usize>,
    pub coeffs: Vec<C>,
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

    /// Adds `q` to the coefficient of `alpha`.
    pub fn add(&mut self, alpha: &[usize], q: &Rational) {
        let i = self.position(alpha);
        self.coeffs[i] += q;
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

impl<C> Tensor<C> {
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

    /// Start positions of every fiber along `axis` (all indices but `axis`
    /// free, `axis` index 0).
    fn fiber_starts(&self, axis: usize) -> Vec<usize> {
        let stride = self.stride(axis);
        let block = stride * (self.degrees[axis] + 1);
        (0..self.coeffs.len())
            .filter(|i| i % block < stride)
            .collect()
    }
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
    /// The subdivision spent its [`MAX_COEFFICIENT_WORK`] without a
    /// decision (after this many boxes).
    OutOfBudget { boxes: usize },
}

/// Most coefficient operations of one subdivision (each box costs its
/// number of Bernstein coefficients times the degree it is split along):
/// the budget is counted, not timed, so a decision never depends on the
/// machine or its load. No claim of the catalog or of `examples/` comes
/// near it: the largest subdivision of the audit and of every spec file
/// of `examples/` takes fewer than 100,000.
pub const MAX_COEFFICIENT_WORK: u64 = 50_000_000;

/// One variable: `b_k = Σ_{i≤k} C(k,i)/C(n,i) · a_i`.
pub fn power_to_bernstein(a: &[Rational]) -> Vec<Rational> {
    crate::minors::power_to_bernstein(a, a.len() - 1)
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

/// One de Casteljau split at 1/2 of a sequence of integer numerators, all
/// outputs over `2ⁿ⁻¹` times the input's denominator (`n` terms): the sums
/// of level `r` without the halvings are `2ʳ` times the midpoint values,
/// shifted up by the `n − 1 − r` halvings they lack.
fn split_seq(c: &[Integer]) -> (Vec<Integer>, Vec<Integer>) {
    let mut work = c.to_vec();
    let n = work.len();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![Integer::new(); n];
    for r in 0..n {
        let lack = (n - 1 - r) as u32;
        left.push(Integer::from(&work[0] << lack));
        right[n - 1 - r] = Integer::from(&work[n - 1 - r] << lack);
        for i in 0..n - 1 - r {
            let (head, tail) = work.split_at_mut(i + 1);
            head[i] += &tail[0];
        }
    }
    (left, right)
}

/// Bernstein coefficients over a sub-box of `[0,1]^d`: integer numerators
/// over one positive denominator (signs are the numerators' signs).
#[derive(Debug, Clone)]
struct Patch {
    b: Tensor<Integer>,
    den: Integer,
    cell: Vec<(Rational, Rational)>,
    depth: u32,
}

impl Patch {
    /// The patch of rational Bernstein coefficients over the unit cube.
    fn unit(b: &Tensor) -> Patch {
        let den = b
            .coeffs
            .iter()
            .fold(Integer::from(1), |acc, x| acc.lcm(x.denom()));
        let coeffs = b
            .coeffs
            .iter()
            .map(|x| x.numer() * Integer::from(&den / x.denom()))
            .collect();
        let unit = (Rational::new(), Rational::from(1));
        Patch {
            b: Tensor {
                degrees: b.degrees.clone(),
                coeffs,
            },
            den,
            cell: vec![unit; b.degrees.len()],
            depth: 0,
        }
    }

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
            let fiber: Vec<Integer> = (0..n)
                .map(|k| self.b.coeffs[start + k * stride].clone())
                .collect();
            let (l, r) = split_seq(&fiber);
            for (k, (l, r)) in l.into_iter().zip(r).enumerate() {
                lo.coeffs[start + k * stride] = l;
                hi.coeffs[start + k * stride] = r;
            }
        }
        let den = Integer::from(&self.den << (n - 1) as u32);
        let (a, c) = self.cell[axis].clone();
        let m = (a.clone() + &c) / 2u32;
        let mut lcell = self.cell.clone();
        lcell[axis] = (a, m.clone());
        let mut hcell = self.cell.clone();
        hcell[axis] = (m, c);
        let patch = |b: Tensor<Integer>, cell| {
            let (b, den) = without_common_twos(b, den.clone());
            Patch {
                b,
                den,
                cell,
                depth: self.depth + 1,
            }
        };
        (patch(lo, lcell), patch(hi, hcell))
    }

    /// Whether the corner coordinate of `axis` (upper when `upper`) lies on
    /// an excluded face of the unit cube.
    fn on_excluded(&self, axis: usize, upper: bool, excluded: &[Excluded]) -> bool {
        let (lo, hi) = &self.cell[axis];
        if upper {
            excluded[axis].hi && *hi == 1
        } else {
            excluded[axis].lo && *lo == 0
        }
    }

    /// A corner with a negative (or, when strict, nonpositive) value that
    /// lies on no excluded face.
    fn bad_corner(&self, strict: bool, excluded: &[Excluded]) -> Option<(Vec<Rational>, Rational)> {
        let d = self.cell.len();
        (0..1usize << d).find_map(|mask| {
            let upper = |k: usize| mask >> k & 1 == 1;
            // a corner of a degree-0 direction is counted once
            if (0..d).any(|k| upper(k) && self.b.degrees[k] == 0) {
                return None;
            }
            if (0..d).any(|k| self.on_excluded(k, upper(k), excluded)) {
                return None;
            }
            let alpha: Vec<usize> = (0..d)
                .map(|k| if upper(k) { self.b.degrees[k] } else { 0 })
                .collect();
            let v = &self.b.coeffs[self.b.position(&alpha)];
            (*v < 0 || (strict && *v == 0)).then(|| {
                let point = (0..d)
                    .map(|k| {
                        if upper(k) {
                            self.cell[k].1.clone()
                        } else {
                            self.cell[k].0.clone()
                        }
                    })
                    .collect();
                (point, Rational::from((v.clone(), self.den.clone())))
            })
        })
    }

    /// True when the coefficients prove the sign on this cell (minus the
    /// excluded faces it touches): all `≥ 0`, and when strict, `> 0` on the
    /// indices whose Bernstein polynomials are positive off those faces.
    fn proves(&self, strict: bool, excluded: &[Excluded]) -> bool {
        if self.b.coeffs.iter().any(|x| *x < 0) {
            return false;
        }
        if !strict {
            return true;
        }
        // per axis, the index that must carry the positivity (None: any)
        let pinned: Vec<Option<usize>> = (0..self.cell.len())
            .map(|k| {
                if self.on_excluded(k, true, excluded) {
                    Some(0)
                } else if self.on_excluded(k, false, excluded) {
                    Some(self.b.degrees[k])
                } else {
                    None
                }
            })
            .collect();
        let strides: Vec<usize> = (0..pinned.len()).map(|k| self.b.stride(k)).collect();
        self.b.coeffs.iter().enumerate().all(|(i, x)| {
            let selected = pinned.iter().enumerate().all(|(k, pin)| {
                pin.is_none_or(|j| (i / strides[k]) % (self.b.degrees[k] + 1) == j)
            });
            !selected || *x > 0
        })
    }
}

/// `b/den` with the powers of two common to every numerator and the
/// denominator divided out (the halvings of a subdivision would otherwise
/// grow them by a factor per split).
fn without_common_twos(mut b: Tensor<Integer>, mut den: Integer) -> (Tensor<Integer>, Integer) {
    let twos = b
        .coeffs
        .iter()
        .filter_map(|x| x.find_one(0))
        .chain(den.find_one(0))
        .min()
        .unwrap_or(0);
    if twos > 0 {
        for x in &mut b.coeffs {
            *x >>= twos;
        }
        den >>= twos;
    }
    (b, den)
}

/// Which faces of one axis of the unit cube are not part of the set: the
/// face at infinity of a half-line, the face of an open range end.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Excluded {
    /// The face `x = 0`.
    pub lo: bool,
    /// The face `x = 1`.
    pub hi: bool,
}

/// Decides the sign of `P` (power coefficients on `[0,1]^d`) by subdivision
/// up to `max_depth` halvings: `P ≥ 0`, or `P > 0` when `strict` (then a
/// corner value `≤ 0` is the counterexample), on the cube minus the
/// `excluded` faces (one entry per axis; missing entries exclude nothing).
pub fn sign_on_unit_cube(
    a: &Tensor,
    max_depth: u32,
    strict: bool,
    excluded: &[Excluded],
) -> SignNd {
    let d = a.degrees.len();
    let mut excluded = excluded.to_vec();
    excluded.resize(d, Excluded::default());
    let mut stack = vec![Patch::unit(&tensor_to_bernstein(a))];
    let mut boxes = 0;
    let mut spent = 0u64;
    while let Some(p) = stack.pop() {
        if p.proves(strict, &excluded) {
            boxes += 1;
            continue;
        }
        if let Some((point, value)) = p.bad_corner(strict, &excluded) {
            return SignNd::Negative { point, value };
        }
        if p.depth >= max_depth {
            return SignNd::Undecided { cell: p.cell };
        }
        let degree = p.b.degrees.iter().max().map_or(1, |d| d + 1);
        spent = spent.saturating_add((p.b.coeffs.len() * degree) as u64);
        if spent > MAX_COEFFICIENT_WORK {
            return SignNd::OutOfBudget { boxes };
        }
        let (l, r) = p.split();
        stack.push(r);
        stack.push(l);
    }
    SignNd::NonNegative { boxes }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    fn r(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    /// `Σ a[i][j] zⁱ yʲ` as a tensor.
    fn rows(a: &[Vec<Rational>]) -> Tensor {
        Tensor {
            degrees: vec![a.len() - 1, a[0].len() - 1],
            coeffs: a.iter().flatten().cloned().collect(),
        }
    }

    #[test]
    fn a_split_at_one_half_is_de_casteljau() {
        // [a, b, c]: left [a, (a+b)/2, (a+2b+c)/4], right [(a+2b+c)/4,
        // (b+c)/2, c], all over 4
        let z = |n: i64| Integer::from(n);
        let (left, right) = split_seq(&[z(8), z(3), z(-5)]);
        assert_eq!(left, [z(32), z(22), z(9)]);
        assert_eq!(right, [z(9), z(-4), z(-20)]);
        // common powers of two come off the numerators and the denominator
        let t = Tensor {
            degrees: vec![2],
            coeffs: vec![z(12), z(-4), z(0)],
        };
        let (t, den) = without_common_twos(t, z(8));
        assert_eq!((t.coeffs, den), (vec![z(3), z(-1), z(0)], z(2)));
    }

    #[test]
    fn a_nonnegative_polynomial_is_certified_and_a_negative_one_refuted() {
        // (z − 1/2)² + (y − 1/2)² + 1/100 > 0: the coefficients on the whole
        // square are not all ≥ 0, subdivision proves it
        let sq = rows(&[
            vec![r(51, 100), q(-1), q(1)],
            vec![q(-1), q(0), q(0)],
            vec![q(1), q(0), q(0)],
        ]);
        assert!(tensor_to_bernstein(&sq).coeffs.iter().any(|x| *x < 0));
        assert!(matches!(
            sign_on_unit_cube(&sq, 20, false, &[]),
            SignNd::NonNegative { .. }
        ));
        // z − 1/2 is negative at z = 0
        let lin = rows(&[vec![r(-1, 2)], vec![q(1)]]);
        match sign_on_unit_cube(&lin, 20, false, &[]) {
            SignNd::Negative { point, value } => {
                assert_eq!(point[0], 0);
                assert_eq!(value, r(-1, 2));
            }
            other => panic!("{other:?}"),
        }
        // (z − 1/2)² − 1/1000 dips below zero only inside: found by subdivision
        let dip = rows(&[vec![r(1, 4) - r(1, 1000)], vec![q(-1)], vec![q(1)]]);
        assert!(matches!(
            sign_on_unit_cube(&dip, 30, false, &[]),
            SignNd::Negative { .. }
        ));
    }

    #[test]
    fn bernstein_coefficients_of_one_are_all_one() {
        let one = rows(&[vec![q(1), q(0)], vec![q(0), q(0)]]);
        assert!(tensor_to_bernstein(&one).coeffs.iter().all(|x| *x == 1));
    }

    #[test]
    fn excluded_faces_are_not_counterexamples_and_allow_strictness() {
        // 1 − y vanishes only on the face y = 1: strictly positive off it
        let p = rows(&[vec![q(1), q(-1)]]);
        let off_top = [
            Excluded::default(),
            Excluded {
                lo: false,
                hi: true,
            },
        ];
        assert!(matches!(
            sign_on_unit_cube(&p, 10, true, &[]),
            SignNd::Negative { ref point, .. } if point[1] == 1
        ));
        assert!(matches!(
            sign_on_unit_cube(&p, 10, true, &off_top),
            SignNd::NonNegative { .. }
        ));
        // (1 − y)(1 − 2z + 2z²) + 2y z(1 − z): the rational quadratic's
        // denominator for w = y/(1 − y), zero at the face y = 1 only
        let d = rows(&[vec![q(1), q(-1)], vec![q(-2), q(4)], vec![q(2), q(-4)]]);
        assert!(matches!(
            sign_on_unit_cube(&d, 30, true, &off_top),
            SignNd::NonNegative { .. }
        ));
        // y − 1/2 is negative near y = 0 whatever faces are excluded
        let e = rows(&[vec![r(-1, 2), q(1)]]);
        let both = [Excluded::default(), Excluded { lo: true, hi: true }];
        match sign_on_unit_cube(&e, 30, false, &both) {
            SignNd::Negative { point, value } => {
                assert!(point[1] > 0 && point[1] < r(1, 2), "{point:?}");
                assert!(value < 0);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn three_variables_certify_and_refute() {
        // x + y + z − 1/10 on [0,1]³: negative at the origin corner
        let mut t = Tensor::zeros(vec![1, 1, 1]);
        t.coeffs[0] = r(-1, 10);
        t.add(&[1, 0, 0], &q(1));
        t.add(&[0, 1, 0], &q(1));
        t.add(&[0, 0, 1], &q(1));
        match sign_on_unit_cube(&t, 30, false, &[]) {
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
            sign_on_unit_cube(&s, 40, false, &[]),
            SignNd::NonNegative { boxes } if boxes > 1
        ));
    }
}
