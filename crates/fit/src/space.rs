//! A spline space in one direction for the surface fit: `[0, 1]` cut into
//! `n` equal segments, segment `k` a curve `Σᵢ V_{3k+i} bᵢ(t)` of a
//! four-function, end-point-interpolating basis in its local parameter
//! `t = n·s − k` (each segment with its own shape parameters), joined
//!
//! * **C⁰** by sharing the end control point: `V_{3k+3}` ends segment `k`
//!   and starts segment `k + 1`; `3n + 1` free coefficients;
//! * **C¹** in addition by `Q_k'(1) = Q_{k+1}'(0)` (thesis (4.5); the
//!   segments are equally long, so this is C¹ in `s` too), with the end
//!   slopes `eᵢ = b'ᵢ(1)` of segment `k` and `dᵢ = b'ᵢ(0)` of segment `k + 1`
//!   from the basis's Taylor jets ([`SegmentBasis::end_slopes`]):
//!   `Σᵢ eᵢ V_{3k+i} = Σᵢ dᵢ V_{3k+3+i}`, solved for the second control
//!   point of segment `k + 1`,
//!   `V_{3k+4} = (Σᵢ eᵢ V_{3k+i} − d₀V_{3k+3} − d₂V_{3k+5} − d₃V_{3k+6}) / d₁`
//!   (for the thesis's basis, `e = (0, 0, −c, c)`, `d = (−c, c, 0, 0)`: the
//!   thesis's `V_{3k+4} = 2V_{3k+3} − V_{3k+2}`, (4.6)); `2n + 2` free
//!   coefficients.
//!
//! The constraint is the one the curve fit's C¹ refinement imposes
//! ([`crate::refine`]); here it is eliminated rather than kept with a
//! multiplier, so the space has a basis of its own and a tensor product of
//! two such spaces is fitted by one separable least-squares solve
//! ([`crate::surface`]). The space is the linear map `M` from the free
//! coefficients to the `3n + 1` control points; its collocation matrix at
//! the data parameters `s₁ … s_m` is `B·M`, `B` the `m × (3n + 1)` matrix of
//! the basis values.

use nalgebra::DMatrix;
use serde::Serialize;

use crate::basis::SegmentBasis;
use crate::error::{FitError, Result};

/// How neighbouring segments join.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Join {
    /// Shared end control points.
    C0,
    /// Shared end control points and equal first derivatives.
    C1,
}

/// `|d₁|` below this (relative to the largest slope) cannot carry the C¹
/// constraint: the basis's second function has no slope at `t = 0`.
const SLOPE_TOL: f64 = 1e-12;

/// `n` equal segments of `[0, 1]` joined C⁰ or C¹.
#[derive(Debug, Clone)]
pub struct Space {
    segments: Vec<SegmentBasis>,
    /// Control points (rows) as combinations of the free coefficients (columns).
    map: DMatrix<f64>,
}

impl Space {
    /// The space of `segments` (one basis per segment, at least one) joined by `join`.
    pub fn new(segments: Vec<SegmentBasis>, join: Join) -> Result<Space> {
        let n = segments.len();
        if n == 0 {
            return Err(FitError::Option(
                "a direction needs at least one patch".into(),
            ));
        }
        let controls = 3 * n + 1;
        let map = match join {
            Join::C0 => DMatrix::identity(controls, controls),
            Join::C1 => {
                let free = 2 * n + 2;
                let mut map = DMatrix::zeros(controls, free);
                for i in 0..4 {
                    map[(i, i)] = 1.0;
                }
                for k in 1..n {
                    // V_{3k+2}, V_{3k+3} are free; V_{3k+1} is forced
                    let (c, f) = (3 * k, 2 * k + 2);
                    map[(c + 2, f)] = 1.0;
                    map[(c + 3, f + 1)] = 1.0;
                    let (_, e) = segments[k - 1].end_slopes();
                    let (d, _) = segments[k].end_slopes();
                    let scale = d.iter().chain(&e).fold(0.0_f64, |a, v| a.max(v.abs()));
                    if d[1].abs() <= SLOPE_TOL * scale {
                        return Err(FitError::Unsuitable {
                            family: segments[k].basis().basis_id(),
                            reason: format!(
                                "its second function has slope {} at t = 0: no C¹ join forces the second control point",
                                d[1]
                            ),
                        });
                    }
                    let mut row = map.row(c - 3) * e[0]
                        + map.row(c - 2) * e[1]
                        + map.row(c - 1) * e[2]
                        + map.row(c) * (e[3] - d[0])
                        - map.row(c + 2) * d[2]
                        - map.row(c + 3) * d[3];
                    row /= d[1];
                    map.set_row(c + 1, &row);
                }
                map
            }
        };
        Ok(Space { segments, map })
    }

