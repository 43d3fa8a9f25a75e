//! Knot vectors: validation and span lookup.

use rug::Rational;

use crate::error::{CoreError, Result};
use crate::scalar::Real;

/// Checks that `knots` has at least `min_len` finite, strictly increasing
/// entries (no zero-length interval).
pub fn check_knots<T: Real>(knots: &[T], min_len: usize) -> Result<()> {
    if let Some(i) = knots.iter().position(|k| !k.is_finite()) {
        return Err(CoreError::Knots(format!("knot n_{i} is not finite")));
    }
    check_increasing(knots, min_len, |i| knots[i].to_f64().to_string())
}

/// Checks that `knots` has at least `min_len` strictly increasing entries;
/// `show(i)` prints knot `i` in the message (exact knots: as typed).
pub fn check_increasing<T: PartialOrd>(
    knots: &[T],
    min_len: usize,
    show: impl Fn(usize) -> String,
) -> Result<()> {
    if knots.len() < min_len {
        return Err(CoreError::Knots(format!(
            "need at least {min_len} knots, got {}",
            knots.len()
        )));
    }
    for (i, w) in knots.windows(2).enumerate() {
        if w[1] <= w[0] {
            let what = if w[1] == w[0] {
                "a zero-length interval"
            } else {
                "decreasing"
            };
            return Err(CoreError::Knots(format!(
                "n_{} = {} and n_{} = {}: {what}",
                i,
                show(i),
                i + 1,
                show(i + 1)
            )));
        }
    }
    Ok(())
}

/// The span `i` with `knots[i] ≤ x < knots[i+1]` (the last span is closed on
/// the right), and the local coordinate `(x − knots[i])/(knots[i+1] − knots[i]) ∈ [0, 1]`.
pub fn locate<T: Real>(knots: &[T], x: &T) -> Result<(usize, T)> {
    let last = knots.len() - 1;
    if !x.is_finite() {
        return Err(CoreError::NotFinite {
            what: "the evaluation point".into(),
        });
    }
    if *x < knots[0] || *x > knots[last] {
        return Err(CoreError::PointOutsideDomain {
            value: format!("{}", x.to_f64()),
            domain: format!("[{}, {}]", knots[0].to_f64(), knots[last].to_f64()),
        });
    }
    let i = knots[1..last].iter().take_while(|k| **k <= *x).count();
    let local = (x.clone() - &knots[i]) / &(knots[i + 1].clone() - &knots[i]);
    Ok((i, local))
}

/// The span `i` with `knots[i] ≤ x < knots[i+1]` (the last span closed)
/// and the exact local coordinate, for strictly increasing exact knots;
/// `input` is the point as printed in the error.
pub fn locate_exact(knots: &[Rational], x: &Rational, input: &str) -> Result<(usize, Rational)> {
    let last = knots.len() - 1;
    if *x < knots[0] || *x > knots[last] {
        return Err(CoreError::PointOutsideDomain {
            value: input.to_string(),
            domain: format!("[{}, {}]", knots[0], knots[last]),
        });
    }
    let i = knots[1..last].iter().take_while(|k| *k <= x).count();
    let local = Rational::from(x - &knots[i]) / Rational::from(&knots[i + 1] - &knots[i]);
    Ok((i, local))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_knot_vectors() {
        assert!(check_knots(&[0.0, 1.0, 2.0], 2).is_ok());
        assert!(check_knots(&[0.0, 1.0, 1.0], 2).is_err());
        assert!(check_knots(&[0.0, 2.0, 1.0], 2).is_err());
        assert!(check_knots(&[0.0, f64::NAN], 2).is_err());
        assert!(check_knots::<f64>(&[], 2).is_err());
    }

    #[test]
    fn locates_spans_with_closed_last_span() {
        let k = [0.0, 1.0, 3.0];
        assert_eq!(locate(&k, &0.5).unwrap(), (0, 0.5));
        assert_eq!(locate(&k, &1.0).unwrap(), (1, 0.0));
        assert_eq!(locate(&k, &3.0).unwrap(), (1, 1.0));
        assert!(locate(&k, &3.5).is_err());
    }
}
