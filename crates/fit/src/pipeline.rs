//! The whole pipeline of thesis Figure 6.1 for one outline and one family:
//! segments → chord-length parameters → least squares per segment (with a
//! fixed or optimised shape parameter) → metrics → optional C¹ refinement →
//! metrics again.

use std::sync::Arc;

use serde::Serialize;

use crate::basis::{NumericBasis, SegmentBasis};
use crate::chord::chord_parameters;
use crate::corners::{Corners, Span, segment};
use crate::data::{Outline, P2};
use crate::error::{FitError, Result};
use crate::lsq::{Control, curve_point, design, fit_segment};
use crate::metrics::{Metrics, Summary};
use crate::optimise::golden_section;
use crate::refine::{Continuity, Piece, refine};

/// Fewest points a segment needs: its two end points and two inner points
/// to determine `V₁`, `V₂`.
pub const MIN_SEGMENT_POINTS: usize = 4;

/// How the shape parameter of each segment is chosen.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// The same parameters for every segment (the thesis: 0.6).
    Fixed(Vec<f64>),
    /// One shape parameter is chosen per segment by golden-section search
    /// on `[lo, hi]` ([`crate::optimise`]), the others at the values
    /// `fixed` (by index; none for a basis with one parameter).
    Optimise {
        lo: f64,
        hi: f64,
        fixed: Vec<(usize, f64)>,
    },
}

/// The index of the one parameter an optimisation searches (every other
/// one fixed in `fixed`), or why there is not exactly one.
pub fn searched_index(basis: &dyn NumericBasis, fixed: &[(usize, f64)]) -> Result<usize> {
    let (_, n) = basis.counts();
    let free: Vec<usize> = (0..n)
        .filter(|k| !fixed.iter().any(|(j, _)| j == k))
        .collect();
    let [index] = free[..] else {
        return Err(FitError::Option(format!(
            "`{}` has {n} shape parameters; optimisation searches one, the others fixed ({} fixed)",
            basis.basis_id(),
            fixed.len()
        )));
    };
    Ok(index)
}

/// Options of [`fit_outline`].
#[derive(Debug, Clone, PartialEq)]
pub struct FitOptions {
    pub corners: Corners,
    /// Longest run of points one segment may cover (0: no splitting).
    pub max_points: usize,
    /// Bad-point threshold on the squared error (thesis: 1.5).
    pub threshold: f64,
    /// C¹ refinement, if wanted.
    pub refine: Option<Continuity>,
    pub shape: Shape,
}

/// One fitted segment.
#[derive(Debug, Clone, Serialize)]
pub struct SegmentFit {
    pub span: Span,
    /// Shape parameters used for this segment.
    pub params: Vec<f64>,
    /// Control points of the C⁰ fit, `[x, y]` each.
    pub control: [[f64; 2]; 4],
    pub metrics: Metrics,
    /// Control points and metrics after C¹ refinement.
    pub refined: Option<([[f64; 2]; 4], Metrics)>,
}

/// The fit of one outline with one family.
#[derive(Debug, Clone, Serialize)]
pub struct OutlineFit {
    pub glyph: String,
    pub family: String,
    #[serde(skip)]
    pub basis: Arc<dyn NumericBasis>,
    pub optimised: bool,
    pub continuity: Option<Continuity>,
    pub threshold: f64,
    pub segments: Vec<SegmentFit>,
    /// Whole-outline metrics of the C⁰ fit.
    pub before: Summary,
    /// Whole-outline metrics after refinement.
    pub after: Option<Summary>,
}

fn xy(c: &Control) -> [[f64; 2]; 4] {
    c.map(|p| [p.x, p.y])
}

/// Squared errors `‖F(tᵢ) − Pᵢ‖²` of one segment.
fn squared_errors(basis: &SegmentBasis, control: &Control, points: &[P2], t: &[f64]) -> Vec<f64> {
    design(basis, t)
        .iter()
        .zip(points)
        .map(|(b, p)| (curve_point(b, control) - p).norm_squared())
        .collect()
}

