//! The [`Basis`] abstraction: anything that evaluates a list of basis
//! functions generically over a [`Ring`] — the catalog's [`Family`] or a
//! basis read from a spec file (crate `trig-specfile`). Derivative tables, jets
//! and the audit's checkers take `impl Basis`, so a user-supplied basis runs
//! through the same machinery as the catalog: one evaluator.

use crate::domain::Domain;
use crate::scalar::Ring;
use crate::variable::Atoms;

/// A basis of functions `b₀ … b_{n−1}` in one [`Variable`] with shape
/// parameters, evaluated once generically (f64, MPFR, jets, the exact ring).
pub trait Basis {
    /// Stable id used in reports and error messages.
    fn id(&self) -> String;

    /// The domain `x ∈ [a, b]` and the atoms the formulas are written in.
    fn domain(&self) -> Domain;

    /// ASCII names of the shape parameters, in evaluation order.
    fn param_names(&self) -> Vec<String>;

    /// Names of the functions, in order.
    fn function_names(&self) -> Vec<String>;

    /// Every function at the atoms `x` (`s = sin θ`, `c = cos θ`, `t`) with
    /// parameters `p` in the order of [`Basis::param_names`].
    ///
    /// # Panics
    /// May panic if `p` has the wrong length or the basis has no formulas;
    /// callers validate first.
    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T>;
}

impl<B: Basis + ?Sized> Basis for &B {
    fn id(&self) -> String {
        (**self).id()
    }

    fn domain(&self) -> Domain {
        (**self).domain()
    }

    fn param_names(&self) -> Vec<String> {
        (**self).param_names()
    }

    fn function_names(&self) -> Vec<String> {
        (**self).function_names()
    }

    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        (**self).eval(x, p)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::family::Family;
    use crate::variable::Variable;

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
