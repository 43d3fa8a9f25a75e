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
//!   point in the box or certified not to meet it; on each closed face
//!   `pₖ = a` of the box the set is that of two parameters (the minors of
//!   the matrix with `pₖ = a`: curves and points of the face, exact);
//!   inside the box the common zeros of the `E_k` (curves and points) are
//!   not computed, a bracket.
//!
//! Computed when every entry of the coefficient matrix is a polynomial in
//! the parameters alone (no parameter in a denominator, no atom of a
//! parameter, no range in multiples of π), with at most [`MAX_MINORS`]
//! maximal minors.

use rug::Rational;
use trig_certify::minors::{binomial, index_sets};
use trig_certify::plane_zeros::{PlanePoint, common_zeros, point_on, roots_in};
use trig_certify::sturm::UPoly;
use trig_core::{End, ParamRange};
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

/// True when every entry of the coefficient matrix is a polynomial in the
/// parameters alone (no parameter in a denominator, no atom of one, no
/// range in multiples of π).
fn polynomial(ctx: &Context<'_>) -> bool {
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
    !ctx.ranges.iter().any(|r| r.pi)
        && ctx.matrix.rows.iter().flatten().all(alone)
        && ctx.matrix.scales.iter().all(|s| s.as_constant().is_some())
        && ctx.fs.iter().all(in_basis)
}

/// The nonzero maximal minors of `rows` (`n` rows), when they are few
/// enough.
fn minors_of(rows: &[Vec<Poly>]) -> Option<Vec<Poly>> {
    let (n, m) = (rows.len(), rows.first().map_or(0, Vec::len));
    if m > 31 || n > m || binomial(m, n).is_none_or(|c| c > MAX_MINORS as u64) {
        return None;
    }
    let minors: Vec<Poly> = index_sets(m, n)
        .iter()
        .map(|cols| minor_on(rows, cols).ok())
        .collect::<Option<_>>()?;
    Some(minors.into_iter().filter(|d| !d.is_zero()).collect())
}

/// The maximal minors of a matrix polynomial in the parameters.
pub(super) fn maximal_minors(ctx: &Context<'_>) -> Option<Vec<Poly>> {
    if !polynomial(ctx) {
        return None;
    }
    minors_of(&ctx.matrix.rows)
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
        if g.factor().is_trivial() {
            factor_text(&g.canonical().1)
        } else {
            shown(&g.canonical().1)
        }
    )
}

/// Two of the parameters, `axes`, the others fixed: the box of two
/// parameters, or a face of a box of three.
struct Plane {
    axes: [usize; 2],
    fixed: Option<(usize, Rational)>,
}

impl Plane {
    fn names<'a>(&self, ctx: &'a Context<'_>) -> (&'a str, &'a str) {
        (
            &ctx.params[self.axes[0]].name,
            &ctx.params[self.axes[1]].name,
        )
    }

    /// The point of every parameter.
    fn full(&self, q: &[Rational; 2]) -> Vec<Rational> {
        let mut out = q.to_vec();
        if let Some((k, a)) = &self.fixed {
            out.insert(*k, a.clone());
        }
        out
    }

    /// The point, every parameter in order.
    fn text(&self, ctx: &Context<'_>, p: &PlanePoint) -> String {
        let [i, j] = self.axes;
        let mut parts = vec![
            (
                i,
                format!(
                    "{} = {}",
                    ctx.params[i].symbol,
                    p.x.describe(&ctx.params[i].symbol, DIGITS)
                ),
            ),
            (
                j,
                format!(
                    "{} = {}",
                    ctx.params[j].symbol,
                    p.y.describe(&ctx.params[j].symbol, DIGITS)
                ),
            ),
        ];
        if let Some((k, a)) = &self.fixed {
            parts.push((*k, format!("{} = {a}", ctx.params[*k].symbol)));
        }
        parts.sort_by_key(|(k, _)| *k);
        parts
            .into_iter()
            .map(|(_, t)| t)
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn box_text(&self, ctx: &Context<'_>) -> String {
        let [i, j] = self.axes;
        format!(
            "{} ∈ {}, {} ∈ {}",
            ctx.params[i].symbol, ctx.ranges[i], ctx.params[j].symbol, ctx.ranges[j]
        )
    }
}

