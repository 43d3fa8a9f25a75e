//! Work units: a deterministic measure of arithmetic work, so that every
//! budget of a certified computation is counted, never timed — the same
//! input gets the same output on any machine, at any load.
//!
//! Every rounded operation of an [`crate::Interval`] charges the units of
//! its precision to the current thread: `4 + ℓ·⌊√ℓ⌋` for `ℓ` 64-bit limbs
//! (a fixed cost per operation, then the growth of MPFR's multiplication
//! between schoolbook and FFT sizes: 5 units at 64 bits, 32,772 at
//! 65,536; measured at 3·10⁷–1.4·10⁸ units per second, BENCHMARKS.md),
//! and sine, cosine and exponential
//! [`TRANSCENDENTAL`] times that. A computation's cost is what it charged
//! ([`measure`]); the cost of the same work at a higher precision is
//! predicted by [`scale`].

use std::cell::Cell;

thread_local! {
    static SPENT: Cell<u64> = const { Cell::new(0) };
}

/// Units of one sine, cosine or exponential relative to one operation.
pub const TRANSCENDENTAL: u64 = 16;

/// The units of one rounded operation at `bits`.
pub fn op_units(bits: u32) -> u64 {
    let limbs = u64::from(bits.div_ceil(64).max(1));
    4 + limbs * limbs.isqrt()
}

/// Charges `units` to the current thread.
pub fn charge(units: u64) {
    SPENT.with(|s| s.set(s.get().saturating_add(units)));
}

/// Units charged on this thread so far.
pub fn spent() -> u64 {
    SPENT.with(Cell::get)
}

/// `f()` and the units it charged.
pub fn measure<R>(f: impl FnOnce() -> R) -> (R, u64) {
    let before = spent();
    let r = f();
    (r, spent().saturating_sub(before))
}

/// The predicted units of work that cost `units` at `from` bits when done
/// at `to` bits (the same operations, each at the new price).
pub fn scale(units: u64, from: u32, to: u32) -> u64 {
    let (a, b) = (op_units(from), op_units(to));
    (u128::from(units) * u128::from(b) / u128::from(a)).min(u128::from(u64::MAX)) as u64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Interval;
    use rug::Rational;

    #[test]
    fn interval_arithmetic_charges_deterministic_units() {
        let run = |bits: u32| {
            measure(|| {
                let x = Interval::from_rational(bits, &Rational::from((1, 3)));
                let y = x.clone() * &x + &x;
                crate::Real::sin_cos(&y)
            })
            .1
        };
        assert_eq!(op_units(64), 5);
        assert_eq!(op_units(65_536), 32_772);
        let (a, b) = (run(64), run(4096));
        assert!(a > 0);
        assert_eq!(a, run(64), "the same work, the same units");
        assert_eq!(b, scale(a, 64, 4096));
    }
}
