//! The cost bound of one formula lowered into the exact ring [`Sym`]: every
//! intermediate value has at most [`MAX_TERMS`] terms, total degree
//! [`MAX_DEGREE`] and coefficients of at most [`MAX_BITS`] bits, and the
//! multiplications of one formula (powers included) at most [`MAX_WORK`]
//! term products — checked before each product is formed, so a hostile
//! formula (`((2^64)^64)^64`, `((1 + s)^64)^64`) is refused, not expanded.

use std::cell::Cell;

use rug::Rational;
use trig_symbolic::Sym;

use crate::error::FormulaError;

/// Most terms of any intermediate value (numerator and denominator factors).
pub const MAX_TERMS: usize = 4_000;
/// Highest total degree of any intermediate value.
pub const MAX_DEGREE: u64 = 128;
/// Most term products (`|a|·|b|` per multiplication) of one formula.
pub const MAX_WORK: u64 = 20_000_000;
/// Most significant bits of a number (numerator or denominator of a
/// coefficient) in any intermediate value.
pub const MAX_BITS: u32 = 65_536;

/// The work spent so far on one formula.
#[derive(Debug, Default)]
pub(crate) struct Budget {
    /// Term products spent so far.
    work: Cell<u64>,
}

/// `(terms, degree)` of an exact value: numerator and denominator factors.
fn size(x: &Sym) -> (usize, u64) {
    let num = x.numerator();
    x.denominator()
        .iter()
        .fold((num.len(), num.total_degree()), |(t, d), (f, e)| {
            (t + f.len(), d + f.total_degree() * u64::from(*e))
        })
}

/// The most significant bits of a number in `q`'s numerator or denominator.
pub(crate) fn bits(q: &Rational) -> u32 {
    q.numer()
        .significant_bits()
        .max(q.denom().significant_bits())
}

/// The most bits of any coefficient of an exact value.
fn coefficient_bits(x: &Sym) -> u32 {
    std::iter::once(x.numerator())
        .chain(x.denominator().keys())
        .flat_map(|p| p.terms().map(|(_, q)| q.significant_bits()))
        .max()
        .unwrap_or(0)
}

/// The error of a number larger than [`MAX_BITS`] formed at `pos`.
pub(crate) fn too_large(pos: usize) -> FormulaError {
    FormulaError::new(pos, format!("a number here would exceed {MAX_BITS} bits"))
}

impl Budget {
    /// Checks the bounds of an intermediate value (formed at `pos`).
    pub(crate) fn bounded(&self, x: Sym, pos: usize) -> Result<Sym, FormulaError> {
        if coefficient_bits(&x) > MAX_BITS {
            return Err(too_large(pos));
        }
        let (terms, degree) = size(&x);
        if terms > MAX_TERMS || degree > MAX_DEGREE {
            return Err(FormulaError::new(
                pos,
                format!(
                    "the formula is too large here: an intermediate value has {terms} terms and degree {degree} (limits {MAX_TERMS} terms, degree {MAX_DEGREE})"
                ),
            ));
        }
        Ok(x)
    }

    /// `a·b`, after charging its cost and checking the degree bound.
    pub(crate) fn product(&self, a: &Sym, b: &Sym, pos: usize) -> Result<Sym, FormulaError> {
        let ((ta, da), (tb, db)) = (size(a), size(b));
        if da + db > MAX_DEGREE {
            return Err(FormulaError::new(
                pos,
                format!(
                    "the formula's degree would exceed {MAX_DEGREE} here (degrees {da} and {db})"
                ),
            ));
        }
        // a coefficient of a·b has about the bits of the two factors' largest
        if u64::from(coefficient_bits(a)) + u64::from(coefficient_bits(b)) > u64::from(MAX_BITS) {
            return Err(too_large(pos));
        }
        let spent = self.work.get() + (ta as u64).max(1) * (tb as u64).max(1);
        if spent > MAX_WORK {
            return Err(FormulaError::new(
                pos,
                format!(
                    "the formula is too costly to expand exactly (more than {MAX_WORK} term products); simplify it"
                ),
            ));
        }
        self.work.set(spent);
        self.bounded(a.clone() * b, pos)
    }
}
