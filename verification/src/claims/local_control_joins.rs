//! The join and interpolation claims beside local control (see
//! [`super::local_control`]): the thesis's G² condition against curvature
//! (T51), the control points
//! its C¹ refinement moves (T65), and seed 002's open and closed
//! interpolating splines (D17); with the two curves they share with the
//! local-control claims (seed 002's segment (4), the thesis cubic's end
//! tangents).

use std::fmt;

use rug::Rational;
use trig_core::{Family, Ring};
use trig_deriv::{End, Wrt};
use trig_symbolic::Sym;

use super::seed002::rational_ends;
use super::thesis_interp::derivs;
use trig_judge::exact::{IDENTITY, TARGET, VALUE, basis, identities, identity_item, symbols};
use trig_verdict::evidence::{Evidence, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

/// `κ²` of a plane curve from its first and second derivative vectors:
/// `(x'y'' − y'x'')² / (x'² + y'²)³`.
fn curvature_squared(d1: &[Sym; 2], d2: &[Sym; 2]) -> Sym {
    let cross = d1[0].clone() * &d2[1] - &(d1[1].clone() * &d2[0]);
    let speed = d1[0].square() + &d1[1].square();
    cross.square() / &speed.powi(3)
}

/// `lhs = rhs` as a verdict of one item; where it fails, the witness is
/// taken at `point` when the two sides differ there (a point inside the
/// printed ranges), else found by the generic search.
fn one_item(label: &str, lhs: &Sym, rhs: &Sym, point: &[(&str, i64)]) -> Verdict {
    let mut item = identity_item(label, lhs, rhs);
    let point: Vec<(String, Rational)> = point
        .iter()
        .map(|(n, v)| (n.to_string(), Rational::from(*v)))
        .collect();
    let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    if item.status == Some(Status::Fails)
        && let (Some(l), Some(r)) = (witness::at(lhs, &point), witness::at(rhs, &point))
        && !(l - &r).is_zero()
    {
        item.witness = witness::of_exprs(&point, &names, &[(VALUE, lhs), (TARGET, rhs)]);
    }
    Verdict::new(
        item.status.unwrap_or(Status::NotCheckable),
        IDENTITY,
        [item],
    )
}

/// T51: with `P'(1) = λQ'(0)`, `P''(1) = μQ''(0) + γQ'(0)` at the joint,
/// `P' × P'' = λμ (Q' × Q'')` and `|P'|³ = λ³|Q'|³`, so `κ_P = (μ/λ²) κ_Q`:
/// the curvatures match for every `Q` exactly when `μ = λ²`. The summary
/// sentence gives G² "the same velocity and acceleration vector", which
/// `P' = λQ'` has only for `λ = 1`.
pub(super) fn t51() -> Verdict {
    let q1 = [Sym::var("a1"), Sym::var("a2")];
    let q2 = [Sym::var("c1"), Sym::var("c2")];
    let (lambda, mu, gamma) = (Sym::var("lambda"), Sym::var("mu"), Sym::var("gamma"));
    let p1 = [lambda.clone() * &q1[0], lambda.clone() * &q1[1]];
    let p2 = |mu: &Sym| -> [Sym; 2] {
        [
            mu.clone() * &q2[0] + &(gamma.clone() * &q1[0]),
            mu.clone() * &q2[1] + &(gamma.clone() * &q1[1]),
        ]
    };
    let kq = curvature_squared(&q1, &q2);
    let kp = curvature_squared(&p1, &p2(&mu));
    let kp_matched = curvature_squared(&p1, &p2(&lambda.square()));
    // witnesses inside the printed ranges λ, μ > 0 (the search would try 0)
    let unit = [("a1", 1), ("a2", 0), ("c1", 0), ("c2", 1), ("gamma", 0)];
    let printed = one_item(
        "κ_P(1)² = κ_Q(0)² for every μ > 0 (as printed)",
        &kp,
        &kq,
        &[&unit[..], &[("lambda", 1), ("mu", 2)]].concat(),
    );
    let ratio = identities(vec![(
        "κ_P(1)² = (μ/λ²)² κ_Q(0)² (derived)".into(),
        kp,
        (mu.clone() / &lambda.square()).square() * &kq,
    )]);
    let matched = identities(vec![(
        "κ_P(1)² = κ_Q(0)² with μ = λ²".into(),
        kp_matched,
        kq,
    )]);
    let same = Verdict::all(
        IDENTITY,
        vec![
            (
                "G²: P'(1) = Q'(0) (\"same velocity\")".into(),
                one_item(
                    "P'(1) = λQ'(0) against Q'(0)",
                    &p1[0],
                    &q1[0],
                    &[("lambda", 2), ("a1", 1)],
                ),
            ),
            (
                "G²: P''(1) = Q''(0) (\"same acceleration\")".into(),
                one_item(
                    "P''(1) = μQ''(0) + γQ'(0) against Q''(0)",
                    &p2(&mu)[0],
                    &q2[0],
                    &[("mu", 2), ("gamma", 0), ("a1", 1), ("c1", 1)],
                ),
            ),
        ],
    );
    let mut v = Verdict::all(
        IDENTITY,
        vec![
            (
                "the printed G² condition matches curvatures".into(),
                printed,
            ),
            ("the curvature ratio".into(), ratio),
            ("curvature continuity exactly when μ = λ²".into(), matched),
            (
                "\"C² and G² … have the same velocity and acceleration vector\", read for G²"
                    .into(),
                same,
            ),
        ],
    );
    v.evidence.insert(0, Evidence::note("plane curves, Q'(0) = (a1, a2), Q''(0) = (c1, c2) symbolic; κ² = (x'y'' − y'x'')²/(x'² + y'²)³; λ, μ > 0 keep the sign of x'y'' − y'x'', so κ² decides"));
    if v.status == Status::Fails {
        v = v.with_correction("the curvatures match iff μ = λ² (P''(1) = λ²Q''(0) + γQ'(0)); G² has proportional, not equal, velocity and acceleration vectors (equal only for λ = 1, γ = 0: C²)");
    }
    v
}

/// T65: the first curve `Q1` on `P0 … P3`, the next `Q2` on `P4 … P7`,
/// C⁰ by (4.4) `P4 = P3`, C¹ by (4.5) `Q2'(0) = Q1'(1)`, (4.6)
/// `P5 = 2P3 − P2`. The refinement (4.6) keeps the corner `P3 = P4` and
/// moves `P5`, the `V1` of the next curve; a refinement moving only `V3`
/// of the first and `V0` of the next curve (`P3 = P4 = X`) must put the
/// corner at `X = (P2 + P5)/2`, so it does not retain it.
pub(super) fn t65() -> Verdict {
    let p = symbols("P", 8);
    let two = Sym::int(2);
    let q1_end = thesis_tangents(&p[0..4], End::End);
    let c0 = |q: &[Sym]| -> Vec<Sym> {
        let mut q = q.to_vec();
        q[0] = p[3].clone();
        q
    };
    let mut after = c0(&p[4..8]);
    after[1] = two.clone() * &p[3] - &p[2];
    let refined = identities(vec![(
        "(4.5) after (4.4), (4.6): Q2'(0) = Q1'(1)".into(),
        thesis_tangents(&after, End::Start),
        q1_end.clone(),
    )]);
    // the point (4.6) moves: V1 of the next curve, P5 ↦ 2P3 − P2
    let kept = identity_item(
        "V1 of the next curve unchanged by (4.6) (P5 = 2P3 − P2)",
        &p[5],
        &after[1],
    );
    let moved = Verdict::new(
        kept.status.unwrap_or(Status::NotCheckable),
        IDENTITY,
        [kept],
    );
    // moving only V3 and V0: P3 = P4 = X, X solved from (4.5)
    let x = Sym::var("X");
    let mut left = p[0..4].to_vec();
    left[3] = x.clone();
    let mut right = p[4..8].to_vec();
    right[0] = x.clone();
    let residual = thesis_tangents(&right, End::Start) - &thesis_tangents(&left, End::End);
    let coefficient = residual.diff("X");
    let corner = -(residual.subs("X", &Sym::zero()) / &coefficient);
    let only = identities(vec![
        (
            "moving only V3, V0: the corner X solving (4.5) equals (P2 + P5)/2".into(),
            corner.clone(),
            (p[2].clone() + &p[5]) / &two,
        ),
        (
            "moving only V3, V0: the corner retained (X = P3)".into(),
            corner,
            p[3].clone(),
        ),
    ]);
    let only_status = if only.evidence[0].status == Some(Status::Holds) {
        only.evidence[1].status.unwrap_or(Status::NotCheckable)
    } else {
        Status::NotCheckable
    };
    let mut parts = vec![
        (
            "(4.6) gives C¹ with the corner retained".to_string(),
            refined,
        ),
        (
            "\"affects only V3 of the first curve and V0 of the next\" under (4.6)".to_string(),
            moved,
        ),
    ];
    parts.push((
        "\"retains the corner points\" when only V3, V0 move".to_string(),
        Verdict {
            status: only_status,
            ..only
        },
    ));
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(0, Evidence::note("Q1 = Σ b_k(u; m) P_k (k = 0…3), Q2 = Σ b_k(u; m) P_{4+k}, (3.7) with one m (Condition 1 of 4.1.1, where (4.6) is derived); derivatives in u"));
    v
}

/// An index `k·n + c` of seed 002's construction (`n`: the last point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Ix {
    n: i64,
    c: i64,
}

