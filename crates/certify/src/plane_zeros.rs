//! Real zeros in a box of polynomials in two variables `x`, `y`, exact.
//!
//! - **Common zeros** of polynomials `p₁, …, p_k` with no common factor (a
//!   finite set): two coprime combinations `F`, `H` of them (a pair of the
//!   `pᵢ`, else `Σ jⁱ·pᵢ`) have finitely many common zeros, whose `x` lie
//!   among the real roots of `Res_y(F, H)` and whose `y` among those of
//!   `Res_x(F, H)` (both nonzero as `F`, `H` are coprime). Over a rational
//!   root `x₀` the common zeros are the real roots of
//!   `gcd(p₁(x₀, y), …, p_k(x₀, y))` in `y` (Sturm sequences), and
//!   symmetrically over a rational `y₀`. Over an irrational `x₀` (a root
//!   of `h`), the gcd of the fibres in `(Q[x]/(h))[y]` (Euclid, `h` split
//!   where a zero divisor is met): when it is linear, `y = φ(x₀)`, the
//!   root of `Res_x(h, y − φ)` isolated by enclosing `φ` on finer
//!   intervals of `x₀`; of higher degree, the answer says so (a bracket,
//!   not a set).
//! - **A point on a curve** `f = 0` in the box: over a few rational values
//!   of one coordinate in its range (the closed ends, the middle, the
//!   quarters), the real roots of `f(x₀, y)` in the other range, a
//!   rational one preferred. Finding none proves nothing.
//!
//! Each coordinate is a rational or an [`Algebraic`] number (a squarefree
//! polynomial and an isolating interval), every step exact.

use rug::Rational;
use trig_core::{End, ParamRange};
use trig_symbolic::Poly;

use crate::algebraic::Algebraic;
use crate::resultant::resultant;
use crate::sturm::UPoly;

/// A real root of a polynomial in one variable, exact.
pub type Coordinate = Algebraic;

/// A point `(x, y)` of the plane, exact.
#[derive(Debug, Clone, PartialEq)]
pub struct PlanePoint {
    pub x: Coordinate,
    pub y: Coordinate,
}

impl PlanePoint {
    /// The rational coordinates, when both are.
    pub fn rational(&self) -> Option<[Rational; 2]> {
        Some([self.x.rational.clone()?, self.y.rational.clone()?])
    }
}

/// The common zeros in the box.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CommonZeros {
    pub points: Vec<PlanePoint>,
    /// Why the set may be incomplete (empty when it is exact).
    pub undecided: Option<String>,
}

/// Why the common zeros were not computed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PlaneError {
    #[error("a polynomial is not in {0} and {1} alone")]
    OtherVariables(String, String),
    #[error("no two coprime combinations of the polynomials were found (they may share a factor)")]
    NoCoprimePair,
}

/// `p` with the constant `v` for `var`, as a polynomial in `other`.
fn fiber(p: &Poly, var: &str, v: &Rational, other: &str) -> UPoly {
    let q = p.subs(var, &Poly::constant(v.clone()));
    UPoly::from_poly(&q, other).unwrap_or_else(|| UPoly::new(vec![]))
}

/// The finite ends of `r` (a root bound `b` of `p` for an unbounded end).
fn ends(r: &ParamRange, p: &UPoly) -> (Rational, Rational) {
    let bound = p.root_bound() + Rational::from(1);
    let lo = r.lo.value().cloned().unwrap_or_else(|| -bound.clone());
    let hi = r.hi.value().cloned().unwrap_or(bound);
    (lo, hi)
}

/// The distinct real roots of `p ≢ 0` in `r`, increasing, exact.
pub fn roots_in(p: &UPoly, r: &ParamRange) -> Vec<Algebraic> {
    if p.degree() == 0 {
        return Vec::new();
    }
    let (lo, hi) = ends(r, p);
    let mut out = Vec::new();
    if let End::Closed(v) = &r.lo
        && p.sign_at(v) == 0
    {
        out.push(Algebraic::new(p, v.clone(), v.clone()));
    }
    if lo < hi {
        out.extend(
            p.isolate(&lo, &hi)
                .into_iter()
                .map(|(a, b)| Algebraic::new(p, a, b)),
        );
    }
    if let End::Closed(v) = &r.hi
        && p.sign_at(v) == 0
        && r.lo.value() != Some(v)
    {
        out.push(Algebraic::new(p, v.clone(), v.clone()));
    }
    out
}

