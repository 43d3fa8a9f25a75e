//! Batch evaluation: every function of a family at many points, into a
//! caller's buffer.
//!
//! [`Family::eval_at`] is the checked evaluation at one point: it converts
//! the exact parameters, allocates a `Vec` and calls `sin_cos` every time.
//! A [`Batch`] converts the parameters once, keeps its scratch buffers,
//! takes the angles' sines and cosines a chunk at a time (in f64 with the
//! vectorised kernel of [`crate::sincos`], in MPFR in place), and runs the
//! family's one generic formula ([`Family::with_formula`]) over the chunk,
//! writing straight into the output: no allocation per point in f64, and
//! none beyond the formula's own intermediate values in MPFR.
//!
//! The checks are those of [`Family::eval_at`]: points must be finite and
//! (unless allowed) in the domain, and a non-finite value (a vanishing
//! denominator) is a typed error.
//!
//! ```
//! use rug::Rational;
//! use trig_core::{Family, batch::Batch};
//! let mut batch = Batch::new(Family::ThesisCubic, &[Rational::from((3, 5))], &0.0, false).unwrap();
//! let xs = [0.0, 0.5, 1.0];
//! let mut out = vec![0.0; batch.functions() * xs.len()];
//! batch.eval_into(&xs, &mut out).unwrap();
//! // function-major: b₀ at the three points, then b₁, …
//! assert_eq!(&out[0..3], &[1.0, out[1], 0.0]);
//! assert!((out.chunks(3).map(|b| b[1]).sum::<f64>() - 1.0).abs() < 1e-15);
//! ```

use rug::Rational;

use crate::error::{CoreError, Result};
use crate::family::{Family, Formula, FormulaVisitor};
use crate::mpfr::Mpfr;
use crate::scalar::Real;
use crate::sincos;
use crate::variable::Variable;

/// Points evaluated together: enough for the vector units, few enough for
/// the scratch buffers to stay in the first-level cache.
pub const CHUNK: usize = 256;

/// A numeric scalar with the in-place operations a batch needs.
pub trait BatchReal: Real {
    /// Replaces every `theta[i]` by its sine and writes its cosine to
    /// `cos[i]`.
    fn sin_cos_in_place(theta: &mut [Self], cos: &mut [Self]);

    /// `self = a · b`, rounded to the precision of `self` (reusing its
    /// storage).
    fn set_product(&mut self, a: &Self, b: &Self);
}

impl BatchReal for f64 {
    fn sin_cos_in_place(theta: &mut [f64], cos: &mut [f64]) {
        sincos::sin_cos_in_place(theta, cos);
    }

    fn set_product(&mut self, a: &f64, b: &f64) {
        *self = a * b;
    }
}

impl BatchReal for Mpfr {
    fn sin_cos_in_place(theta: &mut [Mpfr], cos: &mut [Mpfr]) {
        for (t, c) in theta.iter_mut().zip(cos) {
            t.0.sin_cos_mut(&mut c.0);
        }
    }

    fn set_product(&mut self, a: &Mpfr, b: &Mpfr) {
        use rug::Assign;
        self.0.assign(&a.0 * &b.0);
    }
}

/// A family with its parameters converted once, ready to evaluate at many
/// points.
#[derive(Debug, Clone)]
pub struct Batch<T> {
    family: Family,
    variable: Variable,
    /// The parameters as given, for error messages.
    labels: Vec<String>,
    /// The exact parameters, when given so ([`Batch::new`]).
    exact: Option<Vec<Rational>>,
    params: Vec<T>,
    /// `dθ/dx`: `π/2` for `u`, 1 for the angle.
    rate: T,
    allow_outside: bool,
    /// Scratch: angles, then their sines, and their cosines.
    sin: Vec<T>,
    cos: Vec<T>,
}

impl<T: BatchReal> Batch<T> {
    /// The family with exact parameters `params` (in the order of its
    /// [`crate::FamilyInfo::params`]) converted to the scalar of `like`
    /// (its precision, for MPFR). With `allow_outside`, points outside the
    /// domain are evaluated too.
    pub fn new(
        family: Family,
        params: &[Rational],
        like: &T,
        allow_outside: bool,
    ) -> Result<Batch<T>> {
        let values = params.iter().map(|q| like.rational(q)).collect();
        let mut batch = Batch::from_values(family, values, like, allow_outside)?;
        batch.labels = params.iter().map(ToString::to_string).collect();
        batch.exact = Some(params.to_vec());
        Ok(batch)
    }

    /// The family with parameters already in the scalar type (e.g. a shape
    /// parameter found by optimisation), otherwise as [`Batch::new`].
    pub fn from_values(
        family: Family,
        params: Vec<T>,
        like: &T,
        allow_outside: bool,
    ) -> Result<Batch<T>> {
        let info = family.info();
        if !family.has_formulas() {
            return Err(CoreError::NoFormulas(info.id.to_string()));
        }
        if params.len() != info.params.len() {
            return Err(CoreError::Count {
                what: format!("parameters for `{}`", info.id),
                expected: info.params.len(),
                got: params.len(),
            });
        }
        let zero = like.int(0);
        Ok(Batch {
            family,
            variable: info.variable,
            labels: params.iter().map(|p| p.to_f64().to_string()).collect(),
            exact: None,
            params,
            rate: info.variable.angle_rate(like),
            allow_outside,
            sin: vec![zero.clone(); CHUNK],
            cos: vec![zero; CHUNK],
        })
    }

