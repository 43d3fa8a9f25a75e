//! C¹ refinement of the joined segments (thesis 6.6, Figure 6.8).
//!
//! The thesis makes consecutive segments C¹ "segmentally … using (4.6)"
//! (`P₅ = 2P₃ − P₂`, i.e. `Q₂'(0) = Q₁'(1)` (4.5)) without saying which
//! points are re-fitted afterwards. Here the refinement is one global
//! least-squares problem with equality constraints:
//!
//! * **fixed:** every breakpoint (each segment's `V₀`, `V₃` stay the data
//!   points where the contour was cut, so corners are kept exactly), the
//!   shape parameters of every segment, the parameters `tᵢ` of the data;
//! * **moving:** the inner control points `V₁`, `V₂` of every segment;
//! * **objective:** the sum over all segments of (6.8);
//! * **constraints:** at every smooth breakpoint (a cut that is not a
//!   corner, see [`crate::corners`]), including the wrap-around join of a
//!   closed contour, `σ_k Q_k'(1) = σ_{k+1} Q_{k+1}'(0)`, where `'` is
//!   `d/dt` in the local parameter and `σ` is 1 for [`Continuity::Local`]
//!   (thesis (4.5): each segment over a unit interval) or `1/L_k`, the
//!   reciprocal chord length of the segment's data, for
//!   [`Continuity::ArcLength`] (C¹ in the global chord-length parameter).
//!   Joins at corners stay C⁰.
//!
//! The end slopes come from the family's Taylor jets, so segments with
//! different shape parameters join as in thesis (4.7). The KKT system
//! `[H Cᵀ; C 0][x; μ] = [g; d]` is sparse — `H` is block diagonal (2 × 2 per
//! segment) and each constraint touches two neighbouring segments — so it
//! is solved as a banded system after a bandwidth-reducing ordering
//! ([`crate::banded`]): linear in the number of segments, with no dense
//! matrix, one right-hand side per coordinate.

use serde::Serialize;

use crate::banded::{Sparse, breadth_first};
use crate::basis::SegmentBasis;
use crate::data::P2;
use crate::error::{FitError, Result};
use crate::lsq::{Control, design, residual_targets};

/// Which first derivatives must agree at a smooth join.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Continuity {
    /// `Q_k'(1) = Q_{k+1}'(0)` in each segment's own `t ∈ [0, 1]` (thesis (4.5)).
    Local,
    /// Derivatives with respect to the global chord-length parameter agree:
    /// `Q_k'(1)/L_k = Q_{k+1}'(0)/L_{k+1}`.
    ArcLength,
}

/// One segment as the refinement sees it.
#[derive(Debug, Clone)]
pub struct Piece<'a> {
    pub basis: &'a SegmentBasis,
    pub points: &'a [P2],
    pub t: &'a [f64],
    /// Chord length `L_k` of the data.
    pub length: f64,
    /// Index of the segment that follows this one at a smooth join, if any.
    pub smooth_successor: Option<usize>,
}

/// Re-fits the inner control points of all pieces under the C¹ constraints.
/// Returns the new control points, one per piece.
pub fn refine(pieces: &[Piece<'_>], continuity: Continuity) -> Result<Vec<Control>> {
    let k = pieces.len();
    let joins: Vec<(usize, usize)> = pieces
        .iter()
        .enumerate()
        .filter_map(|(a, p)| p.smooth_successor.map(|b| (a, b)))
        .collect();
    let size = 2 * k + joins.len();
    let mut m = Sparse::new(size);
    let mut rhs = vec![[0.0; 2]; size];
    for (j, p) in pieces.iter().enumerate() {
        let rows = design(p.basis, p.t);
        let (v0, v3) = (p.points[0], p.points[p.points.len() - 1]);
        let mut h = [[0.0; 2]; 2];
        for (b, r) in rows.iter().zip(residual_targets(&rows, p.points, &v0, &v3)) {
            for (u, bu) in [(0, b[1]), (1, b[2])] {
                for (v, bv) in [(0, b[1]), (1, b[2])] {
                    h[u][v] += bu * bv;
                }
                rhs[2 * j + u][0] += bu * r.x;
                rhs[2 * j + u][1] += bu * r.y;
            }
        }
        for (u, row) in h.iter().enumerate() {
            for (v, &value) in row.iter().enumerate() {
                m.add(2 * j + u, 2 * j + v, value);
            }
        }
    }
    let sigma = |p: &Piece<'_>| match continuity {
        Continuity::Local => 1.0,
        Continuity::ArcLength => 1.0 / p.length,
    };
    let mut edges: Vec<(usize, usize)> = (0..k).map(|j| (2 * j, 2 * j + 1)).collect();
    for (row, &(a, b)) in joins.iter().enumerate() {
        let r = 2 * k + row;
        let (pa, pb) = (&pieces[a], &pieces[b]);
        let (_, e) = pa.basis.end_slopes();
        let (d, _) = pb.basis.end_slopes();
        let (sa, sb) = (sigma(pa), sigma(pb));
        // sa(e1 V1ᵃ + e2 V2ᵃ) − sb(d1 V1ᵇ + d2 V2ᵇ) = sb(d0 V0ᵇ + d3 V3ᵇ) − sa(e0 V0ᵃ + e3 V3ᵃ)
        let coeffs = [
            (2 * a, sa * e[1]),
            (2 * a + 1, sa * e[2]),
            (2 * b, -sb * d[1]),
            (2 * b + 1, -sb * d[2]),
        ];
        for (col, c) in coeffs {
            m.add(r, col, c);
            m.add(col, r, c);
            edges.push((r, col));
        }
        let (a0, a3) = (pa.points[0].coords, pa.points[pa.points.len() - 1].coords);
        let (b0, b3) = (pb.points[0].coords, pb.points[pb.points.len() - 1].coords);
        let fixed = (b0 * d[0] + b3 * d[3]) * sb - (a0 * e[0] + a3 * e[3]) * sa;
        rhs[r] = [fixed.x, fixed.y];
    }
    let x = m
        .solve(&rhs, &breadth_first(size, &edges))
        .ok_or_else(|| FitError::Singular {
            what: format!(
                "C1 refinement ({} segments, {} smooth joins)",
                k,
                joins.len()
            ),
        })?;
    Ok(pieces
        .iter()
        .enumerate()
        .map(|(j, p)| {
            [
                p.points[0],
                P2::new(x[2 * j][0], x[2 * j][1]),
                P2::new(x[2 * j + 1][0], x[2 * j + 1][1]),
                p.points[p.points.len() - 1],
            ]
        })
        .collect())
}
