//! Derivative estimates `d_i` at the knots: the arithmetic mean method the
//! thesis names (4.3.1, "Arithmetic Mean Method from Hussain & Sarfraz
//! (2009)"), in the form used throughout Sarfraz & Hussain's
//! positivity-preserving schemes. With `h_i = x_{i+1} − x_i` and
//! `Δ_i = (f_{i+1} − f_i)/h_i`:
//!
//! * interior knots, `i = 1 … n−1`:
//!   `d_i = (h_i Δ_{i−1} + h_{i−1} Δ_i) / (h_{i−1} + h_i)`;
//! * end points:
//!   `d_0 = Δ_0 + (Δ_0 − Δ_1) h_0 / (h_0 + h_1)`,
//!   `d_n = Δ_{n−1} + (Δ_{n−1} − Δ_{n−2}) h_{n−1} / (h_{n−1} + h_{n−2})`.
//!
//! All exact (rationals in, rationals out).

use rug::Rational;

use crate::InterpError;

/// `Δ_i = (f_{i+1} − f_i)/h_i`.
pub fn differences(x: &[Rational], f: &[Rational]) -> Vec<Rational> {
    x.windows(2)
        .zip(f.windows(2))
        .map(|(x, f)| (f[1].clone() - &f[0]) / (x[1].clone() - &x[0]))
        .collect()
}

/// The arithmetic-mean estimates `d_0 … d_n` (needs at least three points).
pub fn arithmetic_mean(x: &[Rational], f: &[Rational]) -> Result<Vec<Rational>, InterpError> {
    let n = x.len().saturating_sub(1);
    if n < 2 || f.len() != x.len() {
        return Err(InterpError::Malformed(format!(
            "the arithmetic mean method needs at least 3 points with one value each (got {} abscissae, {} values)",
            x.len(),
            f.len()
        )));
    }
    let h: Vec<Rational> = x.windows(2).map(|w| w[1].clone() - &w[0]).collect();
    let delta = differences(x, f);
    let mut d = Vec::with_capacity(n + 1);
    d.push(delta[0].clone() + (delta[0].clone() - &delta[1]) * &h[0] / (h[0].clone() + &h[1]));
    for i in 1..n {
        d.push(
            (h[i].clone() * &delta[i - 1] + h[i - 1].clone() * &delta[i])
                / (h[i - 1].clone() + &h[i]),
        );
    }
    d.push(
        delta[n - 1].clone()
            + (delta[n - 1].clone() - &delta[n - 2]) * &h[n - 1] / (h[n - 1].clone() + &h[n - 2]),
    );
    Ok(d)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(v: &[i64]) -> Vec<Rational> {
        v.iter().map(|&k| Rational::from(k)).collect()
    }

    #[test]
    fn table_4_1_by_hand() {
        // Δ = 3, −1, 3, −7; d₀ = 3 + 4/2 = 5, d₁ = 1, d₂ = 1, d₃ = −2, d₄ = −7 − 10/2 = −12
        let d = arithmetic_mean(&q(&[1, 2, 3, 4, 5]), &q(&[3, 6, 5, 8, 1])).unwrap();
        assert_eq!(d, q(&[5, 1, 1, -2, -12]));
    }

    #[test]
    fn linear_data_give_the_exact_slope_and_unequal_steps_are_weighted() {
        let d = arithmetic_mean(&q(&[0, 1, 3, 7]), &q(&[1, 3, 7, 15])).unwrap();
        assert_eq!(d, q(&[2, 2, 2, 2]));
        // x = 0, 1, 3; f = 0, 1, 1: Δ = 1, 0; d₁ = (2·1 + 1·0)/3 = 2/3
        let d = arithmetic_mean(&q(&[0, 1, 3]), &q(&[0, 1, 1])).unwrap();
        assert_eq!(d[1], Rational::from((2, 3)));
        assert!(arithmetic_mean(&q(&[0, 1]), &q(&[0, 1])).is_err());
    }
}