impl Ix {
    const fn at(n: i64, c: i64) -> Ix {
        Ix { n, c }
    }
    fn plus(self, c: i64) -> Ix {
        Ix::at(self.n, self.c + c)
    }
}

impl fmt::Display for Ix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.n, self.c) {
            (0, c) => write!(f, "{c}"),
            (1, 0) => write!(f, "n"),
            (1, c) if c > 0 => write!(f, "n+{c}"),
            (1, c) => write!(f, "n−{}", -c),
            (k, c) => write!(f, "{k}n{c:+}"),
        }
    }
}

/// An index range `[lo, hi]`, with `n` large enough for the order of the
/// ends to be that of their constants when their `n`-coefficients agree.
type Range = (Ix, Ix);

fn contains(outer: Range, inner: Range) -> bool {
    outer.0 <= inner.0 && inner.1 <= outer.1
}

fn text(r: Range) -> String {
    format!("{} … {}", r.0, r.1)
}

/// Segments `Q_a … Q_b` of (6): each `Q_i(t, α_i, α_{i+1})` uses the points
/// `V_{i−1} … V_{i+2}`, the knots `u_i, u_{i+1}`, the parameters `α_i,
/// α_{i+1}`, and runs from `V_i` to `V_{i+1}`; the check that what it needs
/// is given, and the points it interpolates.
fn bookkeeping(
    name: &str,
    segments: Range,
    points: Range,
    knots: Range,
    params: Range,
    want: Range,
) -> Verdict {
    let (a, b) = segments;
    let needs = [
        ("points V", (a.plus(-1), b.plus(2)), points),
        ("knots u", (a, b.plus(1)), knots),
        ("parameters α", (a, b.plus(1)), params),
    ];
    let mut items: Vec<Evidence> = needs
        .iter()
        .map(|(what, need, given)| {
            let ok = contains(*given, *need);
            Evidence::new(
                Kind::Derived,
                format!(
                    "segments Q_{{{}}} need {what}_{{{}}}; given {what}_{{{}}}",
                    text(segments),
                    text(*need),
                    text(*given)
                ),
            )
            .about(
                format!("{name}: {what}"),
                if ok { Status::Holds } else { Status::Fails },
            )
        })
        .collect();
    let reached = (a, b.plus(1));
    items.push(
        Evidence::new(
            Kind::Derived,
            format!(
                "Q_i(0) = V_i, Q_i(π/2) = V_{{i+1}}: interpolated V_{{{}}}; claimed V_{{{}}}",
                text(reached),
                text(want)
            ),
        )
        .about(
            format!("{name}: interpolated points"),
            if reached == want {
                Status::Holds
            } else {
                Status::Fails
            },
        ),
    );
    let status = Status::conjunction(items.iter().filter_map(|e| e.status));
    Verdict::new(status, IDENTITY, items)
}

