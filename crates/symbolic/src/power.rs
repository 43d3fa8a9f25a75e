//! Powers by repeated squaring, for every type of the ring.

/// `xⁿ` from `one` and the product `mul`: `⌊log₂ n⌋` squarings and one
/// product per set bit of `n`.
pub(crate) fn by_squaring<T: Clone>(x: &T, n: u32, one: T, mul: impl Fn(&T, &T) -> T) -> T {
    let (mut result, mut base, mut e) = (one, x.clone(), n);
    while e > 0 {
        if e & 1 == 1 {
            result = mul(&result, &base);
        }
        e >>= 1;
        if e > 0 {
            base = mul(&base, &base);
        }
    }
    result
}
