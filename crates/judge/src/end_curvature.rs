//! The curvature at a common end point of rational curves on different
//! bases: "the curve lies between the other curve and the control
//! polygon", "is closer to the polygon" (seed 002, Theorem 2 and its
//! Conclusion) read geometrically, without a correspondence of parameters.
//!
//! Every curve `R = Σ wᵢbᵢPᵢ / Σ wᵢbᵢ` of an end-point-interpolating basis
//! leaves `P0` along `P1 − P0`; in the frame of that edge `y ≈ κx²/2`, so a
//! curve between another and the polygon near `P0` (`0 ≤ y_R ≤ y_Q`) has
//! `κ_R ≤ κ_Q` there — a necessary condition only: a violation refutes,
//! compliance proves nothing globally. With the first edge on the positive
//! x-axis (`y′ = 0`, `x′ > 0` at `P0`) the curvature
//! `κ = (x′y″ − y′x″)/(x′² + y′²)^{3/2}` is `y″/x′²`, exact: the end
//! derivatives of each basis by Taylor jets over the symbolic ring
//! ([`trig_deriv::endpoint_derivatives`], in the basis's own variable —
//! curvature does not depend on the parameter), the quotient by
//! [`quotient_derivatives`] (Leibniz's rule for `N = R·W`).

use rug::Rational;
use trig_core::Basis;
use trig_deriv::continuity::quotient_derivatives;
use trig_deriv::{End, Wrt};
use trig_specfile::WeightedCurve;
use trig_symbolic::Sym;

use crate::shape_effect::Point;
use trig_verdict::evidence::{Evidence, Expr, Kind, Relation};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How the curvatures are decided, as the report states it.
pub const METHOD: &str = "exact: end derivatives of the bases (Taylor jets over the symbolic ring), the rational curve by the quotient rule; curvature at the common end point compared";

/// One rational curve `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ` on the polygon's first points
/// (one per function).
#[derive(Debug, Clone)]
pub struct EndCurve {
    /// Short name (`quintic`, in `κ_quintic`).
    pub name: String,
    /// How the report names it.
    pub label: String,
    /// A curve the claim is about (the others are compared with it).
    pub claimed: bool,
    /// `bᵢ, bᵢ′, bᵢ″` at the start, per function ([`start_jets`]).
    pub jets: Vec<Vec<Sym>>,
    /// `wᵢ > 0`, one per function.
    pub weights: Vec<Rational>,
}

/// `bᵢ, bᵢ′, bᵢ″` of every function at the start of the domain, in the
/// basis's own variable (its parameters as symbols).
pub fn start_jets<B: Basis>(basis: &B) -> Vec<Vec<Sym>> {
    let params: Vec<Sym> = basis.param_names().iter().map(|n| Sym::var(n)).collect();
    trig_deriv::endpoint_derivatives::<Sym, 3>(basis, &params, End::Start, Wrt::Angle, &Sym::one())
}

/// The curves of a claim: those without a basis of their own on the
/// claim's `basis`.
pub fn curves_of<B: Basis>(basis: &B, curves: &[WeightedCurve]) -> Vec<EndCurve> {
    curves
        .iter()
        .map(|k| EndCurve {
            name: k.name.clone(),
            label: k.label.clone(),
            claimed: k.basis.is_none(),
            jets: k
                .basis
                .as_deref()
                .map_or_else(|| start_jets(basis), start_jets),
            weights: k.weights.clone(),
        })
        .collect()
}

/// `x′, y′, x″, y″` at the start of `R = N/W` (`N = Σ wᵢbᵢPᵢ`,
/// `W = Σ wᵢbᵢ`) from the basis jets there.
fn start_derivatives(jets: &[Vec<Sym>], weights: &[Sym], points: &[(Sym, Sym)]) -> [Sym; 4] {
    let sum = |order: usize, coordinate: Option<usize>| -> Sym {
        jets.iter()
            .zip(weights)
            .zip(points)
            .fold(Sym::zero(), |acc, ((jet, w), p)| {
                let value = jet[order].clone() * w;
                acc + &match coordinate {
                    None => value,
                    Some(0) => value * &p.0,
                    Some(_) => value * &p.1,
                }
            })
    };
    let w: Vec<Sym> = (0..3).map(|k| sum(k, None)).collect();
    let [x, y] = [0, 1].map(|c| (0..3).map(|k| sum(k, Some(c))).collect::<Vec<Sym>>());
    let r = quotient_derivatives(&[&x, &y], &w);
    [
        r[0][1].clone(),
        r[1][1].clone(),
        r[0][2].clone(),
        r[1][2].clone(),
    ]
}

