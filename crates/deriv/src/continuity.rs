//! Knot continuity of piecewise functions, exactly in the symbolic ring.
//!
//! A piecewise function is a list of pieces, each given by its one-sided
//! derivatives of orders `0…6` at its two ends, in the *global* knot
//! parameter. At the knot between pieces `i` and `i + 1` the jump of order
//! `r` is `f_{i+1}^{(r)}(start) − f_i^{(r)}(end)`; a B-spline basis function
//! is extended by zero outside its support, so its first and last knots are
//! joins with the zero function. The continuity order achieved at a knot is
//! `C^r` when the jumps of orders `0…r` vanish identically (for all parameter
//! values) and the jump of order `r + 1` does not; the parameter values where
//! that jump vanishes (rational roots of its exact numerator) are listed with
//! the order achieved there.
//!
//! Adaptors build pieces from the catalog: the uniform B-spline basis
//! function of a piecewise family ([`uniform_bspline`]), a polynomial or
//! rational curve segment ([`curve_piece`]); the judges assemble others
//! (a B-spline on a knot vector from its spans' segment functions).

use std::collections::BTreeMap;
use std::fmt;

use rug::{Integer, Rational};
use trig_core::Basis;
use trig_symbolic::{Poly, Sym, rational_roots};

use crate::table::{End, Wrt, curve_endpoint_derivatives, knot_derivatives};

/// Highest derivative order examined.
pub const MAX_ORDER: usize = 6;
/// Jet length for orders `0…MAX_ORDER`.
const K: usize = MAX_ORDER + 1;

/// One piece: derivatives of orders `0…MAX_ORDER` at its start and end.
#[derive(Debug, Clone, PartialEq)]
pub struct Piece {
    pub start: Vec<Sym>,
    pub end: Vec<Sym>,
}

/// Continuity order at a knot.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Smoothness {
    /// The value itself jumps.
    Discontinuous,
    /// `C^r` and not `C^{r+1}`: the jump of order `r + 1` is nonzero.
    Exactly(usize),
    /// Every jump of order `0…MAX_ORDER` vanishes.
    AtLeast(usize),
}

impl Smoothness {
    /// From the jumps of orders `0…`: the first nonzero one decides.
    pub fn of(jumps: &[Sym]) -> Smoothness {
        match jumps.iter().position(|j| !j.is_zero()) {
            Some(0) => Smoothness::Discontinuous,
            Some(r) => Smoothness::Exactly(r - 1),
            None => Smoothness::AtLeast(jumps.len() - 1),
        }
    }

    /// `r` for `C^r` (−1 when discontinuous), for comparisons.
    pub fn rank(&self) -> i64 {
        match self {
            Smoothness::Discontinuous => -1,
            Smoothness::Exactly(r) | Smoothness::AtLeast(r) => *r as i64,
        }
    }

    /// True when the function is at least `C^r` at the knot.
    pub fn is_at_least(&self, r: usize) -> bool {
        self.rank() >= r as i64
    }
}

impl fmt::Display for Smoothness {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Smoothness::Discontinuous => f.write_str("discontinuous (C^-1)"),
            Smoothness::Exactly(r) => write!(f, "exactly C^{r}"),
            Smoothness::AtLeast(r) => write!(f, "at least C^{r} (jumps of orders 0–{r} vanish)"),
        }
    }
}

/// The continuity at a parameter value where the generic first jump vanishes.
#[derive(Debug, Clone, PartialEq)]
pub struct Exception {
    pub value: Rational,
    pub smoothness: Smoothness,
    /// The first nonzero jump there (order, value).
    pub jump: Option<(usize, Sym)>,
}

/// Continuity at one knot.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotContinuity {
    /// Knot index (0 = first knot of the first piece).
    pub knot: usize,
    /// `right − left`, orders `0…MAX_ORDER`.
    pub jumps: Vec<Sym>,
    /// Order achieved for all parameter values.
    pub smoothness: Smoothness,
    /// Parameter values where the generic first jump vanishes.
    pub exceptions: Vec<Exception>,
    /// Rational roots could not all be searched (coefficients too large).
    pub roots_incomplete: bool,
}

impl KnotContinuity {
    /// The first nonzero jump (order, value).
    pub fn first_jump(&self) -> Option<(usize, &Sym)> {
        first_jump(&self.jumps)
    }
}

