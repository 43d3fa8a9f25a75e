//! `f64` as a [`Ring`] and [`Real`].

use crate::scalar::{Real, Ring};

impl Ring for f64 {
    fn int(&self, n: i64) -> Self {
        n as f64
    }

    fn ratio(&self, num: i64, den: i64) -> Self {
        // Both operands exact (|n| ≤ 2⁵³) ⇒ one IEEE division is the correctly
        // rounded quotient; otherwise round the exact rational once.
        const EXACT: u64 = 1 << 53;
        if num.unsigned_abs() <= EXACT && den.unsigned_abs() <= EXACT {
            num as f64 / den as f64
        } else {
            rug::Rational::from((num, den)).to_f64()
        }
    }

    fn rational(&self, q: &rug::Rational) -> Self {
        q.to_f64()
    }

    fn pi(&self) -> Self {
        std::f64::consts::PI
    }

    fn is_zero(&self) -> bool {
        *self == 0.0
    }

    fn try_sin_cos(&self) -> Option<(Self, Self)> {
        Some(Real::sin_cos(self))
    }

    fn try_exp(&self) -> Option<Self> {
        Some(Real::exp(self))
    }

    fn try_sqrt(&self) -> Option<Self> {
        (*self >= 0.0).then(|| f64::sqrt(*self))
    }
}

impl Real for f64 {
    fn sin_cos(&self) -> (Self, Self) {
        f64::sin_cos(*self)
    }

    fn exp(&self) -> Self {
        f64::exp(*self)
    }

    fn to_f64(&self) -> f64 {
        *self
    }

    fn is_finite(&self) -> bool {
        f64::is_finite(*self)
    }

    fn to_rational(&self) -> Option<rug::Rational> {
        rug::Rational::from_f64(*self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_exact_where_representable() {
        let x = 0.25_f64;
        assert_eq!(x.int(3), 3.0);
        assert_eq!(x.ratio(1, 4), 0.25);
        assert_eq!(x.ratio(1, 3), 1.0 / 3.0);
        assert_eq!(x.powi(3), 0.015625);
    }
}