/// D17: the segment of (6) interpolates its middle points (exactly, from
/// the curve (2) with the points of (3)); the index bookkeeping of the
/// construction, with the added points, knots and parameters, for every
/// `n`; and what the closing knot needs.
pub(super) fn d17() -> Verdict {
    let q = seed002_segment();
    let at = |s: i64, c: i64| q.subs("s", &Sym::int(s)).subs("c", &Sym::int(c));
    let ends = identities(vec![
        ("Q_i(0) = V_i (local V1)".into(), at(0, 1), Sym::var("V1")),
        (
            "Q_i(π/2) = V_{i+1} (local V2)".into(),
            at(1, 0),
            Sym::var("V2"),
        ),
    ]);
    let (zero, n) = (Ix::at(0, 0), Ix::at(1, 0));
    let one = Ix::at(0, 1);
    let printed = bookkeeping(
        "(6) as given",
        (one, n.plus(-2)),
        (zero, n),
        (one, n.plus(-1)),
        (one, n.plus(-1)),
        (one, n.plus(-1)),
    );
    let open = bookkeeping(
        "open",
        (zero, n.plus(-1)),
        (Ix::at(0, -1), n.plus(1)),
        (zero, n),
        (zero, n),
        (zero, n),
    );
    let closed = bookkeeping(
        "closed",
        (zero, n),
        (Ix::at(0, -1), n.plus(2)),
        (zero, n.plus(1)),
        (zero, n.plus(1)),
        (zero, n.plus(1)),
    );
    // the closing knot: Q_n ends at V_{n+1} = V_0 with tangent
    // α_{n+1}(V_{n+2} − V_n) = α_{n+1}(V_1 − V_n) (in t), Q_0 starts with
    // α_0(V_1 − V_{−1}) = α_0(V_1 − V_n): (8) there needs α_{n+1} = α_0
    let (a0, an1) = (Sym::var("a0"), Sym::var("aN"));
    let chord = Sym::var("V1") - &Sym::var("Vn");
    let closing = identity_item(
        "closing knot, t-tangents of Q_n(π/2) and Q_0(0): α_{n+1}(V_1 − V_n) = α_0(V_1 − V_n) (a0 = α_0, aN = α_{n+1}, Vn = V_n)",
        &(an1 * &chord),
        &(a0 * &chord),
    );
    let mut v = Verdict::all(
        IDENTITY,
        vec![
            ("each segment interpolates".into(), ends),
            ("the spline (6)–(7)".into(), printed),
            ("open curve".into(), open),
            ("closed curve".into(), closed),
        ],
    );
    v.evidence.insert(0, Evidence::note("Q_i of (6) on V_{i−1} … V_{i+2} is the rational curve (2) with P0…P5 from (3) (reading D6b); the print names the interpolation points Q_i (and P_i for the closed curve) where (6) has V_i; (7) lists i = 1 … n − 1, but (6) defines segments for i = 1 … n − 2 only (Q_{n−1} would need V_{n+1}); index ranges are decided for every n ≥ 3"));
    let mut note = Evidence::new(
        Kind::Derived,
        "not claimed by the text, but needed for Theorem 1's relations (8) at the closing knot u_{n+1} ≡ u_0: the third added parameter α_{n+1} must equal α_0 (the print leaves it free); otherwise the tangents there differ by the factor α_0/α_{n+1}",
    );
    note.exprs = closing.exprs.clone();
    note.witness = closing.witness.clone();
    v.evidence.push(note);
    v
}

