//! Per-segment choice of the shape parameter (beyond the thesis, which fixes
//! it at 0.6 for every method, 6.6).
//!
//! For one segment, `E(p)` is the total squared error (6.8) of the
//! least-squares fit (6.11)–(6.18) with shape parameter `p`. It is minimised
//! over a closed interval `[lo, hi]` by golden-section search: the bracket
//! shrinks by `1/φ ≈ 0.618` per step until it is narrower than
//! `10⁻⁸·(1 + |lo| + |hi|)` (at most 80 steps); the result is the best of the
//! search's final point and the two interval ends. Golden section finds the
//! minimum of a unimodal `E`; for a non-unimodal `E` it finds a local
//! minimum, never worse than either end. A `p` where the fit is singular
//! counts as `E = +∞`.

use trig_core::{Bound, Range};

use crate::error::{FitError, Result};

/// `1/φ = (√5 − 1)/2`.
const INV_PHI: f64 = 0.618_033_988_749_894_8;
const MAX_STEPS: usize = 80;
const REL_WIDTH: f64 = 1e-8;
/// An open end is replaced by the end moved inward by this fraction of the width.
pub const OPEN_END_MARGIN: f64 = 1e-3;

/// The closed search interval for a published (or certified) range: closed
/// ends as they are, open ends moved inward by [`OPEN_END_MARGIN`] of the
/// width. Unbounded ranges have no search interval.
pub fn search_interval(range: &Range) -> Result<(f64, f64)> {
    let end = |b: Bound| {
        b.value()
            .map(|v| (v.to_f64(), matches!(b, Bound::Open(..))))
    };
    match (end(range.lo), end(range.hi)) {
        (Some(lo), Some(hi)) => Ok(search_between(lo, hi)),
        _ => Err(FitError::Option(format!(
            "the range {range} is unbounded: give a closed search interval"
        ))),
    }
}

/// The closed search interval between two ends `(value, open)`: open ends
/// moved inward by [`OPEN_END_MARGIN`] of the width.
pub fn search_between((lo, lo_open): (f64, bool), (hi, hi_open): (f64, bool)) -> (f64, f64) {
    let margin = OPEN_END_MARGIN * (hi - lo);
    (
        if lo_open { lo + margin } else { lo },
        if hi_open { hi - margin } else { hi },
    )
}

/// Minimises `f` over `[lo, hi]` by golden-section search; returns `(p, f(p))`.
/// `f` returning an error counts as `+∞`; if every evaluation fails, the
/// last error is returned.
pub fn golden_section(
    mut f: impl FnMut(f64) -> Result<f64>,
    lo: f64,
    hi: f64,
) -> Result<(f64, f64)> {
    if !(lo.is_finite() && hi.is_finite() && lo <= hi) {
        return Err(FitError::Option(format!(
            "bad search interval [{lo}, {hi}]"
        )));
    }
    let mut last_error = None;
    let mut eval = |x: f64| match f(x) {
        Ok(v) if v.is_finite() => v,
        Ok(_) => f64::INFINITY,
        Err(e) => {
            last_error = Some(e);
            f64::INFINITY
        }
    };
    let (mut a, mut b) = (lo, hi);
    let mut c = b - INV_PHI * (b - a);
    let mut d = a + INV_PHI * (b - a);
    let (mut fc, mut fd) = (eval(c), eval(d));
    let width = REL_WIDTH * (1.0 + lo.abs() + hi.abs());
    for _ in 0..MAX_STEPS {
        if b - a < width {
            break;
        }
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - INV_PHI * (b - a);
            fc = eval(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + INV_PHI * (b - a);
            fd = eval(d);
        }
    }
    let inner = if fc <= fd { (c, fc) } else { (d, fd) };
    let best = [(lo, eval(lo)), (hi, eval(hi)), inner].into_iter().fold(
        (f64::NAN, f64::INFINITY),
        |acc, x| if x.1 < acc.1 { x } else { acc },
    );
    if best.1.is_finite() {
        Ok(best)
    } else {
        Err(last_error
            .unwrap_or_else(|| FitError::Option("no finite value on the interval".into())))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_interior_and_end_minima() {
        let (x, fx) = golden_section(|x| Ok((x - 0.3).powi(2) + 1.0), -2.0, 1.0).unwrap();
        assert!((x - 0.3).abs() < 1e-6 && (fx - 1.0).abs() < 1e-12, "{x}");
        // decreasing on the whole interval: the upper end
        let (x, _) = golden_section(|x| Ok(-x), -2.0, 1.0).unwrap();
        assert_eq!(x, 1.0);
        // failures count as +inf
        let (x, _) = golden_section(
            |x| {
                if x < 0.5 {
                    Err(FitError::Option("no".into()))
                } else {
                    Ok(x)
                }
            },
            0.0,
            1.0,
        )
        .unwrap();
        assert!((x - 0.5).abs() < 1e-6, "{x}");
        assert!(golden_section(|_| Err(FitError::Option("no".into())), 0.0, 1.0).is_err());
    }

    #[test]
    fn open_ends_move_inward() {
        let r = Range {
            lo: Bound::Open(0, 1),
            hi: Bound::Open(2, 1),
        };
        assert_eq!(search_interval(&r).unwrap(), (0.002, 1.998));
        assert_eq!(
            search_interval(&Range::closed((-2, 1), (1, 1))).unwrap(),
            (-2.0, 1.0)
        );
        assert!(search_interval(&Range::ALL).is_err());
    }
}
