//! The linear-independence judge: the functions of a basis are linearly
//! independent ("basis functions" of the space they span) for every
//! parameter value of a range.
//!
//! Decided by the exact rank of their coefficient matrix (`rank.rs`): over
//! one common denominator, the numerators' coefficients in the monomials
//! `tᵃ cᵇ sᵉ` (`e ≤ 1`) of the ring's normal form, which are independent
//! functions ([`matrix`]); any number of functions and parameters.
//!
//! Where the formulas use atoms whose monomials are not known to be
//! independent (`exp`, `sinh`, …), by the Wronskian `W = det[bⱼ⁽ⁱ⁾]`,
//! `0 ≤ i, j < n`, computed in the exact ring: analytic functions are
//! dependent exactly where `W ≡ 0` in the variable, so `W ≡ 0` for a
//! parameter value exactly when every coefficient of `W`'s numerator in
//! those monomials vanishes there:
//! - one coefficient certified nonzero on the range proves independence;
//! - a rational parameter value where the whole numerator vanishes (found
//!   among the rational roots, checked exactly) refutes it.

mod at_root;
mod exceptional_set;
pub mod matrix;
mod maximal;
mod one_parameter;
mod rank;

pub use maximal::maximal;
pub use rank::RANK;

use trig_certify::branch::{self, Outcome};
use trig_core::ParamRange;
use trig_symbolic::{Poly, Sym};

use super::by_intervals::axes;
use crate::exact::{ExactBasis, basis_of};
use trig_symbolic::rational_roots;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How independence is decided, as the report states it.
pub const METHOD: &str = "exact Wronskian in the symbolic ring; its coefficients in the independent monomials t^a·c^b·s^e (e ≤ 1) of the normal form; a coefficient certified nonzero on the range (interval branch and bound) proves independence, a rational parameter value where all vanish (exact) refutes it";

/// Most functions whose Wronskian is expanded (`n!` terms).
const MAX_FUNCTIONS: usize = 6;

/// The atoms of the variable whose monomials are independent in the
/// normal form of the exact ring.
pub(crate) const VARIABLE_ATOMS: [&str; 3] = ["s", "c", "t"];

/// One derivative in the variable of the basis (`d/dθ` for formulas in
/// `s`, `c` alone: a constant factor per row does not change `W ≡ 0`).
fn derive<B: ExactBasis>(basis: &B, f: &Sym) -> Sym {
    let domain = basis.domain();
    if domain.is_pure_trigonometric() {
        f.d_angle()
    } else {
        trig_certify::atoms::d_variable(f, &domain)
    }
}

/// The Wronskian of the functions of `basis`.
pub fn wronskian<B: ExactBasis>(basis: &B) -> Sym {
    let mut rows = vec![basis_of(basis)];
    for _ in 1..rows[0].len() {
        let next = rows[rows.len() - 1]
            .iter()
            .map(|f| derive(basis, f))
            .collect();
        rows.push(next);
    }
    Sym::determinant(&rows)
}

/// The coefficients of `p` in the monomials of the variable's atoms.
pub(crate) fn coefficients(p: &Poly) -> Vec<Poly> {
    let mut out = vec![p.clone()];
    for atom in VARIABLE_ATOMS {
        out = out
            .iter()
            .flat_map(|q| q.coefficients_in(atom))
            .filter(|q| !q.is_zero())
            .collect();
    }
    out
}

/// The functions of `basis` are linearly independent for every parameter
/// value in `range` (the only parameter's; the declared ranges otherwise):
/// by exact rank ([`by_rank`]), by the Wronskian where the atoms are not
/// independent monomials.
pub fn independent<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    match by_rank(basis, range) {
        Ok(v) => v,
        Err(why) => {
            let n = basis.function_names().len();
            if n > MAX_FUNCTIONS {
                return Verdict::not_checkable(format!(
                    "{why}, so the rank of the coefficient matrix does not decide; the Wronskian is expanded for at most {MAX_FUNCTIONS} functions ({n} here)"
                ));
            }
            by_wronskian(basis, range)
        }
    }
}

/// Why the rank method does not apply to a basis.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NotMonomial(pub String);

