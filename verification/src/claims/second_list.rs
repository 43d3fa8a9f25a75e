//! Seed 004: the EH surfaces of revolution (E18), the one claim of the
//! second list of `shared/claims.md` still decided in Rust (the others are
//! data: `identity`, `all` with `not-printed` parts, `convex-hull`).

use rug::Rational;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_core::{Affine, Family};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::basis;
use trig_judge::span;
use trig_judge::surface::cylinder_distance;
use trig_verdict::evidence::Evidence;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

/// In report order (after the other second-list claims of each document).
pub const CLAIMS: &[Claim] = &[Claim {
    id: "E18",
    check: e18,
}];

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
