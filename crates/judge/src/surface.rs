//! Tensor-product surfaces ([`trig_core::surface::TensorSurface`]) against
//! their control net and against a surface of revolution, for any basis in
//! each direction: the surface's own points and bounds, computed by the
//! surface's one evaluation (`combine`) in the exact ring and in intervals.
//!
//! - [`leaves_net`]: one exact point of the surface outside the net's
//!   bounding box (a supporting half-space of the net's hull), searched on
//!   a grid of each domain: decides "leaves the control net"; none found
//!   leaves it undecided (a sample proves no containment).
//! - [`inside_net`]: the product weights `B_i(u) B_j(v)` are ≥ 0 and sum to
//!   1 when each direction's functions are (the convex-hull judge of each
//!   direction at its parameter values): the surface lies in the net's hull.
//! - [`cylinder_distance`]: the largest distance of the surface from the
//!   cylinder `x² + y² = r²` (the surface of revolution of a vertical line),
//!   certified by the Bernstein coefficients of `x² + y² − r²` on the unit
//!   square, with one exact point off the cylinder.

use rug::Rational;
use trig_certify::bernstein::{Tensor, tensor_to_bernstein};
use trig_core::net::ControlNet;
use trig_core::surface::{Direction, TensorSurface};
use trig_core::{Affine, Interval, ParamRange, Ring};
use trig_specfile::ListedNet;
use trig_symbolic::{Poly, Sym};
use trig_verdict::evidence::Evidence;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness;

use crate::exact::{ExactBasis, values_at};
use crate::nonnegative::convex_hull;

/// The method of [`leaves_net`].
pub const OUTSIDE_NET: &str = "exact: the surface S(u, v) = Σ Σ P_ij B_i(u) B_j(v) at rational grid points of both domains, each coordinate exact (the functions exact there) and placed against the net's bounding box by a certified interval enclosure of the same sum";

/// The method of [`cylinder_distance`].
pub const CYLINDER: &str = "certified: x² + y² − r² = g of the surface, an exact polynomial in (u, v), bounded by its Bernstein coefficients over a subdivision of [0, 1]² in rational arithmetic; the distance |√(r² + g) − r| at the ends of that range, in interval arithmetic";

/// Bits of the interval enclosures that place an exact coordinate.
const PREC: u32 = 128;

/// Every function of `dir` at the exact point `x` (its parameters exact):
/// `None` where the exact ring cannot take a function there.
pub fn exact_values<B: ExactBasis>(dir: &Direction<B>, x: &Affine) -> Option<Vec<Sym>> {
    values_at(&dir.basis, &dir.params, x).into_iter().collect()
}

/// The point `S(u, v)` exactly, when every function of both directions is
/// exact there.
pub fn exact_point<B: ExactBasis>(
    surface: &TensorSurface<B>,
    u: &Affine,
    v: &Affine,
) -> Option<[Sym; 3]> {
    let bu = exact_values(surface.u(), u)?;
    let bv = exact_values(surface.v(), v)?;
    surface.combine(&bu, &bv).ok()
}

/// `steps + 1` evenly spaced exact points of a direction's domain, ends
/// included.
fn grid<B: ExactBasis>(dir: &Direction<B>, steps: i64) -> Vec<Affine> {
    let domain = dir.basis.domain();
    let (start, end) = (domain.start.at(&dir.params), domain.end.at(&dir.params));
    let width = end.plus(&start.scale(&Rational::from(-1)));
    (0..=steps)
        .map(|k| start.plus(&width.scale(&Rational::from((k, steps)))))
        .collect()
}

/// The smallest and largest value of each coordinate over the net.
fn bounding_box<B: ExactBasis>(surface: &TensorSurface<B>) -> [(Rational, Rational); 3] {
    let points = surface.net().points().iter().flatten();
    std::array::from_fn(|k| {
        let mut values = points.clone().map(|p| &p[k]);
        let first = values.next().cloned().unwrap_or_default();
        values.fold((first.clone(), first), |(lo, hi), x| {
            (lo.min(x.clone()), hi.max(x.clone()))
        })
    })
}

/// `u` as an interval (its parameters exact).
fn enclose(x: &Affine) -> Interval {
    x.eval(&Interval::from_rational(PREC, &Rational::new()), &[])
}

