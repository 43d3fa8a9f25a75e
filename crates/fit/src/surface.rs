//! Least-squares tensor-product fit of a gridded height field (beyond the
//! thesis, whose Chapter 6 fits outlines; its surfaces are (5.3)–(5.11)).
//!
//! The grid's rows and columns are the parameters `uᵢ = i/(r − 1)`,
//! `vⱼ = j/(c − 1)`. In each direction a [`Space`] of `pu` (resp. `pv`)
//! segments of one basis, joined C⁰ or C¹; a patch `(k, l)` is
//! `S(u, v) = Σᵢ Σⱼ P_{3k+i, 3l+j} bᵢ(u) bⱼ(v)` over its segment pair, and
//! the free coefficients form an `nu × nv` matrix `X` with
//! `S(uᵢ, vⱼ) = (A_u X A_vᵀ)ᵢⱼ`, `A_u`, `A_v` the collocation matrices.
//! The least-squares problem `min ‖A_u X A_vᵀ − Z‖_F` is
//! `min ‖(A_v ⊗ A_u) vec X − vec Z‖₂`, whose solution separates:
//! `X = A_u⁺ Z (A_v⁺)ᵀ` (the pseudo-inverse of a Kronecker product is the
//! Kronecker product of the pseudo-inverses), two small solves instead of
//! one of size `(r·c) × (nu·nv)`. Each is done by nalgebra's SVD; a
//! collocation matrix of deficient rank (fewer data rows in a direction
//! than its coefficients, or a segment without data) is refused as
//! singular, not solved in some minimal-norm sense.
//!
//! The shape parameter is fixed, or optimised by golden section
//! ([`crate::optimise`]) on the total squared error, by coordinate descent
//! (two rounds, starting from the middle of the interval; a searched value
//! is taken only when it lowers the error): [`Scope::Direction`] one value
//! for every segment of a direction, `u`'s with `v`'s fixed, then `v`'s;
//! [`Scope::Segment`] from there one value per segment of each direction —
//! per row and per column of patches, each searched with the others fixed —
//! so never worse than the per-direction optimum. A value per patch would
//! break the separation: the basis of patch `(k, l)` along `u` would then
//! depend on `l`.

use std::sync::Arc;

use nalgebra::DMatrix;
use serde::Serialize;

use crate::basis::{NumericBasis, SegmentBasis};
use crate::error::{FitError, Result};
use crate::grid::Grid;
use crate::optimise::golden_section;
use crate::pipeline::{Shape, searched_index};
use crate::space::{Join, Space};

/// Smallest singular value, relative to the largest, of a collocation
/// matrix that is fitted.
const RANK_TOL: f64 = 1e-10;

/// Rounds of coordinate descent of the optimisation.
const ROUNDS: usize = 2;

/// The shape parameters of each segment of a direction.
pub type SegmentParams = Vec<Vec<f64>>;

/// What one optimised shape parameter covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Scope {
    /// Every segment of a direction.
    Direction,
    /// One segment of a direction: a row or a column of patches.
    Segment,
}

/// Options of [`fit_surface`].
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceOptions {
    /// Patches along the rows (`u`) and along the columns (`v`).
    pub patches: (usize, usize),
    pub join: Join,
    pub shape: Shape,
    /// What one optimised value covers (with [`Shape::Optimise`]).
    pub scope: Scope,
}

/// Error statistics of a set of data points: `|S(uᵢ, vⱼ) − zᵢⱼ|`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stats {
    pub points: usize,
    /// `max |e|`.
    pub max: f64,
    /// `Σ |e| / N`.
    pub mean: f64,
    /// `√(Σ e² / N)`.
    pub rms: f64,
}

impl Stats {
    /// Statistics of the errors `e` (nonempty).
    pub fn of(e: &[f64]) -> Stats {
        let n = e.len() as f64;
        Stats {
            points: e.len(),
            max: e.iter().fold(0.0_f64, |a, v| a.max(v.abs())),
            mean: e.iter().map(|v| v.abs()).sum::<f64>() / n,
            rms: (e.iter().map(|v| v * v).sum::<f64>() / n).sqrt(),
        }
    }
}

/// One patch's errors.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PatchStats {
    /// Patch index along `u` and along `v`, from 0.
    pub patch: (usize, usize),
    pub stats: Stats,
}

