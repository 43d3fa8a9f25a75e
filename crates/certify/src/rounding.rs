//! Outward rounding of f64 bounds: the next representable value above or
//! below, so that a bound computed in f64 stays a bound of the exact value.

/// The next f64 above a nonnegative `x` (an upper bound of the exact value
/// that `x` rounds to nearest); `+∞` stays.
pub fn up(x: f64) -> f64 {
    if x.is_nan() {
        return f64::INFINITY;
    }
    if x < 0.0 {
        return -down(-x);
    }
    if x.is_infinite() {
        return x;
    }
    f64::from_bits(x.to_bits() + 1)
}

/// The next f64 below a nonnegative `x` (`0` stays `0` for `x = 0`).
pub fn down(x: f64) -> f64 {
    if x <= 0.0 {
        return if x == 0.0 { 0.0 } else { -up(-x) };
    }
    if x.is_infinite() {
        return f64::MAX;
    }
    f64::from_bits(x.to_bits() - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn up_and_down_bracket() {
        for x in [0.0, 1.0, 1e-300, 3.5, f64::MAX] {
            assert!(up(x) > x || up(x).is_infinite());
            assert!(down(x) < x || x == 0.0);
        }
        assert_eq!(up(f64::INFINITY), f64::INFINITY);
        assert!(up(f64::NAN).is_infinite());
    }
}