fn rational(q: &Rational) -> Algebraic {
    Algebraic::new(
        &UPoly::new(vec![-q.clone(), Rational::from(1)]),
        q.clone(),
        q.clone(),
    )
}

/// Two coprime combinations of `ps`.
fn coprime_pair(ps: &[Poly]) -> Option<(Poly, Poly)> {
    let coprime = |a: &Poly, b: &Poly| {
        trig_symbolic::gcd::gcd(a, b).is_some_and(|g| g.as_constant().is_some())
    };
    for (i, a) in ps.iter().enumerate() {
        for b in &ps[i + 1..] {
            if coprime(a, b) {
                return Some((a.clone(), b.clone()));
            }
        }
    }
    let combination = |k: i64| {
        ps.iter().enumerate().fold(Poly::zero(), |acc, (i, p)| {
            acc + &p.scale(&Rational::from(k.pow(i as u32)))
        })
    };
    (2..6)
        .map(|k| (combination(k), combination(-k - 1)))
        .find(|(a, b)| coprime(a, b))
}

/// The common real zeros of `ps` (no common factor) in `rx × ry`.
pub fn common_zeros(
    ps: &[Poly],
    x: &str,
    y: &str,
    rx: &ParamRange,
    ry: &ParamRange,
) -> Result<CommonZeros, PlaneError> {
    if ps
        .iter()
        .any(|p| p.variables().iter().any(|v| v != x && v != y))
    {
        return Err(PlaneError::OtherVariables(x.into(), y.into()));
    }
    let ps: Vec<Poly> = ps.iter().filter(|p| !p.is_zero()).cloned().collect();
    if ps.iter().any(|p| p.as_constant().is_some()) {
        return Ok(CommonZeros::default());
    }
    let (f, h) = coprime_pair(&ps).ok_or(PlaneError::NoCoprimePair)?;
    let projection = |var: &str, other: &str| {
        let r = resultant(&f, &h, other);
        UPoly::from_poly(&r, var).unwrap_or_else(|| UPoly::new(vec![]))
    };
    let (px, py) = (projection(x, y), projection(y, x));
    let (xs, ys) = (roots_in(&px, rx), roots_in(&py, ry));
    let mut points = Vec::new();
    // over each rational x₀: every y; over each rational y₀: the irrational x
    for (a, var, other, r_other, swap) in [(&xs, x, y, ry, false), (&ys, y, x, rx, true)] {
        for q in a.iter().filter_map(|c| c.rational.as_ref()) {
            let g = ps.iter().fold(UPoly::new(vec![]), |acc, p| {
                acc.gcd(&fiber(p, var, q, other))
            });
            for root in roots_in(&g, r_other) {
                if swap && root.rational.is_some() {
                    continue;
                }
                let (u, v) = (rational(q), root);
                points.push(if swap {
                    PlanePoint { x: v, y: u }
                } else {
                    PlanePoint { x: u, y: v }
                });
            }
        }
    }
    // both irrational: over each irrational x₀, the gcd of the fibres in
    // Q(x₀)[y]
    let mut undecided = Vec::new();
    if ys.iter().any(|c| c.rational.is_none()) {
        for x0 in xs.iter().filter(|c| c.rational.is_none()) {
            match over_irrational(&ps, x, y, x0, ry) {
                Ok(Some(p)) => points.push(p),
                Ok(None) => {}
                Err(why) => undecided.push(format!("over {x} = {}: {why}", x0.describe(x, 12))),
            }
        }
    }
    let undecided = (!undecided.is_empty()).then(|| {
        format!(
            "common zeros with both coordinates irrational are not all isolated ({})",
            undecided.join("; ")
        )
    });
    Ok(CommonZeros { points, undecided })
}

/// A polynomial in `y` with coefficients in `Q[x]/(h)`, lowest degree
/// first, no zero (mod `h`) leading coefficient.
type Fibre = Vec<UPoly>;