fn first_jump(jumps: &[Sym]) -> Option<(usize, &Sym)> {
    jumps.iter().enumerate().find(|(_, j)| !j.is_zero())
}

/// The jumps at every knot of consecutive `pieces`. With `zero_outside`, the
/// function is zero before the first and after the last piece (B-spline
/// basis functions); otherwise only the interior knots are examined (their
/// indices still count from the first knot).
pub fn knot_jumps(pieces: &[Piece], zero_outside: bool) -> Vec<(usize, Vec<Sym>)> {
    let zeros = vec![Sym::zero(); K];
    let mut out = Vec::new();
    for knot in 0..=pieces.len() {
        let left = if knot == 0 {
            zero_outside.then_some(&zeros)
        } else {
            Some(&pieces[knot - 1].end)
        };
        let right = if knot == pieces.len() {
            zero_outside.then_some(&zeros)
        } else {
            Some(&pieces[knot].start)
        };
        if let (Some(l), Some(r)) = (left, right) {
            let jumps = r.iter().zip(l).map(|(a, b)| a.clone() - b).collect();
            out.push((knot, jumps));
        }
    }
    out
}

/// Continuity at every knot, with the exceptional values of `param` (the one
/// shape parameter, if any) where the generic first jump vanishes.
pub fn continuity(
    pieces: &[Piece],
    zero_outside: bool,
    param: Option<&str>,
) -> Vec<KnotContinuity> {
    knot_jumps(pieces, zero_outside)
        .into_iter()
        .map(|(knot, jumps)| classify(knot, jumps, param))
        .collect()
}

/// Smoothness of the jumps, and the exceptions in `param`.
pub fn classify(knot: usize, jumps: Vec<Sym>, param: Option<&str>) -> KnotContinuity {
    let smoothness = Smoothness::of(&jumps);
    let mut exceptions = Vec::new();
    let mut roots_incomplete = false;
    if let (Some(name), Some((_, j))) = (param, first_jump(&jumps)) {
        let (roots, complete) = rational_roots(j.numerator(), name);
        roots_incomplete = !complete;
        for value in roots {
            let at: Option<Vec<Sym>> = jumps
                .iter()
                .map(|x| x.try_subs(name, &Sym::rational(value.clone())).ok())
                .collect();
            if let Some(at) = at {
                exceptions.push(Exception {
                    value,
                    smoothness: Smoothness::of(&at),
                    jump: first_jump(&at).map(|(r, j)| (r, j.clone())),
                });
            }
        }
    }
    KnotContinuity {
        knot,
        jumps,
        smoothness,
        exceptions,
        roots_incomplete,
    }
}

/// The least order achieved over all knots (for all parameter values).
pub fn achieved(knots: &[KnotContinuity]) -> Option<Smoothness> {
    knots
        .iter()
        .map(|k| k.smoothness)
        .min_by_key(Smoothness::rank)
}

/// The `n` pieces of the uniform B-spline basis function assembled from
/// the `n` functions of `basis` (piece `k` is function `n − 1 − k`), unit
/// knot spacing, derivatives in the global knot parameter.
pub fn uniform_bspline<B: Basis>(basis: &B, params: &[Sym]) -> Vec<Piece> {
    let knots = knot_derivatives::<Sym, K>(basis, params, Wrt::U, &Sym::one());
    knots
        .windows(2)
        .map(|w| Piece {
            start: w[0]
                .right
                .clone()
                .expect("a right limit before the last knot"),
            end: w[1]
                .left
                .clone()
                .expect("a left limit after the first knot"),
        })
        .collect()
}

/// One segment of a curve `Σ bᵢPᵢ` (or, with weights, `Σ wᵢbᵢPᵢ / Σ wᵢbᵢ`)
/// of `basis` on a unit knot interval, derivatives in the global parameter.
/// `points` are one coordinate of each control point or symbols.
///
/// # Panics
/// As [`curve_end`].
pub fn curve_piece<B: Basis + ?Sized>(
    basis: &B,
    params: &[Sym],
    points: &[Sym],
    weights: Option<&[Sym]>,
) -> Piece {
    Piece {
        start: curve_end(basis, params, points, weights, End::Start),
        end: curve_end(basis, params, points, weights, End::End),
    }
}

