//! Least squares for the inner control points with fixed end points,
//! thesis (6.8), (6.11)–(6.18).
//!
//! `V₀ = P₁`, `V₃ = P_N` are fixed; `V₁`, `V₂` minimise
//! `S = Σᵢ ‖V₀b₀(tᵢ) + V₁b₁(tᵢ) + V₂b₂(tᵢ) + V₃b₃(tᵢ) − Pᵢ‖²` (6.8). The normal
//! equations are the 2×2 system (6.15)/(6.16):
//!
//! `[Σb₁² Σb₁b₂; Σb₁b₂ Σb₂²] [V₁; V₂] = [Σ b₁(Pᵢ − V₀b₀ − V₃b₃); Σ b₂(Pᵢ − V₀b₀ − V₃b₃)]`,
//!
//! one right-hand side per coordinate. (6.15) as printed repeats the first
//! row's right-hand side in the second row (`Pᵢbᵢ` and `b₀b₁`, `b₁b₃`); the
//! definitions of `B₁₁`, `B₁₂` after (6.16) give the row above, which is what
//! `∂S/∂V₂ = 0` yields. The system is solved by nalgebra's Cholesky
//! factorisation (symmetric positive definite whenever the columns `b₁(tᵢ)`,
//! `b₂(tᵢ)` are independent), not by the explicit inverse (6.17)–(6.18).

use nalgebra::{Matrix2, Vector2};

use crate::basis::SegmentBasis;
use crate::data::P2;
use crate::error::{FitError, Result};

/// Control points `V₀ … V₃` of one fitted segment.
pub type Control = [P2; 4];

/// The basis values `b₀(tᵢ) … b₃(tᵢ)` at every parameter (the design matrix).
pub fn design(basis: &SegmentBasis, t: &[f64]) -> Vec<[f64; 4]> {
    basis.values_at(t)
}

/// `Pᵢ − V₀b₀(tᵢ) − V₃b₃(tᵢ)`: the data less the fixed end control points.
pub fn residual_targets(rows: &[[f64; 4]], points: &[P2], v0: &P2, v3: &P2) -> Vec<Vector2<f64>> {
    rows.iter()
        .zip(points)
        .map(|(b, p)| p.coords - v0.coords * b[0] - v3.coords * b[3])
        .collect()
}

/// Fits `V₁`, `V₂` to `points` at parameters `t` with `V₀ = points[0]`,
/// `V₃ = points[N−1]`. `what` names the segment in errors.
pub fn fit_segment(basis: &SegmentBasis, points: &[P2], t: &[f64], what: &str) -> Result<Control> {
    let rows = design(basis, t);
    let (v0, v3) = (points[0], points[points.len() - 1]);
    let targets = residual_targets(&rows, points, &v0, &v3);
    let mut a = Matrix2::<f64>::zeros();
    // one column per coordinate: [B₁₁ B₁₂]ᵀ for x and for y
    let mut rhs = Matrix2::<f64>::zeros();
    for (b, r) in rows.iter().zip(&targets) {
        let inner = Vector2::new(b[1], b[2]);
        a += inner * inner.transpose();
        rhs += inner * r.transpose();
    }
    let solution = a
        .cholesky()
        .map(|c| c.solve(&rhs))
        .filter(|s| s.iter().all(|v| v.is_finite()))
        .ok_or_else(|| FitError::Singular {
            what: format!("{what}: normal equations (6.16)"),
        })?;
    let v1 = P2::new(solution[(0, 0)], solution[(0, 1)]);
    let v2 = P2::new(solution[(1, 0)], solution[(1, 1)]);
    Ok([v0, v1, v2, v3])
}

/// The curve point `Σ bᵢ Vᵢ` for basis values `b`.
pub fn curve_point(b: &[f64; 4], v: &Control) -> P2 {
    P2::from(v[0].coords * b[0] + v[1].coords * b[1] + v[2].coords * b[2] + v[3].coords * b[3])
}
