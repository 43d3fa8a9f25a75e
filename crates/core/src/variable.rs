//! The native variable of a family and the atoms its formulas are written in.

use std::fmt;

use crate::scalar::{Real, Ring};

/// The variable a family is printed in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Variable {
    /// `u ∈ [0, 1]` with angle `θ = πu/2` (thesis (3.1), (3.7); Han (6.2); Usman (6.3)).
    UnitAngle,
    /// The angle itself, `t ∈ [0, π/2]` (seed 000 (4), seed 002 (1), Majeed & Qayyum (6.1)).
    Angle,
    /// A polynomial variable `t ∈ [0, 1]` (seed 004, Bernstein, B-spline).
    Polynomial,
}

impl Variable {
    /// Checks an evaluation point: finite, and inside the domain unless
    /// `allow_outside`.
    pub fn check_point<T: Real>(&self, x: &T, allow_outside: bool) -> crate::error::Result<()> {
        if !x.is_finite() {
            return Err(crate::error::CoreError::NotFinite {
                what: "the evaluation point".into(),
            });
        }
        if !allow_outside && !self.contains(x) {
            return Err(crate::error::CoreError::PointOutsideDomain {
                value: format!("{}", x.to_f64()),
                domain: self.domain().into(),
            });
        }
        Ok(())
    }

    /// The variable's name in formulas: `u` or `t`.
    pub fn name(&self) -> &'static str {
        match self {
            Variable::UnitAngle => "u",
            Variable::Angle | Variable::Polynomial => "t",
        }
    }

    /// The domain as printed.
    pub fn domain(&self) -> &'static str {
        match self {
            Variable::UnitAngle => "u in [0, 1]",
            Variable::Angle => "t in [0, pi/2]",
            Variable::Polynomial => "t in [0, 1]",
        }
    }

    /// True for the trigonometric variables, whose formulas use `s = sin θ`,
    /// `c = cos θ`.
    pub fn is_trigonometric(&self) -> bool {
        !matches!(self, Variable::Polynomial)
    }

    /// The right end of the domain in the native variable.
    pub fn end<T: Ring>(&self, like: &T) -> T {
        match self {
            Variable::UnitAngle | Variable::Polynomial => like.int(1),
            Variable::Angle => like.pi() * &like.ratio(1, 2),
        }
    }

    /// `dθ/dx`: the factor by which one derivative in the native variable `x`
    /// exceeds one derivative in the angle (π/2 for `u`, 1 otherwise).
    pub fn angle_rate<T: Ring>(&self, like: &T) -> T {
        match self {
            Variable::UnitAngle => like.pi() * &like.ratio(1, 2),
            Variable::Angle | Variable::Polynomial => like.int(1),
        }
    }

    /// The atoms at a point `x` of the native variable.
    pub fn atoms<T: Real>(&self, x: &T) -> Atoms<T> {
        let theta = match self {
            Variable::UnitAngle => x.clone() * &(x.pi() * &x.ratio(1, 2)),
            Variable::Angle | Variable::Polynomial => x.clone(),
        };
        let (s, c) = theta.sin_cos();
        Atoms {
            s,
            c,
            t: x.clone(),
            e: x.int(1),
        }
    }

    /// True when `x` lies in the domain.
    pub fn contains<T: Real>(&self, x: &T) -> bool {
        let zero = x.int(0);
        *x >= zero && *x <= self.end(x)
    }
}

impl fmt::Display for Variable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.domain())
    }
}

/// The quantities a formula is written in: `s = sin θ`, `c = cos θ` for the
/// trigonometric families, `t` (the variable itself) for the polynomial
/// ones, and `e = exp(κx)` for exponential and hyperbolic bases
/// ([`crate::Domain`]; `1` where unused).
///
/// Numeric backends fill all three from a point ([`Variable::atoms`]); the
/// exact ring fills them with symbols, and jets with truncated series, so the
/// same formula serves every backend.
#[derive(Debug, Clone, PartialEq)]
pub struct Atoms<T> {
    pub s: T,
    pub c: T,
    pub t: T,
    pub e: T,
}