    /// The family.
    pub fn family(&self) -> Family {
        self.family
    }

    /// Number of functions, i.e. of output values per point.
    pub fn functions(&self) -> usize {
        self.family.info().functions.len()
    }

    /// Every function at every point of `xs` (in the family's native
    /// variable), function-major: `out[k·xs.len() + i] = b_k(xs[i])`.
    ///
    /// # Errors
    /// A wrong output length, a point that is not finite or (unless
    /// allowed) outside the domain, or a non-finite value (a vanishing
    /// denominator). `out` is unspecified after an error.
    pub fn eval_into(&mut self, xs: &[T], out: &mut [T]) -> Result<()> {
        let len = xs.len();
        if out.len() != self.functions() * len {
            return Err(CoreError::Count {
                what: "output values (functions × points)".into(),
                expected: self.functions() * len,
                got: out.len(),
            });
        }
        // Fast path: every point in the domain (NaN fails the comparisons).
        let (zero, end) = (self.rate.int(0), self.variable.end(&self.rate));
        if !xs
            .iter()
            .fold(true, |ok, x| ok & (*x >= zero) & (*x <= end))
        {
            for x in xs {
                self.variable.check_point(x, self.allow_outside)?;
            }
        }
        if !self.fill(xs, out) {
            let at = self
                .family
                .info()
                .params
                .iter()
                .zip(&self.labels)
                .map(|(s, v)| format!("{}={v}", s.name))
                .collect::<Vec<_>>()
                .join(", ");
            let quantity = format!("`{}` at {at}", self.family.info().id);
            // the first point with a non-finite value, judged as eval_at does
            let n = xs.len();
            let first = (0..n)
                .find(|&i| (0..self.functions()).any(|k| !out[k * n + i].is_finite()))
                .unwrap_or(0);
            return Err(match &self.exact {
                Some(p) => crate::certified::nonfinite_error(&self.family, &xs[first], p, quantity),
                None => CoreError::DivisionByZero { quantity },
            });
        }
        Ok(())
    }

    /// The formula's values at every point, without the checks of
    /// [`Batch::eval_into`] (as [`Family::eval`] is to
    /// [`Family::eval_at`]): any point, and non-finite values as they come.
    ///
    /// # Panics
    /// If `out.len()` is not [`Batch::functions`] × `xs.len()`.
    pub fn values_into(&mut self, xs: &[T], out: &mut [T]) {
        assert_eq!(out.len(), self.functions() * xs.len(), "output length");
        self.fill(xs, out);
    }

    /// Fills `out`; true when every value is finite.
    fn fill(&mut self, xs: &[T], out: &mut [T]) -> bool {
        let len = xs.len();
        let mut finite = true;
        for start in (0..len).step_by(CHUNK) {
            let chunk = &xs[start..len.min(start + CHUNK)];
            let m = chunk.len();
            let trig = self.variable.is_trigonometric();
            if trig {
                for (theta, x) in self.sin.iter_mut().zip(chunk) {
                    theta.set_product(x, &self.rate);
                }
                T::sin_cos_in_place(&mut self.sin[..m], &mut self.cos[..m]);
            }
            let (s, c) = if trig {
                (&self.sin[..m], &self.cos[..m])
            } else {
                (chunk, chunk)
            };
            finite &= self.family.with_formula(Fill {
                s,
                c,
                t: chunk,
                params: &self.params,
                out: &mut *out,
                len,
                start,
            });
        }
        finite
    }

    /// Every function at every point, as a new function-major vector (see
    /// [`Batch::eval_into`]).
    pub fn eval(&mut self, xs: &[T]) -> Result<Vec<T>> {
        let zero = self.rate.int(0);
        let mut out = vec![zero; self.functions() * xs.len()];
        self.eval_into(xs, &mut out)?;
        Ok(out)
    }
}

/// Runs a formula over one chunk of atoms, writing function-major.
struct Fill<'a, T> {
    s: &'a [T],
    c: &'a [T],
    t: &'a [T],
    params: &'a [T],
    out: &'a mut [T],
    /// Points in the whole batch (the stride between functions).
    len: usize,
    /// Index of the chunk's first point.
    start: usize,
}

