//! Tensor-product surfaces of any basis in each direction: the double sum
//! of thesis (5.3), `S(u, v) = Σ_i Σ_j P_{i,j} B_i(u) B_j(v)`, with each
//! direction its own basis and parameters as in (5.11) `S(u, v; m₁, m₂)`
//! (seed `001_cf6c2ede0355a863.txt`, Chapter 5), and the rational surface
//! `Σ w_{i,j} P_{i,j} B_i(u) B_j(v) / Σ w_{i,j} B_i(u) B_j(v)` (seed 002,
//! Definition 2, in both directions). The surface holds exact inputs and
//! evaluates in any [`Real`] (f64, MPFR, intervals) through the basis's one
//! generic `eval`; [`SurfaceAt`] is its certified [`Computation`]. The
//! matrix form `[T][A][V][A]ᵀ[U]` of (5.4)–(5.8) is kept for the thesis
//! cubic (claim T25 compares it with the double sum).

use nalgebra::{Point3, SMatrix};
use rug::Rational;

use crate::basis::Basis;
use crate::domain::Affine;
use crate::echo::echo;
use crate::error::{CoreError, Result};
use crate::evaluation::{Computation, named_affine};
use crate::families::thesis::{surface_matrix_a, surface_row_t};
use crate::net::ControlNet;
use crate::scalar::{Real, Ring};

/// One direction of a surface: a basis with its exact parameters (in the
/// order of [`crate::Described::param_names`]).
#[derive(Debug, Clone)]
pub struct Direction<B> {
    pub basis: B,
    pub params: Vec<Affine>,
}

impl<B: Basis> Direction<B> {
    /// The functions of the basis at `x`: the point inside the domain
    /// unless `allow_outside`, every value finite.
    pub fn values<T: Real>(&self, x: &T, allow_outside: bool) -> Result<Vec<T>> {
        let zero = x.int(0);
        let p: Vec<T> = self.params.iter().map(|a| a.eval(&zero, &[])).collect();
        let domain = self.basis.domain();
        domain.check_point(x, &p, allow_outside)?;
        let values = self.basis.eval(&domain.atoms(x), &p);
        if values.iter().any(|v| !v.is_finite()) {
            return Err(CoreError::DivisionByZero {
                quantity: format!("`{}` at this point", self.basis.id()),
            });
        }
        Ok(values)
    }

    /// The number of functions (control points in this direction).
    pub fn len(&self) -> usize {
        self.basis.function_names().len()
    }

    /// True when the basis has no functions.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// `S(u, v) = Σ_i Σ_j P_{i,j} B_i(u) B_j(v)`, optionally rational, over a
/// net of `n_u × n_v` control points (`n_u`, `n_v` the numbers of functions
/// of the two bases): row `i` of the net goes with `B_i(u)`.
#[derive(Debug, Clone)]
pub struct TensorSurface<B> {
    u: Direction<B>,
    v: Direction<B>,
    net: ControlNet,
}

impl<B: Basis> TensorSurface<B> {
    /// A surface over `net`, checked against the sizes of the two bases.
    pub fn new(u: Direction<B>, v: Direction<B>, net: ControlNet) -> Result<Self> {
        net.check_size((&u.basis.id(), u.len()), (&v.basis.id(), v.len()))?;
        Ok(TensorSurface { u, v, net })
    }

    /// The `u` direction.
    pub fn u(&self) -> &Direction<B> {
        &self.u
    }

    /// The `v` direction.
    pub fn v(&self) -> &Direction<B> {
        &self.v
    }

    /// The control net.
    pub fn net(&self) -> &ControlNet {
        &self.net
    }

    /// The point at `(u, v)` in each direction's own variable; a point
    /// outside a domain is an error unless `allow_outside`.
    pub fn eval<T: Real>(&self, u: &T, v: &T, allow_outside: bool) -> Result<[T; 3]> {
        let bu = self.u.values(u, allow_outside)?;
        let bv = self.v.values(v, allow_outside)?;
        self.combine(&bu, &bv)
    }

