//! Seed `000_7005c3bc62610462.txt` (Majeed et al. 2020, cubic trigonometric
//! B-spline with shape parameter `ζ`, also printed `ξ`).

use crate::scalar::Ring;

/// `s(ξ) = ξ² − ξ + 1` (Appendix B).
pub fn s_of_xi<T: Ring>(xi: &T) -> T {
    xi.square() - xi + &xi.int(1)
}

/// The four blending functions (4), angle `t ∈ [0, π/2]`:
///
/// `l₀ = (1−sin t)²(s(ξ) − sin t)`, `l₁ = (1+cos t)²(s(ξ) + cos t)`,
/// `l₂ = (1+sin t)²(s(ξ) + sin t)`, `l₃ = (1−cos t)²(s(ξ) − cos t)`.
pub fn blending<T: Ring>(s: &T, c: &T, xi: &T) -> [T; 4] {
    let one = s.int(1);
    let k = s_of_xi(xi);
    [
        (one.clone() - s).square() * &(k.clone() - s),
        (one.clone() + c).square() * &(k.clone() + c),
        (one.clone() + s).square() * &(k.clone() + s),
        (one - c).square() * &(k - c),
    ]
}

/// The normaliser of Appendix A: `6ζ² − 6ζ + 10`.
pub fn uniform_normaliser<T: Ring>(xi: &T) -> T {
    xi.square() * &xi.int(6) - &(xi.clone() * &xi.int(6)) + &xi.int(10)
}

/// Uniform case as in Appendix A (A1): `F_k = l_k / (6ζ² − 6ζ + 10)`, the four
/// functions that are nonzero on one knot interval, in the order of (5).
pub fn uniform<T: Ring>(s: &T, c: &T, xi: &T) -> [T; 4] {
    let d = uniform_normaliser(xi);
    blending(s, c, xi).map(|l| l / &d)
}