impl std::fmt::Display for NotMonomial {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// Independence by the exact rank of the coefficient matrix ([`RANK`]);
/// an error when the functions use atoms whose monomials are not known to
/// be independent (or an angle whose rate depends on a parameter).
pub fn by_rank<B: ExactBasis>(
    basis: &B,
    range: Option<&ParamRange>,
) -> Result<Verdict, NotMonomial> {
    let params = basis.parameters();
    let atoms: Vec<String> = trig_certify::atoms::param_atoms(&basis.domain())
        .into_iter()
        .map(|a| a.name)
        .collect();
    let symbols: Vec<&String> = params.iter().map(|p| &p.name).chain(&atoms).collect();
    with_context(basis, range, inexact_division, |ctx, e| {
        if e.rank < ctx.names.len() {
            return rank::short_rank(ctx, e);
        }
        if !e.minor.variables().iter().any(|v| symbols.contains(&v)) {
            return rank::constant_minor(ctx, e);
        }
        let decided = match params.len() {
            1 => one_parameter::one_parameter(ctx, e),
            2 => exceptional_set::two_parameters(ctx, e),
            3 => Some(exceptional_set::three_parameters(ctx, e)),
            _ => None,
        };
        decided.unwrap_or_else(|| rank::general(ctx, e))
    })
}

/// `decide` on the rank judge's reading of `basis` (its coefficient matrix
/// and its elimination; `inexact` where the elimination meets a division
/// that is not exact); an error when the rank method does not apply.
fn with_context<B: ExactBasis, R>(
    basis: &B,
    range: Option<&ParamRange>,
    inexact: impl FnOnce() -> R,
    decide: impl FnOnce(&rank::Context<'_>, &matrix::Echelon<Poly>) -> R,
) -> Result<R, NotMonomial> {
    let names = basis.function_names();
    let fs = basis_of(basis);
    let params = basis.parameters();
    let domain = basis.domain();
    if let Some(w) = &domain.angle
        && (!w.is_constant() || w.as_rational().is_some_and(|q| *q == 0))
    {
        return Err(NotMonomial(format!(
            "the angle rate {} of sin and cos is not a nonzero constant",
            w.text(&domain.param_names)
        )));
    }
    let atoms: Vec<String> = trig_certify::atoms::param_atoms(&domain)
        .into_iter()
        .map(|a| a.name)
        .collect();
    let mut unknown: Vec<String> = fs
        .iter()
        .flat_map(Sym::variables)
        .filter(|v| {
            !VARIABLE_ATOMS.contains(&v.as_str())
                && !params.iter().any(|p| &p.name == v)
                && !atoms.contains(v)
                && v != "pi"
                && !v.starts_with("sqrt(")
        })
        .collect();
    unknown.sort();
    unknown.dedup();
    if !unknown.is_empty() {
        return Err(NotMonomial(format!(
            "the functions are written in {}, whose monomials are not known to be independent in the exact ring",
            unknown.join(", ")
        )));
    }
    let (axes, notes) = axes(basis, range);
    let ctx = rank::Context {
        names: &names,
        fs: &fs,
        params: &params,
        ranges: params
            .iter()
            .map(|p| {
                range
                    .filter(|_| params.len() == 1)
                    .unwrap_or(&p.range)
                    .clone()
            })
            .collect(),
        domain,
        axes,
        notes,
        matrix: matrix::coefficients(&fs),
    };
    let Ok(e) = matrix::echelon_poly(&ctx.matrix.rows) else {
        return Ok(inexact());
    };
    Ok(decide(&ctx, &e))
}

/// Why the rank was not computed: the elimination's division not exact.
fn inexact_division() -> Verdict {
    Verdict::not_checkable(
        "the fraction-free elimination met a division that was not exact (the entries' ring is not an integral domain as written)",
    )
}

/// The window around the declared box of a two-parameter basis,
/// classified for linear independence (`plot region --property
/// independent`): a cell is **inside** where a maximal minor of the
/// coefficient matrix keeps one strict sign on the whole cell (certified by
/// Bernstein subdivision), the **edge** otherwise — the cells that may hold
/// a point of the exceptional set (its curves and isolated points, given
/// exactly by the independence claim's evidence). No cell is outside: the
/// dependence set of functions independent somewhere has no interior.
pub fn independence_region<B: ExactBasis>(
    basis: &B,
    axes: &[crate::region::Axis<'_>; 2],
) -> Result<trig_certify::region::Region, String> {
    let minors = with_context(
        basis,
        None,
        || Err("the fraction-free elimination met a division that was not exact".to_string()),
        |ctx, e| {
            if e.rank < ctx.names.len() {
                return Err("the functions are dependent for every parameter value".to_string());
            }
            exceptional_set::maximal_minors(ctx).ok_or_else(|| {
                "the maximal minors are not polynomials in the parameters, or too many to list"
                    .to_string()
            })
        },
    )
    .map_err(|NotMonomial(why)| why)??;
    let minors: Vec<Sym> = minors.into_iter().map(Sym::from_poly).collect();
    let params = [axes[0].name, axes[1].name];
    Ok(crate::region::classify_window_by(
        &[],
        &[],
        false,
        axes,
        |lo, hi| {
            let cell = [
                (
                    params[0],
                    trig_certify::ParamBox::closed(lo[0].clone(), hi[0].clone()),
                ),
                (
                    params[1],
                    trig_certify::ParamBox::closed(lo[1].clone(), hi[1].clone()),
                ),
            ];
            if minors
                .iter()
                .any(|m| trig_certify::nonneg::definite_sign(m, false, &cell).is_ok())
            {
                trig_certify::region::CellKind::Inside
            } else {
                trig_certify::region::CellKind::Boundary
            }
        },
    ))
}

/// The Wronskian judge (see the module documentation): the method of the
/// catalog's printed independence claims, and of bases in other atoms.
pub fn by_wronskian<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> Verdict {
    let names = basis.function_names();
    let n = names.len();
    if n > MAX_FUNCTIONS {
        return Verdict::not_checkable(format!(
            "the Wronskian is expanded for at most {MAX_FUNCTIONS} functions ({n} here)"
        ));
    }
    let w = wronskian(basis);
    let params = basis.parameters();
    let param_names: Vec<String> = params.iter().map(|p| p.name.clone()).collect();
    let atoms: Vec<String> = trig_certify::atoms::param_atoms(&basis.domain())
        .into_iter()
        .map(|a| a.name)
        .collect();
    let unknown: Vec<String> = w
        .variables()
        .into_iter()
        .filter(|v| {
            !VARIABLE_ATOMS.contains(&v.as_str()) && !param_names.contains(v) && !atoms.contains(v)
        })
        .collect();
    let header = format!(
        "Wronskian of {} (orders 0–{} in the variable)",
        names.join(", "),
        n - 1
    );
    if w.is_zero() {
        return Verdict::new(
            Status::Fails,
            METHOD,
            vec![format!(
                "{header} vanishes identically: the functions are dependent for every parameter value"
            )],
        );
    }
    if !unknown.is_empty() {
        return Verdict::not_checkable(format!(
            "{header} is written in {}, whose monomials are not known to be independent in the exact ring",
            unknown.join(", ")
        ));
    }
    let mut coeffs = coefficients(w.numerator());
    coeffs.sort_by_key(|q| (q.len(), q.total_degree()));
    let (ax, notes) = axes(basis, range);
    let shown_range = range
        .map(ToString::to_string)
        .or_else(|| params.first().map(|p| p.range.to_string()));
    // refute: a rational value in the range where every coefficient vanishes
    if let ([p], false) = (
        params.as_slice(),
        atoms.iter().any(|a| w.variables().contains(a)),
    ) {
        let r = range.unwrap_or(&p.range);
        let (roots, _) = rational_roots(w.numerator(), &p.name);
        if let Some(v) = roots.into_iter().find(|v| r.contains(v)) {
            let at = w.numerator().subs(&p.name, &Poly::constant(v.clone()));
            if at.is_zero() {
                return Verdict::new(
                    Status::Fails,
                    METHOD,
                    vec![format!(
                        "{header}: at {} = {v}, in the range {r}, every coefficient of its numerator vanishes exactly, so W ≡ 0 there: the functions are linearly dependent at {} = {v}",
                        p.symbol, p.symbol
                    )],
                );
            }
        }
    }
    let domain = basis.domain();
    let proved = |f: &Sym| matches!(branch::positive(f, &domain, &ax), Outcome::Proved { .. });
    // one parameter: the common zeros of the coefficients are the zeros of
    // their gcd
    if params.len() == 1 {
        let common = coeffs
            .iter()
            .try_fold(Poly::zero(), |acc, q| trig_symbolic::gcd::gcd(&acc, q));
        if let Some(g) = common {
            if g.as_constant().is_some() {
                return Verdict::new(
                    Status::Holds,
                    METHOD,
                    vec![format!(
                        "{header}: the {} coefficients of its numerator have no common factor (gcd 1, exact), so W is not identically 0 for every parameter value: independent",
                        coeffs.len()
                    )],
                );
            }
            let gs = Sym::from_poly(g.clone());
            if notes.is_empty() && (proved(&gs) || proved(&-gs.clone())) {
                return Verdict::new(
                    Status::Holds,
                    METHOD,
                    vec![format!(
                        "{header}: the gcd {g} of the coefficients of its numerator has one strict sign for {} (certified), so W is not identically 0 there: independent",
                        shown_range.clone().unwrap_or_default()
                    )],
                );
            }
        }
    }
    // prove: one coefficient of one strict sign on the range
    for q in coeffs.iter().take(8) {
        let g = Sym::from_poly(q.clone());
        if let Some(c) = q.as_constant() {
            return Verdict::new(
                Status::Holds,
                METHOD,
                vec![format!(
                    "{header}: its numerator has the constant coefficient {c}, so W is not identically 0 for every parameter value: independent"
                )],
            );
        }
        if notes.is_empty() && (proved(&g) || proved(&-g.clone())) {
            return Verdict::new(
                Status::Holds,
                METHOD,
                vec![format!(
                    "{header}: the coefficient {q} of its numerator has one strict sign for {} (certified), so W is not identically 0 there: independent",
                    shown_range.clone().unwrap_or_default()
                )],
            );
        }
    }
    let mut evidence = notes;
    evidence.push(format!(
        "{header}: no coefficient of its numerator was certified nonzero on the range and no rational value where all vanish was found ({} coefficients; the simplest: {})",
        coeffs.len(),
        coeffs.first().map(ToString::to_string).unwrap_or_default()
    ));
    Verdict::new(Status::NotCheckable, METHOD, evidence)
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_sets;
