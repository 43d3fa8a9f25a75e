//! Claims of the second list of `shared/claims.md` that need no judge of
//! their own: the thesis's surface proofs and terminal properties (T59,
//! T60), its positivity summary (T58), the EH surfaces (E18, E22), and the
//! statements whose formula or condition this copy does not print (M22,
//! D20, D22, S6–S9, E20) — `not-checkable`, naming what is missing, with
//! whatever part the text does decide.

use rug::Rational;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_core::{Affine, Family};
use trig_deriv::{End, Wrt};
use trig_symbolic::Sym;

use super::thesis_interp::derivs;
use crate::claim::Claim;
use trig_judge::exact::{IDENTITY, basis, identity_item, sum, symbols};
use trig_judge::surface::cylinder_distance;
use trig_judge::{nonnegative, span};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

/// In report order (after the other second-list claims of each document).
pub const CLAIMS: &[Claim] = &[
    Claim {
        id: "T59",
        check: t59,
    },
    Claim {
        id: "S7",
        check: s7,
    },
    Claim {
        id: "S8",
        check: s8,
    },
    Claim {
        id: "E18",
        check: e18,
    },
    Claim {
        id: "E22",
        check: e22,
    },
];

/// `P` at one end of the thesis cubic (3.7), derivatives of order 0–2 in
/// `wrt`, for control points `points` (one coordinate).
fn cubic_end(m: &Sym, points: &[Sym], end: End, wrt: Wrt) -> Vec<Sym> {
    derivs(points, m, end, wrt, &Sym::one())
}

fn q(n: i64) -> Sym {
    Sym::int(n)
}

/// The cross product of two exact 3-vectors.
fn cross(a: &[Sym; 3], b: &[Sym; 3]) -> [Sym; 3] {
    let c = |i: usize, j: usize| a[i].clone() * &b[j] - &(a[j].clone() * &b[i]);
    [c(1, 2), c(2, 0), c(0, 1)]
}

fn show(v: &[Sym]) -> String {
    let parts: Vec<String> = v.iter().map(Sym::to_unicode).collect();
    format!("({})", parts.join(", "))
}