/// The exact curvature `y″/x′²` at the start of the curve on `polygon`,
/// with its first edge on the positive x-axis; `None` otherwise (or when a
/// value is not rational).
fn start_curvature(curve: &EndCurve, polygon: &[Point]) -> Option<Rational> {
    let weights: Vec<Sym> = curve
        .weights
        .iter()
        .map(|w| Sym::rational(w.clone()))
        .collect();
    let points: Vec<(Sym, Sym)> = polygon
        .iter()
        .map(|(x, y)| (Sym::rational(x.clone()), Sym::rational(y.clone())))
        .collect();
    let [x1, y1, _, y2] =
        start_derivatives(&curve.jets, &weights, &points).map(|d| d.as_rational());
    let (x1, y1, y2) = (x1?, y1?, y2?);
    (y1 == 0 && x1 > 0).then(|| y2 / x1.square())
}

/// The curvature `(x′y″ − y′x″)/(x′² + y′²)^{3/2}` at the start, as a
/// formula in the polygon's coordinates `xᵢ, yᵢ` and (`symbolic`) the
/// weights other than 1 as `wᵢ`: numerator and denominator.
fn curvature_formula(curve: &EndCurve, n: usize, symbolic: bool) -> (Sym, Sym) {
    let weights: Vec<Sym> = curve
        .weights
        .iter()
        .enumerate()
        .map(|(i, w)| {
            if symbolic && *w != 1 {
                Sym::var(&format!("w{i}"))
            } else {
                Sym::rational(w.clone())
            }
        })
        .collect();
    let points: Vec<(Sym, Sym)> = (0..n)
        .map(|i| (Sym::var(&format!("x{i}")), Sym::var(&format!("y{i}"))))
        .collect();
    let [x1, y1, x2, y2] = start_derivatives(&curve.jets, &weights, &points);
    (
        x1.clone() * &y2 - &(y1.clone() * &x2),
        x1.clone() * &x1 + &(y1.clone() * &y1),
    )
}

/// The curves the claim is about (`name`: their printed name) against the
/// compared ones at the common start `P0` of `polygon`: fails when a
/// claimed curve's curvature exceeds that of every compared curve (each
/// printed comparison is violated), with the exact witness; otherwise
/// `not-checkable` (a necessary condition holding at one point).
pub fn end_curvature(name: &str, polygon: &[Point], curves: &[EndCurve]) -> Verdict {
    let Some(values) = curves
        .iter()
        .map(|k| start_curvature(k, polygon))
        .collect::<Option<Vec<Rational>>>()
    else {
        return Verdict::not_checkable(
            "the curvature at P0 could not be formed exactly (the polygon's first edge on the positive x-axis, rational values)",
        );
    };
    let compared: Vec<(&EndCurve, &Rational)> = curves
        .iter()
        .zip(&values)
        .filter(|(k, _)| !k.claimed)
        .collect();
    let Some(&(first, first_value)) = compared.first() else {
        return Verdict::not_checkable("no compared curve");
    };
    let violation = curves
        .iter()
        .zip(&values)
        .find(|(k, v)| k.claimed && compared.iter().all(|(_, c)| v > c));
    let status = if violation.is_some() {
        Status::Fails
    } else {
        Status::NotCheckable
    };
    let shown: Vec<String> = curves
        .iter()
        .zip(&values)
        .map(|(k, v)| format!("{}: {v}", k.label))
        .collect();
    let vertices: Vec<String> = polygon.iter().map(|(x, y)| format!("({x}, {y})")).collect();
    let item = Evidence::new(
        Kind::Comparison,
        format!(
            "exact curvatures at P0 (polygon {}; end derivatives of each basis in its own variable, curvature being independent of the parameter): {}",
            vertices.join(", "),
            shown.join("; ")
        ),
    )
    .about(
        format!("κ_{name}(P0) ≤ κ_{}(P0) for weights w_i > 0", first.name),
        status,
    )
    .witnessed(violation.map(|(k, v)| witness(name, polygon, (k, v), (first, first_value))));
    let labels: Vec<&str> = compared.iter().map(|(k, _)| k.label.as_str()).collect();
    Verdict::new(
        status,
        METHOD,
        vec![
            Evidence::note(format!(
                "definition (weakest reasonable; the document gives none): a curve \"between\" another curve and the control polygon, or \"closer\" to the polygon, is read geometrically, without a correspondence of parameters; near P0 both curves leave along P1 − P0 and y ≈ κx²/2 in the frame of the edge P0P1, so lying between them needs κ_{name} ≤ κ_{} at P0 (a necessary condition; where it holds at P0 it proves nothing globally); a violation exceeds the curvature of every compared curve ({})",
                first.name,
                labels.join(", ")
            )),
            item,
        ],
    )
}

