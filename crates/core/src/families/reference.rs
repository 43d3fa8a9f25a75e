//! Textbook references for comparison: cubic Bernstein and the uniform cubic
//! B-spline (e.g. Farin, *Curves and Surfaces for CAGD*, §§ 4 and 7).

use crate::scalar::Ring;

/// Cubic Bernstein polynomials `(1−t)³, 3t(1−t)², 3t²(1−t), t³`.
pub fn bernstein3<T: Ring>(t: &T) -> [T; 4] {
    let omt = t.int(1) - t;
    let three = t.int(3);
    [
        omt.powi(3),
        three.clone() * t * &omt.square(),
        three * &t.square() * &omt,
        t.powi(3),
    ]
}

/// The four uniform cubic B-spline segment functions on one knot interval:
/// `(1−t)³/6`, `(3t³ − 6t² + 4)/6`, `(−3t³ + 3t² + 3t + 1)/6`, `t³/6`.
pub fn bspline3<T: Ring>(t: &T) -> [T; 4] {
    let sixth = t.ratio(1, 6);
    let (t2, t3) = (t.square(), t.powi(3));
    [
        (t.int(1) - t).powi(3) * &sixth,
        (t3.clone() * &t.int(3) - &(t2.clone() * &t.int(6)) + &t.int(4)) * &sixth,
        (-(t3.clone() * &t.int(3)) + &(t2 * &t.int(3)) + &(t.clone() * &t.int(3)) + &t.int(1))
            * &sixth,
        t3 * &sixth,
    ]
}
