//! Chord-length parameterisation, thesis (6.9)–(6.10).
//!
//! As printed, `tᵢ = Σ_{r=1}^{i} DP_r / Σ_{r=1}^{N} DP_r` with
//! `DP_r = ‖P_{r+1} − P_r‖` (6.10) gives `t₁ = DP₁/…` (not 0) and needs the
//! undefined `P_{N+1}`. We use the one reading that makes the data end points
//! `P₁`, `P_N` land on `t = 0` and `t = 1`, where the fixed end control points
//! `V₀`, `V₃` are interpolated (6.11)ff.:
//!
//! `t₁ = 0`, `tᵢ = Σ_{r=1}^{i−1} DP_r / Σ_{r=1}^{N−1} DP_r`.

use crate::data::P2;

/// The chord-length parameters of a polyline, or `None` when all its
/// points coincide (zero total length).
pub fn chord_parameters(points: &[P2]) -> Option<Vec<f64>> {
    let mut t = Vec::with_capacity(points.len());
    let mut acc = 0.0;
    t.push(0.0);
    for w in points.windows(2) {
        acc += (w[1] - w[0]).norm();
        t.push(acc);
    }
    if acc <= 0.0 || !acc.is_finite() {
        return None;
    }
    for v in &mut t {
        *v /= acc;
    }
    if let Some(last) = t.last_mut() {
        // exactly 1 at the end, whatever the rounding of the sum
        *last = 1.0;
    }
    Some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_checked_parameters() {
        // chords 3, 4 (3-4-5 legs), 5: total 12
        let p = [
            P2::new(0.0, 0.0),
            P2::new(3.0, 0.0),
            P2::new(3.0, 4.0),
            P2::new(6.0, 8.0),
        ];
        assert_eq!(
            chord_parameters(&p).unwrap(),
            vec![0.0, 0.25, 7.0 / 12.0, 1.0]
        );
        assert!(chord_parameters(&[P2::new(1.0, 1.0); 3]).is_none());
    }
}