/// The violating curve's and the first compared curve's curvatures at
/// `P0`, each with its formula in the symbols of the point (the polygon's
/// coordinates and the violating curve's weights other than 1 that enter).
fn witness(
    name: &str,
    polygon: &[Point],
    (curve, value): (&EndCurve, &Rational),
    (other, other_value): (&EndCurve, &Rational),
) -> trig_verdict::evidence::Witness {
    let formulas = [
        curvature_formula(curve, polygon.len(), true),
        curvature_formula(other, polygon.len(), false),
    ];
    let occurring: std::collections::BTreeSet<String> = formulas
        .iter()
        .flat_map(|(num, den)| num.variables().into_iter().chain(den.variables()))
        .collect();
    let point: Vec<(String, Rational)> = polygon
        .iter()
        .enumerate()
        .flat_map(|(i, (x, y))| [(format!("x{i}"), x.clone()), (format!("y{i}"), y.clone())])
        .chain(
            curve
                .weights
                .iter()
                .enumerate()
                .map(|(i, w)| (format!("w{i}"), w.clone())),
        )
        .filter(|(n, _)| occurring.contains(n))
        .collect();
    let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    let curvature_of = format!("curvature of the {name} curve at P0");
    let compared = format!("of {}", other.label);
    let mut w = trig_verdict::witness::witness(
        &point,
        &names,
        vec![
            (curvature_of.as_str(), Sym::rational(value.clone())),
            (compared.as_str(), Sym::rational(other_value.clone())),
        ],
    );
    for (v, (num, den)) in w.values.iter_mut().zip(&formulas) {
        v.of = Some(Expr::over_power(num, den, (3, 2)));
    }
    w.stated = Some(Relation::AtMost);
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Bernstein basis of degree `n` (the thesis's spec files).
    fn bernstein(n: usize) -> trig_specfile::Spec {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(format!("../../documents/thesis/bernstein-{n}.toml"));
        trig_specfile::Spec::basis_from_file(&path).expect("the spec file")
    }

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    /// A curve on the Bernstein basis of degree `n` with `w2` (the others 1).
    fn curve(n: usize, w2: Rational, claimed: bool) -> EndCurve {
        let mut weights = vec![q(1, 1); n + 1];
        weights[2] = w2;
        EndCurve {
            name: format!("B{n}"),
            label: format!("degree {n}"),
            claimed,
            jets: start_jets(&bernstein(n)),
            weights,
        }
    }

    /// `(0, 0), (1, 0), (1, 1), …`: the first edge on the x-axis.
    fn polygon(first: Point) -> Vec<Point> {
        [(0, 0), (1, 0), (1, 1), (2, 1), (3, 1), (4, 1)]
            .iter()
            .map(|&(x, y)| (q(x, 1), q(y, 1)))
            .enumerate()
            .map(|(i, p)| if i == 1 { first.clone() } else { p })
            .collect()
    }

    #[test]
    fn a_rational_cubic_bending_more_than_every_compared_curve_fails_exactly() {
        // κ(0) of a rational Bézier curve of degree n:
        // (n − 1)/n · w0w2/w1² · |Δ1 × Δ2|/|Δ1|³ — 4/5 (n = 5), 3/4
        // (n = 4), 2/3·w2 (n = 3, w2)
        let compared = [curve(5, q(1, 1), false), curve(4, q(1, 1), false)];
        let decide = |w2: Rational| {
            let curves = [vec![curve(3, w2, true)], compared.to_vec()].concat();
            end_curvature("C", &polygon((q(1, 1), q(0, 1))), &curves)
        };
        let v = decide(q(3, 1));
        assert_eq!(v.status, Status::Fails, "{:?}", v.evidence);
        let w = v
            .evidence
            .iter()
            .find_map(|e| e.witness.as_ref())
            .expect("a witness");
        assert_eq!(w.values[0].value.plain, "2");
        assert_eq!(w.values[1].value.plain, "4/5");
        assert!(
            w.point.iter().any(|a| a.name == "w₂" && a.value == "3"),
            "{w:?}"
        );
        // 23/30: above the quartic's 3/4, below the quintic's 4/5 — not a
        // violation of every comparison; all weights 1: 2/3
        assert_eq!(decide(q(23, 20)).status, Status::NotCheckable);
        assert_eq!(decide(q(1, 1)).status, Status::NotCheckable);
    }

    #[test]
    fn the_curvature_of_a_rational_curve_takes_its_weights_through_the_quotient() {
        // w0 = w1 = 2: κ(0) = 2/3 · w0w2/w1² = 1/3 (W(0) = w0 enters)
        let mut c = curve(3, q(1, 1), true);
        c.weights[0] = q(2, 1);
        c.weights[1] = q(2, 1);
        let on_axis = polygon((q(1, 1), q(0, 1)));
        assert_eq!(start_curvature(&c, &on_axis), Some(q(1, 3)));
        // the first edge twice as long: κ ∝ 1/|Δ1|² for the same turn
        let longer = polygon((q(2, 1), q(0, 1)));
        assert_eq!(
            start_curvature(&curve(5, q(1, 1), false), &longer),
            Some(q(1, 5))
        );
    }

    #[test]
    fn a_first_edge_off_the_x_axis_is_not_checkable() {
        let curves = [curve(3, q(3, 1), true), curve(5, q(1, 1), false)];
        let v = end_curvature("C", &polygon((q(1, 1), q(1, 1))), &curves);
        assert_eq!(v.status, Status::NotCheckable);
        assert!(
            v.evidence
                .iter()
                .any(|e| e.text.contains("could not be formed"))
        );
    }
}
