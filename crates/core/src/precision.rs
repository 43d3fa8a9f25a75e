//! The working precisions of certified evaluation, and the sign of an
//! exact real `q₀ + q_π·π` decided by climbing them.

use std::cmp::Ordering;

use rug::Rational;

use crate::domain::Affine;
use crate::error::{CoreError, Result};
use crate::interval::Interval;

/// The highest working precision, in bits (about 19,700 decimal digits).
pub const MAX_BITS: u32 = 1 << 16;

/// The smallest working precision.
pub(crate) const MIN_BITS: u32 = 64;

/// The sign of the exact real `a = q₀ + q_π·π` (no parameters): exact when
/// `q_π = 0` (or both vanish), else by enclosures of increasing precision
/// (π is irrational, so a nonzero value is decided).
pub fn affine_sign(a: &Affine) -> Result<Ordering> {
    if a.pi == 0 {
        return Ok(a.constant.cmp0());
    }
    let mut bits = MIN_BITS;
    loop {
        let zero = Interval::from_rational(bits, &Rational::new());
        if let Some(order) = a.eval(&zero, &[]).partial_cmp(&zero) {
            return Ok(order);
        }
        if bits >= MAX_BITS {
            return Err(CoreError::Undecidable {
                what: format!("the sign of {}", a.text(&[])),
                bits,
            });
        }
        bits = bits.saturating_mul(2).min(MAX_BITS);
    }
}