/// The rational curve (2) of seed 002 with the control points fixed by
/// the end conditions (3) (reading D6b): `Q(t, α1, α2)` of (4) on the local
/// points `V0 … V3` (one coordinate), the weights `w0 … w5` as symbols.
/// `P0 = V1`, `P5 = V2`; `P1`, `P2` solve `R'(0)`, `R''(0)`, and `P4`, `P3`
/// solve `R'(π/2)`, `R''(π/2)`, each linear in its point.
pub(super) fn seed002_segment() -> Sym {
    let v = symbols("V", 4);
    let w = symbols("w", 6);
    let mut p = symbols("P", 6);
    let (a1, a2) = (Sym::var("alpha1"), Sym::var("alpha2"));
    let two = Sym::int(2);
    p[0] = v[1].clone();
    p[5] = v[2].clone();
    // (end, order, the unknown point, its right-hand side in (3))
    let steps = [
        (0, 1, 1, a1.clone() * &(v[2].clone() - &v[0])),
        (
            0,
            2,
            2,
            a1 * &(v[0].clone() - &(two.clone() * &v[1]) + &v[2]),
        ),
        (1, 1, 4, a2.clone() * &(v[3].clone() - &v[1])),
        (1, 2, 3, a2 * &(v[1].clone() - &(two * &v[2]) + &v[3])),
    ];
    for (end, order, k, rhs) in steps {
        let (r0, r1) = rational_ends(&p, &w);
        let lhs = if end == 0 { &r0[order] } else { &r1[order] };
        let name = format!("P{k}");
        let coefficient = lhs.diff(&name);
        let rest = lhs.subs(&name, &Sym::zero());
        p[k] = (rhs - &rest) / &coefficient;
    }
    let b = basis(Family::Seed002Quartic);
    let num = (0..6).fold(Sym::zero(), |acc, k| acc + &(w[k].clone() * &b[k] * &p[k]));
    let den = (0..6).fold(Sym::zero(), |acc, k| acc + &(w[k].clone() * &b[k]));
    num / &den
}

