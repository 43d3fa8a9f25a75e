//! Join conditions between two segments and the control points they force,
//! derived exactly in the symbolic ring.
//!
//! Two segments `Q₁ = Σ bᵢ(·; p₁) Pᵢ` and `Q₂ = Σ bᵢ(·; p₂) Qᵢ` of one family
//! (shape parameters `p₁`, `p₂`, equal or different) join at `Q₁(end) = Q₂(start)`
//! with
//!
//! * `Cᵏ`: `Q₂⁽ʲ⁾(0) = Q₁⁽ʲ⁾(1)` for `j = 0…k`;
//! * `G¹`: `Q₂(0) = Q₁(1)`, `Q₂'(0) = α Q₁'(1)` (`α > 0`);
//! * `G²`: additionally `Q₂''(0) = α² Q₁''(1) + β Q₁'(1)`,
//!
//! derivatives taken in one convention ([`Wrt`]): the angle `θ`, `u` with
//! `θ = πu/2`, or a data abscissa `x` with interval lengths `h₁`, `h₂` (so the
//! two sides carry different rates `π/(2h₁)`, `π/(2h₂)`). The conditions are
//! linear in the second segment's control points; [`solve_join`] eliminates
//! them in index order (Gauss–Jordan over the symbolic field), so each forced
//! point is an exact formula in the first segment's points, the remaining free
//! points, the parameters and `α`, `β`. Every pivot is reported: where it
//! vanishes (e.g. `m = −2` for the thesis basis) the formula is singular.

use std::fmt;
use std::str::FromStr;

use trig_core::{Basis, Family, Ring};
use trig_symbolic::Sym;

use crate::table::{End, Wrt, endpoint_derivatives};

/// Orders `0…3` of every derivative a join can involve.
const ORDERS: usize = 4;

/// The kind of join.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JoinKind {
    /// Parametric continuity `Cᵏ`, `k = 0…3`.
    C(u8),
    /// `Q₂'(0) = α Q₁'(1)`.
    G1,
    /// `G¹` and `Q₂''(0) = α² Q₁''(1) + β Q₁'(1)`.
    G2,
}

impl JoinKind {
    /// Every kind, in order.
    pub const ALL: [JoinKind; 6] = [
        JoinKind::C(0),
        JoinKind::C(1),
        JoinKind::C(2),
        JoinKind::C(3),
        JoinKind::G1,
        JoinKind::G2,
    ];

    /// The highest derivative order the conditions involve.
    pub fn order(&self) -> usize {
        match self {
            JoinKind::C(k) => usize::from(*k),
            JoinKind::G1 => 1,
            JoinKind::G2 => 2,
        }
    }

    /// The right-hand side of the order-`j` condition from the first
    /// segment's derivatives `d` at its end (orders `0…`), with the `G`
    /// factors `α`, `β`.
    fn target(&self, j: usize, d: &[Sym], [alpha, beta]: &[Sym; 2]) -> Sym {
        match (self, j) {
            (JoinKind::C(_), _) | (_, 0) => d[j].clone(),
            (JoinKind::G1 | JoinKind::G2, 1) => alpha.clone() * &d[1],
            (JoinKind::G2, 2) => alpha.square() * &d[2] + &(beta.clone() * &d[1]),
            _ => unreachable!("order {j} exceeds the kind's order"),
        }
    }
}

impl fmt::Display for JoinKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            JoinKind::C(k) => write!(f, "C{k}"),
            JoinKind::G1 => f.write_str("G1"),
            JoinKind::G2 => f.write_str("G2"),
        }
    }
}

impl FromStr for JoinKind {
    type Err = JoinError;

    fn from_str(s: &str) -> Result<Self, JoinError> {
        match s.to_ascii_lowercase().as_str() {
            "c0" => Ok(JoinKind::C(0)),
            "c1" => Ok(JoinKind::C(1)),
            "c2" => Ok(JoinKind::C(2)),
            "c3" => Ok(JoinKind::C(3)),
            "g1" => Ok(JoinKind::G1),
            "g2" => Ok(JoinKind::G2),
            _ => Err(JoinError::UnknownKind(s.to_string())),
        }
    }
}

