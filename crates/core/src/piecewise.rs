//! Uniform piecewise basis functions assembled from segment functions.
//!
//! For a family whose four segment functions `F₀…F₃` live on one knot
//! interval (seed 000's uniform case, the uniform cubic B-spline), the
//! B-spline basis function over the four intervals `[k, k+1)`, `k = 0…3`, is
//! `F_{3−k}` on interval `k` — seed 000 eq. (1) with the uniform coefficients
//! of Appendix A.

use rug::Rational;

use crate::basis::Described;
use crate::domain::Affine;
use crate::echo::echo;
use crate::error::{CoreError, Result};
use crate::evaluation::{Computation, named_affine};
use crate::family::Family;
use crate::knots::{locate, locate_exact};
use crate::scalar::Real;

/// Number of knot intervals of a cubic B-spline basis function.
pub const PIECES: usize = 4;

/// Index of the segment function used on interval `piece`.
pub fn segment_function(piece: usize) -> usize {
    PIECES - 1 - piece
}

/// An error unless `family` has uniform B-spline segment functions.
fn require_segments(family: Family) -> Result<()> {
    if family.info().piecewise {
        return Ok(());
    }
    Err(CoreError::Malformed {
        input: family.info().id.into(),
        expected: "a family with uniform B-spline segment functions (seed000-uniform, bspline3)"
            .into(),
    })
}

/// The uniform B-spline basis function of `family` at global `n ∈ [0, 4]`
/// (unit knot spacing). Its local variable on interval `k` is `n − k` mapped to
/// the family's native domain (`t = π/2 (n − k)` for angle families).
pub fn eval_uniform<T: Real>(family: Family, n: &T, p: &[Rational]) -> Result<T> {
    require_segments(family)?;
    let knots: Vec<T> = (0..=PIECES as i64).map(|k| n.int(k)).collect();
    let (piece, local) = locate(&knots, n)?;
    let x = local * &family.info().variable.end(n);
    let values = family.eval_at(&x, p, false)?;
    Ok(values[segment_function(piece)].clone())
}

/// The uniform B-spline basis function of a family at one exact global
/// point `n ∈ [0, 4]`, located exactly on its piece (a [`Computation`]).
#[derive(Debug, Clone)]
pub struct UniformAt {
    family: Family,
    piece: usize,
    local: Rational,
    params: Vec<Affine>,
}

impl UniformAt {
    /// The piece of `n` (typed as `n_text`) and its local coordinate, for a
    /// family with segment functions; `params` exact, already read.
    pub fn new(family: Family, n: &Rational, n_text: &str, params: Vec<Affine>) -> Result<Self> {
        require_segments(family)?;
        let knots: Vec<Rational> = (0..=PIECES as i64).map(Rational::from).collect();
        let (piece, local) = locate_exact(&knots, n, &echo(n_text))?;
        Ok(UniformAt {
            family,
            piece,
            local,
            params,
        })
    }
}

impl Computation for UniformAt {
    fn inputs(&self) -> Vec<(String, &Rational)> {
        named_affine(&self.family.param_names(), &self.params)
    }

    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>> {
        let local = make(&self.local);
        let variable = &self.family.info().variable;
        let x = local.clone() * &variable.end(&local);
        let p: Vec<T> = self.params.iter().map(|a| a.eval(&local, &[])).collect();
        let values = self.family.eval(&variable.atoms(&x), &p);
        Ok(vec![values[segment_function(self.piece)].clone()])
    }
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