    /// `Σ_i Σ_j c_{i,j} P_{i,j}` with `c_{i,j} = bu_i bv_j` (times `w_{i,j}`
    /// over the weighted sum for a rational surface).
    pub fn combine<T: Ring>(&self, bu: &[T], bv: &[T]) -> Result<[T; 3]> {
        let like = &bu[0];
        let mut sum: [T; 3] = std::array::from_fn(|_| like.int(0));
        let mut den = like.int(0);
        for (i, row) in self.net.points().iter().enumerate() {
            for (j, p) in row.iter().enumerate() {
                let mut c = bu[i].clone() * &bv[j];
                if let Some(w) = self.net.weight(i, j) {
                    c = c * &like.rational(w);
                    den = den + &c;
                }
                for (s, q) in sum.iter_mut().zip(p) {
                    *s = s.clone() + &(c.clone() * &like.rational(q));
                }
            }
        }
        if !self.net.is_rational() {
            return Ok(sum);
        }
        if den.is_zero() {
            return Err(CoreError::DivisionByZero {
                quantity: "the weighted sum Σ w_ij B_i(u) B_j(v) of the rational surface".into(),
            });
        }
        Ok(sum.map(|s| s / &den))
    }
}

/// The point of a surface at one exact `(u, v)`: a certified
/// [`Computation`] (the three coordinates).
#[derive(Debug, Clone)]
pub struct SurfaceAt<'a, B> {
    surface: &'a TensorSurface<B>,
    at: [(Affine, String); 2],
    /// Coordinates known to be exactly 0 (decided by the caller in the
    /// exact ring): computed as an exact 0.
    zero: [bool; 3],
}

impl<'a, B: Basis> SurfaceAt<'a, B> {
    /// The point `(u, v)`, each with its text as typed (for messages); a
    /// point outside a domain (decided exactly) is an error unless
    /// `allow_outside`.
    pub fn new(
        surface: &'a TensorSurface<B>,
        at: [(Affine, String); 2],
        allow_outside: bool,
    ) -> Result<Self> {
        if !allow_outside {
            for ((x, text), dir) in at.iter().zip([&surface.u, &surface.v]) {
                crate::certified::check_domain(&dir.basis.domain(), x, &dir.params, text)?;
            }
        }
        Ok(SurfaceAt {
            surface,
            at,
            zero: [false; 3],
        })
    }

    /// The same with the coordinates marked in `zero` known to be exactly
    /// 0 (decided in the exact ring, which this crate does not hold):
    /// computed as an exact 0 in every arithmetic, no precision spent on
    /// them.
    pub fn with_zeros(mut self, zero: [bool; 3]) -> Self {
        self.zero = zero;
        self
    }
}