/// Why a join cannot be solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JoinError {
    #[error("unknown join kind `{0}` (expected c0, c1, c2, c3, g1 or g2)")]
    UnknownKind(String),
    #[error("{kind} needs {needed} control points per segment; the family has {available}")]
    TooFewPoints {
        kind: JoinKind,
        needed: usize,
        available: usize,
    },
    #[error("the order-{order} condition of {kind} cannot be met: it reduces to {residual} = 0")]
    Inconsistent {
        kind: JoinKind,
        order: usize,
        residual: String,
    },
}

/// The usual names of the `G¹`/`G²` factors: `α`, `β`.
pub fn default_factors() -> [Sym; 2] {
    [Sym::var("alpha"), Sym::var("beta")]
}

/// The names of the `G¹`/`G²` factors of a join of a basis with the
/// parameters `params`: `alpha`, `beta`, or `gamma`, `delta` when a
/// parameter is called `alpha` or `beta`.
pub fn factor_names(params: &[String]) -> [String; 2] {
    if params.iter().any(|p| p == "alpha" || p == "beta") {
        ["gamma".into(), "delta".into()]
    } else {
        ["alpha".into(), "beta".into()]
    }
}

/// Two segments of one basis (a catalog family or a spec file) meeting at
/// a join.
#[derive(Debug, Clone)]
pub struct JoinSetup<'a, B: Basis = Family> {
    pub basis: B,
    /// Shape parameters of the first segment `Q₁`.
    pub first_params: &'a [Sym],
    /// Shape parameters of the second segment `Q₂`.
    pub second_params: &'a [Sym],
    /// Derivative convention.
    pub wrt: Wrt,
    /// Interval lengths of the two segments (used by [`Wrt::X`] only).
    pub h: (Sym, Sym),
    /// The symbols of the `G` factors `α`, `β` ([`default_factors`]; a spec
    /// whose parameter is called `alpha` renames them).
    pub factors: [Sym; 2],
}

/// The derivatives of orders `0…3` of every function of a setup's basis at
/// the end of the first segment and at the start of the second, in the
/// setup's convention: what every residual of one setup shares, whatever
/// the control points ([`JoinSetup::end_derivatives`]).
#[derive(Debug, Clone)]
pub struct EndDerivatives {
    /// `bᵢ⁽ʲ⁾(end; p₁)`, indexed `[i][j]`.
    first: Vec<Vec<Sym>>,
    /// `bᵢ⁽ʲ⁾(start; p₂)`, indexed `[i][j]`.
    second: Vec<Vec<Sym>>,
}

impl<B: Basis> JoinSetup<'_, B> {
    /// The basis's derivatives at the join ([`EndDerivatives`]).
    pub fn end_derivatives(&self) -> EndDerivatives {
        let at = |params: &[Sym], end: End, h: &Sym| {
            endpoint_derivatives::<Sym, ORDERS>(&self.basis, params, end, self.wrt, h)
        };
        EndDerivatives {
            first: at(self.first_params, End::End, &self.h.0),
            second: at(self.second_params, End::Start, &self.h.1),
        }
    }

    /// `Q₂⁽ʲ⁾(0) − target_j(Q₁)` for `j = 0…order`, for the given control
    /// points (symbols, numbers or printed formulas): all zero exactly when
    /// the join holds.
    pub fn residuals(&self, kind: JoinKind, first: &[Sym], second: &[Sym]) -> Vec<Sym> {
        self.residuals_with(&self.end_derivatives(), kind, first, second)
    }

    /// [`JoinSetup::residuals`] from derivatives computed once
    /// ([`JoinSetup::end_derivatives`] of this setup).
    pub fn residuals_with(
        &self,
        ends: &EndDerivatives,
        kind: JoinKind,
        first: &[Sym],
        second: &[Sym],
    ) -> Vec<Sym> {
        let q1 = curve(&ends.first, first);
        let q2 = curve(&ends.second, second);
        (0..=kind.order())
            .map(|j| q2[j].clone() - &kind.target(j, &q1, &self.factors))
            .collect()
    }
}

