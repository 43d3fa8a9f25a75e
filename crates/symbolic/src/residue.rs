//! Residues modulo the prime `p = 2³¹ − 1`.
//!
//! Reduction modulo `p` is a ring homomorphism from the rationals whose
//! denominators `p` does not divide onto `𝔽_p`. So when two rational
//! functions are evaluated at one rational point, every denominator met is
//! nonzero modulo `p` and the two images differ, the two values differ —
//! a proof, at the cost of word arithmetic instead of growing fractions.
//! Equal images prove nothing; an undefined image ([`None`]) neither.

use std::ops::{Add, Mul, Neg, Sub};

use rug::Rational;

use crate::coef::Coef;

/// The prime `2³¹ − 1`: products of residues fit in `u64`.
pub(crate) const P: u64 = 2_147_483_647;

/// An element of `𝔽_p`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Residue(u64);

impl Residue {
    /// Zero.
    pub const ZERO: Residue = Residue(0);

    /// The image of `q`, or `None` when `p` divides its denominator.
    pub fn of(q: &Rational) -> Option<Residue> {
        Residue::fraction(
            u64::from(q.numer().mod_u(P as u32)),
            u64::from(q.denom().mod_u(P as u32)),
        )
    }

    /// The image of a polynomial's coefficient (as [`Residue::of`]).
    pub fn of_coef(q: &Coef) -> Option<Residue> {
        match q.small() {
            Some((n, d)) => Residue::fraction(n.rem_euclid(P as i64) as u64, d % P),
            None => Residue::of(&q.to_rational()),
        }
    }

    /// `num/den` from the residues of a numerator and a denominator
    /// (`None` when the denominator's is `0`).
    fn fraction(num: u64, den: u64) -> Option<Residue> {
        match den {
            0 => None,
            1 => Some(Residue(num)),
            _ => Some(Residue(num * inverse(den) % P)),
        }
    }

    /// The representative in `0…p − 1`.
    pub fn value(self) -> u64 {
        self.0
    }

    /// True for the zero residue.
    pub fn is_zero(self) -> bool {
        self.0 == 0
    }

    pub fn pow(self, n: u32) -> Residue {
        Residue(pow(self.0, u64::from(n)))
    }

    /// `self / other`, or `None` when `other` is zero.
    pub fn checked_div(self, other: Residue) -> Option<Residue> {
        (!other.is_zero()).then(|| self * Residue(inverse(other.0)))
    }
}

impl Add for Residue {
    type Output = Residue;
    fn add(self, other: Residue) -> Residue {
        Residue((self.0 + other.0) % P)
    }
}

impl Sub for Residue {
    type Output = Residue;
    fn sub(self, other: Residue) -> Residue {
        Residue((self.0 + P - other.0) % P)
    }
}

impl Neg for Residue {
    type Output = Residue;
    fn neg(self) -> Residue {
        Residue((P - self.0) % P)
    }
}

impl Mul for Residue {
    type Output = Residue;
    fn mul(self, other: Residue) -> Residue {
        Residue(self.0 * other.0 % P)
    }
}

pub(crate) fn pow(mut base: u64, mut e: u64) -> u64 {
    let mut out = 1;
    base %= P;
    while e > 0 {
        if e & 1 == 1 {
            out = out * base % P;
        }
        base = base * base % P;
        e >>= 1;
    }
    out
}

/// `a⁻¹` for `a ≢ 0` (Fermat).
pub(crate) fn inverse(a: u64) -> u64 {
    pow(a, P - 2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn images_of_rationals() {
        let q = |a: i64, b: i64| Residue::of(&Rational::from((a, b))).unwrap();
        assert_eq!(q(1, 3) * q(3, 1), q(1, 1));
        assert_eq!(q(1, 2) + q(1, 3), q(5, 6));
        assert_eq!(q(1, 2) - q(1, 3), q(1, 6));
        assert_eq!(-q(-2, 7), q(2, 7));
        assert_eq!(q(2, 3).pow(3), q(8, 27));
        assert_eq!(q(1, 4).checked_div(q(1, 2)), Some(q(1, 2)));
        assert_eq!(q(1, 4).checked_div(q(0, 1)), None);
        // p divides the denominator: no image
        assert_eq!(Residue::of(&Rational::from((1, P))), None);
        assert!(Residue::of(&Rational::from(P)).unwrap().is_zero());
    }
}