/// Which bound coordinate `k` of the enclosed point violates, certified:
/// below `lo` or above `hi`.
fn violated(point: &[Interval; 3], bounds: &[(Rational, Rational); 3]) -> Option<(usize, String)> {
    let names = ["x", "y", "z"];
    point
        .iter()
        .zip(bounds)
        .enumerate()
        .find_map(|(k, (c, (lo, hi)))| {
            if *c.hi() < *lo {
                Some((k, format!("{} < {lo}", names[k])))
            } else if *c.lo() > *hi {
                Some((k, format!("{} > {hi}", names[k])))
            } else {
                None
            }
        })
}

/// One exact point of the surface outside its net's bounding box, searched
/// on `(steps + 1)²` grid points (only points where both directions are
/// exact count): `holds` with the point (rational `u`, `v` and the three
/// exact coordinates as a witness), `not-checkable` without one.
pub fn leaves_net<B: ExactBasis>(surface: &TensorSurface<B>, steps: i64) -> Verdict {
    let bounds = bounding_box(surface);
    let shown = bounds
        .iter()
        .zip(["x", "y", "z"])
        .map(|((lo, hi), n)| format!("{lo} ≤ {n} ≤ {hi}"))
        .collect::<Vec<_>>()
        .join(", ");
    let (gu, gv) = (grid(surface.u(), steps), grid(surface.v(), steps));
    let found = gu
        .iter()
        .flat_map(|u| gv.iter().map(move |v| (u, v)))
        .find_map(|(u, v)| {
            let (qu, qv) = (u.as_rational()?, v.as_rational()?);
            let point = surface.eval(&enclose(u), &enclose(v), true).ok()?;
            let (_, why) = violated(&point, &bounds)?;
            let exact = exact_point(surface, u, v)?;
            Some((qu.clone(), qv.clone(), exact, why))
        });
    let Some((u, v, exact, why)) = found else {
        return Verdict::new(
            Status::NotCheckable,
            OUTSIDE_NET,
            [format!(
                "no point of the {0} × {0} grid of rational points outside the box {shown} that contains the net (a sample proves no containment: not decided)",
                steps + 1
            )],
        );
    };
    let point = vec![("u".to_string(), u.clone()), ("v".to_string(), v.clone())];
    let names = ["u".to_string(), "v".to_string()];
    let [x, y, z] = &exact;
    let w = witness::witness(
        &point,
        &names,
        vec![("x", x.clone()), ("y", y.clone()), ("z", z.clone())],
    );
    Verdict::new(
        Status::Holds,
        OUTSIDE_NET,
        [Evidence::note(format!(
            "S({u}, {v}) = ({}, {}, {}) has {why}: outside the box {shown} that contains the net",
            x.to_unicode(),
            y.to_unicode(),
            z.to_unicode()
        ))
        .witnessed(Some(w))],
    )
}

/// The range `[p, p]` of a direction's one parameter value, for the
/// convex-hull judge; `None` for a basis without exactly one rational
/// parameter.
fn point_range<B: ExactBasis>(dir: &Direction<B>) -> Option<ParamRange> {
    let [p] = &dir.params[..] else { return None };
    let q = p.as_rational()?;
    ParamRange::parse(&format!("[{q}, {q}]")).ok()
}

/// The surface lies in the convex hull of its net when the functions of
/// each direction are ≥ 0 and sum to 1 at its parameter values (then so do
/// the products `B_i(u) B_j(v)`): the convex-hull judge of each direction.
pub fn inside_net<B: ExactBasis>(surface: &TensorSurface<B>) -> Verdict {
    let hull = |dir: &Direction<B>, side: &str| match point_range(dir) {
        Some(range) => convex_hull(&dir.basis, Some(&range)),
        None if dir.params.is_empty() => convex_hull(&dir.basis, None),
        None => Verdict::not_checkable(format!(
            "the {side} direction's parameters are not one rational value: the convex-hull judge takes one"
        )),
    };
    let (u, v) = (surface.u(), surface.v());
    let same = u.basis.id() == v.basis.id() && u.params == v.params;
    let mut v = if same {
        hull(u, "u")
    } else {
        let parts = vec![
            ("the u direction".to_string(), hull(u, "u")),
            ("the v direction".to_string(), hull(v, "v")),
        ];
        let method = parts[0].1.method.clone();
        Verdict::all(method, parts)
    };
    v.evidence.insert(
        0,
        "the product weights b_i(u) b_j(v) are ≥ 0 and sum to 1 exactly when the b_i are (a negative b_i(u₀) times a positive b_j(v) is negative): the surface lies in the convex hull of the net",
    );
    v
}

