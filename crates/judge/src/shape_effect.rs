//! The shape-effect judge: how the weights `bᵢ` of a curve `Σ bᵢPᵢ` move
//! as one shape parameter `p` increases, for any basis.
//!
//! Papers print "the curve approaches the control polygon as `p`
//! increases" without a definition. The weakest reasonable one, stated in
//! every verdict: on the whole domain and parameter box the end weights do
//! not increase and the inner weights do not decrease,
//!
//! `∂b₀/∂p ≤ 0`, `∂bₙ/∂p ≤ 0`, `∂bᵢ/∂p ≥ 0` (`0 < i < n`),
//!
//! so weight moves monotonically from the end control points to the inner
//! ones at every point of the curve ("towards the polygon"); "away from
//! the polygon" is the opposite. A claim about other target points (a
//! segment `P_{i−3}P_{i−1}` of a B-spline segment) names them: their
//! weights rise, the others' fall ([`ONTO`], [`target_moves`]). A printed
//! "as `p` increases (or decreases)" holds when one direction holds
//! ([`either_way`]); several parameters changed concurrently,
//! `pₖ = pₖ₀ + τ`, move the weights by the total derivative
//! `∂bᵢ/∂τ = Σₖ ∂bᵢ/∂pₖ` ([`CONCURRENT`]; seed 004 §IV (i)–(iii)).
//!
//! Each sign is decided by the one certification engine on the exact
//! derivative `∂bᵢ/∂p` at a fixed point of the variable
//! ([`trig_certify::atoms::d_param`]: the parameter and its atoms
//! `sin(bp)`, `exp(bp)`; on a domain `[a, b]` that moves with `p`, at a
//! fixed point of `u = (x − a)/(b − a)`): exact Bernstein
//! subdivision over (z = tan(θ/2) or t) × parameter box on the standard
//! pieces of the domain, the interval engine ([`super::by_intervals`])
//! for other bases. A failure shows an exact point and the derivative's
//! exact value there.

use rug::Rational;
use trig_certify::atoms::{d_param, d_variable, param_atoms};
use trig_certify::branch::Axis;
use trig_certify::nonneg::{BoxCertificate, certify_box};
use trig_certify::{ParamBox, standardize};
use trig_core::{Affine, ParamRange, Parameter};
use trig_specfile::{Direction, Target};
use trig_symbolic::Sym;

use super::by_intervals;
use super::certificate::{CERTIFIED, counterexample};
use crate::exact::{ExactBasis, basis_of};
use trig_verdict::evidence::{Evidence, Expr, Kind, Value};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How a shape effect is decided, as the report states it.
pub const SHAPE: &str =
    "certified sign of the exact derivative ∂b_i/∂p on the whole domain × parameter box; ";

/// The definition of "towards the control polygon", as the report states it.
pub const TOWARDS: &str = "definition (weakest reasonable; the source gives none): the curve Σ b_i P_i moves towards its control polygon as the parameter increases when, on the whole domain and parameter box, the end weights do not increase and the inner weights do not decrease (∂b_0/∂p ≤ 0, ∂b_n/∂p ≤ 0, ∂b_i/∂p ≥ 0 for 0 < i < n): weight moves monotonically from the end control points to the inner ones; away from the polygon is the opposite";

/// The definition of "approaches the control points `P_a, P_b, …`" (a
/// segment of the polygon), as the report states it.
pub const ONTO: &str = "definition (weakest reasonable; the source gives none): the curve Σ b_i P_i approaches the named control points (a segment P_aP_b of its polygon) as the parameter increases when, on the whole domain and parameter box, their weights do not decrease and the weights of the other control points do not increase (weight moves monotonically onto them)";

/// How a concurrent change of several parameters is decided, as the report
/// states it.
pub const CONCURRENT: &str = "the parameters change concurrently, each p_k = p_k0 + τ: the weights move with the total derivative ∂b_i/∂τ = Σ_k ∂b_i/∂p_k, certified on the whole box of starting values (the weakest reasonable reading of \"concurrent increasing\")";

/// How one weight is claimed to move as the parameter increases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Move {
    /// `∂bᵢ/∂p ≥ 0`.
    Increases,
    /// `∂bᵢ/∂p ≤ 0`.
    Decreases,
}

