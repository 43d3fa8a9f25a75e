//! A basis with numeric shape parameters — a catalog family or any other
//! [`Basis`] (a spec file's) — evaluated over the local segment parameter
//! `t ∈ [0, 1]`.
//!
//! `t` is mapped to the basis's own variable `x = a + (b − a)t` over its
//! domain `[a, b]`: `u = t` (thesis (3.7), Han (6.2), Usman (6.3)),
//! `θ = πt/2` (Majeed & Qayyum (6.1), `t ∈ [0, π/2]`), `x = αt` for a
//! C-curve on `[0, α]`, or the polynomial variable itself (Bernstein). The
//! functions are those of [`Basis::eval`] — never re-typed here; catalog
//! families take the vectorised [`Batch`] path.

use std::any::Any;
use std::fmt;
use std::sync::Arc;

use trig_core::{Basis, Batch, Described, Domain, Family};
use trig_deriv::table::{End, Wrt, endpoint_derivatives};

use crate::error::{FitError, Result};

/// Tolerance of the end-point interpolation check `b(0) = (1,0,0,0)`,
/// `b(1) = (0,0,0,1)`: a few ulps of the values at the ends (cos(π/2) in
/// f64 is 6·10⁻¹⁷, not 0).
const INTERPOLATION_TOL: f64 = 1e-12;

/// What the fit needs of a basis, object-safe (implemented for every
/// [`Basis`] that is `Debug + Send + Sync + 'static`).
pub trait NumericBasis: fmt::Debug + Send + Sync {
    /// The basis as a catalog family, when it is one (the batch path).
    fn as_family(&self) -> Option<Family>;
    /// Stable id.
    fn basis_id(&self) -> String;
    /// Its domain.
    fn basis_domain(&self) -> Domain;
    /// Number of functions and of shape parameters.
    fn counts(&self) -> (usize, usize);
    /// The functions at the f64 point `x` of its variable.
    fn values(&self, domain: &Domain, x: f64, params: &[f64]) -> Vec<f64>;
    /// `dbᵢ/dt` at one end (`x = a + (b − a)t`).
    fn slopes(&self, params: &[f64], end: End) -> Vec<f64>;
}

impl<B: Basis + fmt::Debug + Send + Sync + 'static> NumericBasis for B {
    fn as_family(&self) -> Option<Family> {
        (self as &dyn Any).downcast_ref::<Family>().copied()
    }

    fn basis_id(&self) -> String {
        Described::id(self)
    }

    fn basis_domain(&self) -> Domain {
        Described::domain(self)
    }

    fn counts(&self) -> (usize, usize) {
        (self.function_names().len(), self.param_names().len())
    }

    fn values(&self, domain: &Domain, x: f64, params: &[f64]) -> Vec<f64> {
        self.eval(&domain.atoms(&x), params)
    }

    fn slopes(&self, params: &[f64], end: End) -> Vec<f64> {
        endpoint_derivatives::<f64, 2>(self, params, end, Wrt::U, &1.0)
            .iter()
            .map(|d| d[1])
            .collect()
    }
}

/// A four-function basis with fixed numeric parameters, fit for
/// end-point-interpolating least squares (thesis (6.6)).
#[derive(Debug, Clone)]
pub struct SegmentBasis {
    basis: Arc<dyn NumericBasis>,
    domain: Domain,
    params: Vec<f64>,
    /// The domain `[a, b]` at these parameters: `x = a + (b − a)t`.
    start: f64,
    length: f64,
}

impl SegmentBasis {
    /// Checks that the basis has four functions, the right number of finite
    /// parameters, and interpolates its end control points.
    pub fn new(basis: Arc<dyn NumericBasis>, params: &[f64]) -> Result<SegmentBasis> {
        let unsuitable = |reason: String| FitError::Unsuitable {
            family: basis.basis_id(),
            reason,
        };
        if basis.as_family().is_some_and(|f| !f.has_formulas()) {
            return Err(unsuitable("its formulas are missing from our copy".into()));
        }
        let (functions, count) = basis.counts();
        if functions != 4 {
            return Err(unsuitable(format!(
                "it has {functions} functions; the fit needs four (V0..V3)"
            )));
        }
        if params.len() != count {
            return Err(unsuitable(format!(
                "it takes {count} parameter(s), {} given",
                params.len()
            )));
        }
        if let Some(p) = params.iter().find(|p| !p.is_finite()) {
            return Err(FitError::Option(format!(
                "shape parameter {p} is not finite"
            )));
        }
        let domain = basis.basis_domain();
        let start = domain.start_value(&0.0, params);
        let length = domain.end_value(&0.0, params) - start;
        if !(length.is_finite() && length > 0.0) {
            return Err(unsuitable(format!(
                "its domain {domain} has length {length} at these parameters"
            )));
        }
        let segment = SegmentBasis {
            basis: basis.clone(),
            domain,
            params: params.to_vec(),
            start,
            length,
        };
        for (t, expected) in [(0.0, [1.0, 0.0, 0.0, 0.0]), (1.0, [0.0, 0.0, 0.0, 1.0])] {
            let b = segment.values(t);
            if b.iter()
                .zip(expected)
                .any(|(v, e)| (v - e).abs() > INTERPOLATION_TOL || !v.is_finite())
            {
                return Err(unsuitable(format!(
                    "at t = {t} its functions are {b:?}, not {expected:?}: it does not interpolate its end control points in f64 (or its formula cancels at these parameters)"
                )));
            }
        }
        Ok(segment)
    }

