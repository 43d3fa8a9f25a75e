//! "Outside the range the curve and the surface leave the convex hull /
//! the control net" (`check = "leaves-hull"`), for any basis with one
//! parameter, at printed values of it.
//!
//! - A curve `Q(x) = Σ bᵢ(x) Pᵢ` of a printed polygon leaves the polygon's
//!   convex hull when one point of it lies outside a supporting half-plane
//!   of the hull (an edge's line, the hull on one side). The curve is
//!   evaluated exactly at rational points of the variable: on a
//!   trigonometric domain the rational points of the circle
//!   `z = tan(θ/2) = z₀ + k(z₁ − z₀)/N`, `sin θ = 2z/(1 + z²)`,
//!   `cos θ = (1 − z²)/(1 + z²)` (the domain's ends need rational `sin`,
//!   `cos`: `z = sin θ/(1 + cos θ)` there); on a polynomial one `t = a +
//!   k(b − a)/N`; `k = 0 … N`, `N = 20`.
//! - The tensor-product surface over a listing's net leaves the net: the
//!   surface judge ([`leaves_net`]), one exact point outside the net's
//!   bounding box on a `7 × 7` grid (`u, v = k/6`).
//!
//! A sample never proves that a curve stays inside: a case without such a
//! point is `not-checkable`, never `fails`.

use rug::{Integer, Rational};
use trig_core::Affine;
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_specfile::ListedNet;
use trig_symbolic::Sym;
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

use crate::exact::{ExactBasis, basis_of};
use crate::surface::{OUTSIDE_NET, leaves_net};

/// The method of the curve's half.
pub const CURVE: &str = "exact: the curve evaluated in rational arithmetic at rational points of the circle, against supporting half-planes of the hull";

/// Sample points of the curve: `k = 0 … CURVE_STEPS`.
const CURVE_STEPS: i64 = 20;

/// The surface's grid: `u, v = k/NET_STEPS` (on the unit-angle variable
/// `θ = πu/2` a multiple of `π/12`, where the functions are exact).
const NET_STEPS: i64 = 6;

/// A point of the plane, exactly.
type Point = (Rational, Rational);

/// A supporting half-plane `a·x + b·y + c ≥ 0` of the hull, with the
/// edge it comes from (`P3P0`).
struct HalfPlane {
    a: Rational,
    b: Rational,
    c: Rational,
    edge: String,
}

impl HalfPlane {
    fn value(&self, (x, y): &Point) -> Rational {
        Rational::from(&self.a * x) + Rational::from(&self.b * y) + &self.c
    }

    /// `3x − y ≥ 0`, `y ≤ 6`: integer coefficients without a common
    /// factor, the side with positive coefficients on the left.
    fn shown(&self) -> String {
        let lcm = [&self.a, &self.b, &self.c]
            .iter()
            .fold(Integer::from(1), |l, q| l.lcm(q.denom()));
        let ints: Vec<Integer> = [&self.a, &self.b, &self.c]
            .iter()
            .map(|q| q.numer() * (&lcm / Integer::from(q.denom())))
            .collect();
        let gcd = ints.iter().fold(Integer::new(), |g, n| g.gcd(n));
        let [mut a, mut b, mut c] = [0, 1, 2].map(|k| Integer::from(&ints[k] / &gcd));
        let mut relation = "≥";
        if a <= 0 && b <= 0 {
            (a, b, c) = (-a, -b, -c);
            relation = "≤";
        }
        let mut lhs = String::new();
        for (k, name) in [(&a, "x"), (&b, "y")] {
            if *k == 0 {
                continue;
            }
            let magnitude = if k.clone().abs() == 1 {
                String::new()
            } else {
                k.clone().abs().to_string()
            };
            let sign = match (lhs.is_empty(), *k < 0) {
                (true, true) => "−",
                (true, false) => "",
                (false, true) => " − ",
                (false, false) => " + ",
            };
            lhs.push_str(&format!("{sign}{magnitude}{name}"));
        }
        let rhs = Integer::from(-&c).to_string().replace('-', "−");
        format!("{lhs} {relation} {rhs}")
    }
}

/// `(B − A) × (X − A)`: positive for `X` left of the line `A → B`.
fn cross(a: &Point, b: &Point, x: &Point) -> Rational {
    Rational::from(&b.0 - &a.0) * Rational::from(&x.1 - &a.1)
        - Rational::from(&b.1 - &a.1) * Rational::from(&x.0 - &a.0)
}

