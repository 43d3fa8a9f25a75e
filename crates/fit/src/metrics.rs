//! Approximation error, thesis 6.7.
//!
//! For each data point the squared distance `Sᵢ = ‖F(tᵢ) − Pᵢ‖²` (6.7)
//! between the point and the curve at its own parameter `tᵢ` (not the
//! closest curve point: the thesis's distance is the fitting objective
//! (6.8)). Per segment: total `Σ Sᵢ`, maximum and minimum `Sᵢ`, average
//! `Σ Sᵢ / N`, and the number of bad points `Sᵢ > threshold` (the thesis uses
//! threshold 1.5, squared pixels). (6.19) prints the distance without the
//! square, but the text ("the highest and lowest squared distances", the
//! totals) uses squared distances, as here.

use serde::Serialize;

/// The thesis's bad-point threshold (6.7), in squared data units.
pub const THESIS_THRESHOLD: f64 = 1.5;

/// Error metrics of one segment (or of any set of squared errors).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Metrics {
    /// Number of data points, both end points included.
    pub points: usize,
    /// `Σ Sᵢ`.
    pub total: f64,
    /// `max Sᵢ`.
    pub max: f64,
    /// `min Sᵢ`.
    pub min: f64,
    /// `Σ Sᵢ / N`.
    pub average: f64,
    /// `#{i : Sᵢ > threshold}`.
    pub bad: usize,
}

impl Metrics {
    /// Metrics of the squared errors `s` (nonempty) with bad-point threshold `threshold`.
    pub fn from_squared(s: &[f64], threshold: f64) -> Metrics {
        let total: f64 = s.iter().sum();
        Metrics {
            points: s.len(),
            total,
            max: s.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            min: s.iter().copied().fold(f64::INFINITY, f64::min),
            average: total / s.len() as f64,
            bad: s.iter().filter(|&&v| v > threshold).count(),
        }
    }
}

/// Metrics of a whole outline from its segments.
///
/// Adjacent segments share their end point, where every fit interpolates the
/// data (`Sᵢ = 0` up to rounding), so summing segment totals and bad counts
/// counts every data point once.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Summary {
    /// Distinct data points of the outline.
    pub points: usize,
    /// Sum of the segment totals.
    pub total: f64,
    /// Largest segment maximum.
    pub max: f64,
    /// Smallest segment minimum.
    pub min: f64,
    /// `total / points`: the average squared error per data point.
    pub average: f64,
    /// Mean of the segment averages: the "Ave. error" of the thesis's TOTAL
    /// rows and Tables 6.14–6.16 (e.g. Table 6.2: mean of the eleven segment
    /// averages 0.71585), which weights short segments like long ones.
    pub mean_segment_average: f64,
    /// Sum of the segment bad-point counts.
    pub bad: usize,
}

impl Summary {
    /// Combines segment metrics; `points` is the number of distinct data points.
    pub fn of(segments: &[Metrics], points: usize) -> Summary {
        let total: f64 = segments.iter().map(|m| m.total).sum();
        Summary {
            points,
            total,
            max: segments
                .iter()
                .map(|m| m.max)
                .fold(f64::NEG_INFINITY, f64::max),
            min: segments.iter().map(|m| m.min).fold(f64::INFINITY, f64::min),
            average: total / points as f64,
            mean_segment_average: segments.iter().map(|m| m.average).sum::<f64>()
                / segments.len() as f64,
            bad: segments.iter().map(|m| m.bad).sum(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_checked_metrics() {
        // squared errors 0, 1, 4, 2.25: total 7.25, average 1.8125,
        // two above 1.5 (4 and 2.25; 1.5 itself would not count)
        let m = Metrics::from_squared(&[0.0, 1.0, 4.0, 2.25], THESIS_THRESHOLD);
        assert_eq!(
            m,
            Metrics {
                points: 4,
                total: 7.25,
                max: 4.0,
                min: 0.0,
                average: 1.8125,
                bad: 2
            }
        );
        assert_eq!(Metrics::from_squared(&[1.5, 1.5], 1.5).bad, 0);
        let other = Metrics::from_squared(&[0.0, 0.75], THESIS_THRESHOLD);
        let s = Summary::of(&[m, other], 5);
        assert_eq!(s.total, 8.0);
        assert_eq!(s.average, 1.6);
        assert_eq!(s.mean_segment_average, (1.8125 + 0.375) / 2.0);
        assert_eq!((s.max, s.min, s.bad), (4.0, 0.0, 2));
    }
}