/// `(Σ bᵢ Pᵢ)⁽ʲ⁾ = Σ bᵢ⁽ʲ⁾ Pᵢ` for `j = 0…3`.
///
/// # Panics
/// If there is not one point per function.
fn curve(functions: &[Vec<Sym>], points: &[Sym]) -> Vec<Sym> {
    assert_eq!(
        functions.len(),
        points.len(),
        "one control point per function"
    );
    (0..ORDERS)
        .map(|j| {
            functions
                .iter()
                .zip(points)
                .fold(Sym::zero(), |acc, (b, p)| acc + &(b[j].clone() * p))
        })
        .collect()
}

/// One control point of the second segment forced by the join.
#[derive(Debug, Clone)]
pub struct Forced {
    /// Index in the second segment.
    pub index: usize,
    /// Its formula in the first segment's points, the free points of the
    /// second segment, the parameters, `α`, `β`.
    pub value: Sym,
    /// The pivot divided by in the elimination; the formula is singular
    /// where it vanishes.
    pub pivot: Sym,
}

/// The solved join: forced points in index order.
#[derive(Debug, Clone)]
pub struct Join {
    pub kind: JoinKind,
    pub forced: Vec<Forced>,
    /// The `G²` factor `β` and its value when a condition involves no free
    /// control point of the second segment but is met, for every control
    /// point, by that value of `β` alone (a `G²` join is the existence of
    /// such factors).
    pub factor: Option<(Sym, Sym)>,
}

impl Join {
    /// The second segment's control points with the forced ones substituted
    /// (the free ones stay the given symbols).
    pub fn second_points(&self, symbols: &[Sym]) -> Vec<Sym> {
        let mut points = symbols.to_vec();
        for f in &self.forced {
            points[f.index] = f.value.clone();
        }
        points
    }
}

/// Solves the join conditions for the second segment's control points,
/// named by `second` (symbols), with the first segment's points `first`;
/// each condition is solved for its first free point in index order.
pub fn solve_join<B: Basis>(
    setup: &JoinSetup<'_, B>,
    kind: JoinKind,
    first: &[Sym],
    second: &[Sym],
) -> Result<Join, JoinError> {
    solve_join_for(setup, kind, first, second, &[])
}

/// [`solve_join`], each condition solved for the first point of `prefer`
/// (indices of the second segment) that it involves and that is still
/// free, else for its first free point in index order — so a derived
/// formula can be shown for the point a paper prints.
pub fn solve_join_for<B: Basis>(
    setup: &JoinSetup<'_, B>,
    kind: JoinKind,
    first: &[Sym],
    second: &[Sym],
    prefer: &[usize],
) -> Result<Join, JoinError> {
    solve_join_with(setup, &setup.end_derivatives(), kind, first, second, prefer)
}