    /// The basis.
    pub fn basis(&self) -> &Arc<dyn NumericBasis> {
        &self.basis
    }

    /// The shape parameters.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// `b₀(t) … b₃(t)` at the local parameter `t ∈ [0, 1]`.
    pub fn values(&self, t: f64) -> [f64; 4] {
        self.values_at(&[t])[0]
    }

    /// `b₀ … b₃` at every local parameter of `ts`: a catalog family in one
    /// batch ([`Batch`]: parameters converted once, vectorised `sin`/`cos`),
    /// any other basis point by point.
    pub fn values_at(&self, ts: &[f64]) -> Vec<[f64; 4]> {
        let xs: Vec<f64> = ts.iter().map(|t| self.start + t * self.length).collect();
        let four = |v: &[f64]| [v[0], v[1], v[2], v[3]];
        let Some(family) = self.basis.as_family() else {
            return xs
                .iter()
                .map(|&x| four(&self.basis.values(&self.domain, x, &self.params)))
                .collect();
        };
        let mut batch = Batch::from_values(family, self.params.clone(), &0.0, true)
            .expect("checked by SegmentBasis::new: formulas, parameter count");
        let mut out = vec![0.0; 4 * xs.len()];
        batch.values_into(&xs, &mut out);
        let n = xs.len();
        (0..n)
            .map(|i| [out[i], out[n + i], out[2 * n + i], out[3 * n + i]])
            .collect()
    }

    /// First derivatives `dbᵢ/dt` at `t = 0` and at `t = 1` (Taylor jets of
    /// `trig-deriv` seeded with the exact end atoms, `x = a + (b − a)t`).
    pub fn end_slopes(&self) -> ([f64; 4], [f64; 4]) {
        let at = |end| {
            let d = self.basis.slopes(&self.params, end);
            [d[0], d[1], d[2], d[3]]
        };
        (at(End::Start), at(End::End))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thesis_cubic_end_slopes_are_the_printed_ones() {
        // thesis Chapter 4: Q'(0) = (m+2)(P1 − P0) in θ, times π/2 in u
        let m = 0.6;
        let b = SegmentBasis::new(Arc::new(Family::ThesisCubic), &[m]).unwrap();
        let (start, end) = b.end_slopes();
        let k = (m + 2.0) * std::f64::consts::FRAC_PI_2;
        let want_start = [-k, k, 0.0, 0.0];
        let want_end = [0.0, 0.0, -k, k];
        for (g, w) in start
            .iter()
            .chain(&end)
            .zip(want_start.iter().chain(&want_end))
        {
            assert!((g - w).abs() < 1e-12, "{start:?} {end:?}");
        }
    }

    #[test]
    fn bernstein_values_and_slopes() {
        let b = SegmentBasis::new(Arc::new(Family::Bernstein3), &[]).unwrap();
        assert_eq!(b.values(0.5), [0.125, 0.375, 0.375, 0.125]);
        assert_eq!(
            b.end_slopes(),
            ([-3.0, 3.0, 0.0, 0.0], [0.0, 0.0, -3.0, 3.0])
        );
    }

    #[test]
    fn families_that_cannot_be_fitted_are_refused() {
        for (family, params) in [
            (Family::Seed002Quartic, vec![]),
            (Family::BSpline3, vec![]),
            (Family::Hermite, vec![]),
            (Family::ThesisCubic, vec![]),
        ] {
            assert!(
                matches!(
                    SegmentBasis::new(Arc::new(family), &params),
                    Err(FitError::Unsuitable { .. })
                ),
                "{family:?}"
            );
        }
        assert!(matches!(
            SegmentBasis::new(Arc::new(Family::ThesisCubic), &[f64::NAN]),
            Err(FitError::Option(_))
        ));
    }
}