/// A polynomial in `u`, `v` as the tensor of its power coefficients; `None`
/// for one with another variable or an irrational coefficient.
fn tensor(p: &Poly) -> Option<Tensor> {
    let rows = p.coefficients_in("u");
    let columns: Vec<_> = rows.iter().map(|r| r.coefficients_in("v")).collect();
    let dv = columns.iter().map(Vec::len).max().unwrap_or(1).max(1);
    let mut t = Tensor::zeros(vec![rows.len().max(1) - 1, dv - 1]);
    for (i, row) in columns.iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            t.add(&[i, j], &c.as_constant()?);
        }
    }
    Some(t)
}

/// The surface's functions in its own variables renamed `u` and `v`.
fn symbolic_point<B: ExactBasis>(surface: &TensorSurface<B>) -> Option<[Sym; 3]> {
    let functions = |dir: &Direction<B>, name: &str| -> Option<Vec<Sym>> {
        let params: Vec<Sym> = dir
            .params
            .iter()
            .map(|a| a.eval(&Sym::zero(), &[]))
            .collect();
        let var = Sym::var(name);
        dir.basis
            .exact_functions_at(&params)
            .into_iter()
            .map(|f| Some(f?.subs("t", &var)))
            .collect()
    };
    let (bu, bv) = (functions(surface.u(), "u")?, functions(surface.v(), "v")?);
    surface.combine(&bu, &bv).ok()
}

/// Pieces per variable of the subdivision that bounds `x² + y² − r²`.
const PIECES: i64 = 16;

/// `p` on the piece `[i/n, (i+1)/n]` of `name`, rescaled to `[0, 1]`.
fn piece(p: &Poly, name: &str, i: i64, n: i64) -> Poly {
    if n == 1 {
        return p.clone();
    }
    let x =
        Poly::var(name).scale(&Rational::from((1, n))) + &Poly::constant(Rational::from((i, n)));
    p.subs(name, &x)
}

/// The smallest and largest Bernstein coefficient of `p` over the pieces
/// of a uniform subdivision of `[0, 1]²` (bounds of `p` there), and the
/// value of largest modulus at the pieces' corners with its point.
fn bounds(p: &Poly) -> Option<[Rational; 2]> {
    let n = |name: &str| {
        let d = i64::from(p.degree_in(name));
        if d == 0 { 1 } else { PIECES.max(d + 1) }
    };
    let (nu, nv) = (n("u"), n("v"));
    let (mut lo, mut hi) = (Rational::new(), Rational::new());
    for i in 0..nu {
        let pu = piece(p, "u", i, nu);
        for j in 0..nv {
            let b = tensor_to_bernstein(&tensor(&piece(&pu, "v", j, nv))?);
            for c in &b.coeffs {
                lo = lo.min(c.clone());
                hi = hi.max(c.clone());
            }
        }
    }
    Some([lo, hi])
}

/// The grid point `(i/n, j/n)` where `|g|` is largest, with `g` there.
fn largest_at(g: &Sym, n: i64) -> (Rational, Rational, Rational) {
    let mut best = (Rational::new(), Rational::new(), Rational::new());
    for i in 0..=n {
        for j in 0..=n {
            let (u, v) = (Rational::from((i, n)), Rational::from((j, n)));
            let at = g
                .subs("u", &Sym::rational(u.clone()))
                .subs("v", &Sym::rational(v.clone()));
            if let Some(x) = at.as_rational()
                && x.clone().abs() > best.0.clone().abs()
            {
                best = (x, u, v);
            }
        }
    }
    best
}

