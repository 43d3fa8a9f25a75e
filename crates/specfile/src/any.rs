//! Any basis a user names: a catalog family by its id, or the basis of a
//! spec file. [`AnyBasis`] is a [`Basis`] like either of them, so the
//! commands built on it never ask where a basis came from.

use std::path::Path;

use trig_core::{
    Atoms, Basis, CoreError, Described, Domain, Family, Parameter, Ring, SEED000_NONUNIFORM,
    Variable,
};
use trig_symbolic::Sym;

use crate::error::SpecError;
use crate::spec::Spec;

/// A catalog family or a spec file's basis.
#[derive(Debug, Clone)]
pub enum AnyBasis {
    Family(Family),
    Spec(Box<Spec>),
}

/// Why a named basis cannot be opened.
#[derive(Debug, thiserror::Error)]
pub enum OpenError {
    /// The spec file is unreadable or invalid.
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// The family id is unknown, or the family has no formulas.
    #[error(transparent)]
    Core(#[from] CoreError),
    /// `seed000-nonuniform` changes from span to span: only a knot vector
    /// makes it a basis.
    #[error(
        "`{0}` needs a knot vector: its segment functions change from span to span, so only `trig-audit eval {0} --knots …` evaluates it; for the uniform case use seed000-uniform"
    )]
    NeedsKnots(String),
    /// Neither a family nor a spec file was named.
    #[error("expected a family id or --spec FILE")]
    Nothing,
}

impl AnyBasis {
    /// The basis of the spec file `spec` when one is given, else the
    /// catalog family `family` (which must have formulas).
    pub fn open(family: Option<&str>, spec: Option<&Path>) -> Result<AnyBasis, OpenError> {
        match (family, spec) {
            (_, Some(path)) => Ok(AnyBasis::Spec(Box::new(Spec::from_file(path)?))),
            (Some(id), None) => {
                let family = AnyBasis::family(id)?;
                if !family.has_formulas() {
                    return Err(CoreError::NoFormulas(id.into()).into());
                }
                Ok(AnyBasis::Family(family))
            }
            (None, None) => Err(OpenError::Nothing),
        }
    }

    /// The catalog family `id`; `seed000-nonuniform`, whose segment
    /// functions depend on a knot vector, is named with what it needs
    /// instead of being called unknown.
    pub fn family(id: &str) -> Result<Family, OpenError> {
        if id == SEED000_NONUNIFORM.id {
            return Err(OpenError::NeedsKnots(id.to_string()));
        }
        Ok(Family::from_id(id)?)
    }

    /// The catalog family, when the basis is one.
    pub fn as_family(&self) -> Option<Family> {
        match self {
            AnyBasis::Family(f) => Some(*f),
            AnyBasis::Spec(_) => None,
        }
    }

    /// The spec file, when the basis comes from one.
    pub fn as_spec(&self) -> Option<&Spec> {
        match self {
            AnyBasis::Family(_) => None,
            AnyBasis::Spec(s) => Some(s),
        }
    }

    /// The symbols of the `G¹`/`G²` factors of a join of this basis.
    pub fn join_factors(&self) -> [Sym; 2] {
        match self {
            AnyBasis::Spec(spec) => spec.join_factors().map(|n| Sym::var(&n)),
            AnyBasis::Family(_) => trig_deriv::default_factors(),
        }
    }

    /// The metadata side of whichever basis it is.
    fn inner(&self) -> &dyn Described {
        match self {
            AnyBasis::Family(f) => f,
            AnyBasis::Spec(s) => s.as_ref(),
        }
    }
}

impl Described for AnyBasis {
    fn id(&self) -> String {
        self.inner().id()
    }

    fn title(&self) -> String {
        self.inner().title()
    }

    fn citation(&self) -> String {
        self.inner().citation()
    }

    fn domain(&self) -> Domain {
        self.inner().domain()
    }

    fn variable(&self) -> Option<Variable> {
        self.inner().variable()
    }

    fn variable_name(&self) -> String {
        self.inner().variable_name()
    }

    fn parameters(&self) -> Vec<Parameter> {
        self.inner().parameters()
    }

    fn function_names(&self) -> Vec<String> {
        self.inner().function_names()
    }

    fn piecewise(&self) -> bool {
        self.inner().piecewise()
    }

    fn params_from_pairs(
        &self,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> trig_core::Result<Vec<trig_core::Affine>> {
        self.inner().params_from_pairs(pairs, allow_outside)
    }
}

impl Basis for AnyBasis {
    fn eval<T: Ring>(&self, x: &Atoms<T>, p: &[T]) -> Vec<T> {
        match self {
            AnyBasis::Family(f) => Basis::eval(f, x, p),
            AnyBasis::Spec(s) => Basis::eval(s.as_ref(), x, p),
        }
    }
}
