//! Claims of the second list of `shared/claims.md` about the effect of a
//! shape parameter ("the curve approaches the control polygon as `m`
//! increases"): each states what is printed and calls the shape-effect
//! judge ([`trig_judge::shape_effect`]), which decides under the weakest
//! reasonable definition and states it (E21: weights moving onto a
//! segment, concurrent parameters), or compares curves where the document
//! names no shape parameter (D15).

use rug::Rational;
use trig_core::{Family, Ring};
use trig_deriv::continuity::quotient_derivatives;
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::shape_effect::Point;
use trig_verdict::evidence::{Evidence, Expr};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// In report order (after the second list's other claims).
pub const CLAIMS: &[Claim] = &[Claim {
    id: "D15",
    check: d15,
}];

fn q(n: i64, d: i64) -> Rational {
    Rational::from((n, d))
}

fn polygon(points: &[(i64, i64, i64, i64)]) -> Vec<Point> {
    points
        .iter()
        .map(|&(a, b, c, d)| (q(a, b), q(c, d)))
        .collect()
}

/// The curvature at the start `P0 = (0, 0)` of the curve `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`
/// from the values and first two derivatives of each `bᵢ` there (any
/// parameter: curvature does not depend on it), with the polygon's first
/// edge on the x-axis: `κ = y''/x'²` where `y' = 0` and `x' > 0`; `None`
/// otherwise.
fn start_curvature(jets: &[Vec<Sym>], weights: &[Rational], points: &[Point]) -> Option<Rational> {
    let weights: Vec<Sym> = weights.iter().map(|w| Sym::rational(w.clone())).collect();
    let points: Vec<(Sym, Sym)> = points
        .iter()
        .map(|(x, y)| (Sym::rational(x.clone()), Sym::rational(y.clone())))
        .collect();
    let [x1, y1, _, y2] = start_derivatives(jets, &weights, &points).map(|d| d.as_rational());
    let (x1, y1, y2) = (x1?, y1?, y2?);
    (y1 == 0 && x1 > 0).then(|| y2 / x1.square())
}

/// `x′, y′, x″, y″` at the start of the rational curve `R = N/W`
/// (`N = Σ wᵢbᵢPᵢ`, `W = Σ wᵢbᵢ`), from the basis jets there.
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
    // R = N/W by the quotient rule of trig-deriv (Leibniz's rule for N = R·W)
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

/// The curvature `(x′y″ − y′x″)/(x′² + y′²)^{3/2}` at the start of `R`
/// (as [`start_derivatives`]), as a formula.
fn curvature_formula(jets: &[Vec<Sym>], weights: &[Sym], points: &[(Sym, Sym)]) -> Expr {
    let [x1, y1, x2, y2] = start_derivatives(jets, weights, points);
    let num = x1.clone() * &y2 - &(y1.clone() * &x2);
    let den = x1.clone() * &x1 + &(y1.clone() * &y1);
    Expr::over_power(&num, &den, (3, 2))
}

/// The Bernstein polynomials of degree `n` in `t` with their first two
/// derivatives at `t = 0`.
fn bernstein_jets(n: u32) -> Vec<Vec<Sym>> {
    let t = Sym::var("t");
    (0..=n)
        .map(|i| {
            let binomial = (0..i).fold(Rational::from(1), |acc, k| acc * (n - k) / (k + 1));
            let b = Sym::rational(binomial) * &t.powi(i) * &(Sym::one() - &t).powi(n - i);
            let (d1, d2) = (b.diff("t"), b.diff("t").diff("t"));
            [b, d1, d2]
                .iter()
                .map(|f| f.subs("t", &Sym::zero()))
                .collect()
        })
        .collect()
}