impl<B: Basis> Computation for SurfaceAt<'_, B> {
    fn inputs(&self) -> Vec<(String, &Rational)> {
        let s = self.surface;
        let mut inputs = Vec::new();
        for (dir, side) in [(&s.u, "u"), (&s.v, "v")] {
            let names: Vec<String> = dir
                .basis
                .param_names()
                .iter()
                .map(|n| format!("{n} ({side})"))
                .collect();
            inputs.extend(named_affine(&names, &dir.params));
        }
        for (x, text) in &self.at {
            let name = format!("the point {}", echo(text));
            inputs.extend([(name.clone(), &x.constant), (name, &x.pi)]);
        }
        inputs.extend(s.net.inputs());
        inputs
    }

    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>> {
        let zero = make(&Rational::new());
        let [u, v] = [&self.at[0].0, &self.at[1].0].map(|a| a.eval(&zero, &[]));
        // the domain was checked exactly in `new`: an enclosure of an end
        // point may straddle it
        let point = self.surface.eval(&u, &v, true)?;
        Ok(point
            .into_iter()
            .zip(self.zero)
            .map(|(x, z)| if z { zero.clone() } else { x })
            .collect())
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluation::{Arithmetic, Value, evaluate};
    use crate::{Family, Mpfr};

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    /// `P_{i,j} = (i, j, i·j + 1)` with `rows × 4` points, weighted
    /// `w_{i,j} = w + step·j` when `weights` is `Some((w, step))`.
    fn net(rows: usize, weights: Option<(i64, i64)>) -> ControlNet {
        let text: String = (0..rows)
            .map(|i| {
                (0..4)
                    .map(|j| {
                        let w = weights.map_or(String::new(), |(w, step)| {
                            format!(" {}", w + step * j as i64)
                        });
                        format!("{i} {j} {}{w}\n", i * j + 1)
                    })
                    .collect::<String>()
                    + "\n"
            })
            .collect();
        ControlNet::parse(&text, "net").unwrap()
    }

    fn surface(net: ControlNet) -> Result<TensorSurface<Family>> {
        let u = Direction {
            basis: Family::ThesisCubic,
            params: vec![Affine::rational(q(1, 2))],
        };
        let v = Direction {
            basis: Family::Bernstein3,
            params: vec![],
        };
        TensorSurface::new(u, v, net)
    }

    #[test]
    fn corners_interpolate_and_the_net_reproduces_bilinear_data() {
        let s = surface(net(4, None)).unwrap();
        // the corner points are interpolated
        assert_eq!(s.eval(&0.0, &0.0, false).unwrap(), [0.0, 0.0, 1.0]);
        let [x, y, z] = s.eval(&1.0, &1.0, false).unwrap();
        assert!((x - 3.0).abs() < 1e-15 && (y - 3.0).abs() < 1e-15 && (z - 10.0).abs() < 1e-14);
        // a point outside the domain is refused unless allowed
        assert!(matches!(
            s.eval(&2.0, &0.5, false),
            Err(CoreError::PointOutsideDomain { .. })
        ));
        assert!(s.eval(&2.0, &0.5, true).is_ok());
    }

    #[test]
    fn a_net_of_the_wrong_size_names_expected_and_got() {
        let e = surface(net(3, None)).unwrap_err();
        assert!(
            matches!(
                e,
                CoreError::Count {
                    expected: 4,
                    got: 3,
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("3 × 4"), "{e}");
    }

    #[test]
    fn equal_weights_give_the_polynomial_surface_and_others_do_not() {
        let plain = surface(net(4, None)).unwrap();
        let equal = surface(net(4, Some((3, 0)))).unwrap();
        let rational = surface(net(4, Some((1, 1)))).unwrap();
        let (u, v) = (0.3, 0.7);
        let a = plain.eval(&u, &v, false).unwrap();
        let b = rational.eval(&u, &v, false).unwrap();
        let c = equal.eval(&u, &v, false).unwrap();
        assert!(a.iter().zip(&b).any(|(x, y)| (x - y).abs() > 1e-3));
        assert!(a.iter().zip(&c).all(|(x, y)| (x - y).abs() < 1e-14));
        let text = "1 0 0 5\n0 1 0 5\n\n0 0 1 5\n1 1 1 5\n";
        let bilinear = TensorSurface::new(
            Direction {
                basis: Family::Bernstein3,
                params: vec![],
            },
            Direction {
                basis: Family::Bernstein3,
                params: vec![],
            },
            ControlNet::parse(text, "n").unwrap(),
        );
        assert!(matches!(
            bilinear,
            Err(CoreError::Count {
                expected: 4,
                got: 2,
                ..
            })
        ));
    }

    #[test]
    fn certified_evaluation_agrees_with_f64_and_mpfr() {
        let s = surface(net(4, Some((2, 1)))).unwrap();
        let at = SurfaceAt::new(
            &s,
            [
                (Affine::rational(q(1, 3)), "1/3".into()),
                (Affine::rational(q(2, 5)), "2/5".into()),
            ],
            false,
        )
        .unwrap();
        let f64s = s.eval(&(1.0 / 3.0), &0.4, false).unwrap();
        let mpfr = s
            .eval(
                &Mpfr::from_rational(200, &q(1, 3)),
                &Mpfr::from_rational(200, &q(2, 5)),
                false,
            )
            .unwrap();
        let proved = evaluate(&at, Arithmetic::Digits(40), "s").unwrap();
        for ((v, f), m) in proved.values.iter().zip(f64s).zip(&mpfr) {
            let Value::Proved(d) = v else { panic!("{v:?}") };
            assert!(d.digits() >= 40);
            let x: f64 = d.to_string().parse().unwrap();
            assert!(
                (x - f).abs() < 1e-14 && (x - m.to_f64()).abs() < 1e-15,
                "{x} {f}"
            );
        }
        let outside = SurfaceAt::new(
            &s,
            [
                (Affine::rational(q(3, 2)), "3/2".into()),
                (Affine::rational(q(0, 1)), "0".into()),
            ],
            false,
        );
        assert!(matches!(outside, Err(CoreError::PointOutsideDomain { .. })));
    }
}