/// `|√(r² + g) − r|`, the distance from the cylinder of a point at
/// `x² + y² = r² + g`, enclosed; `None` when `r² + g < 0` is possible.
fn radial_gap(radius: &Rational, g: &Rational) -> Option<Interval> {
    let r = Interval::from_rational(PREC, radius);
    let square = Rational::from(radius * radius) + g;
    let root = Interval::from_rational(PREC, &square).try_sqrt()?;
    let d = if *g < 0 { r - &root } else { root - &r };
    d.fault().is_none().then_some(d)
}

/// A certified end shown to 5 digits, rounded outward.
fn shown(x: &rug::Float, round: rug::float::Round) -> String {
    x.to_string_radix_round(10, Some(5), round)
}

/// The largest distance of a polynomial surface over `[0, 1]²` from the
/// cylinder `x² + y² = radius²` about the `z` axis: `fails` (the surface
/// is not the cylinder) with an exact point off it and certified bounds of
/// the largest distance, `holds` when `x² + y² − r²` is identically 0.
pub fn cylinder_distance<B: ExactBasis>(surface: &TensorSurface<B>, radius: &Rational) -> Verdict {
    let polynomial = [surface.u(), surface.v()].iter().all(|dir| {
        let domain = dir.basis.domain();
        !domain.is_trigonometric()
            && domain.start.as_rational() == Some(&Rational::new())
            && domain.end.as_rational() == Some(&Rational::from(1))
    });
    let r2 = Sym::rational(Rational::from(radius * radius));
    let gap = symbolic_point(surface)
        .filter(|_| polynomial && *radius > 0)
        .map(|[x, y, _]| x.clone() * &x + &(y.clone() * &y) - &r2)
        .filter(|g| g.denominator().is_empty());
    let Some((gap, [lo, hi])) = gap.and_then(|g| Some((g.clone(), bounds(g.numerator())?))) else {
        return Verdict::not_checkable(
            "the cylinder distance is bounded for polynomial bases on [0, 1] in both directions and a positive radius only",
        );
    };
    if gap.is_zero() {
        return Verdict::new(
            Status::Holds,
            CYLINDER,
            ["x² + y² − r² ≡ 0: the surface lies on the cylinder"],
        );
    }
    // the distance |√(r² + g) − r| grows with |g| on either side of 0: its
    // largest value over g ∈ [lo, hi] is at an end
    let (off, u, v) = largest_at(&gap, PIECES);
    // x² + y² ≥ 0, so g ≥ −r² wherever the Bernstein bound is lower (a
    // surface through the axis inside a piece): at most r inside
    let lo = lo.max(-Rational::from(radius * radius));
    let ends = [radial_gap(radius, &lo), radial_gap(radius, &hi)];
    let (Some(at_point), [Some(below), Some(above)]) = (radial_gap(radius, &off), ends) else {
        return Verdict::not_checkable(
            "the distance from the cylinder is not enclosed here (an interval fault)",
        );
    };
    let upper = if below.hi() > above.hi() {
        below.hi()
    } else {
        above.hi()
    };
    let point = vec![("u".to_string(), u.clone()), ("v".to_string(), v.clone())];
    let names = ["u".to_string(), "v".to_string()];
    let off = Sym::rational(off);
    let (down, up) = (rug::float::Round::Down, rug::float::Round::Up);
    Verdict::new(
        Status::Fails,
        CYLINDER,
        [
            Evidence::note(format!(
                "x² + y² − r² = {} (r = {radius}) is not identically 0",
                gap.to_unicode()
            )),
            Evidence::note(format!(
                "x² + y² − r² = {} at (u, v) = ({u}, {v}): the surface point is off the cylinder, at distance ≥ {}",
                off.to_unicode(),
                shown(at_point.lo(), down)
            ))
            .witnessed(witness::of_exprs(&point, &names, &[("x² + y² − r²", &gap)])),
            Evidence::note(format!(
                "the largest distance from the cylinder lies in [{}, {}] (certified: below, the point of largest |x² + y² − r²| of a {PIECES} × {PIECES} grid; above, x² + y² − r² ∈ [{}, {}] by its Bernstein coefficients over {PIECES} pieces per variable of [0, 1]²)",
                shown(at_point.lo(), down),
                shown(upper, up),
                shown(&rug::Float::with_val_round(53, &lo, down).0, down),
                shown(&rug::Float::with_val_round(53, &hi, up).0, up)
            )),
        ],
    )
}