impl Move {
    /// The move as the parameter decreases.
    pub fn reversed(self) -> Self {
        match self {
            Self::Increases => Self::Decreases,
            Self::Decreases => Self::Increases,
        }
    }
}

/// The moves of `n` weights for a direction: towards the polygon, the end
/// weights decrease and the inner ones increase; away, the opposite.
pub fn moves(direction: Direction, n: usize) -> Vec<Move> {
    let (end, inner) = match direction {
        Direction::TowardsPolygon => (Move::Decreases, Move::Increases),
        Direction::AwayFromPolygon => (Move::Increases, Move::Decreases),
    };
    (0..n)
        .map(|i| if i == 0 || i + 1 == n { end } else { inner })
        .collect()
}

/// The moves of `n` weights for a target as the parameters increase: onto
/// named control points, theirs rise and the others fall.
pub fn target_moves(target: &Target, n: usize) -> Vec<Move> {
    match target {
        Target::Polygon(direction) => moves(*direction, n),
        Target::Onto(points) => (0..n)
            .map(|i| {
                if points.contains(&i) {
                    Move::Increases
                } else {
                    Move::Decreases
                }
            })
            .collect(),
    }
}

/// A printed shape effect: the curve goes to `target` as the `parameters`
/// increase (several: concurrently, [`CONCURRENT`]; `either`: "increases
/// (or decreases)", [`either_way`]); `range`: the one parameter's range,
/// the declared one unless given; the other parameters over their declared
/// ranges. Under the definition [`TOWARDS`] or [`ONTO`].
pub fn shape_effect<B: ExactBasis>(
    basis: &B,
    parameters: &[String],
    target: &Target,
    either: bool,
    range: Option<&ParamRange>,
) -> Verdict {
    let ranges: Vec<(&str, ParamRange)> = parameters
        .first()
        .zip(range)
        .map(|(p, r)| (p.as_str(), r.clone()))
        .into_iter()
        .collect();
    let names: Vec<&str> = parameters.iter().map(String::as_str).collect();
    let rising = target_moves(target, basis.function_names().len());
    let mut v = if either {
        let falling: Vec<Move> = rising.iter().map(|m| m.reversed()).collect();
        either_way(
            weights_move(basis, &names, &rising, &ranges),
            weights_move(basis, &names, &falling, &ranges),
        )
    } else {
        weights_move(basis, &names, &rising, &ranges)
    };
    if parameters.len() > 1 {
        v.evidence.insert(0, CONCURRENT);
    }
    let definition = match target {
        Target::Polygon(_) => TOWARDS,
        Target::Onto(_) => ONTO,
    };
    v.evidence.insert(0, definition);
    v
}

/// A printed alternative "as `p` increases (or decreases)": holds when one
/// of the two directions holds, and then that direction's evidence decides
/// (the other is summarised); otherwise both are shown.
pub fn either_way(increasing: Verdict, decreasing: Verdict) -> Verdict {
    let method = increasing.method.clone();
    let named = [
        ("as the parameter increases", increasing),
        ("as the parameter decreases", decreasing),
    ];
    let mut v = match named.iter().position(|(_, v)| v.status == Status::Holds) {
        Some(k) => {
            let [a, b] = named;
            let ((name, holds), (other, rest)) = if k == 0 { (a, b) } else { (b, a) };
            let mut v = Verdict::all(method, vec![(name.to_string(), holds)]);
            v.evidence.push(Evidence::note(format!(
                "{other}: {} (every move reverses), not the direction that decides",
                rest.status
            )));
            v
        }
        None => Verdict::all(
            method,
            named.into_iter().map(|(n, v)| (n.to_string(), v)).collect(),
        ),
    };
    v.evidence.insert(
        0,
        "printed \"increases (or decreases)\": holds when one direction holds",
    );
    v
}