fn reduced(a: Fibre, h: &UPoly) -> Fibre {
    let mut a: Fibre = a.into_iter().map(|c| c.div_rem(h).1).collect();
    while a.last().is_some_and(UPoly::is_zero) {
        a.pop();
    }
    a
}

/// The inverse of `c` modulo `h`, or (a zero divisor) the factor of `h`
/// with the root in `(lo, hi)`, to go on with.
fn inverse(c: &UPoly, h: &UPoly, lo: &Rational, hi: &Rational) -> Result<UPoly, UPoly> {
    let (g, s) = c.ext_gcd(h);
    if g.degree() > 0 {
        let other = h.div_rem(&g).0;
        return Err(if g.count_roots(lo, hi) > 0 { g } else { other });
    }
    Ok(s.mul(&UPoly::new(vec![Rational::from(1) / g.leading()])))
}

/// `a mod b` in `(Q[x]/(h))[y]`.
fn remainder(
    a: &Fibre,
    b: &Fibre,
    h: &UPoly,
    lo: &Rational,
    hi: &Rational,
) -> Result<Fibre, UPoly> {
    let inv = inverse(&b[b.len() - 1], h, lo, hi)?;
    let mut r = a.clone();
    while r.len() >= b.len() {
        let f = r[r.len() - 1].mul(&inv).div_rem(h).1;
        let shift = r.len() - b.len();
        for (j, bj) in b.iter().enumerate() {
            r[shift + j] = r[shift + j].sub(&f.mul(bj));
        }
        r = reduced(r, h);
    }
    Ok(r)
}

/// The monic gcd of the fibres in `(Q[x]/(h))[y]`; `Err` with the factor
/// of `h` to continue with where a zero divisor was met.
fn fibre_gcd(fs: &[Fibre], h: &UPoly, lo: &Rational, hi: &Rational) -> Result<Fibre, UPoly> {
    let mut g: Fibre = Vec::new();
    for f in fs {
        let (mut a, mut b) = (g, reduced(f.clone(), h));
        while !b.is_empty() {
            let r = remainder(&a, &b, h, lo, hi)?;
            (a, b) = (b, r);
        }
        g = a;
    }
    if let Some(lead) = g.last() {
        let inv = inverse(lead, h, lo, hi)?;
        g = reduced(g.iter().map(|c| c.mul(&inv)).collect(), h);
    }
    Ok(g)
}

/// An enclosure of `p` over `[lo, hi]` (interval Horner, exact rationals).
fn enclose(p: &UPoly, lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    let (mut a, mut b) = (Rational::new(), Rational::new());
    for c in p.coeffs().iter().rev() {
        let products = [
            Rational::from(&a * lo),
            Rational::from(&a * hi),
            Rational::from(&b * lo),
            Rational::from(&b * hi),
        ];
        let min = products.iter().min().cloned().unwrap_or_default();
        let max = products.iter().max().cloned().unwrap_or_default();
        (a, b) = (min + c, max + c);
    }
    (a, b)
}

/// `a` in `r` (exact comparisons with the ends).
fn within(a: &mut Algebraic, r: &ParamRange) -> bool {
    use std::cmp::Ordering::{Greater, Less};
    let above = match &r.lo {
        End::Closed(q) => a.cmp_rational(q) != Less,
        End::Open(q) => a.cmp_rational(q) == Greater,
        End::Unbounded => true,
    };
    let below = match &r.hi {
        End::Closed(q) => a.cmp_rational(q) != Greater,
        End::Open(q) => a.cmp_rational(q) == Less,
        End::Unbounded => true,
    };
    above && below
}

