//! Exact trigonometric identities in any [`Ring`]: multiple angles and
//! angle sums, used to expand `sin(kθ)`, `cos(kθ)` and `sin(θ + φ)` from
//! the atoms of one base angle, so that exact rings keep one pair of
//! atoms per angle.

use crate::scalar::Ring;

/// `(sin kθ, cos kθ)` from `s = sin θ`, `c = cos θ` for any integer `k`:
/// `sₖ = 2c·sₖ₋₁ − sₖ₋₂`, `cₖ = 2c·cₖ₋₁ − cₖ₋₂` (Chebyshev), and
/// `sin(−kθ) = −sin kθ`.
pub fn multiple_angle<T: Ring>(s: &T, c: &T, k: i64) -> (T, T) {
    let two_c = c.clone() * &c.int(2);
    let (mut s0, mut s1) = (s.int(0), s.clone());
    let (mut c0, mut c1) = (c.int(1), c.clone());
    if k == 0 {
        return (s0, c0);
    }
    for _ in 1..k.unsigned_abs() {
        let s2 = two_c.clone() * &s1 - &s0;
        let c2 = two_c.clone() * &c1 - &c0;
        (s0, s1, c0, c1) = (s1, s2, c1, c2);
    }
    if k < 0 { (-s1, c1) } else { (s1, c1) }
}

/// `(sin(a + b), cos(a + b))` from `(sin a, cos a)` and `(sin b, cos b)`.
pub fn angle_sum<T: Ring>(a: &(T, T), b: &(T, T)) -> (T, T) {
    (
        a.0.clone() * &b.1 + &(a.1.clone() * &b.0),
        a.1.clone() * &b.1 - &(a.0.clone() * &b.0),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identities_in_f64() {
        let x = 0.37_f64;
        let (s, c) = (x.sin(), x.cos());
        for k in -5..=7 {
            let (sk, ck) = multiple_angle(&s, &c, k);
            let y = k as f64 * x;
            assert!(
                (sk - y.sin()).abs() < 1e-13 && (ck - y.cos()).abs() < 1e-13,
                "k = {k}"
            );
        }
        let (sa, ca) = angle_sum(&(s, c), &(1.1_f64.sin(), 1.1_f64.cos()));
        assert!((sa - 1.47_f64.sin()).abs() < 1e-15 && (ca - 1.47_f64.cos()).abs() < 1e-15);
    }
}