/// Each weight `bᵢ` moves as `moves[i]` states when the `params` increase
/// (several: concurrently, by the total derivative `Σₖ ∂bᵢ/∂pₖ`), on the
/// whole domain and the parameter box: each parameter over `ranges` where
/// given (a point range `[v, v]` fixes it), its declared range otherwise.
pub fn weights_move<B: ExactBasis>(
    basis: &B,
    params: &[&str],
    moves: &[Move],
    ranges: &[(&str, ParamRange)],
) -> Verdict {
    let declared = basis.parameters();
    let mut indices = Vec::new();
    for param in params {
        let Some(index) = declared.iter().position(|p| p.name == *param) else {
            return Verdict::not_checkable(format!("the basis has no parameter `{param}`"));
        };
        indices.push(index);
    }
    let symbols: Vec<String> = indices
        .iter()
        .map(|&i| declared[i].symbol.clone())
        .collect();
    let domain = basis.domain();
    if let Some(symbol) = indices
        .iter()
        .zip(&symbols)
        .find(|(index, _)| {
            domain
                .angle
                .as_ref()
                .is_some_and(|w| w.params.iter().any(|(i, _)| i == *index))
        })
        .map(|(_, s)| s)
    {
        return Verdict::not_checkable(format!(
            "{symbol} changes the angle's rate: the weights at a fixed point of the normalised variable are not formed here; not decided"
        ));
    }
    let atoms = param_atoms(&domain);
    let chosen: Vec<(&Parameter, ParamRange)> = declared
        .iter()
        .map(|p| {
            let r = ranges
                .iter()
                .find(|(n, _)| *n == p.name)
                .map_or_else(|| p.range.clone(), |(_, r)| r.clone());
            (p, r)
        })
        .collect();
    let mut evidence = Vec::new();
    let mut velocities = Vec::new();
    for (&index, symbol) in indices.iter().zip(&symbols) {
        let moving = normalised_velocity(&domain, index);
        if moving.is_some() {
            evidence.push(Evidence::note(format!("the domain [{}, {}] moves with {symbol}: the weights are compared at a fixed point of the normalised variable u = (x − a)/(b − a), x = a + (b − a)u, so ∂b_i/∂{symbol} below is the total derivative ∂b_i/∂{symbol} + (∂x/∂{symbol})·∂b_i/∂x with ∂x/∂{symbol} = a' + (b' − a')(x − a)/(b − a)", domain.start.text(&domain.param_names), domain.end.text(&domain.param_names))));
        }
        velocities.push(moving);
    }
    evidence.push(Evidence::note(format!(
        "parameter box {}",
        chosen
            .iter()
            .map(|(p, r)| format!("{} ∈ {r}", p.symbol))
            .collect::<Vec<_>>()
            .join(" × ")
    )));
    // how the change is named: "μ" alone, "λ, μ" together
    let (with, as_) = match symbols.as_slice() {
        [one] => (one.clone(), format!("{one} increases")),
        several => {
            let all = several.join(", ");
            (
                format!("{all} together"),
                format!("{all} increase together"),
            )
        }
    };
    let mut status = Status::Holds;
    let mut interval = false;
    for ((f, name), m) in basis_of(basis)
        .iter()
        .zip(basis.function_names())
        .zip(moves)
    {
        let d = indices
            .iter()
            .zip(&velocities)
            .fold(Sym::zero(), |acc, (&index, moving)| {
                let mut d = d_param(f, &domain, index, &atoms);
                if let Some(v) = moving {
                    d = d + &(v.clone() * &d_variable(f, &domain));
                }
                acc + &d
            });
        let label = symbols
            .iter()
            .map(|s| format!("∂{name}/∂{s}"))
            .collect::<Vec<_>>()
            .join(" + ");
        let subject = match m {
            Move::Increases => format!("{label} ≥ 0 ({name} increases with {with})"),
            Move::Decreases => format!("{label} ≤ 0 ({name} decreases as {as_})"),
        };
        let (s, text, witness) = if d.is_zero() {
            let free = if symbols.len() == 1 {
                format!("{name} does not depend on {with}")
            } else {
                format!("{name} does not change as {as_}")
            };
            (Status::Holds, format!("{label} ≡ 0 exactly ({free})"), None)
        } else {
            let g = match m {
                Move::Increases => d.clone(),
                Move::Decreases => -d.clone(),
            };
            let sign = match m {
                Move::Increases => Rational::from(1),
                Move::Decreases => Rational::from(-1),
            };
            match standardized(basis, &g, &chosen) {
                Some(pieces) => certified(&pieces, &chosen, &label, &sign),
                None => {
                    interval = true;
                    let tested = match m {
                        Move::Increases => label.clone(),
                        Move::Decreases => format!("−{label}"),
                    };
                    by_interval_engine(basis, &tested, &g, &chosen)
                }
            }
        };
        status = Status::conjunction([status, s]);
        evidence.push(
            Evidence::new(Kind::Certificate, text)
                .about(subject, s)
                .with(label, Expr::new(&d))
                .witnessed(witness),
        );
    }
    let engine = if interval {
        by_intervals::INTERVAL
    } else {
        CERTIFIED
    };
    Verdict::new(status, format!("{SHAPE}{engine}"), evidence)
}