/// The convex hull's vertices as indices into `points` (monotone chain,
/// collinear points dropped), in the cyclic order in which the printed
/// indices increase (a convex polygon printed in order: `0, 1, 2, 3`).
fn hull(points: &[Point]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_by(|&i, &j| points[i].cmp(&points[j]));
    order.dedup_by(|i, j| points[*i] == points[*j]);
    if order.len() < 3 {
        return order;
    }
    let chain = |it: &mut dyn Iterator<Item = usize>| {
        let mut h: Vec<usize> = Vec::new();
        for k in it {
            while h.len() >= 2
                && cross(&points[h[h.len() - 2]], &points[h[h.len() - 1]], &points[k]) <= 0
            {
                h.pop();
            }
            h.push(k);
        }
        h.pop();
        h
    };
    let mut h = chain(&mut order.clone().into_iter());
    h.extend(chain(&mut order.into_iter().rev()));
    let first = (0..h.len()).min_by_key(|&k| h[k]).unwrap_or(0);
    h.rotate_left(first);
    if h.len() > 2 && h[1] > h[h.len() - 1] {
        h[1..].reverse();
    }
    h
}

/// The hull's supporting half-planes, one per edge, the hull on the
/// nonnegative side; `None` when the hull has no interior.
fn half_planes(points: &[Point]) -> Option<Vec<HalfPlane>> {
    let h = hull(points);
    if h.len() < 3 {
        return None;
    }
    let n = h.len();
    Some(
        (0..n)
            .map(|k| {
                let (i, j) = (h[k], h[(k + 1) % n]);
                let (p, q) = (&points[i], &points[j]);
                let inside = &points[h[(k + 2) % n]];
                let sign = if cross(p, q, inside) > 0 { 1 } else { -1 };
                // cross(p, q, X) = (q − p) × (X − p) = a·x + b·y + c
                let a = Rational::from(&p.1 - &q.1) * sign;
                let b = Rational::from(&q.0 - &p.0) * sign;
                let c = -(Rational::from(&a * &p.0) + Rational::from(&b * &p.1));
                HalfPlane {
                    a,
                    b,
                    c,
                    edge: format!("P{i}P{j}"),
                }
            })
            .collect(),
    )
}

/// The sample points of the variable as values of the atoms (`s`, `c` or
/// `t`), or why there are none.
fn samples<B: ExactBasis>(
    basis: &B,
    params: &[Affine],
) -> Result<Vec<Vec<(String, Rational)>>, String> {
    let domain = basis.domain();
    let values: Vec<Sym> = params.iter().map(|a| a.eval(&Sym::zero(), &[])).collect();
    let end = |x: &Affine| domain.atoms_at(&x.at(params), &Sym::one(), &values);
    let (Some(start), Some(stop)) = (end(&domain.start), end(&domain.end)) else {
        return Err("the domain's ends are not exact".into());
    };
    let steps = Rational::from(CURVE_STEPS);
    if domain.is_trigonometric() {
        let z = |a: &trig_core::Atoms<Sym>| {
            let (s, c) = (a.s.as_rational()?, a.c.as_rational()?);
            (c != -1).then(|| s / (c + 1))
        };
        let (Some(z0), Some(z1)) = (z(&start), z(&stop)) else {
            return Err("the domain's ends have no rational sin and cos: no rational points of the circle between them".into());
        };
        Ok((0..=CURVE_STEPS)
            .map(|k| {
                let z = Rational::from(&z1 - &z0) * Rational::from(k) / &steps + &z0;
                let z2 = Rational::from(&z * &z);
                let d = Rational::from(1 + &z2);
                vec![
                    ("s".to_string(), Rational::from(2 * &z) / &d),
                    ("c".to_string(), (1 - z2) / d),
                ]
            })
            .collect())
    } else {
        let (Some(a), Some(b)) = (start.t.as_rational(), stop.t.as_rational()) else {
            return Err("the domain's ends are not rational".into());
        };
        Ok((0..=CURVE_STEPS)
            .map(|k| {
                let t = Rational::from(&b - &a) * Rational::from(k) / &steps + &a;
                vec![("t".to_string(), t)]
            })
            .collect())
    }
}

/// One exact point of the curve of `polygon` at `parameter = value`
/// outside the polygon's convex hull: `holds` with it, `not-checkable`
/// without one.
pub fn curve_leaves_hull<B: ExactBasis>(
    basis: &B,
    parameter: &str,
    value: &Rational,
    polygon: &[Point],
) -> Verdict {
    let Some(planes) = half_planes(polygon) else {
        return Verdict::not_checkable("the polygon's convex hull has no interior");
    };
    let params = vec![Affine::rational(value.clone())];
    let points = match samples(basis, &params) {
        Ok(p) => p,
        Err(why) => return Verdict::not_checkable(why),
    };
    let fs = basis_of(basis);
    let found = points.into_iter().find_map(|atoms| {
        let assign = |name: &str| {
            atoms
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, v)| v.clone())
                .or_else(|| (name == parameter).then(|| value.clone()))
        };
        let w: Vec<Rational> = fs
            .iter()
            .map(|f| f.eval_rational(&assign).ok())
            .collect::<Option<_>>()?;
        let coordinate = |k: usize| -> Rational {
            w.iter()
                .zip(polygon)
                .map(|(b, p)| Rational::from(b * if k == 0 { &p.0 } else { &p.1 }))
                .sum()
        };
        let q = (coordinate(0), coordinate(1));
        let plane = planes.iter().find(|h| h.value(&q) < 0)?;
        Some((atoms, q, plane))
    });
    let Some((atoms, (x, y), plane)) = found else {
        return Verdict::new(
            Status::NotCheckable,
            CURVE,
            ["no sample point outside the hull (not decided)"],
        );
    };
    let mut point = vec![(parameter.to_string(), value.clone())];
    point.extend(atoms);
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
            "Q = ({x}, {y}) violates {} (edge {}) — outside the hull of the polygon",
            plane.shown(),
            plane.edge
        ))
        .witnessed(Some(w))],
    )
}