/// [`solve_join_for`] from derivatives computed once
/// ([`JoinSetup::end_derivatives`] of `setup`).
pub fn solve_join_with<B: Basis>(
    setup: &JoinSetup<'_, B>,
    ends: &EndDerivatives,
    kind: JoinKind,
    first: &[Sym],
    second: &[Sym],
    prefer: &[usize],
) -> Result<Join, JoinError> {
    let needed = kind.order() + 1;
    if second.len() < needed {
        return Err(JoinError::TooFewPoints {
            kind,
            needed,
            available: second.len(),
        });
    }
    let names: Vec<String> = second.iter().map(|q| q.to_string()).collect();
    let mut forced: Vec<Forced> = Vec::new();
    let mut factor: Option<(Sym, Sym)> = None;
    for (order, residual) in setup
        .residuals_with(ends, kind, first, second)
        .into_iter()
        .enumerate()
    {
        let reduced = forced
            .iter()
            .fold(residual, |r, f| r.subs(&names[f.index], &f.value));
        let pivot_index = prefer
            .iter()
            .copied()
            .filter(|i| *i < second.len())
            .chain(0..second.len())
            .filter(|i| forced.iter().all(|f| f.index != *i))
            .find(|&i| !reduced.diff(&names[i]).is_zero());
        let Some(index) = pivot_index else {
            if reduced.is_zero() {
                continue;
            }
            if let Some(value) = factor_value(setup, kind, &reduced, first, second) {
                factor = Some((setup.factors[1].clone(), value));
                continue;
            }
            return Err(JoinError::Inconsistent {
                kind,
                order,
                residual: reduced.to_unicode(),
            });
        };
        let pivot = reduced.diff(&names[index]);
        let rest = reduced - &(pivot.clone() * &second[index]);
        let value = -(rest / &pivot);
        for f in &mut forced {
            f.value = f.value.subs(&names[index], &value);
        }
        forced.push(Forced {
            index,
            value,
            pivot,
        });
    }
    forced.sort_by_key(|f| f.index);
    Ok(Join {
        kind,
        forced,
        factor,
    })
}

/// The value of the `G²` factor `β` that makes the condition `residual = 0`
/// hold for every control point, when it is linear in `β` and that value
/// involves no control point; `None` otherwise (or for another kind).
fn factor_value<B: Basis>(
    setup: &JoinSetup<'_, B>,
    kind: JoinKind,
    residual: &Sym,
    first: &[Sym],
    second: &[Sym],
) -> Option<Sym> {
    if kind != JoinKind::G2 {
        return None;
    }
    let beta = setup.factors[1].to_string();
    let slope = residual.diff(&beta);
    if slope.is_zero() || !slope.diff(&beta).is_zero() {
        return None;
    }
    let value = -((residual.clone() - &(slope.clone() * &setup.factors[1])) / &slope);
    let points = first.iter().chain(second);
    points
        .map(ToString::to_string)
        .all(|p| value.diff(&p).is_zero())
        .then_some(value)
}