/// `∂x/∂p` at a fixed `u` for `x = a + (b − a)u` on a domain `[a, b]` that
/// moves with the parameter `index`: `a' + (b' − a')(x − a)/(b − a)`
/// (`a'`, `b'` the rational coefficients of the parameter in the ends);
/// `None` when the ends do not contain it.
fn normalised_velocity(domain: &trig_core::Domain, index: usize) -> Option<Sym> {
    let rate = |a: &Affine| {
        a.params
            .iter()
            .find(|(i, _)| *i == index)
            .map(|(_, q)| q.clone())
    };
    let (da, db) = (rate(&domain.start), rate(&domain.end));
    if da.is_none() && db.is_none() {
        return None;
    }
    let (da, db) = (da.unwrap_or_default(), db.unwrap_or_default());
    let params: Vec<Sym> = domain.param_names.iter().map(|n| Sym::var(n)).collect();
    let one = Sym::one();
    let (a, b) = (
        domain.start.eval(&one, &params),
        domain.end.eval(&one, &params),
    );
    let x = Sym::var("t");
    let slope = Sym::rational(Rational::from(&db - &da));
    Some(Sym::rational(da) + &(slope * &(x - &a) / &(b - &a)))
}

/// The standard pieces of `g` with whether they are trigonometric, or
/// `None` when the Bernstein path does not apply (not polynomial in `sin`,
/// `cos` or the variable on a standard domain, or a range in multiples
/// of π).
fn standardized<B: ExactBasis>(
    basis: &B,
    g: &Sym,
    chosen: &[(&Parameter, ParamRange)],
) -> Option<(bool, Vec<(Sym, String)>)> {
    if chosen.iter().any(|(_, r)| r.pi) {
        return None;
    }
    let st = standardize(g, &basis.domain()).ok()?;
    Some((
        st.trigonometric,
        st.pieces.into_iter().zip(st.labels).collect(),
    ))
}

/// The Bernstein certificate of `g ≥ 0` on every piece (`g = sign·∂bᵢ/∂p`):
/// a counterexample shows the derivative's exact value.
fn certified(
    (trig, pieces): &(bool, Vec<(Sym, String)>),
    chosen: &[(&Parameter, ParamRange)],
    label: &str,
    sign: &Rational,
) -> (Status, String, Option<trig_verdict::evidence::Witness>) {
    // only the parameters the derivative contains: a box of a parameter
    // that does not occur adds nothing to decide (and an open end of it
    // would hide every witness on its excluded faces)
    let occurring = pieces
        .iter()
        .flat_map(|(piece, _)| piece.variables())
        .collect::<std::collections::BTreeSet<String>>();
    let boxes: Vec<(&str, ParamBox)> = chosen
        .iter()
        .filter(|(p, _)| occurring.contains(&p.name))
        .map(|(p, r)| (p.name.as_str(), ParamBox::from_range(r)))
        .collect();
    let mut total = 0;
    for (piece, where_) in pieces {
        let on = if where_.is_empty() {
            String::new()
        } else {
            format!(" on {where_}")
        };
        match certify_box(piece, *trig, &boxes) {
            BoxCertificate::NonNegative { boxes } => total += boxes,
            BoxCertificate::Counterexample { params, z, value } => {
                let named: Vec<(&str, &Rational)> = boxes
                    .iter()
                    .zip(&params)
                    .map(|((n, _), v)| (*n, v))
                    .collect();
                let mut w = counterexample(&named, &z, &value, *trig, None);
                let derivative = Rational::from(sign * &value);
                w.values = vec![Value {
                    of: None,
                    label: format!("{label}{on}"),
                    value: Expr::new(&Sym::rational(derivative)),
                }];
                return (
                    Status::Fails,
                    format!(
                        "violated{on}: the weight moves the other way at the witness point (exact)"
                    ),
                    Some(w),
                );
            }
            BoxCertificate::Pole(why) => {
                return (
                    Status::Fails,
                    format!("not defined on the whole domain and box{on}: {why}"),
                    None,
                );
            }
            BoxCertificate::Undecided(why) => {
                return (Status::NotCheckable, format!("undecided{on} ({why})"), None);
            }
        }
    }
    (
        Status::Holds,
        format!(
            "certified on the whole domain and box ({})",
            trig_verdict::plural(total, "Bernstein box", "Bernstein boxes")
        ),
        None,
    )
}

