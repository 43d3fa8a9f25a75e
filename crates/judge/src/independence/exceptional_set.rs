//! The exceptional set of independence — the parameter values of the box
//! where the functions are linearly dependent — exactly with two
//! parameters, and what is exact of it with three.
//!
//! With generic rank `n` the rank drops exactly where every maximal minor
//! `D_k` vanishes. With `G = gcd(D_k)` and `E_k = D_k / G`,
//! `{D_k = 0 for all k} = {G = 0} ∪ {E_k = 0 for all k}`:
//! - two parameters: the **curves** `f = 0`, `f` a factor of `G` (the
//!   display factorisation: squarefree, irreducibility not checked), each
//!   shown with whether it meets the box — an exact point of it in the
//!   box, or `f` certified of one strict sign on the box (open ends excluded) — and the
//!   **isolated points**, the common real zeros of the `E_k` (no common
//!   factor, so finitely many; `trig_certify::plane_zeros`), each exact,
//!   with the dependence relation at a rational one;
//! - three parameters: the factors of `G` are **surfaces**, shown with a
//!   point in the box or certified not to meet it; the common zeros of the
//!   `E_k` (curves and points) are not computed, a bracket.
//!
//! Computed when every entry of the coefficient matrix is a polynomial in
//! the parameters alone (no parameter in a denominator, no atom of a
//! parameter, no range in multiples of π), with at most [`MAX_MINORS`]
//! maximal minors.

use rug::Rational;
use trig_certify::minors::{binomial, index_sets};
use trig_certify::plane_zeros::{PlanePoint, common_zeros, point_on, roots_in};
use trig_certify::sturm::UPoly;
use trig_symbolic::{Poly, Sym};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use super::matrix::{Echelon, minor_on};
use super::rank::{Context, RANK, dropped, general, how_in, shown, strict_sign};

/// Most maximal minors computed for the exceptional set.
pub const MAX_MINORS: usize = 256;
/// Digits shown of an irrational coordinate's interval.
const DIGITS: usize = 12;

/// What is known of the set of dependence in the box.
struct Set {
    lines: Vec<String>,
    /// A point of the box where the functions are dependent (a rational
    /// one when one was found).
    witness: Option<PlanePoint>,
    /// Every part decided: the set in the box is exactly what is shown.
    complete: bool,
}

/// The maximal minors (nonzero) when the matrix is polynomial in the
/// parameters alone and they are few enough.
fn maximal_minors(ctx: &Context<'_>) -> Option<Vec<Poly>> {
    let names: Vec<&str> = ctx.params.iter().map(|p| p.name.as_str()).collect();
    let alone = |q: &Poly| q.variables().iter().all(|v| names.contains(&v.as_str()));
    let in_basis = |f: &Sym| {
        f.variables()
            .iter()
            .all(|v| names.contains(&v.as_str()) || super::VARIABLE_ATOMS.contains(&v.as_str()))
            && f.denominator()
                .keys()
                .all(|d| !d.variables().iter().any(|v| names.contains(&v.as_str())))
    };
    let (n, m) = (ctx.names.len(), ctx.matrix.columns.len());
    if ctx.ranges.iter().any(|r| r.pi)
        || !ctx.matrix.rows.iter().flatten().all(alone)
        || !ctx.matrix.scales.iter().all(|s| s.as_constant().is_some())
        || !ctx.fs.iter().all(in_basis)
        || m > 31
        || binomial(m, n).is_none_or(|c| c > MAX_MINORS as u64)
    {
        return None;
    }
    let minors: Vec<Poly> = index_sets(m, n)
        .iter()
        .map(|cols| minor_on(&ctx.matrix.rows, cols).ok())
        .collect::<Option<_>>()?;
    Some(minors.into_iter().filter(|d| !d.is_zero()).collect())
}

/// `gcd` of polynomials free of the variable's atoms.
fn gcd_all(ps: &[Poly]) -> Option<Poly> {
    ps.iter()
        .try_fold(Poly::zero(), |acc, p| trig_symbolic::gcd::gcd(&acc, p))
}

/// A factor as printed (expanded, unparenthesised).
fn factor_text(p: &Poly) -> String {
    Sym::from_poly(p.clone()).to_unicode()
}