/// Fits `outline` with `family` (a catalog family or any other basis of
/// four functions; see the module docs).
pub fn fit_outline(
    outline: &Outline,
    family: Arc<dyn NumericBasis>,
    options: &FitOptions,
) -> Result<OutlineFit> {
    if !(options.threshold.is_finite() && options.threshold >= 0.0) {
        return Err(FitError::Option(format!(
            "threshold {} must be a finite number ≥ 0",
            options.threshold
        )));
    }
    if options.max_points != 0 && options.max_points < MIN_SEGMENT_POINTS {
        return Err(FitError::Option(format!(
            "max points per segment {} must be 0 (no splitting) or at least {MIN_SEGMENT_POINTS}",
            options.max_points
        )));
    }
    let spans = segment(outline, &options.corners, options.max_points)?;
    let mut data = Vec::with_capacity(spans.len());
    for (k, span) in spans.iter().enumerate() {
        if span.len < MIN_SEGMENT_POINTS {
            return Err(FitError::TooFewPoints {
                segment: k + 1,
                got: span.len,
                needed: MIN_SEGMENT_POINTS,
            });
        }
        let points = span.points(&outline.contours[span.contour]);
        let t = chord_parameters(&points).ok_or(FitError::Degenerate { segment: k + 1 })?;
        let length: f64 = points.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
        data.push((points, t, length));
    }
    let mut bases = Vec::with_capacity(spans.len());
    let mut controls = Vec::with_capacity(spans.len());
    for (k, (points, t, _)) in data.iter().enumerate() {
        let what = format!("segment {}", k + 1);
        let basis = match &options.shape {
            Shape::Fixed(p) => SegmentBasis::new(family.clone(), p)?,
            Shape::Optimise { lo, hi, fixed } => {
                let (_, n) = family.counts();
                let index = searched_index(family.as_ref(), fixed)?;
                if fixed.len() + 1 != n {
                    return Err(FitError::Option(format!(
                        "`{}` has {n} shape parameters; {} fixed values given",
                        family.basis_id(),
                        fixed.len()
                    )));
                }
                // every parameter: the fixed values, `p` at the searched one
                let with = |p: f64| {
                    let mut all = vec![p; n];
                    for (j, v) in fixed {
                        all[*j] = *v;
                    }
                    all[index] = p;
                    all
                };
                let (p, _) = golden_section(
                    |p| {
                        let b = SegmentBasis::new(family.clone(), &with(p))?;
                        let c = fit_segment(&b, points, t, &what)?;
                        Ok(squared_errors(&b, &c, points, t).iter().sum())
                    },
                    *lo,
                    *hi,
                )?;
                SegmentBasis::new(family.clone(), &with(p))?
            }
        };
        controls.push(fit_segment(&basis, points, t, &what)?);
        bases.push(basis);
    }
    let metrics_of = |cs: &[Control]| -> Vec<Metrics> {
        cs.iter()
            .zip(&bases)
            .zip(&data)
            .map(|((c, b), (p, t, _))| {
                Metrics::from_squared(&squared_errors(b, c, p, t), options.threshold)
            })
            .collect()
    };
    let before = metrics_of(&controls);
    let refined = match options.refine {
        None => None,
        Some(continuity) => {
            let pieces: Vec<Piece<'_>> = spans
                .iter()
                .enumerate()
                .map(|(k, span)| {
                    let next = successor(&spans, k);
                    Piece {
                        basis: &bases[k],
                        points: &data[k].0,
                        t: &data[k].1,
                        length: data[k].2,
                        smooth_successor: (!span.end_corner).then_some(next),
                    }
                })
                .collect();
            let cs = refine(&pieces, continuity)?;
            let ms = metrics_of(&cs);
            Some((cs, ms))
        }
    };
    let points = outline.point_count();
    let segments = spans
        .iter()
        .enumerate()
        .map(|(k, span)| SegmentFit {
            span: *span,
            params: bases[k].params().to_vec(),
            control: xy(&controls[k]),
            metrics: before[k],
            refined: refined.as_ref().map(|(cs, ms)| (xy(&cs[k]), ms[k])),
        })
        .collect();
    Ok(OutlineFit {
        glyph: outline.name.clone(),
        family: family.basis_id(),
        basis: family,
        optimised: matches!(options.shape, Shape::Optimise { .. }),
        continuity: options.refine,
        threshold: options.threshold,
        segments,
        before: Summary::of(&before, points),
        after: refined.as_ref().map(|(_, ms)| Summary::of(ms, points)),
    })
}

/// The segment after `k` along its closed contour.
fn successor(spans: &[Span], k: usize) -> usize {
    let c = spans[k].contour;
    if k + 1 < spans.len() && spans[k + 1].contour == c {
        k + 1
    } else {
        spans
            .iter()
            .position(|s| s.contour == c)
            .expect("span k is in contour c")
    }
}

impl OutlineFit {
    /// Points along every fitted segment (`samples` ≥ 2 per segment) of the
    /// C⁰ fit, or of the refined fit when `refined` and available.
    pub fn curve(&self, refined: bool, samples: usize) -> Result<Vec<Vec<P2>>> {
        self.segments
            .iter()
            .map(|s| {
                let basis = SegmentBasis::new(self.basis.clone(), &s.params)?;
                let c = match (&s.refined, refined) {
                    (Some((c, _)), true) => c,
                    _ => &s.control,
                };
                let control: Control = c.map(|[x, y]| P2::new(x, y));
                let n = samples.max(2);
                let t: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
                Ok(design(&basis, &t)
                    .iter()
                    .map(|b| curve_point(b, &control))
                    .collect())
            })
            .collect()
    }
}
