//! Exact checks in the symbolic ring `Q(params)[s, c]/(s² + c² − 1)`.
//!
//! The catalog's own generic formulas are evaluated on symbols (one source
//! of truth); identities are decided by the exact zero test, and a failure is
//! shown by its exact residual.

use trig_core::{Affine, Atoms, Basis, Family};
use trig_deriv::End;
use trig_specfile::{AnyBasis, Spec};
use trig_symbolic::{Sym, symbolic_atoms};

use trig_verdict::evidence::{Evidence, Expr, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

/// How identities are decided, as the report states it.
pub const IDENTITY: &str =
    "exact identity in the symbolic ring Q(parameters)[s, c]/(s^2 + c^2 - 1), s = sin θ, c = cos θ";

/// Every function of `family` with its parameters as symbols named as in
/// the catalog (`m`, `beta`, …), at the symbolic atoms `s`, `c`, `t`.
pub fn basis(family: Family) -> Vec<Sym> {
    basis_at(family, &symbolic_atoms())
}

/// The same at given atoms.
pub fn basis_at(family: Family, atoms: &Atoms<Sym>) -> Vec<Sym> {
    family.eval(atoms, &params(family))
}

/// A basis the judges can read exactly: its functions in the symbolic
/// ring with the parameters as symbols, in the form the basis holds them —
/// a catalog family evaluated at the symbolic atoms, a spec file's formulas
/// as read (denominators factored as written, so a definition used as a
/// divisor stays one factor for the certifiers).
pub trait ExactBasis: Basis + Sync {
    /// Every function, exactly.
    fn exact_functions(&self) -> Vec<Sym>;

    /// Every function at exact parameter values (`values[i]` the value of
    /// the `i`-th parameter, a rational or a rational multiple of π), in
    /// the exact ring with the variable free: `None` for a function the
    /// ring cannot take there (a denominator that vanishes). Parameter
    /// atoms the basis does not specialise (`sin(α)` of a family) stay
    /// atoms, so a zero found here is identically zero at those values.
    fn exact_functions_at(&self, values: &[Sym]) -> Vec<Option<Sym>> {
        generic_at(self, values)
    }
}

/// The exact functions of `basis` at the point `x` with the parameters
/// `params`, where the exact ring forms them (`None` for a function it
/// cannot specialise, or for all at a point whose atoms are not exact).
pub fn values_at<B: ExactBasis>(basis: &B, params: &[Affine], x: &Affine) -> Vec<Option<Sym>> {
    let values: Vec<Sym> = params.iter().map(|a| a.eval(&Sym::zero(), &[])).collect();
    let atoms = basis.domain().atoms_at(x, &Sym::one(), &values);
    basis
        .exact_functions_at(&values)
        .into_iter()
        .map(|f| Some(at_atoms(&f?, atoms.as_ref()?)))
        .collect()
}

/// An exact function at exact atoms.
pub fn at_atoms(f: &Sym, a: &Atoms<Sym>) -> Sym {
    f.subs("s", &a.s)
        .subs("c", &a.c)
        .subs("t", &a.t)
        .subs("E", &a.e)
}

/// [`ExactBasis::exact_functions_at`] by substituting the parameters'
/// symbols only.
fn generic_at<B: ExactBasis + ?Sized>(basis: &B, values: &[Sym]) -> Vec<Option<Sym>> {
    let names = basis.param_names();
    basis
        .exact_functions()
        .into_iter()
        .map(|f| {
            names.iter().zip(values).try_fold(f, |f, (n, v)| {
                if f.variables().contains(n) {
                    f.try_subs(n, v).ok()
                } else {
                    Some(f)
                }
            })
        })
        .collect()
}

impl ExactBasis for Family {
    fn exact_functions(&self) -> Vec<Sym> {
        basis(*self)
    }
}

impl ExactBasis for Spec {
    fn exact_functions(&self) -> Vec<Sym> {
        self.symbolic()
    }

    /// The spec specialised at the values ([`Spec::at_values`]: its
    /// parameter atoms too, `exp(α)` at `α = 0` is `1`), else the generic
    /// substitution (an atom not exact at the value stays an atom).
    fn exact_functions_at(&self, values: &[Sym]) -> Vec<Option<Sym>> {
        let pairs: Vec<(String, Sym)> = self
            .params
            .iter()
            .map(|p| p.name.clone())
            .zip(values.iter().cloned())
            .collect();
        match self.at_values(&pairs) {
            Ok(fixed) => fixed.symbolic().into_iter().map(Some).collect(),
            Err(_) => generic_at(self, values),
        }
    }
}

impl ExactBasis for AnyBasis {
    fn exact_functions(&self) -> Vec<Sym> {
        match self {
            AnyBasis::Family(f) => f.exact_functions(),
            AnyBasis::Spec(s) => s.exact_functions(),
        }
    }

    fn exact_functions_at(&self, values: &[Sym]) -> Vec<Option<Sym>> {
        match self {
            AnyBasis::Family(f) => f.exact_functions_at(values),
            AnyBasis::Spec(s) => s.exact_functions_at(values),
        }
    }
}

impl<B: ExactBasis + ?Sized> ExactBasis for &B {
    fn exact_functions(&self) -> Vec<Sym> {
        (**self).exact_functions()
    }

    fn exact_functions_at(&self, values: &[Sym]) -> Vec<Option<Sym>> {
        (**self).exact_functions_at(values)
    }
}

/// Every function of any basis with its parameters as symbols (see
/// [`ExactBasis`]).
pub fn basis_of<B: ExactBasis>(b: &B) -> Vec<Sym> {
    b.exact_functions()
}

/// The functions of `basis` as the audit encodes them, with where they are
/// printed: one item a failing claim's entry carries, so that a reader
/// re-checks its witness without opening the seed (every function exactly,
/// in `s = sin θ`, `c = cos θ` or the polynomial variable; the JSON gives
/// each in every form).
pub fn definitions<B: ExactBasis>(basis: &B) -> Evidence {
    let domain = basis.domain();
    let angle = match basis.variable() {
        Some(trig_core::Variable::UnitAngle) => {
            format!("; s = sin θ, c = cos θ, θ = π{}/2", basis.variable_name())
        }
        Some(trig_core::Variable::Angle) => {
            format!("; s = sin {0}, c = cos {0}", basis.variable_name())
        }
        _ if domain.is_trigonometric() => "; s = sin θ, c = cos θ".to_string(),
        _ => String::new(),
    };
    let text = format!(
        "the functions as encoded from {} ({}{angle})",
        basis.citation(),
        domain.to_string().replace(" in ", " ∈ ").replace("pi", "π")
    );
    basis
        .function_names()
        .iter()
        .zip(basis.exact_functions())
        .fold(Evidence::note(text), |item, (name, f)| {
            item.with(name.clone(), Expr::new(&f))
        })
}

/// `v` with the [`definitions`] of `basis` at the end when it does not hold.
pub fn defined_by<B: ExactBasis>(mut v: Verdict, basis: &B) -> Verdict {
    if v.status != Status::Holds {
        v.evidence.push(definitions(basis));
    }
    v
}

/// The family's parameters as symbols.
pub fn params(family: Family) -> Vec<Sym> {
    family
        .info()
        .params
        .iter()
        .map(|p| Sym::var(p.name))
        .collect()
}

/// The reflection `θ ↦ π/2 − θ` (`u ↦ 1 − u`): swaps `s` and `c`; for
/// polynomial families `t ↦ 1 − t`.
pub fn reflect(e: &Sym, trigonometric: bool) -> Sym {
    if trigonometric {
        let tmp = Sym::var("__swap");
        e.subs("s", &tmp)
            .subs("c", &Sym::var("s"))
            .subs("__swap", &Sym::var("c"))
    } else {
        e.subs("t", &(Sym::one() - &Sym::var("t")))
    }
}

/// The value at one end of the domain (`s = 0, c = 1, t = 0` or
/// `s = 1, c = 0, t = 1`).
pub fn at_end(e: &Sym, end: End) -> Sym {
    let (s, c, t) = match end {
        End::Start => (0, 1, 0),
        End::End => (1, 0, 1),
    };
    e.subs("s", &Sym::int(s))
        .subs("c", &Sym::int(c))
        .subs("t", &Sym::int(t))
}

/// The label of an identity's left side at a witness: the value of the
/// expression checked (not a one-sided limit).
pub const VALUE: &str = "value";

/// The label of an identity's right side at a witness: the value the
/// expression should have there.
pub const TARGET: &str = "target";

/// Decides `lhs = rhs` exactly: holds, or fails with the residual.
pub fn identity(label: &str, lhs: &Sym, rhs: &Sym) -> Verdict {
    identities(vec![(label.to_string(), lhs.clone(), rhs.clone())])
}

/// The evidence item of `lhs = rhs` about `label`: the residual exactly 0,
/// or the residual `lhs − rhs` with a witness (a rational point where the
/// two sides differ, both values exact: [`VALUE`] and [`TARGET`], each
/// with the expression it is the value of).
pub fn identity_item(label: &str, lhs: &Sym, rhs: &Sym) -> Evidence {
    identity_item_where(label, lhs, rhs, &[])
}

/// The most terms (numerators and denominators of both sides together)
/// of an identity whose residual is formed when the sides already differ
/// at a point: the residual of larger sides would not be read (hundreds of
/// terms), and its cancellation, a multivariate gcd, is the costly step.
pub const RESIDUAL_TERMS: usize = 400;

/// The terms of `x`'s numerator and denominator factors.
fn terms(x: &Sym) -> usize {
    x.numerator().len() + x.denominator().keys().map(|p| p.len()).sum::<usize>()
}

/// [`identity_item`] with its witness inside the claim's conditions: the
/// symbols of `positive` positive there ([`witness::find_where`]).
///
/// Sides of more than [`RESIDUAL_TERMS`] terms are first compared at the
/// points of the witness search: where they differ at one, the identity
/// fails there (both values exact) and the residual is not formed; only
/// sides that agree at every point tried are subtracted exactly.
pub fn identity_item_where(label: &str, lhs: &Sym, rhs: &Sym, positive: &[String]) -> Evidence {
    let large = terms(lhs) + terms(rhs);
    if large > RESIDUAL_TERMS {
        if let Some(mut w) = witness::find_where(lhs, rhs, (VALUE, TARGET), positive) {
            // each value with the side it is the value of: a reader substitutes
            // the point into it
            for (value, side) in w.values.iter_mut().zip([lhs, rhs]) {
                value.of.get_or_insert_with(|| Expr::new(side));
            }
            return Evidence::new(
                Kind::Identity,
                format!("the sides differ at the witness point (residual not formed: the sides have {large} terms)"),
            )
            .about(label, Status::Fails)
            .witnessed(Some(w));
        }
    }
    let residual = lhs.clone() - rhs;
    if residual.is_zero() {
        return Evidence::new(Kind::Identity, "residual is exactly 0").about(label, Status::Holds);
    }
    Evidence::new(Kind::Identity, "")
        .about(label, Status::Fails)
        .with("residual (value − target)", Expr::new(&residual))
        .witnessed(witness::find_where(lhs, rhs, (VALUE, TARGET), positive))
}

/// The verdict on `lhs = rhs` with the residual as its only evidence.
pub fn residual_verdict(lhs: &Sym, rhs: &Sym) -> Verdict {
    let mut item = identity_item("", lhs, rhs);
    item.subject = None;
    let status = item.status.unwrap_or(Status::NotCheckable);
    Verdict::new(status, IDENTITY, [item])
}

/// Decides several identities that together make one claim.
pub fn identities(parts: Vec<(String, Sym, Sym)>) -> Verdict {
    identities_where(parts, &[])
}

/// [`identities`] with their witnesses inside the claim's conditions (the
/// symbols of `positive` positive).
pub fn identities_where(parts: Vec<(String, Sym, Sym)>, positive: &[String]) -> Verdict {
    let items: Vec<Evidence> = parts
        .iter()
        .map(|(label, l, r)| identity_item_where(label, l, r, positive))
        .collect();
    let status = Status::conjunction(items.iter().filter_map(|e| e.status));
    Verdict::new(status, IDENTITY, items)
}

/// The sum of a list of expressions.
pub fn sum(items: &[Sym]) -> Sym {
    items.iter().fold(Sym::zero(), |acc, x| acc + x)
}

/// The symbols `prefix0, prefix1, …` (control points `P0…`, weights `w0…`).
pub fn symbols(prefix: &str, n: usize) -> Vec<Sym> {
    (0..n).map(|i| Sym::var(&format!("{prefix}{i}"))).collect()
}

/// `Σ cᵢ Pᵢ`: a curve from its basis values and (symbolic) control points.
pub fn combination(coeffs: &[Sym], points: &[Sym]) -> Sym {
    sum(&coeffs
        .iter()
        .zip(points)
        .map(|(c, p)| c.clone() * p)
        .collect::<Vec<_>>())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identity_proves_a_true_one_and_refutes_a_false_one() {
        let s = Sym::var("s");
        let c = Sym::var("c");
        let one = Sym::one();
        assert_eq!(
            identity("pythagoras", &(s.clone() * &s + &(c.clone() * &c)), &one).status,
            Status::Holds
        );
        let v = identity("wrong", &(s.clone() * &s), &one);
        assert_eq!(v.status, Status::Fails);
        assert!(v.evidence[0].contains("-c^2"), "{:?}", v.evidence);
        let w = v.evidence[0].witness.as_ref().expect("a witness");
        // simplified to θ = 0 (s = 0, c = 1): s² = 0 against 1
        assert_eq!(w.values[0].value.unicode, "0");
    }

    #[test]
    fn large_sides_that_differ_at_a_point_fail_without_their_residual() {
        // (a + b + c + d + e + f)⁶ has 462 terms: sides above RESIDUAL_TERMS
        let sum = ["a", "b", "c", "d", "e", "f"]
            .iter()
            .fold(Sym::zero(), |acc, v| acc + &Sym::var(v));
        let p = (0..6).fold(Sym::one(), |acc, _| acc * &sum);
        assert!(terms(&p) > RESIDUAL_TERMS);
        let item = identity_item("shifted", &p, &(p.clone() + &Sym::one()));
        assert_eq!(item.status, Some(Status::Fails));
        assert!(item.text.contains("residual not formed"), "{}", item.text);
        assert!(item.exprs.is_empty(), "no residual: {:?}", item.exprs);
        let w = item.witness.expect("a witness");
        assert_ne!(w.values[0].value, w.values[1].value);
        // each value names the side it is the value of
        assert!(w.values.iter().all(|v| v.of.is_some()));
        // sides that agree at every point tried are subtracted exactly
        let item = identity_item("same", &p, &(p.clone() + &Sym::zero()));
        assert_eq!(item.status, Some(Status::Holds));
        // small sides keep their residual
        let item = identity_item("small", &sum, &(sum.clone() + &Sym::one()));
        assert_eq!(item.status, Some(Status::Fails));
        assert!(!item.exprs.is_empty());
    }

    #[test]
    fn reflection_swaps_the_thesis_cubic_ends() {
        let b = basis(Family::ThesisCubic);
        assert!((reflect(&b[0], true) - &b[3]).is_zero());
        assert!(!(reflect(&b[0], true) - &b[2]).is_zero());
        assert_eq!(at_end(&b[0], End::Start), Sym::one());
        assert_eq!(at_end(&b[0], End::End), Sym::zero());
    }
}
