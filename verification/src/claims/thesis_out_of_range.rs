//! T52: outside `m ∈ (−2, 1]` the thesis's curve (Figure 4.6's polygon)
//! and surface (the 4×4 net of 5.2, Figure 5.3) leave the convex hull.
//!
//! "Leaves the hull" is shown by one exact point: the curve or surface
//! evaluated exactly at `z = tan(θ/2) = k/20` (so `sin θ`, `cos θ` are
//! rational) outside a supporting half-plane of the hull — the polygon's
//! four edges for the curve, the net's bounding box for the surface (every
//! net point has `0 ≤ x, y ≤ 3`, `0 ≤ z ≤ 4`). A sample never proves that
//! a curve stays inside: a value of `m` without such a point is left
//! undecided.

use rug::Rational;
use trig_core::Family;
use trig_symbolic::Sym;

use crate::claim::{Claim, Seed};
use trig_judge::exact::basis;
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "T52",
    seed: Seed::S001,
    source: "4.2.1 Figure 4.6 text; 5.4.1 Figure 5.3 text",
    statement: "for ⟪m⟫ outside ⟪(−2, 1]⟫ the curve (control points ⟪(0,0)⟫, ⟪(2,6)⟫, ⟪(6,6)⟫, ⟪(8,0)⟫) and the surface (the printed ⟪4×4⟫ net, ⟪m = −4, −3, 3, 4⟫) leave the convex hull / control net",
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

/// A surface point outside the net's bounding box.
fn surface_outside(b: &[Sym], m: i64) -> Option<(usize, usize, [Rational; 3])> {
    let w: Vec<Vec<Rational>> = (0..=STEPS)
        .map(|k| weights(b, m, &circle_point(k)))
        .collect();
    let bounds = [(0, 3), (0, 3), (0, 4)];
    for (ku, wu) in w.iter().enumerate() {
        for (kv, wv) in w.iter().enumerate() {
            let coord = |k: usize| -> Rational {
                (0..4)
                    .flat_map(|i| (0..4).map(move |j| (i, j)))
                    .map(|(i, j)| {
                        let p = NET[i][j];
                        let x = [p.0, p.1, p.2][k];
                        Rational::from(&wu[i] * &wv[j]) * x
                    })
                    .sum()
            };
            let point = [coord(0), coord(1), coord(2)];
            if point
                .iter()
                .zip(bounds)
                .any(|(v, (lo, hi))| *v < lo || *v > hi)
            {
                return Some((ku, kv, point));
            }
        }
    }
    None
}

fn t52() -> Verdict {
    let b = basis(Family::ThesisCubic);
    let mut evidence = vec![Evidence::note(
        "Figure 4.6 prints no values of m; the curve is tested at the surface's m = −4, −3, 3, 4. Each case is decided by one exact point outside a supporting half-plane of the hull (z = tan(θ/2) = k/20, k = 0…20); none found leaves it undecided (a sample proves no containment)",
    )];
    let mut status = Status::Holds;
    for m in OUTSIDE {
        let shown = m.to_string().replace('-', "−");
        match curve_outside(&b, m) {
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
                evidence.push(
                    Evidence::note(format!(
                        "curve, m = {shown}: Q = ({x}, {y}) violates {edge} — outside the hull of the polygon"
                    ))
                    .witnessed(Some(w)),
                );
            }
            None => {
                status = Status::NotCheckable;
                evidence.push(Evidence::note(format!(
                    "curve, m = {shown}: no sample point outside the hull (not decided)"
                )));
            }
        }
        match surface_outside(&b, m) {
            Some((ku, kv, [x, y, z])) => evidence.push(Evidence::note(format!(
                "surface, m = {shown}: S at tan(θ_u/2) = {}, tan(θ_v/2) = {} is ({x}, {y}, {z}), outside the box 0 ≤ x, y ≤ 3, 0 ≤ z ≤ 4 that contains the net",
                Rational::from((ku as i64, STEPS)),
                Rational::from((kv as i64, STEPS))
            ))),
            None => {
                status = Status::NotCheckable;
                evidence.push(Evidence::note(format!(
                    "surface, m = {shown}: no sample point outside the net's box (not decided)"
                )));
            }
        }
    }
    Verdict::new(
        status,
        "exact: the curve and surface evaluated in rational arithmetic at rational points of the circle, against supporting half-planes of the hull",
        evidence,
    )
}
