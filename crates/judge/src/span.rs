//! The span judge: which functions a basis reproduces — the question
//! behind every "exact conic arc" claim. `g` lies in the span of
//! `b₀ … b_{n−1}` when `Σ kᵢ bᵢ = g` identically for some coefficients
//! `kᵢ` (functions of the parameters); a curve `(g_x, g_y)` is then traced
//! by the control points `Pᵢ = (kᵢ^x, kᵢ^y)`.
//!
//! Decided exactly: the numerator of `Σ kᵢ bᵢ − g` has, in the monomials
//! `tᵃ cᵇ sᵉ` (`e ≤ 1`) of the ring's normal form (independent functions),
//! coefficients linear in the unknowns `kᵢ`; they are eliminated one by
//! one over `Q(parameters)`. A left-over equation free of the unknowns is
//! the condition on the parameters for `g` to lie in the span.

use trig_symbolic::Sym;

use super::independence::coefficients;
use crate::exact::{ExactBasis, basis_of};
use trig_verdict::verdict::Verdict;

/// The unknown coefficient `k_i` (a name no formula can use).
fn unknown(i: usize) -> String {
    format!("k#{i}")
}

/// The outcome for one target function.
#[derive(Debug, Clone, PartialEq)]
pub enum Span {
    /// `g = Σ kᵢ bᵢ` for every parameter value where no pivot vanishes
    /// (the pivots are given); the coefficients `kᵢ` (free ones set to 0).
    Inside {
        coefficients: Vec<Sym>,
        pivots: Vec<Sym>,
    },
    /// `g` is in the span only where the condition (a function of the
    /// parameters) vanishes; never when it is a nonzero constant.
    Only { condition: Sym },
}

/// Whether `g` lies in the span of the functions `b`.
pub fn span(b: &[Sym], g: &Sym) -> Span {
    let names: Vec<String> = (0..b.len()).map(unknown).collect();
    let combination = b
        .iter()
        .zip(&names)
        .fold(Sym::zero(), |acc, (f, k)| acc + &(f.clone() * &Sym::var(k)));
    let residual = combination - g;
    let mut forced: Vec<(usize, Sym)> = Vec::new();
    let mut pivots = Vec::new();
    for eq in coefficients(residual.numerator()) {
        let reduced = forced
            .iter()
            .fold(Sym::from_poly(eq), |r, (i, v)| r.subs(&names[*i], v));
        let Some(i) = (0..names.len())
            .filter(|i| forced.iter().all(|(j, _)| j != i))
            .find(|&i| !reduced.diff(&names[i]).is_zero())
        else {
            if reduced.is_zero() {
                continue;
            }
            return Span::Only { condition: reduced };
        };
        let pivot = reduced.diff(&names[i]);
        let rest = reduced - &(pivot.clone() * &Sym::var(&names[i]));
        let value = -(rest / &pivot);
        for (_, v) in &mut forced {
            *v = v.subs(&names[i], &value);
        }
        if pivot.as_rational().is_none() {
            pivots.push(pivot);
        }
        forced.push((i, value));
    }
    let coefficients = (0..names.len())
        .map(|i| {
            let v = forced
                .iter()
                .find(|(j, _)| *j == i)
                .map_or_else(Sym::zero, |(_, v)| v.clone());
            names.iter().fold(v, |v, k| v.subs(k, &Sym::zero()))
        })
        .collect();
    Span::Inside {
        coefficients,
        pivots,
    }
}

/// The curve `Σ bᵢPᵢ` with the printed points satisfies the printed
/// implicit equation in `X`, `Y` identically (exact); a failure shows the
/// residual and a point where it is nonzero.
pub fn conic<B: ExactBasis>(
    basis: &B,
    points: &[(Sym, Sym)],
    equation: &Sym,
    equation_text: &str,
) -> Verdict {
    let residual = conic_residual(basis, points, equation);
    let mut v = crate::exact::identity(&conic_label(equation_text), &residual, &Sym::zero());
    v.method = "exact: the printed equation with X, Y replaced by the coordinates of Σ bᵢPᵢ, decided in the symbolic ring".into();
    v
}

/// The printed equation at `(X, Y) = Σ bᵢPᵢ`: zero exactly where the curve
/// lies on the conic.
pub fn conic_residual<B: ExactBasis>(basis: &B, points: &[(Sym, Sym)], equation: &Sym) -> Sym {
    let b = basis_of(basis);
    let along = |pick: fn(&(Sym, Sym)) -> &Sym| {
        b.iter()
            .zip(points)
            .fold(Sym::zero(), |acc, (f, p)| acc + &(f.clone() * pick(p)))
    };
    let (x, y) = (along(|p| &p.0), along(|p| &p.1));
    equation.subs("X", &x).subs("Y", &y)
}

/// How a conic's residual is named in the evidence.
pub fn conic_label(equation_text: &str) -> String {
    format!("{equation_text} at (X, Y) = Σ bᵢPᵢ")
}
