//! The [`Basis`] abstraction: anything that evaluates a list of basis
//! functions generically over a [`Ring`] — the catalog's [`Family`](crate::Family) or a
//! basis read from a spec file (crate `trig-specfile`). Derivative tables, jets
//! and the audit's checkers take `impl Basis`, so a user-supplied basis runs
//! through the same machinery as the catalog: one evaluator.

use rug::Rational;

use crate::domain::{Affine, Domain};
use crate::error::{CoreError, Result};
use crate::param::{Parameter, read_params};
use crate::scalar::{Real, Ring};
use crate::variable::{Atoms, Variable};

/// What a report or a command states about a basis — id, citation,
/// domain, parameters with their published ranges, function names: the
/// metadata side of [`Basis`], object-safe (`&dyn Described`). Catalog
/// families and spec files implement it alike, so every command and every
/// judge reads a basis through it and never asks where it came from.
pub trait Described {
    /// Stable id used in reports and error messages.
    fn id(&self) -> String;

    /// One-line title (may be empty).
    fn title(&self) -> String;

    /// Where the formulas are printed.
    fn citation(&self) -> String;

    /// The domain `x ∈ [a, b]` and the atoms the formulas are written in.
    fn domain(&self) -> Domain;

    /// The catalog variable the basis is written in (`u ∈ [0, 1]` with
    /// `θ = πu/2`, the angle, a polynomial `t`), when it is one of them:
    /// their derivative conventions (angle, `u`, `x`) apply.
    fn variable(&self) -> Option<Variable>;

    /// The variable's name in formulas and reports (`u`, `t`, `x`).
    fn variable_name(&self) -> String;

    /// The shape parameters, in evaluation order, with their published
    /// ranges.
    fn parameters(&self) -> Vec<Parameter>;

    /// ASCII names of the shape parameters, in evaluation order.
    fn param_names(&self) -> Vec<String> {
        self.parameters().into_iter().map(|p| p.name).collect()
    }

    /// Names of the functions, in order.
    fn function_names(&self) -> Vec<String>;

    /// True when the functions are the segments of a uniform B-spline
    /// basis function (piece `k` is function `n − 1 − k`).
    fn piecewise(&self) -> bool {
        false
    }

    /// Reads `name=value` pairs (name or printed symbol) into exact values
    /// in parameter order, checking the published ranges unless
    /// `allow_outside`.
    fn params_from_pairs(
        &self,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> Result<Vec<Affine>> {
        read_params(&self.id(), &self.parameters(), pairs, allow_outside)
    }
}

/// A described basis of functions `b₀ … b_{n−1}` in one variable with
/// shape parameters, evaluated once generically (f64, MPFR, jets, the
/// exact ring).
pub trait Basis: Described {
    /// Every function at the atoms `x` (`s = sin θ`, `c = cos θ`, `t`) with
    /// parameters `p` in the order of [`Described::param_names`].
    ///
    /// # Panics
    /// May panic if `p` has the wrong length or the basis has no formulas;
    /// callers validate first.
    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T>;
}

impl<D: Described + ?Sized> Described for &D {
    fn id(&self) -> String {
        (**self).id()
    }

    fn title(&self) -> String {
        (**self).title()
    }

    fn citation(&self) -> String {
        (**self).citation()
    }

    fn domain(&self) -> Domain {
        (**self).domain()
    }

    fn variable(&self) -> Option<Variable> {
        (**self).variable()
    }

    fn variable_name(&self) -> String {
        (**self).variable_name()
    }

    fn parameters(&self) -> Vec<Parameter> {
        (**self).parameters()
    }

    fn param_names(&self) -> Vec<String> {
        (**self).param_names()
    }

    fn function_names(&self) -> Vec<String> {
        (**self).function_names()
    }

    fn piecewise(&self) -> bool {
        (**self).piecewise()
    }

    fn params_from_pairs(
        &self,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> Result<Vec<Affine>> {
        (**self).params_from_pairs(pairs, allow_outside)
    }
}

impl<B: Basis + ?Sized> Basis for &B {
    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        (**self).eval(x, p)
    }
}

/// Every function of `basis` at the point `x` of its variable with the
/// exact parameters `p`, with typed errors: a wrong number of parameters, a
/// point outside the domain (unless `allow_outside`), a non-finite value
/// (a divisor that vanishes there).
pub fn eval_at<B: Basis + ?Sized, T: Real>(
    basis: &B,
    x: &T,
    p: &[Rational],
    allow_outside: bool,
) -> Result<Vec<T>> {
    let expected = basis.param_names().len();
    if p.len() != expected {
        return Err(CoreError::Count {
            what: format!("parameters of `{}`", basis.id()),
            expected,
            got: p.len(),
        });
    }
    let params: Vec<T> = p.iter().map(|q| x.rational(q)).collect();
    let domain = basis.domain();
    domain.check_point(x, &params, allow_outside)?;
    let values = basis.eval(&domain.atoms(x), &params);
    if values.iter().any(|v| !v.is_finite()) {
        return Err(CoreError::DivisionByZero {
            quantity: format!("`{}` at this point", basis.id()),
        });
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::family::Family;

    fn first_value<B: Basis>(basis: B) -> f64 {
        let atoms = Atoms {
            s: 0.0,
            c: 1.0,
            t: 0.0,
            e: 1.0,
        };
        basis.eval(&atoms, &[0.5])[0]
    }

    /// Through the blanket `impl Basis for &B`.
    fn first_value_by_ref<B: Basis>(basis: &B) -> f64 {
        first_value(basis)
    }

    #[test]
    fn family_and_reference_delegate_to_the_catalog() {
        let f = Family::ThesisCubic;
        assert_eq!(f.id(), "thesis-cubic");
        assert_eq!(
            f.domain(),
            Domain::from_variable(Variable::UnitAngle, &["m"])
        );
        assert_eq!(f.param_names(), vec!["m"]);
        assert_eq!(f.function_names(), vec!["b0", "b1", "b2", "b3"]);
        // b₀(u = 0) = 1 both by value and by reference
        assert_eq!(first_value(f), 1.0);
        assert_eq!(first_value_by_ref(&f), 1.0);
        assert_eq!(first_value(Family::Han), 1.0);
    }
}