/// Where `pivot` vanishes, as readable conditions: `m = −2` when it is
/// linear in one variable (up to a constant factor and powers of `π`),
/// otherwise `pivot = 0`. Empty when it is a nonzero constant.
pub fn vanishing(pivot: &Sym) -> Vec<String> {
    let num = pivot.numerator();
    let vars: Vec<String> = num.variables().into_iter().filter(|v| v != "pi").collect();
    if vars.is_empty() {
        return Vec::new();
    }
    if vars.len() == 1 && num.degree_in(&vars[0]) == 1 {
        let v = &vars[0];
        let root = num.subs(v, &trig_symbolic::Poly::zero());
        let slope = num.diff(v);
        if let Some(q) = (Sym::from_poly(root) / &Sym::from_poly(slope)).as_rational() {
            return vec![format!(
                "{} = {}",
                Sym::var(v).to_unicode(),
                Sym::rational(-q).to_unicode()
            )];
        }
    }
    vec![format!("{} = 0", pivot.to_unicode())]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(prefix: &str, n: usize) -> Vec<Sym> {
        (0..n).map(|i| Sym::var(&format!("{prefix}{i}"))).collect()
    }

    fn setup<'a>(family: Family, p1: &'a [Sym], p2: &'a [Sym], wrt: Wrt) -> JoinSetup<'a> {
        JoinSetup {
            basis: family,
            first_params: p1,
            second_params: p2,
            wrt,
            h: (Sym::var("h1"), Sym::var("h2")),
            factors: default_factors(),
        }
    }

    /// The shared end derivatives give the curve derivatives of
    /// [`curve_endpoint_derivatives`] (`Σ bᵢ⁽ʲ⁾Pᵢ` against `(Σ bᵢPᵢ)⁽ʲ⁾`).
    #[test]
    fn end_derivatives_give_the_curve_derivatives() {
        let (p, q) = (pts("P", 4), pts("Q", 4));
        let (m1, m2) = ([Sym::var("m1")], [Sym::var("m2")]);
        for wrt in [Wrt::Angle, Wrt::U, Wrt::X] {
            let s = setup(Family::ThesisCubic, &m1, &m2, wrt);
            let curve = |params: &[Sym], points: &[Sym], end: End, h: &Sym| {
                crate::table::curve_endpoint_derivatives::<Sym, ORDERS>(
                    Family::ThesisCubic,
                    params,
                    points,
                    None,
                    end,
                    wrt,
                    h,
                )
            };
            let q1 = curve(&m1, &p, End::End, &s.h.0);
            let q2 = curve(&m2, &q, End::Start, &s.h.1);
            let expected: Vec<Sym> = (0..4).map(|j| q2[j].clone() - &q1[j]).collect();
            assert_eq!(s.residuals(JoinKind::C(3), &p, &q), expected, "{wrt:?}");
        }
    }

    #[test]
    fn bernstein_c2_is_the_classical_a_frame() {
        let (p, q) = (pts("P", 4), pts("Q", 4));
        let s = setup(Family::Bernstein3, &[], &[], Wrt::U);
        let join = solve_join(&s, JoinKind::C(2), &p, &q).unwrap();
        let two = Sym::int(2);
        // Q0 = P3, Q1 = 2P3 − P2, Q2 = P1 − 4P2 + 4P3
        assert_eq!(join.forced[0].value, p[3]);
        assert_eq!(join.forced[1].value, two.clone() * &p[3] - &p[2]);
        let q2 = p[1].clone() - &(Sym::int(4) * &p[2]) + &(Sym::int(4) * &p[3]);
        assert_eq!(join.forced[2].value, q2);
        // and the joined points satisfy every condition exactly
        let residuals = s.residuals(JoinKind::C(2), &p, &join.second_points(&q));
        assert!(residuals.iter().all(Sym::is_zero));
        // a wrong formula leaves a residual
        let mut wrong = join.second_points(&q);
        wrong[1] = two * &p[3] + &p[2];
        assert!(!s.residuals(JoinKind::C(1), &p, &wrong)[1].is_zero());
    }

    #[test]
    fn thesis_c1_pivot_vanishes_at_m_minus_two() {
        let (p, q) = (pts("P", 4), pts("Q", 4));
        let (m1, m2) = ([Sym::var("m1")], [Sym::var("m2")]);
        let s = setup(Family::ThesisCubic, &m1, &m2, Wrt::Angle);
        let join = solve_join(&s, JoinKind::C(1), &p, &q).unwrap();
        assert_eq!(
            vanishing(&join.forced[1].pivot),
            vec!["m₂ = −2".to_string()]
        );
        assert!(vanishing(&join.forced[0].pivot).is_empty());
    }

    #[test]
    fn x_convention_scales_by_the_interval_ratio() {
        let (p, q) = (pts("P", 4), pts("Q", 4));
        let s = setup(Family::Bernstein3, &[], &[], Wrt::X);
        let join = solve_join(&s, JoinKind::C(1), &p, &q).unwrap();
        // Q1 = P3 + (h2/h1)(P3 − P2)
        let ratio = Sym::var("h2") / &Sym::var("h1");
        let expected = p[3].clone() + &(ratio * &(p[3].clone() - &p[2]));
        assert_eq!(join.forced[1].value, expected);
    }

    #[test]
    fn kinds_parse_and_reject_unknown_names() {
        assert_eq!("G2".parse::<JoinKind>(), Ok(JoinKind::G2));
        assert!(matches!(
            "c9".parse::<JoinKind>(),
            Err(JoinError::UnknownKind(_))
        ));
        let (p, q) = (pts("P", 2), pts("Q", 2));
        let s = setup(Family::Bernstein3, &[], &[], Wrt::U);
        assert!(matches!(
            solve_join(&s, JoinKind::C(2), &p, &q),
            Err(JoinError::TooFewPoints { .. })
        ));
    }
}
