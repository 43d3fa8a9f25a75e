//! Seed `002_a40e75c8fd798756.txt` (Dube & Mishra 2017, quartic
//! trigonometric Bézier basis), Definition 1, eq. (1), `t ∈ [0, π/2]`.

use crate::scalar::Ring;

/// `b₀ = (1−s)⁴`, `b₁ = 4s(1−s)³`, `b₂ = (1−s)²(1−c)(9+8s+3c)`,
/// `b₃ = (1−s)(1−c)²(9+3s+8c)`, `b₄ = 4c(1−c)³`, `b₅ = (1−c)⁴`.
pub fn quartic<T: Ring>(s: &T, c: &T) -> [T; 6] {
    let one = s.int(1);
    let four = s.int(4);
    let nine = s.int(9);
    let oms = one.clone() - s;
    let omc = one - c;
    [
        oms.powi(4),
        four.clone() * s * &oms.powi(3),
        oms.square() * &omc * &(nine.clone() + &(s.int(8) * s) + &(s.int(3) * c)),
        oms.clone() * &omc.square() * &(nine + &(s.int(3) * s) + &(s.int(8) * c)),
        four * c * &omc.powi(3),
        omc.powi(4),
    ]
}