/// Each "⇔" of the proofs tested in both directions on exact instances
/// (the boundary curves in v of (3.7), one coordinate, m = 0).
fn t59() -> Verdict {
    let m = Sym::zero();
    let status_of = |status: bool| if status { Status::Holds } else { Status::Fails };
    // (a) C⁰ ⇒ C¹? P4 = P3, P5 free: the first derivatives across the boundary
    let first = symbols("P", 4);
    let second: Vec<Sym> = [3, 5, 6, 7].map(|k| Sym::var(&format!("P{k}"))).into();
    let d1 = cubic_end(&m, &first, End::End, Wrt::Angle);
    let d2 = cubic_end(&m, &second, End::Start, Wrt::Angle);
    let jump = d2[1].clone() - &d1[1];
    let c0 = d2[0].clone() - &d1[0];
    // by hand: m = 0, P2 = 0, P3 = 1, P5 = 1
    let point: Vec<(String, rug::Rational)> = [("P2", 0), ("P3", 1), ("P5", 1)]
        .map(|(n, v)| (n.to_string(), rug::Rational::from(v)))
        .into();
    let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    let shown = witness::of_exprs(
        &point,
        &names,
        &[("∂S2/∂v(u, 0)", &d2[1]), ("∂S1/∂v(u, 1)", &d1[1])],
    );
    let a = Verdict::new(
        status_of(jump.is_zero() || !c0.is_zero()),
        IDENTITY,
        [Evidence::note(format!(
            "with P4 = P3 (C⁰: S2(u, 0) − S1(u, 1) = {}) the v-derivatives differ by ∂S2/∂v(u, 0) − ∂S1/∂v(u, 1) = {} at m = 0, zero only when P5 = 2P3 − P2: C⁰ does not give C¹ (C¹ ⇒ C⁰ only)",
            c0.to_unicode(),
            jump.to_unicode()
        ))
        .witnessed(shown.filter(|_| !jump.is_zero()))],
    );
    // (b), (c): a × w = b × w with a ≠ b: (5.18) fixes ∂S2/∂v only up to a
    // multiple of the common ∂S/∂u
    let su = [q(1), q(0), q(0)];
    let s1v = [q(0), q(1), q(0)];
    let s2v = [q(1), q(1), q(0)];
    let (n1, n2) = (cross(&s1v, &su), cross(&s2v, &su));
    let same_normal = n1.iter().zip(&n2).all(|(x, y)| (x.clone() - y).is_zero());
    let same_v = s1v.iter().zip(&s2v).all(|(x, y)| (x.clone() - y).is_zero());
    let b = Verdict::new(
        status_of(!same_normal || same_v),
        IDENTITY,
        [format!(
            "at a boundary point with ∂S/∂u = {} (common to both patches under C⁰), ∂S1/∂v = {} and ∂S2/∂v = {} give equal cross products {} = {} although ∂S2/∂v ≠ ∂S1/∂v: (5.18) does not give (5.19); (5.19) ⇒ (5.18) holds (the same ∂S/∂u on both sides); likewise (5.28) ⇔ (5.29) holds only from right to left",
            show(&su),
            show(&s1v),
            show(&s2v),
            show(&n1),
            show(&n2)
        )],
    );
    // (c) α(u) in (5.29), a constant α in (5.32): along the boundary
    // ∂S/∂v at u is Σ Bᵢ(u)(m+2)(P5ᵢ − P4ᵢ); with P3ᵢ − P2ᵢ = d for every i
    // and P5ᵢ − P4ᵢ = cᵢd the ratio α(u) = Σ Bᵢ(u)cᵢ is not constant
    let c = [q(1), q(1), q(1), q(2)];
    let at = |end| cubic_end(&m, &c, end, Wrt::Angle)[0].clone();
    let (alpha0, alpha1) = (at(End::Start), at(End::End));
    let c_part = Verdict::new(
        status_of((alpha0.clone() - &alpha1).is_zero()),
        IDENTITY,
        [format!(
            "with P3ᵢ − P2ᵢ = d for i = 0…3 and P5ᵢ − P4ᵢ = cᵢd, c = (1, 1, 1, 2), m = 0: (5.29) holds with α(u) = Σ Bᵢ(u)cᵢ > 0, α(0) = {} and α(1) = {}; no constant α satisfies (5.32) — a constant α is a further restriction (sufficient, not equivalent)",
            alpha0.to_unicode(),
            alpha1.to_unicode()
        )],
    );
    // (d) C¹ and the curvature: a straight S1 and a C¹ S2 with P6 off the line
    let xs = [q(0), q(1), q(2), q(3)];
    let ys = [q(0), q(0), q(0), q(0)];
    let (x2, y2) = ([q(3), q(4), q(5), q(6)], [q(0), q(0), q(1), q(1)]);
    let curvature_numerator = |x: &[Sym], y: &[Sym], end| {
        let (dx, dy) = (
            cubic_end(&m, x, end, Wrt::Angle),
            cubic_end(&m, y, end, Wrt::Angle),
        );
        (
            dx[1].clone() * &dy[2] - &(dy[1].clone() * &dx[2]),
            [dx[1].clone(), dy[1].clone()],
        )
    };
    let (k1, t1) = curvature_numerator(&xs, &ys, End::End);
    let (k2, t2) = curvature_numerator(&x2, &y2, End::Start);
    let c1 = t1.iter().zip(&t2).all(|(a, b)| (a.clone() - b).is_zero());
    let d = Verdict::new(
        status_of(!c1 || (k1.clone() - &k2).is_zero()),
        IDENTITY,
        [format!(
            "m = 0, S1 on P0…P3 = (0, 0), (1, 0), (2, 0), (3, 0) and S2 on P3, P4 = P3, P5 = 2P3 − P2 = (4, 0), P6 = (5, 1) (Theorem 5.1's C¹ conditions (5.13) in v): equal first derivatives {} = {}, but x′y″ − y′x″ = {} at the end of S1 and {} at the start of S2 — C¹ does not give equal (normal) curvature; that is G²",
            show(&t1),
            show(&t2),
            k1.to_unicode(),
            k2.to_unicode()
        )],
    );
    Verdict::all(
        IDENTITY,
        vec![
            ("C¹ \"if and only if\" C⁰".into(), a),
            ("(5.18) ⇔ (5.19)".into(), b),
            ("α(u) in (5.29), constant α in (5.32)".into(), c_part),
            ("C¹ ⇒ identical normal curvature".into(), d),
        ],
    )
}

/// The implication from the basis symmetry is exact; its premise needs the
/// lost formulas.
fn s7() -> Verdict {
    let b = symbols("b", 4);
    let p = symbols("p", 4);
    // b_j(1 − t) = b_{3−j}(t): the reflected curve with the points reversed
    let reflected: Vec<Sym> = (0..4).map(|j| b[3 - j].clone() * &p[3 - j]).collect();
    let direct: Vec<Sym> = (0..4).map(|j| b[j].clone() * &p[j]).collect();
    let implication = identity_item(
        "Σ b_j(1 − t) p_{i+3−j} − Σ b_j(t) p_{i+j}, with b_j(1 − t) = b_{3−j}(t)",
        &sum(&reflected),
        &sum(&direct),
    );
    let mut v = Verdict::not_checkable(
        "the basis functions of seed 003 are missing from this copy (see S1): their symmetry b_j(1 − t) = b_{3−j}(t) and unity (the premises) cannot be checked",
    );
    v.evidence.push(implication);
    v.evidence.push(
        "geometric (affine) invariance follows from the partition of unity alone (an affine map commutes with Σ b_j p_j exactly when Σ b_j = 1); the step is valid, its premise unchecked",
    );
    v
}

