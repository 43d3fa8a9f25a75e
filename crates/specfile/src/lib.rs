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

mod ast;
pub mod claims;
pub mod error;
pub mod formula;
pub mod frequencies;
mod names;
pub mod nonvanishing;
pub mod range;
mod raw;
mod source;
pub mod spec;

pub use claims::{Check, Condition, Monotone, Printed, SpecClaim};
pub use error::{FormulaError, Location, SpecError};
pub use range::SpecRange;
pub use spec::{Spec, SpecFunction, SpecParam};

use rug::Rational;
use trig_core::{Atoms, Basis, CoreError, Domain, Real, Ring, parse_exact};
use trig_symbolic::Sym;

impl Basis for Spec {
    fn id(&self) -> String {
        self.id.clone()
    }

    fn domain(&self) -> Domain {
        self.domain.clone()
    }

    fn param_names(&self) -> Vec<String> {
        self.params.iter().map(|p| p.name.clone()).collect()
    }

    fn function_names(&self) -> Vec<String> {
        self.functions.iter().map(|f| f.name.clone()).collect()
    }

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
    /// Reads `name=value` pairs (name or printed symbol) into exact values
    /// in parameter order, checking the declared ranges unless
    /// `allow_outside`.
    pub fn params_from_pairs(
        &self,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> Result<Vec<Rational>, CoreError> {
        let expected = || {
            if self.params.is_empty() {
                "none".to_string()
            } else {
                self.param_names().join(", ")
            }
        };
        for (name, _) in pairs {
            if !self
                .params
                .iter()
                .any(|p| &p.name == name || &p.symbol == name)
            {
                return Err(CoreError::UnknownParameter {
                    family: self.id.clone(),
                    name: name.clone(),
                    expected: expected(),
                });
            }
        }
        self.params
            .iter()
            .map(|spec| {
                let (_, text) = pairs
                    .iter()
                    .rev()
                    .find(|(n, _)| *n == spec.name || *n == spec.symbol)
                    .ok_or_else(|| CoreError::MissingParameter {
                        family: self.id.clone(),
                        name: spec.name.clone(),
                    })?;
                let value = parse_exact(text)?;
                if !allow_outside && !spec.range.contains(&value) {
                    return Err(CoreError::OutOfRange {
                        family: self.id.clone(),
                        name: spec.name.clone(),
                        value: text.clone(),
                        range: spec.range.to_string(),
                    });
                }
                Ok(value)
            })
            .collect()
    }

    /// Every function at a point of the native variable, with typed errors
    /// for points outside the domain (unless `allow_outside`) and for
    /// non-finite results.
    pub fn eval_at<T: Real>(
        &self,
        x: &T,
        p: &[Rational],
        allow_outside: bool,
    ) -> Result<Vec<T>, CoreError> {
        if p.len() != self.params.len() {
            return Err(CoreError::Count {
                what: format!("parameters of `{}`", self.id),
                expected: self.params.len(),
                got: p.len(),
            });
        }
        let params: Vec<T> = p.iter().map(|q| x.rational(q)).collect();
        self.domain.check_point(x, &params, allow_outside)?;
        let values = Basis::eval(self, &self.domain.atoms(x), &params);
        if values.iter().any(|v| !v.is_finite()) {
            return Err(CoreError::DivisionByZero {
                quantity: format!("`{}` at this point", self.id),
            });
        }
        Ok(values)
    }

    /// The functions as exact values with the parameters as symbols.
    pub fn symbolic(&self) -> Vec<Sym> {
        self.functions.iter().map(|f| f.value.clone()).collect()
    }
}