/// The interval engine on `g ≥ 0`, `g` shown as `tested` (bounded ranges
/// only).
fn by_interval_engine<B: ExactBasis>(
    basis: &B,
    tested: &str,
    g: &Sym,
    chosen: &[(&Parameter, ParamRange)],
) -> (Status, String, Option<trig_verdict::evidence::Witness>) {
    let axes: Option<Vec<Axis>> = chosen.iter().map(|(_, r)| Axis::from_range(r)).collect();
    let Some(axes) = axes else {
        return (
            Status::NotCheckable,
            "not polynomial in sin, cos or the variable on a standard domain, and a range is unbounded: the interval engine needs bounded ranges".into(),
            None,
        );
    };
    let (s, line) = by_intervals::nonnegative(basis, tested, g, &axes);
    (s, format!("interval engine: {line}"), None)
}

/// A point of the plane, exactly.
pub type Point = (Rational, Rational);

/// `‖X − Y‖²` for the point `X` nearest to `p` on the polygon's edges
/// (each edge `AB`: the projection `A + τ(B − A)`, `τ` clamped to
/// `[0, 1]`), exact.
pub fn squared_distance_to_polygon(p: &Point, polygon: &[Point]) -> Option<Rational> {
    polygon
        .windows(2)
        .map(|edge| {
            let (a, b) = (&edge[0], &edge[1]);
            let (ux, uy) = (Rational::from(&b.0 - &a.0), Rational::from(&b.1 - &a.1));
            let (vx, vy) = (Rational::from(&p.0 - &a.0), Rational::from(&p.1 - &a.1));
            let len = Rational::from(&ux * &ux) + Rational::from(&uy * &uy);
            let tau = if len == 0 {
                Rational::new()
            } else {
                let dot = Rational::from(&ux * &vx) + Rational::from(&uy * &vy);
                (dot / len).max(Rational::new()).min(Rational::from(1))
            };
            let dx = vx - Rational::from(&tau * &ux);
            let dy = vy - tau * uy;
            Rational::from(&dx * &dx) + Rational::from(&dy * &dy)
        })
        .min()
}