/// The derivatives of orders `0…MAX_ORDER` of one segment of a curve (as in
/// [`curve_piece`]) at one end. The rational curve is the quotient of the
/// polynomial curves with control points `wᵢPᵢ` and `wᵢ`
/// ([`quotient_derivatives`]).
///
/// # Panics
/// If `weights` do not have one entry per control point, or the weight
/// function `Σ wᵢbᵢ` vanishes at the end.
pub fn curve_end<B: Basis + ?Sized>(
    basis: &B,
    params: &[Sym],
    points: &[Sym],
    weights: Option<&[Sym]>,
    end: End,
) -> Vec<Sym> {
    match polynomial_curves(basis, params, points, weights, end) {
        (curve, None) => curve,
        (n, Some(w)) => quotient_derivatives(&[&n], &w).remove(0),
    }
}

/// The derivatives at `end` of the polynomial curve `Σ bᵢPᵢ`, or of the
/// numerator `Σ wᵢbᵢPᵢ` and the denominator `Σ wᵢbᵢ` of the rational one.
fn polynomial_curves<B: Basis + ?Sized>(
    basis: &B,
    params: &[Sym],
    points: &[Sym],
    weights: Option<&[Sym]>,
    end: End,
) -> (Vec<Sym>, Option<Vec<Sym>>) {
    let one = Sym::one();
    let curve = |points: &[Sym]| {
        curve_endpoint_derivatives::<Sym, K>(basis, params, points, None, end, Wrt::U, &one)
    };
    let Some(w) = weights else {
        return (curve(points), None);
    };
    assert_eq!(w.len(), points.len(), "one weight per control point");
    let weighted: Vec<Sym> = points.iter().zip(w).map(|(p, wi)| p.clone() * wi).collect();
    (curve(&weighted), Some(curve(w)))
}

/// The jumps `right − left` of the derivatives of orders `0…MAX_ORDER` of
/// a curve (as in [`curve_piece`]) at the knot between a segment with
/// control points `left` (at its end) and one with `right` (at its start);
/// `weights` are the two segments' weights of a rational curve
/// ([`quotient_jumps`]).
///
/// # Panics
/// As [`curve_end`].
pub fn curve_jumps<B: Basis + ?Sized>(
    basis: &B,
    params: &[Sym],
    (left, right): (&[Sym], &[Sym]),
    weights: Option<(&[Sym], &[Sym])>,
) -> Vec<Sym> {
    let at = |points, weights, end| polynomial_curves(basis, params, points, weights, end);
    let (nl, wl) = at(left, weights.map(|w| w.0), End::End);
    let (nr, wr) = at(right, weights.map(|w| w.1), End::Start);
    match (wl, wr) {
        (Some(wl), Some(wr)) => quotient_jumps((&nl, &wl), (&nr, &wr)),
        _ => differences(&nr, &nl),
    }
}

/// The jumps `Dₖ = qₖᴿ − qₖᴸ` of the derivatives of orders `0…` of a
/// quotient `q = n/w` at a knot, from those of `n` and `w` on its two
/// sides (`(n, w)` each), exactly. Leibniz's rule for `n = q·w` on each
/// side gives, with `Δ = right − left`,
/// `Dₖ·w₀ᴿ = Δnₖ − Σ_{j=1..k} C(k,j) D_{k−j} wⱼᴿ − Σ_{j=0..k} C(k,j) q_{k−j}ᴸ Δwⱼ`.
/// So the left quotient is needed only to the order `K − 1 − j₀`, `j₀` the
/// first order where `w` jumps, and where `n` and `w` join smoothly the
/// jumps are formed from small terms, not as differences of large ones.
///
/// # Panics
/// If the lengths differ or `w(0) = 0` on the right.
pub fn quotient_jumps((nl, wl): (&[Sym], &[Sym]), (nr, wr): (&[Sym], &[Sym])) -> Vec<Sym> {
    let order = wr.len();
    assert!(
        [nl.len(), wl.len(), nr.len()].iter().all(|n| *n == order),
        "as many derivatives on each side"
    );
    let (dn, dw) = (differences(nr, nl), differences(wr, wl));
    let needed = dw
        .iter()
        .position(|d| !d.is_zero())
        .map_or(0, |j0| order - j0);
    let ql = if needed == 0 {
        Vec::new()
    } else {
        quotient_derivatives(&[&nl[..needed]], &wl[..needed]).remove(0)
    };
    let mut jumps: Vec<Sym> = Vec::with_capacity(order);
    for k in 0..order {
        let mut acc = dn[k].clone();
        for j in 1..=k {
            if !jumps[k - j].is_zero() && !wr[j].is_zero() {
                acc = acc - &(binomial(k, j) * &jumps[k - j] * &wr[j]);
            }
        }
        for j in 0..=k {
            if !dw[j].is_zero() {
                acc = acc - &(binomial(k, j) * &ql[k - j] * &dw[j]);
            }
        }
        jumps.push(
            acc.checked_div(&wr[0])
                .expect("the denominator is nonzero at the point"),
        );
    }
    jumps
}

