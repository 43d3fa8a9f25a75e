//! Where an identity holds: the parameter values at which a residual
//! vanishes identically in the variable — for claims stated with a
//! quantifier, "for some value of λ the curve is a circle", "for no value
//! of λ is it a conic".
//!
//! In the normal form of the exact ring the monomials `tᵃcᵇsᵉ` (`e ≤ 1`)
//! are independent functions, so the residual's numerator vanishes
//! identically exactly where all its coefficients in them vanish together.
//! With one free parameter that is the set of real roots of their gcd `g`
//! in the range — decided exactly (rational roots, and irrational ones by
//! Sturm sequences with an isolating interval); with none, the residual is
//! zero or not; with two or more, a nonzero constant coefficient proves
//! "no value", and otherwise the common zeros are not computed
//! (`not-checkable`).

use rug::Rational;
use trig_certify::algebraic::Algebraic;
use trig_certify::sturm::UPoly;
use trig_core::{End, ParamRange};
use trig_symbolic::{Poly, Sym};

use super::independence::{VARIABLE_ATOMS, coefficients};
use crate::exact::ExactBasis;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use trig_specfile::Quantifier;

/// How the quantified claims are decided, as the report states it.
pub const METHOD: &str = "exact: the residual's numerator in the independent monomials t^a·c^b·s^e (e ≤ 1) vanishes identically exactly where all its coefficients vanish; with one parameter, the real roots of their gcd in the range (rational roots exactly, irrational ones by Sturm sequences with an isolating interval)";

/// The values of the free parameter in the range where `residual ≡ 0`:
/// `Ok(None)` when it vanishes for every value, `Ok(Some(roots))` else.
fn zeros<B: ExactBasis>(basis: &B, residual: &Sym) -> Result<Option<Vec<Algebraic>>, String> {
    if residual.is_zero() {
        return Ok(None);
    }
    let params = basis.parameters();
    let names: Vec<&str> = params.iter().map(|p| p.name.as_str()).collect();
    let num = residual.numerator();
    if let Some(other) = num
        .variables()
        .into_iter()
        .find(|v| !VARIABLE_ATOMS.contains(&v.as_str()) && !names.contains(&v.as_str()))
    {
        return Err(format!(
            "the residual is written in `{other}`, whose monomials are not known to be independent in the exact ring"
        ));
    }
    let coeffs = coefficients(num);
    if coeffs
        .iter()
        .any(|c| c.as_constant().is_some_and(|q| q != 0))
    {
        return Ok(Some(Vec::new()));
    }
    let [p] = params.as_slice() else {
        return Err(format!(
            "the common zeros of the residual's {} coefficients in {} parameters are not computed",
            coeffs.len(),
            params.len()
        ));
    };
    let g = coeffs
        .iter()
        .try_fold(Poly::zero(), |acc, q| trig_symbolic::gcd::gcd(&acc, q))
        .ok_or("the gcd of the residual's coefficients could not be formed")?;
    if g.as_constant().is_some() {
        return Ok(Some(Vec::new()));
    }
    let u = UPoly::from_poly(&g, &p.name).ok_or("the gcd is not a polynomial in the parameter")?;
    roots_in(&u, &p.range).map(Some)
}

/// The real roots of `u` in the range, exactly.
fn roots_in(u: &UPoly, range: &ParamRange) -> Result<Vec<Algebraic>, String> {
    if range.pi {
        return Err(format!(
            "the range {range} has ends in multiples of π; the roots are compared with rational ends only"
        ));
    }
    let u = u.squarefree();
    let bound = u.root_bound() + Rational::from(1);
    let end = |e: &End, unbounded: Rational| e.value().cloned().unwrap_or(unbounded);
    let (a, b) = (end(&range.lo, -bound.clone()), end(&range.hi, bound));
    let mut out = Vec::new();
    if matches!(range.lo, End::Closed(_)) && u.sign_at(&a) == 0 {
        out.push(Algebraic::new(&u, a.clone(), a.clone()));
    }
    let width = Rational::from((1, 10u64.pow(14)));
    out.extend(u.isolate(&a, &b).into_iter().map(|(lo, hi)| {
        let mut r = Algebraic::new(&u, lo, hi);
        r.refine(&width);
        r
    }));
    if matches!(range.hi, End::Closed(_)) && u.sign_at(&b) == 0 && a != b {
        out.push(Algebraic::new(&u, b.clone(), b.clone()));
    }
    Ok(out)
}

/// The claim that `residual ≡ 0` (named by `label`) holds for some or for
/// no value of the parameters (for every value the identity judge
/// decides, [`crate::exact::identity`]).
pub fn quantified<B: ExactBasis>(
    basis: &B,
    label: &str,
    residual: &Sym,
    quantifier: Quantifier,
) -> Verdict {
    let symbol = basis
        .parameters()
        .first()
        .map_or("p".to_string(), |p| p.symbol.clone());
    let found = match zeros(basis, residual) {
        Ok(found) => found,
        Err(why) => return Verdict::not_checkable(format!("{label}: {why}")),
    };
    let (somewhere, text) = match &found {
        None => (
            true,
            format!("{label} vanishes identically, for every parameter value"),
        ),
        Some(roots) if roots.is_empty() => (
            false,
            format!(
                "{label} vanishes identically for no parameter value in the range: its coefficients in the monomials t^a·c^b·s^e have no common zero there (exact)"
            ),
        ),
        Some(roots) => (
            true,
            format!(
                "{label} vanishes identically exactly for {symbol} = {} in the range (the common zeros of its coefficients, exact)",
                roots
                    .iter()
                    .map(|r| r.describe(&symbol, 12))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        ),
    };
    let holds = match quantifier {
        Quantifier::Some => somewhere,
        Quantifier::No => !somewhere,
    };
    Verdict::new(
        if holds { Status::Holds } else { Status::Fails },
        METHOD,
        vec![text],
    )
}