    /// Number of segments.
    pub fn segments(&self) -> usize {
        self.segments.len()
    }

    /// The basis of segment `k`.
    pub fn segment(&self, k: usize) -> &SegmentBasis {
        &self.segments[k]
    }

    /// Number of free coefficients (the dimension of the space).
    pub fn dim(&self) -> usize {
        self.map.ncols()
    }

    /// The segment of `s ∈ [0, 1]` and its local parameter `t ∈ [0, 1]`
    /// (a break point belongs to the segment it starts, `s = 1` to the last).
    pub fn locate(&self, s: f64) -> (usize, f64) {
        let n = self.segments.len();
        let scaled = s.clamp(0.0, 1.0) * n as f64;
        let k = (scaled.floor() as usize).min(n - 1);
        (k, scaled - k as f64)
    }

    /// The collocation matrix `B·M` at the parameters `s` (one row each).
    pub fn collocation(&self, s: &[f64]) -> DMatrix<f64> {
        let mut b = DMatrix::zeros(s.len(), self.map.nrows());
        let located: Vec<(usize, f64)> = s.iter().map(|&x| self.locate(x)).collect();
        for (k, segment) in self.segments.iter().enumerate() {
            let rows: Vec<usize> = (0..s.len()).filter(|&r| located[r].0 == k).collect();
            let t: Vec<f64> = rows.iter().map(|&r| located[r].1).collect();
            for (&r, values) in rows.iter().zip(segment.values_at(&t)) {
                for (i, v) in values.iter().enumerate() {
                    b[(r, 3 * k + i)] = *v;
                }
            }
        }
        b * &self.map
    }

    /// The control points `M·c` of the free coefficients `c` (one column
    /// per set of coefficients).
    pub fn controls(&self, coefficients: &DMatrix<f64>) -> DMatrix<f64> {
        &self.map * coefficients
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use trig_core::Family;

    use super::*;

    fn thesis(n: usize, m: f64) -> Vec<SegmentBasis> {
        vec![SegmentBasis::new(Arc::new(Family::ThesisCubic), &[m]).unwrap(); n]
    }

    /// The C¹ space's curves have equal one-sided slopes at every break,
    /// measured by difference quotients (not by the slopes the space was
    /// built from), and the thesis's rule (4.6) holds for its control points.
    #[test]
    fn c1_space_is_c1_at_its_breaks() {
        let n = 3;
        let space = Space::new(thesis(n, 0.6), Join::C1).unwrap();
        assert_eq!(space.dim(), 2 * n + 2);
        let c = DMatrix::from_fn(space.dim(), 1, |i, _| ((i * 7 % 5) as f64) - 1.3 * i as f64);
        let v = space.controls(&c);
        for k in 1..n {
            let j = 3 * k;
            assert!(
                (v[j + 1] - (2.0 * v[j] - v[j - 1])).abs() < 1e-12,
                "(4.6) at {k}"
            );
        }
        let h = 1e-6;
        for k in 1..n {
            let s = k as f64 / n as f64;
            let a = space.collocation(&[s - 2.0 * h, s - h, s, s + h, s + 2.0 * h]) * &c;
            let left = (a[2] - a[1]) / h;
            let right = (a[3] - a[2]) / h;
            assert!(
                (left - right).abs() < 1e-3 * left.abs().max(1.0),
                "{left} {right}"
            );
        }
        // the C⁰ space has a curve with a kink at a break
        let c0 = Space::new(thesis(n, 0.6), Join::C0).unwrap();
        assert_eq!(c0.dim(), 3 * n + 1);
        let kink = DMatrix::from_fn(c0.dim(), 1, |i, _| if i == 2 { 1.0 } else { 0.0 });
        let a = c0.collocation(&[1.0 / 3.0 - h, 1.0 / 3.0, 1.0 / 3.0 + h]) * kink;
        assert!(((a[1] - a[0]) - (a[2] - a[1])).abs() > 1e-3 * h);
    }

    #[test]
    fn the_spaces_reproduce_straight_lines() {
        // partition of unity and linear precision of the Bernstein basis:
        // control points k/(3n) give the curve s
        let b = SegmentBasis::new(Arc::new(Family::Bernstein3), &[]).unwrap();
        for join in [Join::C0, Join::C1] {
            let space = Space::new(vec![b.clone(); 4], join).unwrap();
            let s: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
            let a = space.collocation(&s);
            let line = nalgebra::DVector::from_iterator(s.len(), s.iter().copied());
            let c = a.clone().svd(true, true).solve(&line, 1e-14).unwrap();
            assert!((a * c - line).norm() < 1e-12, "{join:?}");
        }
    }
}
