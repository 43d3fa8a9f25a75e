//! # trig-specfile
//!
//! Bring your own basis: a spec file (TOML) states a published basis — its
//! id and citation, the variable (`u ∈ [0, 1]` with angle `θ = πu/2`, the
//! angle `t ∈ [0, π/2]`, or a polynomial variable `t ∈ [0, 1]`), the shape
//! parameters with their published ranges, the functions as formulas, and
//! the claims the paper prints. Formulas are parsed into the exact ring
//! [`trig_symbolic::Sym`]; a [`Spec`] implements [`trig_core::Basis`], so
//! derivative tables, jets, f64/MPFR evaluation and the audit run through
//! the same machinery as the built-in catalog. The format is documented in
//! `docs/spec.md`.
//!
//! ```
//! use trig_specfile::Spec;
//! let spec = Spec::from_str_named(r#"
//! id = "bernstein2"
//! citation = "textbook"
//! variable = "polynomial"
//! [[functions]]
//! name = "B0"
//! formula = "(1 - t)^2"
//! [[functions]]
//! name = "B1"
//! formula = "2*t*(1 - t)"
//! [[functions]]
//! name = "B2"
//! formula = "t^2"
//! "#, "inline").unwrap();
//! let v = spec.eval_at(&0.5_f64, &[], false).unwrap();
//! assert_eq!(v, vec![0.25, 0.5, 0.25]);
//! ```

mod any;
mod ast;
mod budget;
pub mod check;
mod claims;
mod curvature_read;
pub mod data_query;
mod derivative_read;
mod direction_read;
pub mod document;
pub mod error;
pub mod exact_range;
mod expression;
mod fields;
pub mod formula;
pub mod frequencies;
pub mod given;
mod given_read;
mod identity_read;
mod join_read;
pub mod knots;
mod listing;
mod load;
mod names;
mod nonnegative_read;
pub mod nonvanishing;
mod property_read;
mod raw;
mod region_read;
mod source;
pub mod spec;

pub use any::{AnyBasis, OpenError};
pub use ast::Grammar;
pub use check::Continuous;
pub use check::Correction;
pub use check::Margin;
pub use check::{
    Across, Application, Applied, Argument, Change, Check, ClaimFigure, Condition, Curve,
    Differentiated, Direction, Identity, JoinSegments, Let, ListedNet, Monotone, NamedCurve,
    Polygons, Printed, PrintedDerivative, Quantifier, RationalCurve, Reading, Seam, SpecClaim,
    Target, Varied, WeightedCurve,
};
pub use check::{Between, Fixed, Given};
pub use document::{DocumentClaim, DocumentFile, Part};
pub use error::{FormulaError, Location, SpecError};
pub use exact_range::{ExactEnd, ExactRange};
pub use expression::Expression;
pub use given::GivenError;
pub use spec::{Spec, SpecFunction};

use rug::Rational;
use trig_core::{Atoms, Basis, CoreError, Described, Domain, Parameter, Real, Ring, Variable};
use trig_symbolic::Sym;

impl Described for Spec {
    fn id(&self) -> String {
        self.id.clone()
    }

    fn title(&self) -> String {
        self.title.clone()
    }

    fn citation(&self) -> String {
        self.citation.clone()
    }

    fn domain(&self) -> Domain {
        self.domain.clone()
    }

    fn variable(&self) -> Option<Variable> {
        self.legacy
    }

    fn variable_name(&self) -> String {
        self.var_name.clone()
    }

    fn parameters(&self) -> Vec<Parameter> {
        self.params.clone()
    }

    fn function_names(&self) -> Vec<String> {
        self.functions.iter().map(|f| f.name.clone()).collect()
    }

    /// As the file declares (`piecewise = true`).
    fn piecewise(&self) -> bool {
        self.piecewise
    }
}

impl Basis for Spec {
    /// Each function's exact value evaluated in the ring of the atoms
    /// (numerator and denominator factors through [`trig_symbolic::Poly::eval`],
    /// then one division with the ring's own semantics: IEEE values in
    /// floating rings, which [`Spec::eval_at`] turns into typed errors).
    /// The atoms of parameters (`sin(α/2)`, `exp(β)`) and radicals are
    /// formed in the ring from the parameter values.
    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        assert_eq!(p.len(), self.params.len(), "parameter count");
        let atoms = trig_certify::atoms::param_atoms(&self.domain);
        let assign = |name: &str| trig_certify::atoms::value(name, &self.domain, x, p, &atoms);
        self.functions
            .iter()
            .map(|f| eval_sym(&f.value, &x.t, &assign))
            .collect()
    }
}

/// `x` in the ring of `like`: numerator over the product of its
/// denominator factors.
fn eval_sym<T: Ring>(x: &Sym, like: &T, assign: &dyn Fn(&str) -> Option<T>) -> T {
    let bound = "spec formulas use only the variable, the parameters and pi (validated when read)";
    let num = x.numerator().eval(like, assign).expect(bound);
    let den = x.denominator().iter().fold(like.int(1), |acc, (f, e)| {
        acc * &f.eval(like, assign).expect(bound).powi(*e)
    });
    num / &den
}

impl Spec {
    /// Every function at a point of the native variable, with typed errors
    /// for points outside the domain (unless `allow_outside`) and for
    /// non-finite results.
    pub fn eval_at<T: Real>(
        &self,
        x: &T,
        p: &[Rational],
        allow_outside: bool,
    ) -> Result<Vec<T>, CoreError> {
        trig_core::basis::eval_at(self, x, p, allow_outside)
    }

    /// The functions as exact values with the parameters as symbols.
    pub fn symbolic(&self) -> Vec<Sym> {
        self.functions.iter().map(|f| f.value.clone()).collect()
    }
}