/// The printed (15) lost its symbols; the extreme point of the one
/// quadratic the definitions of A, B, C allow is derived exactly.
fn s8() -> Verdict {
    let (a, b, c, x) = (
        Sym::var("A"),
        Sym::var("B"),
        Sym::var("C"),
        Sym::var("alpha"),
    );
    // E(α) = Aα² + 2Bα + C (r = αH + G); E'(α) = 2Aα + 2B
    let energy = a.clone() * &x * &x + &(q(2) * &b * &x) + &c;
    let slope = energy.diff("alpha");
    let at_printed = slope.subs("alpha", &(b.clone() / &a));
    let at_derived = slope.subs("alpha", &(-b.clone() / &a));
    let mut v = Verdict::not_checkable(
        "equation (15) is printed without its symbols (\"2 2 …(15)\"), and (14) lost the parameter (\"r_i(t) = H_i(t) G_i(t)\"): the energy as a function of α cannot be read, so the printed extreme point B/A cannot be confirmed or refuted",
    );
    v.evidence.push(format!(
        "for the reading E(α) = Aα² + 2Bα + C (r_i = αH_i + G_i, with the printed A = Σ∫H_i², B = Σ∫H_iG_i, C = Σ∫G_i²): E′(α) = {}, E′(B/A) = {} and E′(−B/A) = {}: the extreme point is −B/A; B/A is it only if (15) reads Aα² − 2Bα + C",
        slope.to_unicode(),
        at_printed.to_unicode(),
        at_derived.to_unicode()
    ));
    v.evidence.push(
        "A = Σ∫H_i² ≥ 0: for A > 0 the quadratic is convex, so its minimum on [0.3, 0.5] is the extreme point when it lies inside and the nearer end otherwise — the printed cases (i)/(ii) are right (in (ii) the comparison with F(0.3) and F(0.5) is redundant); their comparison signs are lost in this copy",
    );
    v
}

/// The EH basis is polynomial in t: the circle is not in its span, and no
/// polynomial curve lies on a circle.
fn e18() -> Verdict {
    let mut v = span::reproduces(
        &Family::Eh,
        "unit circle arc (cos t, sin t)",
        &[("x", Sym::var("c")), ("y", Sym::var("s"))],
    );
    v.evidence.insert(
        0,
        "a surface of revolution contains circles (its parallels): a sphere, a torus or a cylinder has them through every point. The EH basis functions are polynomials in t, so every EH surface piece is a polynomial surface; a polynomial curve (x(t), y(t)) on a circle x² + y² = 1 is constant (the leading terms of x² + y² cannot cancel over the reals). Decided below: the circle is not in the span of the EH basis for any λ, μ",
    );
    // every Σ kᵢbᵢ has a vanishing fifth t-derivative; cos t does not
    let fifth = |f: &Sym, d: &dyn Fn(&Sym) -> Sym| (0..5).fold(f.clone(), |g, _| d(&g));
    let polynomial = basis(Family::Eh)
        .iter()
        .all(|f| fifth(f, &|g| g.diff("t")).is_zero());
    let cosine = fifth(&Sym::var("c"), &|g| g.d_angle());
    let point: Vec<(String, rug::Rational)> = vec![
        ("s".into(), rug::Rational::from(1)),
        ("c".into(), rug::Rational::from(0)),
    ];
    let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    let at_quarter = witness::at(&cosine, &point).unwrap_or_else(|| cosine.clone());
    if polynomial && !at_quarter.is_zero() {
        v.evidence.push(
            Evidence::note(format!(
                "the fifth derivative in t of every EH basis function is 0 (they are quartics), so d⁵/dt⁵ Σ kᵢbᵢ ≡ 0 for all kᵢ, λ, μ; d⁵/dt⁵ cos t = {} is {} at t = π/2",
                cosine.to_unicode(),
                at_quarter.to_unicode()
            ))
            .witnessed(witness::of_exprs(
                &point,
                &names,
                &[("d⁵/dt⁵ Σ kᵢbᵢ", &Sym::zero()), ("d⁵/dt⁵ cos t", &cosine)],
            )),
        );
    }
    v.evidence.push("paraboloids of revolution and cones are polynomial surfaces and can be EH surfaces; \"the surfaces of revolution\" in general (spheres, tori, cylinders) cannot");
    let mut parts = vec![("the circle in the span of the EH basis".to_string(), v)];
    for (lambda, mu) in EH_PARAMETERS {
        let cylinder = eh_cylinder(Rational::from(lambda), Rational::from(mu));
        parts.push((
            format!("an EH surface of the cylinder x² + y² = 1 at λ = {lambda}, μ = {mu}")
                .replace('-', "−"),
            cylinder_distance(&cylinder, &Rational::from(1)),
        ));
    }
    let method = parts[0].1.method.clone();
    let mut all = Verdict::all(method, parts);
    all.evidence.push(format!(
        "the cylinder's EH surface piece (5): rows of the net go with b_k(u), columns with b_l(v); as the EH bases are Hermite's (b₀, b₁ the end points, b₂, b₃ the end tangents), the net holds the quarter circle (1, 0), (0, 1) with tangents (0, {K}), (−{K}, 0) at heights 0, 1 and the height's tangents: S(u, v) = (C(v), z(u)) with C the EH quarter circle (K = {K} ≈ 4(√2 − 1), the tangent that puts the standard Hermite arc's midpoint on the circle; the paper prints no net). λ, μ: the standard Hermite bases and Figure 1's λ = 2, μ = −2 and λ = −2, μ = 2"
    ));
    all
}