/// Curves with different parameters compared where no convention is
/// needed: the curvature at the common start `P0`, where both leave along
/// `P1 − P0`. A curve between the quintic Bézier curve and the polygon
/// near `P0` (`0 ≤ y_R ≤ y_Q` for `y ≈ κx²/2` in the frame of the edge
/// `P0P1`) has `κ_R ≤ κ_Q`; the weights `wᵢ > 0` are free (Theorem 2).
fn d15() -> Verdict {
    let polygon = polygon(&[
        (0, 1, 0, 1),
        (1, 1, 0, 1),
        (1, 1, 1, 1),
        (2, 1, 1, 1),
        (3, 1, 1, 1),
        (4, 1, 0, 1),
    ]);
    let rqtb = trig_deriv::endpoint_derivatives::<Sym, 3>(
        Family::Seed002Quartic,
        &[],
        trig_deriv::End::Start,
        trig_deriv::Wrt::Angle,
        &Sym::one(),
    );
    let ones = vec![q(1, 1); 6];
    let mut weighted = ones.clone();
    weighted[2] = q(2, 1);
    let curvatures = [
        (
            "the RQTB curve, weights 1",
            start_curvature(&rqtb, &ones, &polygon),
        ),
        (
            "the RQTB curve, w2 = 2, other weights 1",
            start_curvature(&rqtb, &weighted, &polygon),
        ),
        (
            "the quintic Bézier curve",
            start_curvature(&bernstein_jets(5), &ones, &polygon),
        ),
        (
            "the quartic Bézier curve",
            start_curvature(&bernstein_jets(4), &ones[..5], &polygon[..5]),
        ),
    ];
    let Some(values) = curvatures
        .iter()
        .map(|(_, k)| k.clone())
        .collect::<Option<Vec<Rational>>>()
    else {
        return Verdict::not_checkable("the curvature at P0 could not be formed exactly");
    };
    let shown: Vec<String> = curvatures
        .iter()
        .zip(&values)
        .map(|((name, _), k)| format!("{name}: {k}"))
        .collect();
    let (weighted_k, quintic, quartic) = (&values[1], &values[2], &values[3]);
    let status = if weighted_k > quintic && weighted_k > quartic {
        Status::Fails
    } else {
        Status::NotCheckable
    };
    let point: Vec<(String, Rational)> = polygon
        .iter()
        .take(3)
        .enumerate()
        .flat_map(|(i, (x, y))| [(format!("x{i}"), x.clone()), (format!("y{i}"), y.clone())])
        .chain([("w2".to_string(), q(2, 1))])
        .collect();
    let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    let mut witness = trig_verdict::witness::witness(
        &point,
        &names,
        vec![
            (
                "curvature of the RQTB curve at P0",
                Sym::rational(weighted_k.clone()),
            ),
            (
                "of the quintic Bézier curve",
                Sym::rational(quintic.clone()),
            ),
        ],
    );
    // each value as the curvature formula in the point's symbols (the
    // polygon's first three points, w2; the later points do not enter)
    let symbolic: Vec<(Sym, Sym)> = polygon
        .iter()
        .enumerate()
        .map(|(i, (x, y))| {
            if i < 3 {
                (Sym::var(&format!("x{i}")), Sym::var(&format!("y{i}")))
            } else {
                (Sym::rational(x.clone()), Sym::rational(y.clone()))
            }
        })
        .collect();
    let mut w = vec![Sym::one(); 6];
    w[2] = Sym::var("w2");
    let formulas = [
        curvature_formula(&rqtb, &w, &symbolic),
        curvature_formula(&bernstein_jets(5), &vec![Sym::one(); 6], &symbolic),
    ];
    for (value, formula) in witness.values.iter_mut().zip(formulas) {
        value.of = Some(formula);
    }
    witness.stated = Some(trig_verdict::evidence::Relation::AtMost);
    let item = Evidence::new(
        trig_verdict::evidence::Kind::Comparison,
        format!(
            "exact curvatures at P0 (polygon (0,0), (1,0), (1,1), …; derivatives of (1) in θ, of the Bernstein polynomials in u, curvature being independent of the parameter): {}",
            shown.join("; ")
        ),
    )
    .about("κ_RQTB(P0) ≤ κ_quintic(P0) for weights w_i > 0", status)
    .witnessed((status == Status::Fails).then_some(witness));
    Verdict::new(
        status,
        "exact: end derivatives of the bases (Taylor jets over the symbolic ring), the rational curve by the quotient rule; curvature at the common end point compared",
        vec![
            Evidence::note(
                "definition (weakest reasonable; the document gives none): \"between the quintic Bézier curve and the control polygon\" and \"closer\" are read geometrically, without a correspondence of parameters; near P0 both curves leave along P1 − P0 and y ≈ κx²/2 in the frame of the edge P0P1, so lying between them needs κ_RQTB ≤ κ_quintic at P0 (a necessary condition; with all weights 1 it holds at P0, which proves nothing globally)",
            ),
            item,
        ],
    )
}