/// `the gcd of the k nonzero maximal minors is G`.
fn gcd_line(minors: &[Poly], g: &Poly) -> String {
    format!(
        "the gcd of the {} nonzero maximal minor{} is {}",
        minors.len(),
        if minors.len() == 1 { "" } else { "s" },
        shown(&g.canonical().1)
    )
}

impl Context<'_> {
    fn plane_names(&self) -> (&str, &str) {
        (&self.params[0].name, &self.params[1].name)
    }

    fn plane_text(&self, p: &PlanePoint) -> String {
        p.describe(&self.params[0].symbol, &self.params[1].symbol, DIGITS)
    }
}

/// The exceptional set of two parameters in the box of `ctx`.
fn two_set(ctx: &Context<'_>, minors: &[Poly]) -> Option<Set> {
    let g = gcd_all(minors)?;
    let (x, y) = ctx.plane_names();
    let (rx, ry) = (&ctx.ranges[0], &ctx.ranges[1]);
    let mut lines = vec![format!(
        "exceptional set (where every maximal minor vanishes, so the functions are dependent), exact: {}",
        gcd_line(minors, &g)
    )];
    let mut witness: Option<PlanePoint> = None;
    // real roots are isolated exactly on unbounded ranges too (root
    // bounds); only a curve's strict sign needs a bounded box
    let mut complete = true;
    let keep = |p: PlanePoint, w: &mut Option<PlanePoint>| {
        if w.as_ref()
            .is_none_or(|q| q.rational().is_none() && p.rational().is_some())
        {
            *w = Some(p);
        }
    };
    let curves: Vec<Poly> = g
        .factor()
        .factors
        .into_iter()
        .map(|(f, _)| f)
        .filter(|f| f.as_constant().is_none())
        .collect();
    for f in &curves {
        let text = factor_text(f);
        if let Some(p) = point_on(f, x, y, rx, ry) {
            lines.push(format!(
                "curve {text} = 0: meets the box {} at {} (a point on it, exact)",
                ctx.point_ranges(),
                ctx.plane_text(&p)
            ));
            keep(p, &mut witness);
        } else if strict_sign(ctx, &Sym::from_poly(f.clone())).is_ok() && ctx.notes.is_empty() {
            lines.push(format!(
                "curve {text} = 0: does not meet the box {} ({text} certified of one strict sign on the box, interval branch and bound, open ends excluded)",
                ctx.point_ranges()
            ));
        } else {
            complete = false;
            lines.push(format!(
                "curve {text} = 0: not decided whether it meets the box {} (no point of it found over rational values, no strict sign certified)",
                ctx.point_ranges()
            ));
        }
    }
    if curves.is_empty() {
        lines.push("no curve of dependence (the gcd is a constant)".into());
    }
    let rest: Vec<Poly> = minors
        .iter()
        .map(|d| d.exact_div(&g))
        .collect::<Option<_>>()?;
    match common_zeros(&rest, x, y, rx, ry) {
        Ok(z) => {
            let shown: Vec<String> = z
                .points
                .iter()
                .map(|p| {
                    let relation = p
                        .rational()
                        .and_then(|q| ctx.rank_at(&q).ok())
                        .and_then(|at| at.relation);
                    match relation {
                        Some(r) => format!("{} ({r}, exact)", ctx.plane_text(p)),
                        None => ctx.plane_text(p),
                    }
                })
                .collect();
            lines.push(format!(
                "isolated points (the common real zeros in the box of the minors divided by the gcd, by resultants and Sturm sequences, exact): {}",
                if shown.is_empty() {
                    "none".to_string()
                } else {
                    shown.join("; ")
                }
            ));
            if let Some(why) = z.undecided {
                complete = false;
                lines.push(format!("isolated points not complete (a bracket): {why}"));
            }
            for p in z.points {
                keep(p, &mut witness);
            }
        }
        Err(e) => {
            complete = false;
            lines.push(format!("isolated points not computed: {e}"));
        }
    }
    Some(Set {
        lines,
        witness,
        complete,
    })
}