impl<T: Real> FormulaVisitor<T> for Fill<'_, T> {
    /// True when every value is finite.
    type Output = bool;

    fn visit<const N: usize>(self, formula: impl Formula<T, N>) -> bool {
        let Fill {
            s,
            c,
            t,
            params,
            out,
            len,
            start,
        } = self;
        let m = t.len();
        let mut columns = out.chunks_exact_mut(len);
        let mut columns: [&mut [T]; N] = std::array::from_fn(|_| {
            &mut columns.next().expect("one column per function")[start..start + m]
        });
        let mut finite = true;
        for (i, ((si, ci), ti)) in s.iter().zip(c).zip(t).enumerate() {
            for (column, v) in columns.iter_mut().zip(formula(si, ci, ti, params)) {
                finite &= v.is_finite();
                column[i] = v;
            }
        }
        finite
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(params: &[(i64, i64)]) -> Vec<Rational> {
        params.iter().map(|&p| Rational::from(p)).collect()
    }

    /// Every family, batch against the checked one-point evaluation, over
    /// more than one chunk. The batch differs from `eval_at` only in how
    /// `sin θ`, `cos θ` are rounded (≤ 3·2⁻⁵³ each, [`crate::sincos`]), and
    /// the formulas are polynomials in `s`, `c` whose partial derivatives
    /// are below 40 for these parameters: `1e-13` covers both with margin.
    #[test]
    fn matches_the_one_point_evaluation_for_every_family() {
        let cases: &[(Family, &[(i64, i64)])] = &[
            (Family::ThesisQuadratic, &[(3, 1)]),
            (Family::ThesisCubic, &[(3, 5)]),
            (Family::Han, &[(-1, 2)]),
            (Family::MajeedQayyum, &[(3, 2)]),
            (Family::Usman, &[(1, 2)]),
            (Family::HanListing, &[(1, 2)]),
            (Family::Seed000Blending, &[(2, 1)]),
            (Family::Seed000Uniform, &[(2, 1)]),
            (Family::Seed002Quartic, &[]),
            (Family::Eh, &[(1, 2), (-1, 3)]),
            (Family::Hermite, &[]),
            (Family::Bernstein3, &[]),
            (Family::BSpline3, &[]),
        ];
        for &(family, params) in cases {
            let p = exact(params);
            let end = family.info().variable.end(&1.0_f64);
            let n = 3 * CHUNK + 5;
            let xs: Vec<f64> = (0..n).map(|i| end * i as f64 / (n - 1) as f64).collect();
            let mut batch = Batch::new(family, &p, &0.0, false).unwrap();
            let out = batch.eval(&xs).unwrap();
            for (i, x) in xs.iter().enumerate() {
                let one = family.eval_at(x, &p, false).unwrap();
                for (k, v) in one.iter().enumerate() {
                    let b = out[k * n + i];
                    assert!((b - v).abs() < 1e-13, "{family:?} at {x}: {b} vs {v}");
                }
            }
        }
    }

    #[test]
    fn mpfr_batch_equals_the_one_point_evaluation_exactly() {
        // Same operations in the same order at the same precision.
        let p = exact(&[(3, 5)]);
        let like = Mpfr::from_f64(336, 0.0);
        let xs: Vec<Mpfr> = (0..=100)
            .map(|i| Mpfr::from_rational(336, &Rational::from((i, 100))))
            .collect();
        let mut batch = Batch::new(Family::ThesisCubic, &p, &like, false).unwrap();
        let out = batch.eval(&xs).unwrap();
        for (i, x) in xs.iter().enumerate() {
            let one = Family::ThesisCubic.eval_at(x, &p, false).unwrap();
            for (k, v) in one.iter().enumerate() {
                assert_eq!(out[k * xs.len() + i], *v);
                assert_eq!(out[k * xs.len() + i].prec(), 336);
            }
        }
    }

    #[test]
    fn bad_input_is_a_typed_error() {
        let p = exact(&[(3, 5)]);
        let mut batch = Batch::new(Family::ThesisCubic, &p, &0.0, false).unwrap();
        assert!(matches!(
            batch.eval(&[0.5, 1.5]),
            Err(CoreError::PointOutsideDomain { .. })
        ));
        assert!(matches!(
            batch.eval(&[f64::NAN]),
            Err(CoreError::NotFinite { .. })
        ));
        assert!(matches!(
            batch.eval_into(&[0.5], &mut [0.0; 3]),
            Err(CoreError::Count { .. })
        ));
        assert!(matches!(
            Batch::new(Family::ThesisCubic, &[], &0.0, false),
            Err(CoreError::Count { .. })
        ));
        assert!(matches!(
            Batch::new(Family::Seed003, &[], &0.0, false),
            Err(CoreError::NoFormulas(_))
        ));
        // β = −1 makes β/(β+1) divide by zero
        let mut pole = Batch::new(Family::ThesisQuadratic, &exact(&[(-1, 1)]), &0.0, true).unwrap();
        assert!(matches!(
            pole.eval(&[0.5]),
            Err(CoreError::DivisionByZero { .. })
        ));
        let mut outside = Batch::new(Family::ThesisCubic, &p, &0.0, true).unwrap();
        let v = outside.eval(&[2.0]).unwrap();
        let one = Family::ThesisCubic.eval_at(&2.0, &p, true).unwrap();
        for (b, e) in v.iter().zip(&one) {
            assert!((b - e).abs() < 1e-13, "{v:?} vs {one:?}");
        }
    }
}