/// The derivatives of orders `0…` of quotients `qᵢ = nᵢ / w` sharing their
/// denominator, from those of the `nᵢ` and of `w`, exactly. Sums of
/// rational functions are expensive in the ring (each seeks
/// cancellations), so everything runs on polynomials over the common
/// denominator: the `nᵢ` and `w` are first multiplied by the common multiple
/// of their denominators (which leaves the `qᵢ` unchanged); then, with
/// `W₀ = w(0)` and `wⱼ = w⁽ʲ⁾(0)`, Leibniz's rule for `nᵢ = qᵢ · w` gives
/// `qᵢ⁽ᵏ⁾ = (nᵢ⁽ᵏ⁾ − Σ_{j=1..k} C(k,j) wⱼ qᵢ⁽ᵏ⁻ʲ⁾) / W₀`, so
/// `qᵢ⁽ᵏ⁾ = Pₖ / W₀^{k+1}` with the polynomials
/// `Pₖ = nᵢ⁽ᵏ⁾ W₀ᵏ − Σ_{j=1..k} C(k,j) wⱼ P_{k−j} W₀^{j−1}`, formed by
/// Horner's rule in `W₀` (every product has a factor as small as `W₀` or
/// `wⱼ`); each `qᵢ⁽ᵏ⁾` is reduced once.
///
/// # Panics
/// If the lengths differ or `w(0) = 0`.
pub fn quotient_derivatives(numerators: &[&[Sym]], w: &[Sym]) -> Vec<Vec<Sym>> {
    let order = w.len();
    assert!(
        numerators.iter().all(|n| n.len() == order),
        "as many derivatives of each numerator as of the denominator"
    );
    let mut common: BTreeMap<Poly, u32> = BTreeMap::new();
    for x in numerators.iter().flat_map(|n| n.iter()).chain(w) {
        for (f, e) in x.denominator() {
            let at = common.entry(f.clone()).or_insert(0);
            *at = (*at).max(*e);
        }
    }
    let m = Sym::from_poly(
        common
            .iter()
            .fold(Poly::one(), |acc, (f, e)| acc * &f.pow(*e)),
    );
    let cleared = |x: &[Sym]| -> Vec<Sym> { x.iter().map(|v| v.clone() * &m).collect() };
    let w = cleared(w);
    let inv = Sym::one()
        .checked_div(&w[0])
        .expect("the denominator is nonzero at the point");
    let mut inv_pow = vec![inv.clone()];
    for k in 1..order {
        inv_pow.push(inv_pow[k - 1].clone() * &inv);
    }
    numerators
        .iter()
        .map(|n| {
            let n = cleared(n);
            let mut p: Vec<Sym> = Vec::with_capacity(order);
            for k in 0..order {
                // Horner in W₀: Pₖ = nₖ W₀ᵏ − Σⱼ C(k,j) wⱼ P_{k−j} W₀^{j−1}
                let mut acc = n[k].clone();
                for j in (1..=k).rev() {
                    acc = acc * &w[0] - &(binomial(k, j) * &w[j] * &p[k - j]);
                }
                p.push(acc);
            }
            p.into_iter()
                .zip(&inv_pow)
                .map(|(pk, inv)| pk * inv)
                .collect()
        })
        .collect()
}

/// `right − left`, entry by entry.
fn differences(right: &[Sym], left: &[Sym]) -> Vec<Sym> {
    right.iter().zip(left).map(|(r, l)| r.clone() - l).collect()
}

