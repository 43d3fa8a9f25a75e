//! T52: outside `m ∈ (−2, 1]` the thesis's curve (Figure 4.6's polygon)
//! and surface (the 4×4 net of 5.2, Figure 5.3) leave the convex hull.
//!
//! "Leaves the hull" is shown by one exact point outside a supporting
//! half-plane of the hull: the curve evaluated exactly at
//! `z = tan(θ/2) = k/20` (so `sin θ`, `cos θ` are rational) against the
//! polygon's four edges; the surface, a [`TensorSurface`] of the printed
//! net, by the surface judge ([`leaves_net`]: an exact point at rational
//! `u, v` outside the net's bounding box). A sample never proves that a
//! curve stays inside: a value of `m` without such a point is left
//! undecided.

use rug::Rational;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_core::{Affine, Family};
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::basis;
use trig_judge::surface::{OUTSIDE_NET, leaves_net};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T52",
    check: t52,
}];

/// The printed `m` of Figure 5.3 (Figure 4.6 prints none; the same values
/// are used for the curve).
const OUTSIDE: [i64; 4] = [-4, -3, 3, 4];

/// Figure 4.6's polygon `P0 … P3`.
const POLYGON: [(i64, i64); 4] = [(0, 0), (2, 6), (6, 6), (8, 0)];

/// The 4×4 net of 5.2, row by row (`P_{i,j}`, `i` the first index).
const NET: [[(i64, i64, i64); 4]; 4] = [
    [(0, 0, 0), (1, 0, 1), (2, 0, 2), (3, 0, 0)],
    [(0, 1, 1), (1, 1, 3), (2, 1, 4), (3, 1, 2)],
    [(0, 2, 2), (1, 2, 4), (2, 2, 3), (3, 2, 1)],
    [(0, 3, 0), (1, 3, 2), (2, 3, 1), (3, 3, 0)],
];

/// Sample points `z = k/20`, `k = 0 … 20`.
const STEPS: i64 = 20;

/// The surface's grid: `u, v = k/6`, where `θ = πu/2` is a multiple of
/// `π/12` and (3.7) is exact.
const GRID: i64 = 6;

/// The method of the curve's half.
const CURVE: &str = "exact: the curve evaluated in rational arithmetic at rational points of the circle, against supporting half-planes of the hull";

/// `(sin θ, cos θ)` at `z = tan(θ/2) = k/STEPS`, exactly.
fn circle_point(k: i64) -> (Rational, Rational) {
    let z = Rational::from((k, STEPS));
    let z2 = Rational::from(&z * &z);
    let d = Rational::from(1 + &z2);
    ((2 * z) / &d, (1 - z2) / d)
}

/// The four functions of (3.7) at `m` and the exact point `(s, c)`.
fn weights(b: &[Sym], m: i64, (s, c): &(Rational, Rational)) -> Vec<Rational> {
    let point = vec![
        ("m".to_string(), Rational::from(m)),
        ("s".to_string(), s.clone()),
        ("c".to_string(), c.clone()),
    ];
    b.iter()
        .map(|f| {
            witness::at(f, &point)
                .and_then(|v| v.as_rational())
                .expect("a polynomial in s, c, m at a rational point")
        })
        .collect()
}

fn combine(w: &[Rational], coords: impl Iterator<Item = i64>) -> Rational {
    w.iter()
        .zip(coords)
        .map(|(a, x)| Rational::from(a * x))
        .sum()
}

/// A curve point outside one of the polygon's edges (`3x − y ≥ 0`,
/// `3(8 − x) − y ≥ 0`, `0 ≤ y ≤ 6` describe the hull), with its `s`, `c`.
fn curve_outside(b: &[Sym], m: i64) -> Option<(Rational, Rational, Rational, Rational, String)> {
    (0..=STEPS).find_map(|k| {
        let sc = circle_point(k);
        let w = weights(b, m, &sc);
        let x = combine(&w, POLYGON.iter().map(|p| p.0));
        let y = combine(&w, POLYGON.iter().map(|p| p.1));
        let edges = [
            (Rational::from(&y), "y ≥ 0 (edge P3P0)"),
            (Rational::from(6 - &y), "y ≤ 6 (edge P1P2)"),
            (Rational::from(3 * &x) - &y, "3x − y ≥ 0 (edge P0P1)"),
            (
                (24 - Rational::from(3 * &x)) - &y,
                "3(8 − x) − y ≥ 0 (edge P2P3)",
            ),
        ];
        let (_, edge) = edges.into_iter().find(|(v, _)| *v < 0)?;
        Some((sc.0, sc.1, x, y, edge.to_string()))
    })
}

/// The thesis surface (5.11) of the printed net at `m` in both directions
/// (T52, T53).
pub(crate) fn thesis_surface(m: &Rational) -> TensorSurface<Family> {
    let direction = || Direction {
        basis: Family::ThesisCubic,
        params: vec![Affine::rational(m.clone())],
    };
    let points = NET
        .iter()
        .map(|row| {
            row.iter()
                .map(|&(x, y, z)| [x, y, z].map(Rational::from))
                .collect()
        })
        .collect();
    let net = ControlNet::new(points).expect("the printed net is 4 × 4");
    TensorSurface::new(direction(), direction(), net).expect("a 4 × 4 net for (3.7)")
}

fn t52() -> Verdict {
    let b = basis(Family::ThesisCubic);
    let mut parts = Vec::new();
    for m in OUTSIDE {
        let shown = m.to_string().replace('-', "−");
        let curve = match curve_outside(&b, m) {
            Some((s, c, x, y, edge)) => {
                let point = vec![
                    ("m".to_string(), Rational::from(m)),
                    ("s".to_string(), s),
                    ("c".to_string(), c),
                ];
                let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
                let w = witness::witness(
                    &point,
                    &names,
                    vec![
                        ("x", Sym::rational(x.clone())),
                        ("y", Sym::rational(y.clone())),
                    ],
                );
                Verdict::new(
                    Status::Holds,
                    CURVE,
                    [Evidence::note(format!(
                        "Q = ({x}, {y}) violates {edge} — outside the hull of the polygon"
                    ))
                    .witnessed(Some(w))],
                )
            }
            None => Verdict::new(
                Status::NotCheckable,
                CURVE,
                ["no sample point outside the hull (not decided)"],
            ),
        };
        parts.push((format!("curve, m = {shown}"), curve));
        parts.push((
            format!("surface, m = {shown}"),
            leaves_net(&thesis_surface(&Rational::from(m)), GRID),
        ));
    }
    let mut v = Verdict::all(format!("{CURVE}; {OUTSIDE_NET}"), parts);
    v.evidence.insert(
        0,
        "Figure 4.6 prints no values of m; the curve is tested at the surface's m = −4, −3, 3, 4. Each case is decided by one exact point outside a supporting half-plane of the hull (curve: z = tan(θ/2) = k/20, k = 0…20; surface: u, v = k/6, where (3.7) is exact); none found leaves it undecided (a sample proves no containment)",
    );
    v
}