/// The exceptional set in the box of a plane of `ctx`, from the maximal
/// minors there.
fn plane_set(ctx: &Context<'_>, plane: &Plane, minors: &[Poly]) -> Option<Set> {
    let g = gcd_all(minors)?;
    let (x, y) = plane.names(ctx);
    let (rx, ry) = (&ctx.ranges[plane.axes[0]], &ctx.ranges[plane.axes[1]]);
    let mut lines = vec![gcd_line(minors, &g)];
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
                plane.box_text(ctx),
                plane.text(ctx, &p)
            ));
            keep(p, &mut witness);
        } else if strict_sign(ctx, &Sym::from_poly(f.clone())).is_ok() && ctx.notes.is_empty() {
            lines.push(format!(
                "curve {text} = 0: does not meet the box {} ({text} certified of one strict sign on the box, interval branch and bound, open ends excluded)",
                plane.box_text(ctx)
            ));
        } else {
            complete = false;
            lines.push(format!(
                "curve {text} = 0: not decided whether it meets the box {} (no point of it found over rational values, no strict sign certified)",
                plane.box_text(ctx)
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
                        .and_then(|q| ctx.rank_at(&plane.full(&q)).ok())
                        .and_then(|at| at.relation);
                    match relation {
                        Some(r) => format!("{} ({r}, exact)", plane.text(ctx, p)),
                        None => plane.text(ctx, p),
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
    let plane = Plane {
        axes: [0, 1],
        fixed: None,
    };
    let mut set = plane_set(ctx, &plane, &minors)?;
    set.lines[0] = format!(
        "exceptional set (where every maximal minor vanishes, so the functions are dependent), exact: {}",
        set.lines[0]
    );
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
                    plane.text(ctx, p)
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
    let mut witness = None;
    for k in 0..3 {
        for a in closed_ends(&ctx.ranges[k]) {
            let (face, found) = face_set(ctx, k, &a);
            lines.extend(face);
            witness = witness.or(found);
        }
    }
    lines.push(
        "not computed (a bracket): inside the box, the common zeros of the minors divided by the gcd (curves and points in three parameters); exact on the closed faces above, decided elsewhere only at the exact points tried".into(),
    );
    if v.status != Status::Fails
        && let Some(q) = witness
        && let Ok(at) = ctx.rank_at(&q)
        && at.rank < ctx.names.len()
    {
        v = dropped(ctx, &q, &at, how_in(ctx, &q));
    }
    v.evidence.extend(lines);
    v
}

fn closed_ends(r: &ParamRange) -> Vec<Rational> {
    [&r.lo, &r.hi]
        .into_iter()
        .filter_map(|e| match e {
            End::Closed(q) => Some(q.clone()),
            _ => None,
        })
        .collect()
}

/// The exceptional set on the face `p_k = a` of a box of three
/// parameters: its lines, and a rational point of it (all parameters).
fn face_set(ctx: &Context<'_>, k: usize, a: &Rational) -> (Vec<String>, Option<Vec<Rational>>) {
    let name = &ctx.params[k].name;
    let head = format!("face {} = {a}", ctx.params[k].symbol);
    let rows = ctx.matrix.rows_with(name, a);
    let Some(minors) = minors_of(&rows) else {
        return (
            vec![format!("{head}: too many maximal minors, not computed")],
            None,
        );
    };
    let plane = Plane {
        axes: match k {
            0 => [1, 2],
            1 => [0, 2],
            _ => [0, 1],
        },
        fixed: Some((k, a.clone())),
    };
    if minors.is_empty() {
        let corner = plane.full(&[0, 1].map(|i| ctx.ranges[plane.axes[i]].interior_point()));
        return (
            vec![format!(
                "{head}: every maximal minor vanishes on the whole face (exact): dependent on all of it"
            )],
            Some(corner),
        );
    }
    match plane_set(ctx, &plane, &minors) {
        Some(set) => {
            let found = set
                .witness
                .and_then(|p| p.rational())
                .map(|q| plane.full(&q));
            let lines = set
                .lines
                .into_iter()
                .map(|l| format!("{head}: {l}"))
                .collect();
            (lines, found)
        }
        None => (
            vec![format!("{head}: the gcd of its minors was not computed")],
            None,
        ),
    }
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