/// A fitted surface.
#[derive(Debug, Clone, Serialize)]
pub struct SurfaceFit {
    pub family: String,
    pub patches: (usize, usize),
    pub join: Join,
    /// Shape parameters of each segment along `u` and along `v`.
    pub params: (SegmentParams, SegmentParams),
    /// Free coefficients `nu · nv`.
    pub coefficients: usize,
    /// Control heights `P`, `(3pu + 1) × (3pv + 1)`, row-major.
    #[serde(skip)]
    pub control: DMatrix<f64>,
    /// Fitted heights at the grid points, `r × c`.
    #[serde(skip)]
    pub fitted: DMatrix<f64>,
    /// Signed errors `S − z` at the grid points, `r × c`.
    #[serde(skip)]
    pub error: DMatrix<f64>,
    pub per_patch: Vec<PatchStats>,
    pub overall: Stats,
}

/// The parameters `k/(n − 1)`, `k = 0 … n − 1`.
fn grid_parameters(n: usize) -> Vec<f64> {
    (0..n).map(|k| k as f64 / (n - 1) as f64).collect()
}

/// The space of the segments of `basis` at `params` (one set each).
fn space(basis: &Arc<dyn NumericBasis>, params: &[Vec<f64>], join: Join) -> Result<Space> {
    let segments = params
        .iter()
        .map(|p| SegmentBasis::new(basis.clone(), p))
        .collect::<Result<Vec<_>>>()?;
    Space::new(segments, join)
}

/// `A⁺ B` for a collocation matrix `A` of full column rank.
fn least_squares(a: DMatrix<f64>, b: &DMatrix<f64>, what: &str) -> Result<DMatrix<f64>> {
    let singular = |why: String| FitError::Singular {
        what: format!("surface fit, {what} ({why})"),
    };
    if a.nrows() < a.ncols() {
        return Err(singular(format!(
            "{} data lines for {} coefficients",
            a.nrows(),
            a.ncols()
        )));
    }
    let deficient = || {
        singular(format!(
            "its {} × {} collocation matrix has deficient rank: a patch without enough data, or functions dependent at these parameters",
            a.nrows(),
            a.ncols()
        ))
    };
    let svd = a.clone().svd(true, true);
    let largest = svd.singular_values.max();
    // a NaN singular value is refused too
    if svd.singular_values.min().partial_cmp(&(RANK_TOL * largest))
        != Some(std::cmp::Ordering::Greater)
    {
        return Err(deficient());
    }
    svd.solve(b, 0.0)
        .ok()
        .filter(|x| x.iter().all(|v| v.is_finite()))
        .ok_or_else(deficient)
}

/// The separable least-squares fit with fixed spaces: `(X, A_u X A_vᵀ)`.
fn solve(u: &Space, v: &Space, grid: &Grid) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
    let au = u.collocation(&grid_parameters(grid.rows));
    let av = v.collocation(&grid_parameters(grid.cols));
    let z = DMatrix::from_row_slice(grid.rows, grid.cols, &grid.z);
    // Y = A_u⁺ Z, then Xᵀ = A_v⁺ Yᵀ
    let y = least_squares(au.clone(), &z, "along u (the rows)")?;
    let x = least_squares(av.clone(), &y.transpose(), "along v (the columns)")?.transpose();
    let fitted = &au * &x * av.transpose();
    Ok((x, fitted))
}

/// The total squared error of the fit at these parameters.
fn objective(
    basis: &Arc<dyn NumericBasis>,
    grid: &Grid,
    join: Join,
    pu: &[Vec<f64>],
    pv: &[Vec<f64>],
) -> Result<f64> {
    let u = space(basis, pu, join)?;
    let v = space(basis, pv, join)?;
    let (_, fitted) = solve(&u, &v, grid)?;
    let z = DMatrix::from_row_slice(grid.rows, grid.cols, &grid.z);
    Ok((fitted - z).norm_squared())
}

