//! Corner detection and the division of each closed contour into segments.
//!
//! **Automatic rule.** At point `i` of a closed contour sampled at (nearly)
//! equal spacing, the turning angle `φᵢ ∈ [0°, 180°]` is the angle between
//! the chords `Pᵢ − P_{i−w}` and `P_{i+w} − Pᵢ` (indices mod `n`, window `w`
//! points). `Pᵢ` is a corner when `φᵢ ≥ φ_min` and `φᵢ` is the largest
//! turning angle within `w` points on either side (the first such point on
//! ties). Defaults `w = 3`, `φ_min = 45°`: with 3-pixel spacing a smooth arc
//! turns by about `2·w·3/R` radians, so only arcs of radius below ≈ 23 px
//! (or true corners) reach 45°.
//!
//! **Explicit corners** are global point indices (file order over all
//! contours, see [`crate::data`]).
//!
//! **Segments.** The corners cut each contour into runs (a contour without
//! corners is one run from its first point back to it). A run longer than
//! `max_points` points is split into the fewest pieces of equal point count
//! that each have at most `max_points` points; the cut points are *smooth*
//! breakpoints, where the C¹ refinement applies, while joins at corners stay
//! C⁰. `max_points = 0` disables splitting.

use serde::Serialize;

use crate::data::{Outline, P2};
use crate::error::{FitError, Result};

/// The automatic corner rule.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CornerRule {
    /// Window `w`, in points.
    pub window: usize,
    /// Minimum turning angle `φ_min`, degrees.
    pub min_angle_deg: f64,
}

impl Default for CornerRule {
    fn default() -> Self {
        CornerRule {
            window: 3,
            min_angle_deg: 45.0,
        }
    }
}

/// How corners are found.
#[derive(Debug, Clone, PartialEq)]
pub enum Corners {
    /// By the automatic rule.
    Auto(CornerRule),
    /// Given as global point indices.
    Explicit(Vec<usize>),
}

/// One segment: consecutive points of a contour, both breakpoints included.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Span {
    /// Contour index.
    pub contour: usize,
    /// Local index of the first point in its contour.
    pub start: usize,
    /// Number of points, both ends included (wraps around the contour).
    pub len: usize,
    /// The first point is a corner (else a smooth breakpoint).
    pub start_corner: bool,
    /// The last point is a corner.
    pub end_corner: bool,
}

impl Span {
    /// The points of the span, in order.
    pub fn points(&self, contour: &[P2]) -> Vec<P2> {
        (0..self.len)
            .map(|k| contour[(self.start + k) % contour.len()])
            .collect()
    }
}

/// Turning angle at every point of a closed contour, degrees.
pub fn turning_angles(contour: &[P2], window: usize) -> Vec<f64> {
    let n = contour.len();
    let w = window.max(1) % n.max(1);
    (0..n)
        .map(|i| {
            let a = contour[i] - contour[(i + n - w) % n];
            let b = contour[(i + w) % n] - contour[i];
            let (na, nb) = (a.norm(), b.norm());
            if na == 0.0 || nb == 0.0 {
                return 0.0;
            }
            (a.dot(&b) / (na * nb)).clamp(-1.0, 1.0).acos().to_degrees()
        })
        .collect()
}

/// Local indices of the corners of a closed contour by the automatic rule.
pub fn detect(contour: &[P2], rule: CornerRule) -> Vec<usize> {
    let n = contour.len();
    if n < 2 * rule.window + 1 {
        return Vec::new();
    }
    let phi = turning_angles(contour, rule.window);
    (0..n)
        .filter(|&i| {
            phi[i] >= rule.min_angle_deg
                && (1..=rule.window).all(|k| {
                    let before = phi[(i + n - k) % n];
                    let after = phi[(i + k) % n];
                    phi[i] > before && phi[i] >= after
                })
        })
        .collect()
}