/// `C(k, j)` in the exact ring.
fn binomial(k: usize, j: usize) -> Sym {
    Sym::rational(Rational::from(Integer::from(k).binomial(j as u32)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::jet::Jet;
    use trig_core::Family;
    use trig_symbolic::Poly;

    fn symbols(prefix: &str, n: usize) -> Vec<Sym> {
        (0..n).map(|i| Sym::var(&format!("{prefix}{i}"))).collect()
    }

    #[test]
    fn uniform_cubic_bspline_is_exactly_c2_at_every_knot() {
        let pieces = uniform_bspline(&Family::BSpline3, &[]);
        let knots = continuity(&pieces, true, None);
        assert_eq!(knots.len(), 5);
        for k in &knots {
            assert_eq!(k.smoothness, Smoothness::Exactly(2), "knot {}", k.knot);
        }
        // third-derivative jumps of the cubic B-spline: 1, −4, 6, −4, 1
        let third: Vec<Sym> = knots.iter().map(|k| k.jumps[3].clone()).collect();
        let want = [1, -4, 6, -4, 1].map(Sym::int);
        assert_eq!(third, want.to_vec());
        assert_eq!(achieved(&knots), Some(Smoothness::Exactly(2)));
    }

    #[test]
    fn quotient_derivatives_agree_with_jet_division() {
        // 1/(1 − x) at 0: derivatives k!
        let (one, zero) = (Sym::one(), Sym::zero());
        let n = [one.clone(), zero.clone(), zero.clone(), zero.clone()];
        let w = [one.clone(), -one.clone(), zero.clone(), zero];
        let q = quotient_derivatives(&[&n], &w).remove(0);
        assert_eq!(q, [1, 1, 2, 6].map(Sym::int).to_vec());
        // symbolic, with denominators in n and w: the jet quotient's derivatives
        let (a, b, m) = (Sym::var("a"), Sym::var("b"), Sym::var("m"));
        let x = Jet::<Sym, 5>::variable(Sym::zero());
        let c = |v: &Sym| Jet::<Sym, 5>::constant(v.clone());
        let nj = (c(&a) + &(x.clone() * &c(&b)) + &(x.clone() * &x)) / &c(&(m.clone() + &one));
        let wj = (c(&b) + &(x.clone() * &c(&m)) + &(x.clone() * &x * &x * &c(&a))) / &c(&m);
        let want = (nj.clone() / &wj).derivatives();
        let (nd, wd) = (nj.derivatives(), wj.derivatives());
        let got = quotient_derivatives(&[&nd, &wd], &wd);
        assert_eq!(got[0], want);
        assert_eq!(got[1][0], one);
        assert!(got[1][1..].iter().all(Sym::is_zero));
        // a wrong derivative in n changes the quotient
        let mut bad = nd.clone();
        bad[2] = bad[2].clone() + &Sym::one();
        assert_ne!(quotient_derivatives(&[&bad], &wd)[0], want);
    }

    #[test]
    fn quotient_jumps_are_the_differences_of_the_quotients() {
        let (a, b, m) = (Sym::var("a"), Sym::var("b"), Sym::var("m"));
        let (one, two) = (Sym::one(), Sym::int(2));
        // left: n = a + b·x + x², w = 1 + m·x; right agrees to order 1 in w
        // and order 0 in n, then jumps
        let nl = [a.clone(), b.clone(), two.clone(), Sym::zero()];
        let wl = [one.clone(), m.clone(), Sym::zero(), Sym::zero()];
        let nr = [a.clone(), b.clone() + &one, m.clone(), a.clone() * &b];
        let wr = [
            one.clone(),
            m.clone(),
            a.clone(),
            b.clone() / &(m.clone() + &two),
        ];
        let difference = |nl: &[Sym], wl: &[Sym], nr: &[Sym], wr: &[Sym]| -> Vec<Sym> {
            let l = quotient_derivatives(&[nl], wl).remove(0);
            let r = quotient_derivatives(&[nr], wr).remove(0);
            r.iter().zip(&l).map(|(r, l)| r.clone() - l).collect()
        };
        let jumps = quotient_jumps((&nl, &wl), (&nr, &wr));
        assert_eq!(jumps, difference(&nl, &wl, &nr, &wr));
        assert!(jumps[0].is_zero() && !jumps[1].is_zero());
        // the weight jumps at order 0 (the whole left quotient is needed)
        let wr0 = [two.clone(), m.clone(), a.clone(), Sym::zero()];
        assert_eq!(
            quotient_jumps((&nl, &wl), (&nr, &wr0)),
            difference(&nl, &wl, &nr, &wr0)
        );
        // no jump at all
        assert!(
            quotient_jumps((&nl, &wl), (&nl, &wl))
                .iter()
                .all(Sym::is_zero)
        );
    }

    #[test]
    fn rational_curve_end_is_the_quotient_of_the_polynomial_curves() {
        // weights all 1: the polynomial curve (Σ bᵢ = 1)
        let p = symbols("P", 4);
        let ones = vec![Sym::one(); 4];
        for end in [End::Start, End::End] {
            let plain = curve_end(&Family::Bernstein3, &[], &p, None, end);
            assert_eq!(
                curve_end(&Family::Bernstein3, &[], &p, Some(&ones), end),
                plain
            );
        }
        // rational cubic Bézier: C(0) = P0, C'(0) = 3 (w1/w0)(P1 − P0)
        let w = symbols("w", 4);
        let r = curve_end(&Family::Bernstein3, &[], &p, Some(&w), End::Start);
        assert_eq!(r[0], p[0]);
        let slope = Sym::int(3) * &w[1] / &w[0] * &(p[1].clone() - &p[0]);
        assert_eq!(r[1], slope);
        assert_ne!(r[1], Sym::int(3) * &(p[1].clone() - &p[0]));
    }

    #[test]
    fn bernstein_segments_join_as_the_textbook_conditions_say() {
        // Q1 on P0..P3, Q2 on P3..P6: C⁰ by the shared point; C¹ iff
        // P4 − P3 = P3 − P2; C² additionally iff P5 − 2P4 + P3 = P3 − 2P2 + P1.
        let p = symbols("P", 7);
        let join = |p: &[Sym]| {
            let pieces = [
                curve_piece(&Family::Bernstein3, &[], &p[0..4], None),
                curve_piece(&Family::Bernstein3, &[], &p[3..7], None),
            ];
            continuity(&pieces, false, None).remove(0)
        };
        let k = join(&p);
        assert_eq!(k.knot, 1);
        assert_eq!(k.smoothness, Smoothness::Exactly(0));
        let c1 = p[3].clone() * &Sym::int(2) - &p[2];
        assert_eq!(k.jumps[1], (p[4].clone() - &c1) * &Sym::int(3));
        let mut q = p.clone();
        q[4] = c1;
        assert_eq!(join(&q).smoothness, Smoothness::Exactly(1));
        q[5] = p[1].clone() - &(p[2].clone() * &Sym::int(4)) + &(p[3].clone() * &Sym::int(4));
        let k2 = join(&q);
        assert_eq!(k2.smoothness, Smoothness::Exactly(2));
        // a single cubic: orders ≥ 4 never jump
        assert!(k2.jumps[4..].iter().all(Sym::is_zero));
    }

    #[test]
    fn exceptional_parameter_values_are_the_rational_roots_of_the_jump() {
        let z = Sym::var("zeta");
        // jump ζ(ζ − 1)(2ζ + 3)(ζ² + 1)·π at order 1, then 5 at order 2
        let j1 = z.clone()
            * &(z.clone() - &Sym::one())
            * &(z.clone() * &Sym::int(2) + &Sym::int(3))
            * &(z.clone() * &z + &Sym::one())
            * &Sym::pi();
        let k = classify(1, vec![Sym::zero(), j1, Sym::int(5)], Some("zeta"));
        assert_eq!(k.smoothness, Smoothness::Exactly(0));
        let values: Vec<Rational> = k.exceptions.iter().map(|e| e.value.clone()).collect();
        assert_eq!(
            values,
            vec![Rational::from((-3, 2)), Rational::new(), Rational::from(1)]
        );
        assert!(
            k.exceptions
                .iter()
                .all(|e| e.smoothness == Smoothness::Exactly(1))
        );
        assert!(!k.roots_incomplete);
        assert!(rational_roots(&Poly::var("x"), "y").0.is_empty());
    }

    #[test]
    fn smoothness_reads_the_first_nonzero_jump() {
        let (o, z) = (Sym::one(), Sym::zero());
        assert_eq!(
            Smoothness::of(std::slice::from_ref(&o)),
            Smoothness::Discontinuous
        );
        assert_eq!(Smoothness::of(&[z.clone(), o]), Smoothness::Exactly(0));
        assert_eq!(Smoothness::of(&[z.clone(), z]), Smoothness::AtLeast(1));
        assert!(Smoothness::AtLeast(6).is_at_least(6));
        assert!(!Smoothness::Exactly(3).is_at_least(4));
    }
}