/// [`cylinder_distance`] of the tensor-product surface of `basis` in both
/// directions over a printed net (a listing's, `check = "cylinder"`): its
/// points rational, every parameter of the basis fixed (the claim's `at`);
/// otherwise `not-checkable`, saying which.
pub fn net_cylinder_distance<B: ExactBasis + Clone>(
    basis: &B,
    net: &ListedNet,
    radius: &Rational,
) -> Verdict {
    if !basis.parameters().is_empty() {
        return Verdict::not_checkable(
            "the surface is formed at fixed parameter values: fix every parameter with `at`",
        );
    }
    let points = match crate::surface::rational_points(net) {
        Ok(points) => points,
        Err(not_rational) => return not_rational,
    };
    let direction = || Direction {
        basis: basis.clone(),
        params: Vec::new(),
    };
    match ControlNet::new(points)
        .map_err(|e| e.to_string())
        .and_then(|n| TensorSurface::new(direction(), direction(), n).map_err(|e| e.to_string()))
    {
        Ok(surface) => cylinder_distance(&surface, radius),
        Err(why) => Verdict::not_checkable(format!("net {}: {why}", net.name)),
    }
}

/// The points of a listing's net as exact rationals, or the `not-checkable`
/// verdict naming the net when one coordinate is not a rational number.
pub fn rational_points(net: &ListedNet) -> Result<Vec<Vec<[Rational; 3]>>, Verdict> {
    net.points
        .iter()
        .map(|row| {
            row.iter()
                .map(|p| {
                    Some([
                        p[0].as_rational()?,
                        p[1].as_rational()?,
                        p[2].as_rational()?,
                    ])
                })
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| {
            Verdict::not_checkable(format!(
                "the points of net {} are not all rational numbers",
                net.name
            ))
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    fn surface(basis: Family, params: Vec<Rational>, net: &str) -> TensorSurface<Family> {
        let dir = || Direction {
            basis,
            params: params.iter().cloned().map(Affine::rational).collect(),
        };
        TensorSurface::new(dir(), dir(), ControlNet::parse(net, "net").unwrap()).unwrap()
    }

    /// The thesis's printed 4×4 net (before Figure 5.1).
    const THESIS: &str = "0 0 0\n1 0 1\n2 0 2\n3 0 0\n\n0 1 1\n1 1 3\n2 1 4\n3 1 2\n\n\
        0 2 2\n1 2 4\n2 2 3\n3 2 1\n\n0 3 0\n1 3 2\n2 3 1\n3 3 0\n";

    #[test]
    fn outside_the_range_the_thesis_surface_leaves_its_net_and_inside_it_stays() {
        let out = surface(Family::ThesisCubic, vec![q(4, 1)], THESIS);
        let v = leaves_net(&out, 6);
        assert_eq!(v.status, Status::Holds, "{v:?}");
        assert!(v.evidence.iter().any(|e| e.contains("z > 4")), "{v:?}");
        assert_ne!(inside_net(&out).status, Status::Holds);
        let inside = surface(Family::ThesisCubic, vec![q(1, 2)], THESIS);
        assert_eq!(leaves_net(&inside, 6).status, Status::NotCheckable);
        assert_eq!(inside_net(&inside).status, Status::Holds);
    }

    #[test]
    fn a_cubic_quarter_circle_is_off_the_cylinder_and_a_vertical_line_is_on_it() {
        // rows: heights 0, 1/3, 2/3, 1; columns: the Bézier quarter circle
        // with handles 1/2 (not on the circle)
        let ring = |z: &str| format!("1 0 {z}\n1 1/2 {z}\n1/2 1 {z}\n0 1 {z}\n\n");
        let net: String = ["0", "1/3", "2/3", "1"].map(ring).concat();
        let v = cylinder_distance(&surface(Family::Bernstein3, vec![], &net), &q(1, 1));
        assert_eq!(v.status, Status::Fails, "{v:?}");
        // the sampled largest distance of C(v) = Σ Bⱼ(v) Pⱼ lies in the bounds
        let text = v.evidence.iter().map(|e| e.line()).collect::<String>();
        let range = text
            .split("lies in [")
            .nth(1)
            .and_then(|r| r.split(']').next());
        let [lo, hi]: [f64; 2] = range
            .map(|r| {
                r.split(", ")
                    .map(|x| x.parse().unwrap())
                    .collect::<Vec<_>>()
            })
            .and_then(|b| b.try_into().ok())
            .unwrap_or_else(|| panic!("{text}"));
        let sampled = (0..=1000)
            .map(|k| {
                let t = f64::from(k) / 1000.0;
                let b = [
                    (1.0 - t).powi(3),
                    3.0 * t * (1.0 - t).powi(2),
                    3.0 * t * t * (1.0 - t),
                    t.powi(3),
                ];
                let (x, y) = (b[0] + b[1] + b[2] / 2.0, b[1] / 2.0 + b[2] + b[3]);
                (x.hypot(y) - 1.0).abs()
            })
            .fold(0.0, f64::max);
        assert!(
            lo <= sampled && sampled <= hi && hi - lo < 1e-3,
            "{lo} {sampled} {hi}"
        );
        let line = ["1 0 0\n"; 4].concat() + "\n";
        let on = cylinder_distance(
            &surface(Family::Bernstein3, vec![], &line.repeat(4)),
            &q(1, 1),
        );
        assert_eq!(on.status, Status::Holds, "{on:?}");
        // through the axis at v = 1/3, inside a piece of the subdivision
        // (x = 3v − 1, y = 1 − 3v: a Bernstein coefficient of x² + y² there
        // is negative, the bound of g below −r²): off the cylinder, farthest
        // at v = 1, √8 − 1 = 1.82843 outside it
        let axis = ["-1 1", "0 0", "1 -1", "2 -2"]
            .map(|p| format!("{p} 0\n"))
            .concat();
        let through = cylinder_distance(
            &surface(Family::Bernstein3, vec![], &(axis + "\n").repeat(4)),
            &q(1, 1),
        );
        assert_eq!(through.status, Status::Fails, "{through:?}");
        let text = through
            .evidence
            .iter()
            .map(|e| e.line())
            .collect::<String>();
        assert!(text.contains("lies in [1.8284, 1.8285]"), "{text}");
        let trig = cylinder_distance(
            &surface(Family::ThesisCubic, vec![q(0, 1)], THESIS),
            &q(1, 1),
        );
        assert_eq!(trig.status, Status::NotCheckable);
    }

    #[test]
    fn a_listed_net_is_decided_against_the_cylinder_with_every_parameter_fixed() {
        let point = |x: &str, y: &str, z: i64| {
            [x, y]
                .map(|c| Sym::rational(c.parse::<Rational>().unwrap()))
                .into_iter()
                .chain([Sym::int(z)])
        };
        let net = |columns: [(&str, &str); 4]| ListedNet {
            name: "S".into(),
            points: (0..4)
                .map(|z| {
                    columns
                        .iter()
                        .map(|(x, y)| {
                            let p: Vec<Sym> = point(x, y, z).collect();
                            [p[0].clone(), p[1].clone(), p[2].clone()]
                        })
                        .collect()
                })
                .collect(),
        };
        // a vertical line on the cylinder, and the Bézier quarter circle off it
        let line = net([("3/5", "4/5"); 4]);
        let v = net_cylinder_distance(&Family::Bernstein3, &line, &q(1, 1));
        assert_eq!(v.status, Status::Holds, "{v:?}");
        let arc = net([("1", "0"), ("1", "1/2"), ("1/2", "1"), ("0", "1")]);
        assert_eq!(
            net_cylinder_distance(&Family::Bernstein3, &arc, &q(1, 1)).status,
            Status::Fails
        );
        // a free parameter or a symbolic point: not decided
        let v = net_cylinder_distance(&Family::Eh, &line, &q(1, 1));
        assert_eq!(v.status, Status::NotCheckable, "{v:?}");
        let mut symbolic = line.clone();
        symbolic.points[0][0][0] = Sym::var("a");
        let v = net_cylinder_distance(&Family::Bernstein3, &symbolic, &q(1, 1));
        assert_eq!(v.status, Status::NotCheckable, "{v:?}");
    }
}