/// Divides every contour of `outline` into segments (see the module docs).
pub fn segment(outline: &Outline, corners: &Corners, max_points: usize) -> Result<Vec<Span>> {
    let count = outline.point_count();
    let offsets = outline.contour_offsets();
    let mut per_contour: Vec<Vec<usize>> = vec![Vec::new(); outline.contours.len()];
    match corners {
        Corners::Auto(rule) => {
            for (c, contour) in outline.contours.iter().enumerate() {
                per_contour[c] = detect(contour, *rule);
            }
        }
        Corners::Explicit(list) => {
            for &g in list {
                if g >= count {
                    return Err(FitError::CornerOutOfRange { index: g, count });
                }
                let c = offsets.iter().rposition(|&o| o <= g).expect("offset 0");
                per_contour[c].push(g - offsets[c]);
            }
            for v in &mut per_contour {
                v.sort_unstable();
                v.dedup();
            }
        }
    }
    let mut spans = Vec::new();
    for (c, contour) in outline.contours.iter().enumerate() {
        let n = contour.len();
        let found = &per_contour[c];
        let (cuts, corner): (Vec<usize>, bool) = if found.is_empty() {
            (vec![0], false)
        } else {
            (found.clone(), true)
        };
        for (k, &a) in cuts.iter().enumerate() {
            let b = cuts[(k + 1) % cuts.len()];
            let gap = if b > a { b - a } else { b + n - a };
            let pieces = if max_points >= 2 {
                gap.div_ceil(max_points - 1)
            } else {
                1
            };
            for j in 0..pieces {
                let from = j * gap / pieces;
                let to = (j + 1) * gap / pieces;
                spans.push(Span {
                    contour: c,
                    start: (a + from) % n,
                    len: to - from + 1,
                    start_corner: corner && j == 0,
                    end_corner: corner && j + 1 == pieces,
                });
            }
        }
    }
    Ok(spans)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square of side 12 sampled every unit, starting mid-side.
    fn square() -> Vec<P2> {
        let mut p = Vec::new();
        for k in 0..12 {
            p.push(P2::new(f64::from(k), 0.0));
        }
        for k in 0..12 {
            p.push(P2::new(12.0, f64::from(k)));
        }
        for k in 0..12 {
            p.push(P2::new(12.0 - f64::from(k), 12.0));
        }
        for k in 0..12 {
            p.push(P2::new(0.0, 12.0 - f64::from(k)));
        }
        p.rotate_left(6);
        p
    }

    #[test]
    fn square_corners_are_found() {
        let sq = square();
        let corners = detect(&sq, CornerRule::default());
        let at: Vec<P2> = corners.iter().map(|&i| sq[i]).collect();
        assert_eq!(
            at,
            vec![
                P2::new(12.0, 0.0),
                P2::new(12.0, 12.0),
                P2::new(0.0, 12.0),
                P2::new(0.0, 0.0)
            ]
        );
        // a circle of radius 100 has none
        let circle: Vec<P2> = (0..200)
            .map(|k| {
                let a = f64::from(k) * std::f64::consts::TAU / 200.0;
                P2::new(100.0 * a.cos(), 100.0 * a.sin())
            })
            .collect();
        assert!(detect(&circle, CornerRule::default()).is_empty());
    }

    #[test]
    fn runs_are_split_and_wrap() {
        let o = Outline {
            name: "sq".into(),
            provenance: vec![],
            contours: vec![square()],
        };
        let spans = segment(&o, &Corners::Auto(CornerRule::default()), 7).unwrap();
        // four sides of 12 steps, each split into two pieces of 6 steps (7 points)
        assert_eq!(spans.len(), 8);
        assert!(spans.iter().all(|s| s.len == 7));
        assert_eq!(spans.iter().filter(|s| s.start_corner).count(), 4);
        let last = spans.last().unwrap();
        assert_eq!((last.start + last.len - 1) % 48, spans[0].start);
        // explicit corners, no splitting: two runs
        let spans = segment(&o, &Corners::Explicit(vec![0, 24]), 0).unwrap();
        assert_eq!(
            spans.iter().map(|s| s.len).collect::<Vec<_>>(),
            vec![25, 25]
        );
        assert!(matches!(
            segment(&o, &Corners::Explicit(vec![48]), 0),
            Err(FitError::CornerOutOfRange {
                index: 48,
                count: 48
            })
        ));
    }
}