/// An explicit quantity for a printed polygon, shown beside the verdict
/// (it illustrates, the weights decide): the squared distance from the
/// curve point `Σ bᵢ(x)Pᵢ` at one exact point `x` of the variable (`at`:
/// the atoms `s`, `c` or `t`, and parameters held fixed) to the polygon,
/// for each value of `param`.
pub fn polygon_distances<B: ExactBasis>(
    basis: &B,
    polygon: &[Point],
    at: &[(&str, Rational)],
    param: &str,
    values: &[Rational],
) -> Evidence {
    let fs = basis_of(basis);
    let symbol = basis
        .parameters()
        .into_iter()
        .find(|p| p.name == param)
        .map_or_else(|| param.to_string(), |p| p.symbol);
    let shown: Vec<String> = polygon.iter().map(|(x, y)| format!("({x}, {y})")).collect();
    let point: Vec<String> = at.iter().map(|(n, v)| format!("{n} = {v}")).collect();
    let distance = |value: &Rational| -> Option<Rational> {
        let assign = |name: &str| {
            at.iter()
                .find(|(n, _)| *n == name)
                .map(|(_, v)| v.clone())
                .or_else(|| (name == param).then(|| value.clone()))
        };
        let weights: Vec<Rational> = fs
            .iter()
            .map(|f| f.eval_rational(&assign).ok())
            .collect::<Option<_>>()?;
        let coordinate = |k: usize| -> Rational {
            weights
                .iter()
                .zip(polygon)
                .map(|(w, p)| Rational::from(w * if k == 0 { &p.0 } else { &p.1 }))
                .sum()
        };
        squared_distance_to_polygon(&(coordinate(0), coordinate(1)), polygon)
    };
    let found: Option<Vec<Rational>> = values.iter().map(distance).collect();
    let text = match found {
        Some(ds) => {
            let trend = if ds.windows(2).all(|w| w[1] < w[0]) {
                "decreasing: the point moves towards the polygon"
            } else if ds.windows(2).all(|w| w[1] > w[0]) {
                "increasing: the point moves away from the polygon"
            } else {
                "not monotone over these values"
            };
            let list: Vec<String> = values
                .iter()
                .zip(&ds)
                .map(|(v, d)| format!("{symbol} = {v}: {d}"))
                .collect();
            format!(
                "explicit quantity on the printed polygon {} (it illustrates; the weights decide): the squared distance from the curve point at {} to the polygon, exact — {} ({trend})",
                shown.join(", "),
                point.join(", "),
                list.join("; ")
            )
        }
        None => format!(
            "the curve point at {} could not be evaluated exactly",
            point.join(", ")
        ),
    };
    Evidence::new(Kind::Derived, text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    fn range(text: &str) -> ParamRange {
        ParamRange::parse(text).expect("a valid range")
    }

    #[test]
    fn distance_to_a_polygon_is_exact() {
        let q = |a: i64, b: i64| Rational::from((a, b));
        let roof = [
            (q(0, 1), q(0, 1)),
            (q(1, 1), q(2, 1)),
            (q(3, 1), q(2, 1)),
            (q(4, 1), q(0, 1)),
        ];
        // below the top edge y = 2: distance 1 (squared 1) from (2, 1)
        assert_eq!(
            squared_distance_to_polygon(&(q(2, 1), q(1, 1)), &roof),
            Some(q(1, 1))
        );
        // beyond the last vertex: the vertex is nearest
        assert_eq!(
            squared_distance_to_polygon(&(q(5, 1), q(0, 1)), &roof),
            Some(q(1, 1))
        );
        // (2, 0) to the edge (0,0)–(1,2): |2·2 − 0|²/5 = 16/5
        assert_eq!(
            squared_distance_to_polygon(&(q(2, 1), q(0, 1)), &roof[..2]),
            Some(q(16, 5))
        );
    }

    #[test]
    fn towards_means_end_weights_fall_and_inner_weights_rise() {
        use Move::{Decreases as D, Increases as I};
        assert_eq!(moves(Direction::TowardsPolygon, 4), vec![D, I, I, D]);
        assert_eq!(moves(Direction::AwayFromPolygon, 3), vec![I, D, I]);
    }

    #[test]
    fn the_thesis_cubic_approaches_its_polygon_as_m_grows() {
        let m = ["m".to_string()];
        let decide = |d| shape_effect(&Family::ThesisCubic, &m, &Target::Polygon(d), false, None);
        let towards = decide(Direction::TowardsPolygon);
        assert_eq!(towards.status, Status::Holds, "{:?}", towards.evidence);
        let away = decide(Direction::AwayFromPolygon);
        assert_eq!(away.status, Status::Fails);
        // ∂b0/∂m = −s(1 − s)², exactly, at the witness's s
        let w = away
            .evidence
            .iter()
            .find_map(|e| e.witness.as_ref())
            .expect("a witness");
        let s: Rational = w
            .point
            .iter()
            .find(|a| a.name == "s")
            .and_then(|a| a.value.parse().ok())
            .expect("a rational s");
        let expected = -(s.clone() * (Rational::from(1) - s.clone()).square());
        assert_eq!(w.values[0].value.plain, expected.to_string(), "{w:?}");
    }

    #[test]
    fn fixing_a_parameter_is_a_point_range_and_a_missing_one_is_not_checkable() {
        // EH bases (1): ∂b2/∂μ = t²(1 − t)² ≥ 0, ∂b3/∂μ = −t²(1 − t)² ≤ 0,
        // b0, b1 free of μ
        use Move::{Decreases as D, Increases as I};
        let fixed = [("lambda", range("[1/2, 1/2]"))];
        let v = weights_move(&Family::Eh, &["mu"], &[I, D, I, D], &fixed);
        assert_eq!(v.status, Status::Holds, "{:?}", v.evidence);
        assert!(v.evidence.iter().any(|e| e.contains("≡ 0 exactly")));
        let w = weights_move(&Family::Eh, &["mu"], &[I, D, D, I], &fixed);
        assert_eq!(w.status, Status::Fails);
        assert_eq!(
            weights_move(&Family::Eh, &["nu"], &[I, D, I, D], &[]).status,
            Status::NotCheckable
        );
    }

    #[test]
    fn weight_moving_onto_a_segment_holds_in_the_direction_that_decides() {
        // EH (1): as μ increases b2 rises and b3 falls (b0, b1 free of μ):
        // weight moves onto P0, P2 and off P1, P3
        let mu = ["mu".to_string()];
        let decide = |onto: Vec<usize>, either: bool| {
            shape_effect(&Family::Eh, &mu, &Target::Onto(onto), either, None)
        };
        let rising = decide(vec![0, 2], false);
        assert_eq!(rising.status, Status::Holds, "{:?}", rising.evidence);
        assert!(rising.evidence[0].text.starts_with(ONTO));
        // onto P1, P3 only as μ decreases: fails as printed "as μ
        // increases", holds with "(or decreases)", that direction deciding
        assert_eq!(decide(vec![1, 3], false).status, Status::Fails);
        let either = decide(vec![1, 3], true);
        assert_eq!(either.status, Status::Holds, "{:?}", either.evidence);
        assert!(
            either
                .evidence
                .iter()
                .any(|e| e.text.starts_with("as the parameter increases: fails"))
        );
        // onto P0, P1: b2 must fall as μ rises, b3 must rise as μ falls
        let neither = decide(vec![0, 1], true);
        assert_eq!(neither.status, Status::Fails, "{:?}", neither.evidence);
    }

    fn two_parameter_spec() -> trig_specfile::Spec {
        // b1 = t(2β − α): ∂b1/∂α = −t, ∂b1/∂β = 2t, along α = α0 + τ,
        // β = β0 + τ the total derivative t ≥ 0
        let text = "id = \"two\"\ncitation = \"test\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"alpha\"\nsymbol = \"α\"\nrange = \"[0, 1]\"\n[[parameters]]\nname = \"beta\"\nsymbol = \"β\"\nrange = \"[0, 1]\"\n[[functions]]\nname = \"b0\"\nformula = \"1 - t*(2*beta - alpha)\"\n[[functions]]\nname = \"b1\"\nformula = \"t*(2*beta - alpha)\"\n";
        trig_specfile::Spec::from_str_named(text, "two.toml").expect("spec")
    }

    #[test]
    fn a_concurrent_change_is_decided_by_the_total_derivative() {
        let spec = two_parameter_spec();
        let both = ["alpha".to_string(), "beta".to_string()];
        let onto = Target::Onto(vec![1]);
        let v = shape_effect(&spec, &both, &onto, false, None);
        assert_eq!(v.status, Status::Holds, "{:?}", v.evidence);
        assert!(v.evidence.iter().any(|e| e.text == CONCURRENT));
        assert!(
            v.evidence.iter().any(|e| e.subject.as_deref()
                == Some("∂b1/∂α + ∂b1/∂β ≥ 0 (b1 increases with α, β together)")),
            "{:?}",
            v.evidence
        );
        // α alone moves weight off P1: not what the concurrent change does
        let alone = shape_effect(&spec, &both[..1], &onto, false, None);
        assert_eq!(alone.status, Status::Fails);
    }
}
