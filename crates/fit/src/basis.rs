//! A catalog family with numeric shape parameters, evaluated over the local
//! segment parameter `t ∈ [0, 1]`.
//!
//! `t` is mapped to the family's native variable: `u = t` (thesis (3.7), Han
//! (6.2), Usman (6.3)), `θ = πt/2` (Majeed & Qayyum (6.1), `t ∈ [0, π/2]`),
//! or the polynomial variable itself (Bernstein). The functions are those of
//! [`Family::eval`] — never re-typed here.

use trig_core::{Batch, Family};
use trig_deriv::table::{End, Wrt, endpoint_derivatives};

use crate::error::{FitError, Result};

/// Tolerance of the end-point interpolation check `b(0) = (1,0,0,0)`,
/// `b(1) = (0,0,0,1)`: a few ulps of the values at the ends (cos(π/2) in
/// f64 is 6·10⁻¹⁷, not 0).
const INTERPOLATION_TOL: f64 = 1e-12;

/// A four-function family with fixed numeric parameters, fit for
/// end-point-interpolating least squares (thesis (6.6)).
#[derive(Debug, Clone, PartialEq)]
pub struct SegmentBasis {
    family: Family,
    params: Vec<f64>,
    /// `dθ_native/dt`: 1, or π/2 for a family in the angle.
    end: f64,
}

impl SegmentBasis {
    /// Checks that the family has four functions, the right number of finite
    /// parameters, and interpolates its end control points.
    pub fn new(family: Family, params: &[f64]) -> Result<SegmentBasis> {
        let info = family.info();
        let unsuitable = |reason: String| FitError::Unsuitable {
            family: info.id.to_string(),
            reason,
        };
        if !family.has_formulas() {
            return Err(unsuitable("its formulas are missing from our copy".into()));
        }
        if info.functions.len() != 4 {
            return Err(unsuitable(format!(
                "it has {} functions; the fit needs four (V0..V3)",
                info.functions.len()
            )));
        }
        if params.len() != info.params.len() {
            return Err(unsuitable(format!(
                "it takes {} parameter(s), {} given",
                info.params.len(),
                params.len()
            )));
        }
        if let Some(p) = params.iter().find(|p| !p.is_finite()) {
            return Err(FitError::Option(format!(
                "shape parameter {p} is not finite"
            )));
        }
        let basis = SegmentBasis {
            family,
            params: params.to_vec(),
            end: info.variable.end(&1.0_f64),
        };
        for (t, expected) in [(0.0, [1.0, 0.0, 0.0, 0.0]), (1.0, [0.0, 0.0, 0.0, 1.0])] {
            let b = basis.values(t);
            if b.iter()
                .zip(expected)
                .any(|(v, e)| (v - e).abs() > INTERPOLATION_TOL || !v.is_finite())
            {
                return Err(unsuitable(format!(
                    "at t = {t} its functions are {b:?}, not {expected:?}: it does not interpolate its end control points"
                )));
            }
        }
        Ok(basis)
    }

    /// The family.
    pub fn family(&self) -> Family {
        self.family
    }

    /// The shape parameters.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    /// `b₀(t) … b₃(t)` at the local parameter `t ∈ [0, 1]`.
    pub fn values(&self, t: f64) -> [f64; 4] {
        self.values_at(&[t])[0]
    }

    /// `b₀ … b₃` at every local parameter of `ts`, in one batch
    /// ([`Batch`]: parameters converted once, vectorised `sin`/`cos`).
    pub fn values_at(&self, ts: &[f64]) -> Vec<[f64; 4]> {
        let xs: Vec<f64> = ts.iter().map(|t| t * self.end).collect();
        let mut batch = Batch::from_values(self.family, self.params.clone(), &0.0, true)
            .expect("checked by SegmentBasis::new: formulas, parameter count");
        let mut out = vec![0.0; 4 * xs.len()];
        batch.values_into(&xs, &mut out);
        let n = xs.len();
        (0..n)
            .map(|i| [out[i], out[n + i], out[2 * n + i], out[3 * n + i]])
            .collect()
    }

    /// First derivatives `dbᵢ/dt` at `t = 0` and at `t = 1` (Taylor jets of
    /// `trig-deriv` seeded with the exact end atoms; `t` is `u`, `θ = πt/2`).
    pub fn end_slopes(&self) -> ([f64; 4], [f64; 4]) {
        let at = |end| {
            let d = endpoint_derivatives::<f64, 2>(self.family, &self.params, end, Wrt::U, &1.0);
            [d[0][1], d[1][1], d[2][1], d[3][1]]
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
        let b = SegmentBasis::new(Family::ThesisCubic, &[m]).unwrap();
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
        let b = SegmentBasis::new(Family::Bernstein3, &[]).unwrap();
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
                    SegmentBasis::new(family, &params),
                    Err(FitError::Unsuitable { .. })
                ),
                "{family:?}"
            );
        }
        assert!(matches!(
            SegmentBasis::new(Family::ThesisCubic, &[f64::NAN]),
            Err(FitError::Option(_))
        ));
    }
}
