//! What the two maximal-set judges of total positivity ([`crate::tp_maximal`]
//! for one parameter, [`crate::tp_maximal_box`] for a box of two or three)
//! share: their method line, total positivity decided at one parameter
//! vector, and the necessary conditions of normalized total positivity the
//! range and region engines decide exactly.

use rug::Rational;
use trig_certify::ParamBox;
use trig_certify::branch::Axis;
use trig_certify::standardize;
use trig_certify::total_positivity::{certify, refute};
use trig_certify::tp_box::BoxOutcome;
use trig_symbolic::Sym;

use super::nonnegative::pieces;
use super::tp_wronskian::at_point;
use crate::exact::{ExactBasis, basis_of};

/// How the maximal set is decided, as the report states it.
pub const METHOD: &str = "total positivity on the printed range by the totally positive factorisation or Karlin's Wronskian criterion; an end where necessary conditions (nonnegativity; b0 non-increasing and bn non-decreasing for a basis interpolating its ends: variation diminishing) stop holding, decided exactly by the range engine, is exact, and so is an end where the domain shrinks to a point; beyond another end, a value where the certificate or the criterion proves total positivity refutes maximality, a negative collocation minor or a consecutive Wronskian negative at a point bounds the end (a bracket)";

/// Total positivity at one parameter vector `at` (values in units of π on
/// a π axis): `Some(false)` refuted (a negative collocation minor, or a
/// consecutive Wronskian negative at a point), `Some(true)` proved (the
/// factorisation's certificate there, else the Wronskian criterion),
/// `None` undecided.
pub(crate) fn totally_positive_at<B: ExactBasis>(
    basis: &B,
    polynomial: Option<&(bool, Vec<Sym>, Vec<String>)>,
    at: &[(&str, &Rational)],
    pi: &[bool],
) -> Option<bool> {
    if let Some((trig, fs, _)) = polynomial {
        // a refutation is cheap; the certificate only where none is found
        if refute(fs, *trig, at).is_some() {
            return Some(false);
        }
        let proved = match at {
            [(name, q)] => certify(fs, *trig, Some((name, &ParamBox::point((*q).clone()))))
                .is_ok_and(|c| c.set.covers),
            _ => {
                let points: Vec<(&str, ParamBox)> = at
                    .iter()
                    .map(|(n, q)| (*n, ParamBox::point((*q).clone())))
                    .collect();
                trig_certify::tp_box::certify(fs, *trig, &points)
                    .is_ok_and(|c| matches!(c.outcome, BoxOutcome::Covers { .. }))
            }
        };
        if proved {
            return Some(true);
        }
    }
    let axes: Vec<Axis> = at
        .iter()
        .zip(pi)
        .map(|((_, q), pi)| Axis {
            lo: (*q).clone(),
            hi: (*q).clone(),
            lo_open: false,
            hi_open: false,
            pi: *pi,
        })
        .collect();
    at_point(&basis_of(basis), &basis.domain(), &axes)
}

/// The necessary conditions of normalized total positivity that the range
/// and region engines decide exactly, as functions that must be `≥ 0`.
pub(crate) struct Necessary {
    pub trig: bool,
    pub functions: Vec<Sym>,
    pub names: Vec<String>,
    /// Which conditions were used, for the notes.
    pub note: String,
}

/// Every function `≥ 0` (the `1 × 1` minors) and, when `b₀` is `1` at the
/// start of the domain and `bₙ` at its end, `b₀` non-increasing and `bₙ`
/// non-decreasing (a normalized totally positive basis is variation
/// diminishing, so `b₀ − κ`, whose coefficients `(1 − κ, −κ, …, −κ)`
/// change sign once, changes sign at most once for every `κ ∈ (0, 1)`;
/// with `b₀(a) = 1` a rise of `b₀` would make two). `None` for a basis the
/// polynomial engines do not take.
pub(crate) fn necessary_functions<B: ExactBasis>(basis: &B) -> Option<Necessary> {
    let (trig, mut fs, mut names) = pieces(basis).ok()?;
    let domain = basis.domain();
    let values = basis_of(basis);
    let (b0, bn) = (
        standardize(values.first()?, &domain).ok()?,
        standardize(values.last()?, &domain).ok()?,
    );
    let at = |f: &Sym, s: i64, c: i64, t: i64| {
        f.subs("s", &Sym::int(s))
            .subs("c", &Sym::int(c))
            .subs("t", &Sym::int(t))
    };
    let one = Sym::one();
    let interpolates = b0
        .pieces
        .first()
        .is_some_and(|f| at(f, 0, 1, 0).equals(&one))
        && bn
            .pieces
            .last()
            .is_some_and(|f| at(f, 1, 0, 1).equals(&one));
    let derivative = |f: &Sym| if trig { f.d_angle() } else { f.d_t() };
    let mut used = "every function ≥ 0".to_string();
    if interpolates {
        fs.extend(b0.pieces.iter().map(|f| -derivative(f)));
        names.extend(b0.pieces.iter().map(|_| "−b0′".to_string()));
        fs.extend(bn.pieces.iter().map(derivative));
        names.extend(bn.pieces.iter().map(|_| "bn′".to_string()));
        used.push_str(", b0 non-increasing and bn non-decreasing (b0 = 1 at the start, bn = 1 at the end: a normalized totally positive basis is variation diminishing)");
    }
    Some(Necessary {
        trig,
        functions: fs,
        names,
        note: format!("necessary conditions used for the ends: {used}"),
    })
}