/// The common zero with an irrational `y` over the irrational `x0`, when
/// the gcd of the fibres over it is linear (`y = φ(x₀)`): `y` a root of
/// `Res_x(h, y − φ)` isolated by enclosing `φ` over ever finer intervals
/// of `x0`. `Err` when the gcd is of higher degree or `y` not isolated.
fn over_irrational(
    ps: &[Poly],
    x: &str,
    y: &str,
    x0: &Algebraic,
    ry: &ParamRange,
) -> Result<Option<PlanePoint>, String> {
    let fibres: Vec<Fibre> = ps
        .iter()
        .map(|p| {
            p.coefficients_in(y)
                .iter()
                .map(|c| UPoly::from_poly(c, x).unwrap_or_else(|| UPoly::new(vec![])))
                .collect()
        })
        .collect();
    let (mut h, lo, hi) = (x0.poly.clone(), x0.lo.clone(), x0.hi.clone());
    let g = loop {
        match fibre_gcd(&fibres, &h, &lo, &hi) {
            Ok(g) => break g,
            Err(factor) if factor.degree() < h.degree() && factor.degree() > 0 => h = factor,
            Err(_) => return Err("the splitting of its polynomial did not settle".into()),
        }
    };
    match g.len() {
        0 => return Err("every fibre vanishes there (a common factor)".into()),
        1 => return Ok(None),
        2 => {}
        n => {
            return Err(format!(
                "the gcd of the fibres is of degree {} in {y} over Q({x}); its roots are not isolated",
                n - 1
            ));
        }
    }
    let phi = UPoly::new(vec![]).sub(&g[0]);
    if phi.degree() == 0 {
        return Ok(None); // a rational y: found over it
    }
    let to_poly = |u: &UPoly, var: &str| {
        let cs: Vec<Poly> = u
            .coeffs()
            .iter()
            .map(|c| Poly::constant(c.clone()))
            .collect();
        crate::resultant::from_coefficients(&cs, var)
    };
    let q = resultant(&to_poly(&h, x), &(Poly::var(y) - &to_poly(&phi, x)), x);
    let q = UPoly::from_poly(&q, y).ok_or("the resultant is not in y alone")?;
    let mut root = Algebraic::new(&h, lo, hi);
    for _ in 0..200 {
        let (a, b) = enclose(&phi, &root.lo, &root.hi);
        if q.sign_at(&a) != 0 && q.sign_at(&b) != 0 && q.count_roots(&a, &b) == 1 {
            let mut y0 = Algebraic::new(&q, a, b);
            if y0.rational.is_some() || !within(&mut y0, ry) {
                return Ok(None);
            }
            return Ok(Some(PlanePoint { x: root, y: y0 }));
        }
        let half = Rational::from(&root.hi - &root.lo) / 2u32;
        root.refine(&half);
    }
    Err(format!("the value of {y} there was not isolated"))
}

/// Rational values of `r` to try: its closed ends, the middle and the
/// quarters of its finite part (of `[−1, 1]` around a finite end, or
/// `[−1, 1]` itself, when unbounded), inside the range.
fn samples(r: &ParamRange) -> Vec<Rational> {
    let one = Rational::from(1);
    let (lo, hi) = match (r.lo.value(), r.hi.value()) {
        (Some(a), Some(b)) => (a.clone(), b.clone()),
        (Some(a), None) => (a.clone(), Rational::from(a + &one)),
        (None, Some(b)) => (Rational::from(b - &one), b.clone()),
        (None, None) => (-one.clone(), one),
    };
    let mut out: Vec<Rational> = (0..=4u32)
        .map(|k| &lo + Rational::from(&hi - &lo) * Rational::from((k, 4u32)))
        .filter(|v| r.contains(v))
        .collect();
    out.sort_by_key(|v| (v != &lo && v != &hi, v.clone()));
    out
}