/// The first derivatives in `u` of the thesis cubic at its ends, for the
/// helpers of the join claims.
pub(super) fn thesis_tangents(points: &[Sym], end: End) -> Sym {
    derivs(points, &Sym::var("m"), end, Wrt::U, &Sym::one())[1].clone()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_seed002_segment_interpolates_its_middle_points() {
        let q = seed002_segment();
        let at = |s: i64, c: i64| q.subs("s", &Sym::int(s)).subs("c", &Sym::int(c));
        assert_eq!(at(0, 1), Sym::var("V1"));
        assert_eq!(at(1, 0), Sym::var("V2"));
    }

    #[test]
    fn index_ranges_print_and_compare() {
        let n = Ix::at(1, 0);
        assert_eq!(n.plus(-2).to_string(), "n−2");
        assert_eq!(n.plus(1).to_string(), "n+1");
        assert!(contains((Ix::at(0, -1), n.plus(1)), (Ix::at(0, 0), n)));
        assert!(!contains((Ix::at(0, 0), n), (Ix::at(0, -1), n)));
    }

    #[test]
    fn the_g2_claims_fail_with_their_corrections() {
        let v = t51();
        assert_eq!(v.status, Status::Fails);
        // the derived ratio and μ = λ² hold exactly
        let holds: Vec<_> = v
            .evidence
            .iter()
            .filter(|e| e.status == Some(Status::Holds))
            .collect();
        assert_eq!(holds.len(), 2, "{:?}", v.evidence);
        assert_eq!(t65().status, Status::Fails);
    }
}
