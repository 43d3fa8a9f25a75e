//! The f64 interpolant for plotting: a list of evaluable pieces.

use crate::InterpError;
use crate::data::DataSet;
use crate::kind::{Scheme, Variant};
use crate::piece::Piece;
use crate::scheme::build;

/// One piece of an interpolant in f64, defined on `[x0, x1]`.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotSegment {
    pub x0: f64,
    pub x1: f64,
    /// The shape parameter `m_i` (f64, for labels).
    pub m: f64,
    /// Control points `[V_i, W_i, X_i, Y_i]`.
    pub points: [f64; 4],
    piece: Piece<f64>,
}

impl PlotSegment {
    /// The piece made from an f64 [`Piece`].
    pub fn new(piece: Piece<f64>) -> PlotSegment {
        PlotSegment {
            x0: piece.x0.to_f64(),
            x1: (piece.x0.clone() + &piece.h).to_f64(),
            m: piece.m.to_f64(),
            points: piece.points,
            piece,
        }
    }

    /// `P_i(x)` (the piece's formula; meant for `x ∈ [x0, x1]`).
    pub fn eval(&self, x: f64) -> f64 {
        self.piece.eval(&x)
    }

    /// `samples + 1` equally spaced points `(x, P_i(x))` from `x0` to `x1` (`samples ≥ 1`).
    pub fn sample(&self, samples: usize) -> Vec<(f64, f64)> {
        let n = samples.max(1);
        (0..=n)
            .map(|k| {
                let x = self.x0 + (self.x1 - self.x0) * (k as f64) / (n as f64);
                (x, self.eval(x))
            })
            .collect()
    }
}

/// The interpolant of `scheme` (`variant`) on the data set `data`
/// (`thesis-table-4.1` … `thesis-table-4.6`), one [`PlotSegment`] per
/// interval, built by the same generic code as the exact spline.
///
/// # Errors
/// Unknown data set, a column the scheme needs and the table lacks, or a
/// singular scheme.
pub fn f64_segments(
    data: &str,
    scheme: Scheme,
    variant: Variant,
) -> Result<Vec<PlotSegment>, InterpError> {
    let data = DataSet::named(data)?;
    let spline = build(&data, scheme, variant, &0.0_f64)?;
    if spline
        .pieces
        .iter()
        .flat_map(|p| p.points.iter())
        .any(|v| !v.is_finite())
    {
        return Err(InterpError::Singular(
            "a control point is not finite".into(),
        ));
    }
    Ok(spline.pieces.into_iter().map(PlotSegment::new).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Ring;

    #[test]
    fn segments_interpolate_the_table() {
        let segs = f64_segments("thesis-table-4.1", Scheme::C1, Variant::Printed).unwrap();
        let f = [3.0, 6.0, 5.0, 8.0, 1.0];
        for (i, s) in segs.iter().enumerate() {
            assert!((s.eval(s.x0) - f[i]).abs() < 1e-12);
            assert!((s.eval(s.x1) - f[i + 1]).abs() < 1e-12);
            assert_eq!(s.sample(4).len(), 5);
        }
        assert!(f64_segments("nope", Scheme::C1, Variant::Printed).is_err());
        assert_eq!(0.0_f64.int(1), 1.0);
    }
}