/// The parameters of each segment along `u` and `v`: fixed, or optimised
/// over `options.scope`.
fn choose_params(
    basis: &Arc<dyn NumericBasis>,
    grid: &Grid,
    options: &SurfaceOptions,
) -> Result<(SegmentParams, SegmentParams)> {
    let (nu, nv) = options.patches;
    let (lo, hi, fixed) = match &options.shape {
        Shape::Fixed(p) => return Ok((vec![p.clone(); nu], vec![p.clone(); nv])),
        Shape::Optimise { lo, hi, fixed } => (*lo, *hi, fixed),
    };
    let (_, n) = basis.counts();
    let index = searched_index(basis.as_ref(), fixed)?;
    let mut start = vec![0.5 * (lo + hi); n];
    for (j, v) in fixed {
        start[*j] = *v;
    }
    // the segments one searched value covers: all of a direction together,
    // or each alone
    let groups = |scope: Scope, count: usize| -> Vec<Vec<usize>> {
        match scope {
            Scope::Direction => vec![(0..count).collect()],
            Scope::Segment => (0..count).map(|k| vec![k]).collect(),
        }
    };
    let set = |params: &[Vec<f64>], group: &[usize], p: f64| {
        let mut trial = params.to_vec();
        for &k in group {
            trial[k][index] = p;
        }
        trial
    };
    let (mut pu, mut pv) = (vec![start.clone(); nu], vec![start; nv]);
    // a start where the fit fails counts as +∞, as in the search
    let mut best = objective(basis, grid, options.join, &pu, &pv).unwrap_or(f64::INFINITY);
    let scopes = match options.scope {
        Scope::Direction => vec![Scope::Direction],
        Scope::Segment => vec![Scope::Direction, Scope::Segment],
    };
    for scope in scopes {
        for _ in 0..ROUNDS {
            for group in groups(scope, nu) {
                let search = |p| objective(basis, grid, options.join, &set(&pu, &group, p), &pv);
                let (p, error) = golden_section(search, lo, hi)?;
                if error < best {
                    (pu, best) = (set(&pu, &group, p), error);
                }
            }
            for group in groups(scope, nv) {
                let search = |p| objective(basis, grid, options.join, &pu, &set(&pv, &group, p));
                let (p, error) = golden_section(search, lo, hi)?;
                if error < best {
                    (pv, best) = (set(&pv, &group, p), error);
                }
            }
        }
    }
    Ok((pu, pv))
}

/// Fits `grid` with patches of `basis` (see the module docs).
pub fn fit_surface(
    grid: &Grid,
    basis: Arc<dyn NumericBasis>,
    options: &SurfaceOptions,
) -> Result<SurfaceFit> {
    let (pu, pv) = options.patches;
    if pu == 0 || pv == 0 {
        return Err(FitError::Option(format!(
            "patches {pu}×{pv}: at least one patch in each direction"
        )));
    }
    // refused before any matrix is built: a huge patch count costs no memory
    let coefficients = |p: usize| match options.join {
        Join::C0 => p.saturating_mul(3).saturating_add(1),
        Join::C1 => p.saturating_mul(2).saturating_add(2),
    };
    for (p, lines, what) in [
        (pu, grid.rows, "along u (the rows)"),
        (pv, grid.cols, "along v (the columns)"),
    ] {
        if coefficients(p) > lines {
            return Err(FitError::Singular {
                what: format!(
                    "surface fit, {what} ({lines} data lines for {} coefficients)",
                    coefficients(p)
                ),
            });
        }
    }
    let (params_u, params_v) = choose_params(&basis, grid, options)?;
    let u = space(&basis, &params_u, options.join)?;
    let v = space(&basis, &params_v, options.join)?;
    let (x, fitted) = solve(&u, &v, grid)?;
    let z = DMatrix::from_row_slice(grid.rows, grid.cols, &grid.z);
    let error = &fitted - z;
    let rows: Vec<usize> = grid_parameters(grid.rows)
        .iter()
        .map(|&s| u.locate(s).0)
        .collect();
    let cols: Vec<usize> = grid_parameters(grid.cols)
        .iter()
        .map(|&s| v.locate(s).0)
        .collect();
    let mut per_patch = Vec::with_capacity(pu * pv);
    for k in 0..pu {
        for l in 0..pv {
            let e: Vec<f64> = (0..grid.rows)
                .filter(|&i| rows[i] == k)
                .flat_map(|i| {
                    let error = &error;
                    (0..grid.cols)
                        .filter(|&j| cols[j] == l)
                        .map(move |j| error[(i, j)])
                })
                .collect();
            if e.is_empty() {
                return Err(FitError::Singular {
                    what: format!("surface fit, patch ({}, {}) has no data", k + 1, l + 1),
                });
            }
            per_patch.push(PatchStats {
                patch: (k, l),
                stats: Stats::of(&e),
            });
        }
    }
    let control = u.controls(&v.controls(&x.transpose()).transpose());
    Ok(SurfaceFit {
        family: basis.basis_id(),
        patches: options.patches,
        join: options.join,
        params: (params_u, params_v),
        coefficients: u.dim() * v.dim(),
        control,
        fitted,
        overall: Stats::of(error.as_slice()),
        error,
        per_patch,
    })
}

#[cfg(test)]
mod tests {
    use trig_core::Family;