/// Two parameters, the matrix polynomial in them: the exceptional set
/// decides — a point of it in the box refutes (the relation there when it
/// is rational), none proves; an incomplete set is shown beside the
/// verdict of [`general`]. `None` when the set is not computed.
pub(super) fn two_parameters(ctx: &Context<'_>, e: &Echelon<Poly>) -> Option<Verdict> {
    let minors = maximal_minors(ctx)?;
    let set = two_set(ctx, &minors)?;
    let n = ctx.names.len();
    let mut v = match (&set.witness, set.complete) {
        (Some(p), _) => match p.rational() {
            Some(q) => match ctx.rank_at(&q) {
                Ok(at) if at.rank < n => dropped(ctx, &q, &at, how_in(ctx, &q)),
                _ => general(ctx, e),
            },
            None => Verdict::new(
                Status::Fails,
                RANK,
                vec![format!(
                    "{}: rank {n} over Q(parameters), but at {}, in the range, every maximal minor vanishes (exact): the functions are linearly dependent there",
                    ctx.header(),
                    ctx.plane_text(p)
                )],
            ),
        },
        (None, true) => Verdict::new(
            Status::Holds,
            RANK,
            vec![format!(
                "{}: rank {n} over Q(parameters); the exceptional set does not meet the box {} (below, exact), so a maximal minor is nonzero at every point of it: the functions are linearly independent there",
                ctx.header(),
                ctx.point_ranges()
            )],
        ),
        (None, false) => general(ctx, e),
    };
    v.evidence.extend(set.lines);
    Some(v)
}

/// Three parameters: what is exact of the exceptional set (the surfaces
/// of the gcd of the maximal minors), beside the verdict of [`general`].
pub(super) fn three_parameters(ctx: &Context<'_>, e: &Echelon<Poly>) -> Verdict {
    let mut v = general(ctx, e);
    let Some(minors) = maximal_minors(ctx) else {
        return v;
    };
    let Some(g) = gcd_all(&minors) else {
        return v;
    };
    let mut lines = vec![format!(
        "exceptional set, exact part: {}",
        gcd_line(&minors, &g)
    )];
    for (f, _) in g.factor().factors {
        if f.as_constant().is_some() {
            continue;
        }
        let text = factor_text(&f);
        let meets = surface_point(ctx, &f);
        lines.push(match meets {
            Some(p) => format!(
                "surface {text} = 0: meets the box at {} (exact)",
                ctx.point_text(&p)
            ),
            None if ctx.notes.is_empty()
                && strict_sign(ctx, &Sym::from_poly(f.clone())).is_ok() =>
            {
                format!("surface {text} = 0: does not meet the box ({text} certified of one strict sign on the box, open ends excluded)")
            }
            None => format!("surface {text} = 0: not decided whether it meets the box"),
        });
    }
    lines.push(
        "not computed (a bracket): the common zeros of the minors divided by the gcd (curves and points in three parameters); dependence there is decided only at the exact points tried".into(),
    );
    v.evidence.extend(lines);
    v
}

/// A rational point of `f = 0` in the box of three parameters: the first
/// two at the closed ends or middles of their ranges, the third a rational
/// root in its range.
fn surface_point(ctx: &Context<'_>, f: &Poly) -> Option<Vec<Rational>> {
    let picks = |i: usize| -> Vec<Rational> {
        let r = &ctx.ranges[i];
        let mut out: Vec<Rational> = [r.lo.value(), r.hi.value()]
            .into_iter()
            .flatten()
            .filter(|v| r.contains(v))
            .cloned()
            .collect();
        out.push(r.interior_point());
        out
    };
    let names: Vec<&str> = ctx.params.iter().map(|p| p.name.as_str()).collect();
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        for a in picks(i) {
            for b in picks(j) {
                let fiber = f
                    .subs(names[i], &Poly::constant(a.clone()))
                    .subs(names[j], &Poly::constant(b.clone()));
                let u = UPoly::from_poly(&fiber, names[k])?;
                let root = if u.is_zero() {
                    Some(ctx.ranges[k].interior_point())
                } else {
                    roots_in(&u, &ctx.ranges[k])
                        .into_iter()
                        .find_map(|r| r.rational)
                };
                if let Some(c) = root {
                    let mut p = vec![Rational::new(); 3];
                    (p[i], p[j], p[k]) = (a.clone(), b.clone(), c);
                    return Some(p);
                }
            }
        }
    }
    None
}