/// The tensor-product surface of `basis` in both directions at the one
/// parameter value over a listing's net leaves the net ([`leaves_net`]).
pub fn surface_leaves_net<B: ExactBasis + Clone>(
    basis: &B,
    value: &Rational,
    net: &ListedNet,
) -> Verdict {
    let points = match crate::surface::rational_points(net) {
        Ok(points) => points,
        Err(not_rational) => return not_rational,
    };
    let direction = || Direction {
        basis: basis.clone(),
        params: vec![Affine::rational(value.clone())],
    };
    match ControlNet::new(points)
        .map_err(|e| e.to_string())
        .and_then(|n| TensorSurface::new(direction(), direction(), n).map_err(|e| e.to_string()))
    {
        Ok(surface) => leaves_net(&surface, NET_STEPS),
        Err(why) => Verdict::not_checkable(format!("net {}: {why}", net.name)),
    }
}

/// Every case of the claim: for each value of `parameter`, the curve of
/// each polygon ("curve, m = −4"; numbered when several) and the surface
/// over `net` ("surface, m = −4"); holds when every case shows its point.
pub fn leaves_hull<B: ExactBasis + Clone>(
    basis: &B,
    parameter: &str,
    values: &[Rational],
    polygons: &[Vec<Point>],
    net: Option<&ListedNet>,
) -> Verdict {
    let params = basis.parameters();
    let [p] = &params[..] else {
        return Verdict::not_checkable(
            "the hull is left at values of the basis's one parameter: this basis has another number of parameters",
        );
    };
    if p.name != parameter {
        return Verdict::not_checkable(format!("`{parameter}` is not the basis's parameter"));
    }
    let mut parts = Vec::new();
    for value in values {
        let shown = format!("{} = {}", p.symbol, value.to_string().replace('-', "−"));
        for (k, polygon) in polygons.iter().enumerate() {
            let name = if polygons.len() == 1 {
                "curve".to_string()
            } else {
                format!("curve {}", k + 1)
            };
            parts.push((
                format!("{name}, {shown}"),
                curve_leaves_hull(basis, parameter, value, polygon),
            ));
        }
        if let Some(net) = net {
            parts.push((
                format!("surface, {shown}"),
                surface_leaves_net(basis, value, net),
            ));
        }
    }
    let method = match (polygons.is_empty(), net.is_some()) {
        (false, true) => format!("{CURVE}; {OUTSIDE_NET}"),
        (false, false) => CURVE.to_string(),
        _ => OUTSIDE_NET.to_string(),
    };
    Verdict::all(method, parts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    fn q(n: i64) -> Rational {
        Rational::from(n)
    }

    fn polygon() -> Vec<Point> {
        [(0, 0), (2, 6), (6, 6), (8, 0)]
            .map(|(x, y)| (q(x), q(y)))
            .to_vec()
    }

    #[test]
    fn the_hull_of_a_convex_polygon_has_its_edges_as_printed() {
        let planes = half_planes(&polygon()).unwrap();
        let shown: Vec<String> = planes
            .iter()
            .map(|h| format!("{} ({})", h.shown(), h.edge))
            .collect();
        assert_eq!(
            shown,
            [
                "3x − y ≥ 0 (P0P1)",
                "y ≤ 6 (P1P2)",
                "3x + y ≤ 24 (P2P3)",
                "y ≥ 0 (P3P0)"
            ]
        );
        // an inner vertex is not on the hull
        let mut inner = polygon();
        inner.push((q(4), q(1)));
        assert_eq!(hull(&inner), [0, 1, 2, 3]);
    }

    #[test]
    fn the_thesis_curve_leaves_its_hull_outside_the_range_and_not_inside() {
        let basis = Family::ThesisCubic;
        let out = curve_leaves_hull(&basis, "m", &q(3), &polygon());
        assert_eq!(out.status, Status::Holds, "{out:?}");
        assert!(out.evidence[0].text.contains("y ≤ 6"), "{out:?}");
        let inside = curve_leaves_hull(&basis, "m", &Rational::from((1, 2)), &polygon());
        assert_eq!(inside.status, Status::NotCheckable, "{inside:?}");
    }
}