    use super::*;

    fn grid(rows: usize, cols: usize, f: impl Fn(f64, f64) -> f64) -> Grid {
        let (u, v) = (grid_parameters(rows), grid_parameters(cols));
        Grid {
            name: "test".into(),
            rows,
            cols,
            z: u.iter()
                .flat_map(|&a| v.iter().map(move |&b| (a, b)))
                .map(|(a, b)| f(a, b))
                .collect(),
        }
    }

    fn fixed(patches: (usize, usize), join: Join, p: &[f64]) -> SurfaceOptions {
        SurfaceOptions {
            patches,
            join,
            shape: Shape::Fixed(p.to_vec()),
            scope: Scope::Direction,
        }
    }

    /// A bicubic polynomial is in every Bernstein space: fitted exactly.
    #[test]
    fn bernstein_reproduces_a_bicubic() {
        let g = grid(13, 11, |u, v| {
            3.0 * u * u * u - u * v + 2.0 * v * v * v * u + 1.0
        });
        for (patches, join) in [((1, 1), Join::C0), ((3, 2), Join::C0), ((2, 3), Join::C1)] {
            let fit =
                fit_surface(&g, Arc::new(Family::Bernstein3), &fixed(patches, join, &[])).unwrap();
            assert!(
                fit.overall.max < 1e-10,
                "{patches:?} {join:?}: {:?}",
                fit.overall
            );
            assert_eq!(fit.per_patch.len(), patches.0 * patches.1);
            assert_eq!(
                fit.per_patch.iter().map(|p| p.stats.points).sum::<usize>(),
                13 * 11
            );
        }
    }

    /// A surface outside the space is not fitted exactly; more patches fit
    /// better; a C¹ fit is never better than the C⁰ fit of the same patches
    /// (its space is a subspace).
    #[test]
    fn errors_shrink_with_patches_and_c1_is_a_subspace() {
        let g = grid(41, 37, |u, v| (5.0 * u).sin() * (4.0 * v).cos());
        let f = |patches, join| {
            fit_surface(
                &g,
                Arc::new(Family::ThesisCubic),
                &fixed(patches, join, &[0.6]),
            )
            .unwrap()
            .overall
        };
        let (one, four) = (f((1, 1), Join::C0), f((4, 4), Join::C0));
        assert!(
            one.rms > 1e-3 && four.rms < one.rms / 10.0,
            "{one:?} {four:?}"
        );
        let c1 = f((4, 4), Join::C1);
        assert!(c1.rms >= four.rms && c1.rms < one.rms, "{c1:?}");
    }

    #[test]
    fn too_many_patches_for_the_data_is_singular() {
        let g = grid(7, 30, |u, v| u + v);
        let e = fit_surface(
            &g,
            Arc::new(Family::Bernstein3),
            &fixed((3, 1), Join::C0, &[]),
        );
        assert!(matches!(e, Err(FitError::Singular { .. })), "{e:?}");
    }

    #[test]
    fn optimising_is_never_worse_than_the_interval_ends() {
        let g = grid(21, 19, |u, v| (3.0 * u).sin() + v * v);
        let basis: Arc<dyn NumericBasis> = Arc::new(Family::ThesisCubic);
        let optimised = |scope| {
            let options = SurfaceOptions {
                patches: (2, 3),
                join: Join::C1,
                shape: Shape::Optimise {
                    lo: -1.0,
                    hi: 1.0,
                    fixed: vec![],
                },
                scope,
            };
            fit_surface(&g, basis.clone(), &options).unwrap()
        };
        let (direction, segment) = (optimised(Scope::Direction), optimised(Scope::Segment));
        for p in [-1.0, 0.0, 1.0] {
            let at = fit_surface(&g, basis.clone(), &fixed((2, 3), Join::C1, &[p])).unwrap();
            assert!(
                direction.overall.rms <= at.overall.rms * (1.0 + 1e-9),
                "{p}"
            );
        }
        // one value per direction, or one per segment (starting from the
        // per-direction optimum: never worse)
        let (u, v) = &direction.params;
        assert!(u.iter().all(|p| p == &u[0]) && v.iter().all(|p| p == &v[0]));
        let (u, v) = &segment.params;
        assert_eq!((u.len(), v.len()), (2, 3));
        assert!(u[0] != u[1] || v[0] != v[1] || v[1] != v[2], "{u:?} {v:?}");
        assert!(segment.overall.rms <= direction.overall.rms * (1.0 + 1e-9));
    }
}
