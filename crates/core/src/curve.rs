//! Curves: `Σ b_i(·) P_i`, rational curves `Σ w_i b_i P_i / Σ w_i b_i`
//! (seed 000 Definition 3, seed 002 Definition 2), and piecewise curves over a
//! knot vector.

use nalgebra::{Point, SVector};
use rug::Rational;

use crate::error::{CoreError, Result};
use crate::family::Family;
use crate::knots::{check_knots, locate};
use crate::scalar::Real;

/// Component type of control points: a numeric scalar nalgebra can store.
pub trait Coord: Real + nalgebra::Scalar {}
impl<T: Real + nalgebra::Scalar> Coord for T {}

/// `Σ_i c_i P_i` for scalar coefficients `c_i`.
pub fn combine<T: Coord, const D: usize>(coeffs: &[T], points: &[Point<T, D>]) -> Point<T, D> {
    let zero = coeffs[0].int(0);
    let coords = SVector::<T, D>::from_fn(|k, _| {
        coeffs
            .iter()
            .zip(points)
            .fold(zero.clone(), |acc, (c, p)| acc + &(c.clone() * &p[k]))
    });
    Point::from(coords)
}

/// One curve segment of a catalog family, optionally rational.
#[derive(Debug, Clone)]
pub struct Segment<T: Coord, const D: usize> {
    family: Family,
    params: Vec<Rational>,
    points: Vec<Point<T, D>>,
    weights: Option<Vec<T>>,
}

impl<T: Coord, const D: usize> Segment<T, D> {
    /// A polynomial (non-rational) segment `Σ b_i P_i`.
    pub fn new(family: Family, params: Vec<Rational>, points: Vec<Point<T, D>>) -> Result<Self> {
        Self::build(family, params, points, None)
    }

    /// A rational segment `Σ w_i b_i P_i / Σ w_i b_i` with positive weights.
    pub fn rational(
        family: Family,
        params: Vec<Rational>,
        points: Vec<Point<T, D>>,
        weights: Vec<T>,
    ) -> Result<Self> {
        Self::build(family, params, points, Some(weights))
    }

    fn build(
        family: Family,
        params: Vec<Rational>,
        points: Vec<Point<T, D>>,
        weights: Option<Vec<T>>,
    ) -> Result<Self> {
        let info = family.info();
        if !family.has_formulas() {
            return Err(CoreError::NoFormulas(info.id.into()));
        }
        let n = info.functions.len();
        let count = |what: &str, got: usize| CoreError::Count {
            what: format!("{what} for `{}`", info.id),
            expected: n,
            got,
        };
        if points.len() != n {
            return Err(count("control points", points.len()));
        }
        if params.len() != info.params.len() {
            return Err(CoreError::Count {
                what: format!("parameters for `{}`", info.id),
                expected: info.params.len(),
                got: params.len(),
            });
        }
        if let Some((i, _)) = points
            .iter()
            .enumerate()
            .find(|(_, p)| p.iter().any(|x| !x.is_finite()))
        {
            return Err(CoreError::NotFinite {
                what: format!("control point P{i}"),
            });
        }
        if let Some(w) = &weights {
            if w.len() != n {
                return Err(count("weights", w.len()));
            }
            if let Some((index, wi)) = w.iter().enumerate().find(|(_, wi)| {
                let zero = wi.int(0);
                !wi.is_finite() || **wi <= zero
            }) {
                return Err(CoreError::NonPositiveWeight {
                    index,
                    value: format!("{}", wi.to_f64()),
                });
            }
        }
        Ok(Segment {
            family,
            params,
            points,
            weights,
        })
    }

    /// The family of the segment.
    pub fn family(&self) -> Family {
        self.family
    }

    /// The point at `x` in the family's native variable.
    pub fn eval(&self, x: &T) -> Result<Point<T, D>> {
        let b = self.family.eval_at(x, &self.params, false)?;
        match &self.weights {
            None => Ok(combine(&b, &self.points)),
            Some(w) => {
                let wb: Vec<T> = w.iter().zip(&b).map(|(wi, bi)| wi.clone() * bi).collect();
                let den = wb.iter().skip(1).fold(wb[0].clone(), |a, x| a + x);
                if den.is_zero() {
                    return Err(CoreError::DivisionByZero {
                        quantity: "the weighted sum of the rational curve".into(),
                    });
                }
                let coeffs: Vec<T> = wb.into_iter().map(|x| x / &den).collect();
                Ok(combine(&coeffs, &self.points))
            }
        }
    }
}

/// A piecewise curve: segment `i` on `[u_i, u_{i+1}]`, evaluated at the local
/// variable `(u − u_i)/h_i` mapped to its native domain (`t = π/2·(u − u_i)/h_i`
/// for angle families, as in thesis 4.3 and seed 002 (7)).
#[derive(Debug, Clone)]
pub struct PiecewiseCurve<T: Coord, const D: usize> {
    knots: Vec<T>,
    segments: Vec<Segment<T, D>>,
}

impl<T: Coord, const D: usize> PiecewiseCurve<T, D> {
    /// Segments over a strictly increasing knot vector of `segments.len() + 1` knots.
    pub fn new(knots: Vec<T>, segments: Vec<Segment<T, D>>) -> Result<Self> {
        check_knots(&knots, 2)?;
        if knots.len() != segments.len() + 1 {
            return Err(CoreError::Count {
                what: "knots for the segments (one more than segments)".into(),
                expected: segments.len() + 1,
                got: knots.len(),
            });
        }
        Ok(PiecewiseCurve { knots, segments })
    }

    /// The point at global parameter `u`.
    pub fn eval(&self, u: &T) -> Result<Point<T, D>> {
        let (i, local) = locate(&self.knots, u)?;
        let segment = &self.segments[i];
        let x = local * &segment.family().info().variable.end(u);
        segment.eval(&x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point2;

    fn zero() -> Vec<Rational> {
        vec![Rational::from(0)]
    }

    #[test]
    fn thesis_cubic_segment_interpolates_its_end_points() {
        let pts = vec![
            Point2::new(0.0, 0.0),
            Point2::new(1.0, 2.0),
            Point2::new(3.0, 2.0),
            Point2::new(4.0, 0.0),
        ];
        let seg = Segment::new(Family::ThesisCubic, zero(), pts).unwrap();
        assert!((seg.eval(&0.0).unwrap() - Point2::new(0.0, 0.0)).norm() < 1e-15);
        assert!((seg.eval(&1.0).unwrap() - Point2::new(4.0, 0.0)).norm() < 1e-15);
    }

    #[test]
    fn bad_curves_are_typed_errors() {
        let three = vec![Point2::new(0.0, 0.0); 3];
        assert!(matches!(
            Segment::new(Family::ThesisCubic, zero(), three),
            Err(CoreError::Count { .. })
        ));
        let four = vec![Point2::new(0.0, 0.0); 4];
        assert!(matches!(
            Segment::rational(Family::ThesisCubic, zero(), four, vec![1.0, 0.0, 1.0, 1.0]),
            Err(CoreError::NonPositiveWeight { index: 1, .. })
        ));
    }
}