/// A point of `f = 0` in `rx × ry` over a rational value of one
/// coordinate (a rational point if one is found), or `None`.
pub fn point_on(
    f: &Poly,
    x: &str,
    y: &str,
    rx: &ParamRange,
    ry: &ParamRange,
) -> Option<PlanePoint> {
    let mut found = None;
    for (var, other, r, r_other, swap) in [(x, y, rx, ry, false), (y, x, ry, rx, true)] {
        for q in samples(r) {
            let g = fiber(f, var, &q, other);
            if g.is_zero() {
                // the whole line var = q lies on the curve: any point of it
                let v = samples(r_other).into_iter().next()?;
                let (u, v) = (rational(&q), rational(&v));
                return Some(if swap {
                    PlanePoint { x: v, y: u }
                } else {
                    PlanePoint { x: u, y: v }
                });
            }
            for root in roots_in(&g, r_other) {
                let (u, v) = (rational(&q), root);
                let p = if swap {
                    PlanePoint { x: v, y: u }
                } else {
                    PlanePoint { x: u, y: v }
                };
                if p.rational().is_some() {
                    return Some(p);
                }
                found.get_or_insert(p);
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: &str) -> Poly {
        Poly::var(n)
    }

    fn k(n: i64) -> Poly {
        Poly::int(n)
    }

    fn range(a: &str) -> ParamRange {
        ParamRange::parse(a).expect("a range")
    }

    #[test]
    fn the_common_zeros_of_a_line_and_a_circle_are_exact() {
        let (x, y) = (v("x"), v("y"));
        // x − y and x² + y² − 2: (1, 1) and (−1, −1); in [0, 2]² only (1, 1)
        let ps = [&x - &y, &(&(&x * &x) + &(&y * &y)) - &k(2)];
        let z = common_zeros(&ps, "x", "y", &range("[0, 2]"), &range("[0, 2]")).expect("zeros");
        assert_eq!(z.points.len(), 1);
        let one = Rational::from(1);
        assert_eq!(z.points[0].rational(), Some([one.clone(), one]));
        assert!(z.undecided.is_none());
        // an open end leaves out (−1, −1) on it
        let z = common_zeros(&ps, "x", "y", &range("(-1, 2]"), &range("[-2, 2]")).expect("zeros");
        assert_eq!(z.points.len(), 1);
        let z = common_zeros(&ps, "x", "y", &range("[-1, 2]"), &range("[-2, 2]")).expect("zeros");
        assert_eq!(z.points.len(), 2);
        // x − 2 and y² − 2 meet at (2, ±√2): irrational y over rational x
        let ps = [&x - &k(2), &(&y * &y) - &k(2)];
        let z = common_zeros(&ps, "x", "y", &range("[0, 3]"), &range("[0, 3]")).expect("zeros");
        assert_eq!(z.points.len(), 1);
        assert!(z.points[0].y.rational.is_none());
        assert!(z.points[0].y.describe("y", 6).contains("y^2 - 2"));
        // both irrational: x² − 2 and y − x − 1 meet at (√2, 1 + √2)
        let ps = [&(&x * &x) - &k(2), &(&y - &x) - &k(1)];
        let z = common_zeros(&ps, "x", "y", &range("[0, 3]"), &range("[0, 3]")).expect("zeros");
        assert!(z.undecided.is_none(), "{z:?}");
        assert_eq!(z.points.len(), 1, "{z:?}");
        let text = [
            z.points[0].x.describe("x", 6),
            z.points[0].y.describe("y", 6),
        ]
        .join(", ");
        assert!(
            text.contains("x^2 - 2") && text.contains("y^2 - 2*y - 1"),
            "{text}"
        );
        // out of the range of y: none
        let z = common_zeros(&ps, "x", "y", &range("[0, 3]"), &range("[0, 2]")).expect("zeros");
        assert!(z.points.is_empty() && z.undecided.is_none(), "{z:?}");
        // x² − 2 and y² − 3: the fibre over √2 is quadratic, a bracket
        let ps = [&(&x * &x) - &k(2), &(&y * &y) - &k(3)];
        let z = common_zeros(&ps, "x", "y", &range("[0, 3]"), &range("[0, 3]")).expect("zeros");
        assert!(z.undecided.is_some());
    }

    #[test]
    fn a_common_factor_is_refused_and_a_curve_shows_a_point() {
        let (x, y) = (v("x"), v("y"));
        let ps = [&x * &(&y - &k(1)), &x * &(&y + &k(1))];
        let none = common_zeros(&ps, "x", "y", &range("[0, 1]"), &range("[0, 1]"));
        assert_eq!(none, Err(PlaneError::NoCoprimePair));
        // y = x² + 1/2: at x = −1/2 the rational point (−1/2, 3/4)
        let half = Poly::constant(Rational::from((1, 2)));
        let curve = &(&y - &(&x * &x)) - &half;
        let on = point_on(&curve, "x", "y", &range("[-1, 1]"), &range("[0, 1]")).expect("a point");
        assert_eq!(
            on.rational(),
            Some([Rational::from((-1, 2)), Rational::from((3, 4))])
        );
        let empty = &(&(&x * &x) + &(&y * &y)) + &k(1);
        assert!(point_on(&empty, "x", "y", &range("[-1, 1]"), &range("[-1, 1]")).is_none());
    }
}