/// Figure 1's printed shape parameters of the EH bases, and the standard
/// Hermite bases (`λ = μ = 0`).
const EH_PARAMETERS: [(i64, i64); 3] = [(0, 0), (2, -2), (-2, 2)];

/// The tangent length of the EH quarter circle (our choice: the paper
/// prints no net).
const K: &str = "5/3";

/// One EH surface piece (5) of the cylinder `x² + y² = 1`, `0 ≤ z ≤ 1`:
/// the Hermite data of the quarter circle in `v` and of the height in `u`.
fn eh_cylinder(lambda: Rational, mu: Rational) -> TensorSurface<Family> {
    let direction = || Direction {
        basis: Family::Eh,
        params: vec![
            Affine::rational(lambda.clone()),
            Affine::rational(mu.clone()),
        ],
    };
    let circle = |z: &str| format!("1 0 {z}\n0 1 {z}\n0 {K} 0\n-{K} 0 0\n\n");
    let height = "0 0 1\n0 0 1\n0 0 0\n0 0 0\n\n";
    let text = circle("0") + &circle("1") + height + height;
    let net = ControlNet::parse(&text, "the EH cylinder net").expect("a 4 × 4 net");
    TensorSurface::new(direction(), direction(), net).expect("a 4 × 4 net for the EH bases")
}

/// The printed product of two points read as the net point
/// `P_{i+k−3, j+l−3}`: the tensor basis is the product of two curve
/// bases, so it sums to 1 and is ≥ 0 exactly where they do — the
/// properties of the EH curves (E4, E6) carry over, whatever they are.
fn e22() -> Verdict {
    let rename = |f: &Sym, x: &str, k: usize| {
        f.subs("t", &Sym::var(x))
            .subs("lambda", &Sym::var(&format!("lambda{k}")))
            .subs("mu", &Sym::var(&format!("mu{k}")))
    };
    let b = basis(Family::Eh);
    let products: Vec<Sym> = b
        .iter()
        .flat_map(|f| b.iter().map(|g| rename(f, "u", 1) * &rename(g, "v", 2)))
        .collect();
    let curve_sum = sum(&b);
    let factored = identity_item(
        "Σ_k Σ_l b_k(λ1, μ1; u) b_l(λ2, μ2; v) − (Σ_k b_k(λ1, μ1; u))·(Σ_l b_l(λ2, μ2; v))",
        &sum(&products),
        &(rename(&curve_sum, "u", 1) * &rename(&curve_sum, "v", 2)),
    );
    let third = Sym::rational(rug::Rational::from((1, 3)));
    let at_third = curve_sum.subs("t", &third);
    let tensor_at_third = at_third.clone() * &at_third;
    let unity = (curve_sum.clone() - &Sym::one()).is_zero();
    let hull = nonnegative::convex_hull(&Family::Eh, None);
    let holds = unity && hull.status == Status::Holds;
    let mut v = Verdict::new(
        if holds {
            Status::HoldsAfterCorrection
        } else {
            Status::Fails
        },
        IDENTITY,
        [factored],
    );
    v.evidence.push(format!(
        "decided for the reading P_{{i+k−3, j+l−3}} (the printed product of two points is not a point): the tensor basis sums to 1 only if the curve basis does, and is ≥ 0 where both factors are; at u = v = 1/3 (every λ, μ) Σ_k b_k = {} and the tensor sum is {}{}",
        at_third.to_unicode(),
        tensor_at_third.to_unicode(),
        if unity { "" } else { " ≠ 1: no convex hull, no affine invariance for the surface, as for the EH curves (E6, E12)" }
    ));
    v.evidence.extend(hull.evidence);
    if holds {
        v = v.with_correction("P_{i+k−3, j+l−3} (one point of the net) for the printed product P_{i+k−3} P_{j+l−3}, which is not an affine combination of points");
    }
    v
}
