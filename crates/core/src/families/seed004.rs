//! Seed `004_338937ef11bf75e2.txt` (Dube & Mishra 2016, EH B-spline),
//! polynomial variable `t ∈ [0, 1]`.

use crate::scalar::Ring;

/// EH bases (1):
/// `b₀ = 1 + (λ−3)t² + 2(1−λ)t³ + λt⁴`, `b₁ = (3−λ)t² + 2(λ−1)t³ − λt⁴`,
/// `b₂ = t + (μ−2)t² + (1−2μ)t³ + μt⁴`, `b₃ = −(μ+1)t² + (1+2μ)t³ − μt⁴`.
pub fn eh<T: Ring>(t: &T, lambda: &T, mu: &T) -> [T; 4] {
    let one = t.int(1);
    let two = t.int(2);
    let three = t.int(3);
    let (t2, t3, t4) = (t.square(), t.powi(3), t.powi(4));
    let b0 = one.clone()
        + &((lambda.clone() - &three) * &t2)
        + &(two.clone() * &(one.clone() - lambda) * &t3)
        + &(lambda.clone() * &t4);
    let b1 = (three - lambda) * &t2 + &(two.clone() * &(lambda.clone() - &one) * &t3)
        - &(lambda.clone() * &t4);
    let b2 = t.clone()
        + &((mu.clone() - &two) * &t2)
        + &((one.clone() - &(two.clone() * mu)) * &t3)
        + &(mu.clone() * &t4);
    let b3 = -((mu.clone() + &one) * &t2) + &((one + &(two * mu)) * &t3) - &(mu.clone() * &t4);
    [b0, b1, b2, b3]
}

/// Standard cubic Hermite bases (section II):
/// `α₀ = 1 − 3t² + 2t³`, `α₁ = 3t² − 2t³`, `β₀ = t − 2t² + t³`, `β₁ = −t² + t³`.
pub fn hermite<T: Ring>(t: &T) -> [T; 4] {
    let (t2, t3) = (t.square(), t.powi(3));
    let two = t.int(2);
    let three = t.int(3);
    [
        t.int(1) - &(three.clone() * &t2) + &(two.clone() * &t3),
        three * &t2 - &(two.clone() * &t3),
        t.clone() - &(two * &t2) + &t3,
        t3 - &t2,
    ]
}
