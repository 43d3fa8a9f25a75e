//! Uniform piecewise basis functions assembled from segment functions.
//!
//! For a family whose four segment functions `F₀…F₃` live on one knot
//! interval (seed 000's uniform case, the uniform cubic B-spline), the
//! B-spline basis function over the four intervals `[k, k+1)`, `k = 0…3`, is
//! `F_{3−k}` on interval `k` — seed 000 eq. (1) with the uniform coefficients
//! of Appendix A.

use rug::Rational;

use crate::error::{CoreError, Result};
use crate::family::Family;
use crate::knots::locate;
use crate::scalar::Real;

/// Number of knot intervals of a cubic B-spline basis function.
pub const PIECES: usize = 4;

/// Index of the segment function used on interval `piece`.
pub fn segment_function(piece: usize) -> usize {
    PIECES - 1 - piece
}

/// The uniform B-spline basis function of `family` at global `n ∈ [0, 4]`
/// (unit knot spacing). Its local variable on interval `k` is `n − k` mapped to
/// the family's native domain (`t = π/2 (n − k)` for angle families).
pub fn eval_uniform<T: Real>(family: Family, n: &T, p: &[Rational]) -> Result<T> {
    if !family.info().piecewise {
        return Err(CoreError::Malformed {
            input: family.info().id.into(),
            expected:
                "a family with uniform B-spline segment functions (seed000-uniform, bspline3)"
                    .into(),
        });
    }
    let knots: Vec<T> = (0..=PIECES as i64).map(|k| n.int(k)).collect();
    let (piece, local) = locate(&knots, n)?;
    let x = local * &family.info().variable.end(n);
    let values = family.eval_at(&x, p, false)?;
    Ok(values[segment_function(piece)].clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_cubic_bspline_has_its_textbook_values_at_knots() {
        let at = |n: f64| eval_uniform(Family::BSpline3, &n, &[]).unwrap();
        assert!((at(0.0) - 0.0).abs() < 1e-15);
        assert!((at(1.0) - 1.0 / 6.0).abs() < 1e-15);
        assert!((at(2.0) - 2.0 / 3.0).abs() < 1e-15);
        assert!((at(3.0) - 1.0 / 6.0).abs() < 1e-15);
        assert!((at(4.0) - 0.0).abs() < 1e-15);
    }

    #[test]
    fn non_piecewise_family_is_rejected() {
        assert!(eval_uniform(Family::ThesisCubic, &1.0, &[Rational::from(0)]).is_err());
    }
}
