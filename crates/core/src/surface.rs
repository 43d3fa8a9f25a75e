//! Tensor-product surfaces: the double sum of thesis (5.3) and its matrix
//! form `[T][A][V][A]ᵀ[U]` of (5.4)–(5.8).

use nalgebra::{Point3, SMatrix};
use rug::Rational;

use crate::curve::{Coord, combine};
use crate::error::{CoreError, Result};
use crate::families::thesis::{surface_matrix_a, surface_row_t};
use crate::family::Family;
use crate::scalar::Real;

/// `S(u, v) = Σ_i Σ_j P_{i,j} B_i(u) B_j(v)` over an `n × n` grid of control
/// points, `n` the number of functions of the family (thesis (5.3)).
#[derive(Debug, Clone)]
pub struct TensorSurface<T: Coord> {
    family: Family,
    params: Vec<Rational>,
    grid: Vec<Vec<Point3<T>>>,
}

impl<T: Coord> TensorSurface<T> {
    /// A surface over `grid[i][j] = P_{i,j}`.
    pub fn new(family: Family, params: Vec<Rational>, grid: Vec<Vec<Point3<T>>>) -> Result<Self> {
        let n = family.info().functions.len();
        if grid.len() != n || grid.iter().any(|row| row.len() != n) {
            return Err(CoreError::Count {
                what: format!("control-point grid rows/columns for `{}`", family.info().id),
                expected: n,
                got: grid
                    .iter()
                    .map(Vec::len)
                    .find(|&l| l != n)
                    .unwrap_or(grid.len()),
            });
        }
        Ok(TensorSurface {
            family,
            params,
            grid,
        })
    }

    /// The double sum (5.3) at `(u, v)`.
    pub fn eval(&self, u: &T, v: &T) -> Result<Point3<T>> {
        let bu = self.family.eval_at(u, &self.params, false)?;
        let bv = self.family.eval_at(v, &self.params, false)?;
        let rows: Vec<Point3<T>> = self.grid.iter().map(|row| combine(&bv, row)).collect();
        Ok(combine(&bu, &rows))
    }
}

/// The matrix form (5.4) of the thesis cubic surface in f64:
/// `F(u, v) = [T][A][V][A]ᵀ[U]`, one product per coordinate, with `[T]` and
/// `[U]` the rows (5.5), (5.8), `[A]` the 7×4 matrix (5.6) and `[V]` the
/// control points (5.7) (`V[i][j] = P_{i,j}`).
pub fn thesis_matrix_form(m: f64, grid: &[[Point3<f64>; 4]; 4], u: f64, v: f64) -> Point3<f64> {
    let a = {
        let entries = surface_matrix_a(&m);
        SMatrix::<f64, 7, 4>::from_fn(|r, c| entries[r][c])
    };
    let row = |x: f64| {
        let (s, c) = (x * std::f64::consts::FRAC_PI_2).sin_cos();
        SMatrix::<f64, 1, 7>::from_row_slice(&surface_row_t(&s, &c))
    };
    let (tu, tv) = (row(u), row(v));
    let coord = |k: usize| {
        let vk = SMatrix::<f64, 4, 4>::from_fn(|i, j| grid[i][j][k]);
        (tu * a * vk * a.transpose() * tv.transpose())[(0, 0)]
    };
    Point3::new(coord(0), coord(1), coord(2))
}

/// Numeric `[T][A]` for the thesis cubic at `u`: the row the audit compares
/// with `[b₀ b₁ b₂ b₃]` (claim T25).
pub fn thesis_row_times_a<T: Real>(m: &T, u: &T) -> [T; 4] {
    let theta = u.clone() * &(u.pi() * &u.ratio(1, 2));
    let (s, c) = theta.sin_cos();
    let t = surface_row_t(&s, &c);
    let a = surface_matrix_a(m);
    std::array::from_fn(|col| (0..7).fold(m.int(0), |acc, r| acc + &(t[r].clone() * &a[r][col])))
}
