//! The maximal set of independence: "the functions are linearly
//! independent exactly for the parameters of the claim's range, within the
//! declared ranges" — independent at every point of the claim's range `C`
//! and dependent at every point of the declared box `D` outside it.
//!
//! `D ∖ C` is the union over the parameters `pᵢ` of the slabs
//! `{pᵢ ∈ Dᵢ ∖ Cᵢ} × Π_{j≠i} D_j`, and `Dᵢ ∖ Cᵢ` is made of at most two
//! pieces, each a point (a closed end of `Dᵢ` that `Cᵢ` leaves open) or an
//! interval of positive length:
//! - over a point `pᵢ = a` the functions are dependent on the whole slab
//!   exactly when the coefficient matrix with `pᵢ = a` substituted has rank
//!   `< n` over `Q(other parameters)` (every maximal minor vanishes there
//!   identically; with one parameter, the rank at `a`), exact;
//! - a slab over an interval has interior, where the functions are
//!   dependent only if every maximal minor vanishes identically (generic
//!   rank `< n`, and then they are dependent in `C` too).
//!
//! A failure shows an exact witness: a point of `C` where the functions
//! are dependent (with the relation), or a point of `D ∖ C` where they are
//! independent (a maximal minor's nonzero value there).

use rug::Rational;
use trig_core::{End, ParamRange};
use trig_symbolic::Poly;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use super::matrix::{column_text, echelon_poly};
use super::rank::{Context, shown};
use crate::exact::ExactBasis;

/// How a maximal set of independence is decided, as the report states it.
pub const MAXIMAL: &str = "exact rank (as for independence) on the claim's range; outside it, within the declared ranges, dependence where a closed end is left out (the rank with that end substituted, over Q(other parameters), exact) and none where the declared range extends the claim's by an interval (a maximal minor nonzero at an exact point there)";

/// Most exact points tried for a witness of independence in a piece.
const TRIES: usize = 12;

/// A piece of `Dᵢ ∖ Cᵢ`.
#[derive(Debug, Clone, PartialEq)]
enum Piece {
    Point(Rational),
    Interval(ParamRange),
}

/// The order of two ends of ranges, both lower (`lower`) or both upper
/// (`None` unbounded: −∞ for a lower end, +∞ for an upper one).
fn below(a: Option<&Rational>, b: Option<&Rational>, lower: bool) -> std::cmp::Ordering {
    use std::cmp::Ordering::{Equal, Greater, Less};
    match (a, b) {
        (Some(x), Some(y)) => x.cmp(y),
        (None, None) => Equal,
        (None, Some(_)) => {
            if lower {
                Less
            } else {
                Greater
            }
        }
        (Some(_), None) => {
            if lower {
                Greater
            } else {
                Less
            }
        }
    }
}

/// The end `e` flipped: what is left beside it.
fn flip(e: &End) -> End {
    match e {
        End::Closed(q) => End::Open(q.clone()),
        End::Open(q) => End::Closed(q.clone()),
        End::Unbounded => End::Unbounded,
    }
}

/// `D ∖ C` in pieces, or why `C ⊄ D`.
fn pieces(d: &ParamRange, c: &ParamRange) -> Result<Vec<Piece>, String> {
    use std::cmp::Ordering::{Equal, Greater, Less};
    if d.pi != c.pi {
        return Err(format!(
            "the claim's range {c} and the declared range {d} are not both in multiples of π"
        ));
    }
    let outside = || {
        Err(format!(
            "the claim's range {c} is not within the declared range {d}"
        ))
    };
    let mut out = Vec::new();
    for lower in [true, false] {
        let (de, ce) = if lower {
            (&d.lo, &c.lo)
        } else {
            (&d.hi, &c.hi)
        };
        let order = below(de.value(), ce.value(), lower);
        let inward = if lower { Less } else { Greater };
        match (order, de, ce) {
            (Equal, End::Closed(a), End::Open(_)) => out.push(Piece::Point(a.clone())),
            (Equal, End::Open(_), End::Closed(_)) => return outside(),
            (Equal, _, _) => {}
            (o, _, _) if o == inward => {
                let piece = if lower {
                    ParamRange {
                        lo: de.clone(),
                        hi: flip(ce),
                        pi: d.pi,
                    }
                } else {
                    ParamRange {
                        lo: flip(ce),
                        hi: de.clone(),
                        pi: d.pi,
                    }
                };
                out.push(Piece::Interval(piece));
            }
            _ => return outside(),
        }
    }
    Ok(out)
}

/// Exact points strictly inside `r` (in multiples of π for such a range).
fn inside(r: &ParamRange) -> Vec<Rational> {
    let (lo, hi) = match (r.lo.value(), r.hi.value()) {
        (Some(a), Some(b)) => (a.clone(), b.clone()),
        (Some(a), None) => (a.clone(), Rational::from(a + 2u32)),
        (None, Some(b)) => (Rational::from(b - 2u32), b.clone()),
        (None, None) => (Rational::from(-1), Rational::from(1)),
    };
    // halves, quarters, eighths…: the simple values first
    let mut out = Vec::new();
    for k in [2u32, 4, 3, 6, 8, 12] {
        for j in 1..k {
            let v = &lo + Rational::from(&hi - &lo) * Rational::from((j, k));
            if !out.contains(&v) {
                out.push(v);
            }
        }
    }
    out.truncate(TRIES);
    out
}

/// Values of a parameter to combine with a piece: its closed ends and
/// points inside.
fn values(r: &ParamRange) -> Vec<Rational> {
    let mut out: Vec<Rational> = [&r.lo, &r.hi]
        .into_iter()
        .filter_map(|e| match e {
            End::Closed(q) => Some(q.clone()),
            _ => None,
        })
        .collect();
    out.extend(inside(r).into_iter().take(3));
    out
}

/// The ranges of a basis's parameters.
fn ranges<B: ExactBasis>(basis: &B) -> Vec<ParamRange> {
    basis.parameters().into_iter().map(|p| p.range).collect()
}

/// An exact point of the slab `pᵢ ∈ piece` (others over `ranges`) where
/// the functions are independent: the point, the columns and the nonzero
/// value of a maximal minor there.
fn independent_at(
    ctx: &Context<'_>,
    i: usize,
    at: &[Rational],
) -> Option<(Vec<Rational>, Vec<usize>, Poly)> {
    let lists: Vec<Vec<Rational>> = (0..ctx.params.len())
        .map(|j| {
            if j == i {
                at.to_vec()
            } else {
                values(&ctx.ranges[j])
            }
        })
        .collect();
    let mut points: Vec<Vec<Rational>> = vec![Vec::new()];
    for list in &lists {
        points = points
            .iter()
            .flat_map(|p| {
                list.iter().map(move |v| {
                    let mut q = p.clone();
                    q.push(v.clone());
                    q
                })
            })
            .take(4 * TRIES)
            .collect();
    }
    let n = ctx.names.len();
    points.into_iter().find_map(|p| {
        let r = ctx.rank_at(&p).ok().filter(|r| r.rank == n)?;
        let value = ctx.minor_at(&p, &r.pivots).ok()?;
        Some((p, r.pivots, value))
    })
}

/// What one piece of the slab of parameter `i` says, with its evidence
/// line: `Some(true)` dependent at every point of it, `Some(false)` a
/// witness of independence there, `None` undecided (the reason in the line).
fn piece(ctx: &Context<'_>, i: usize, p: &Piece) -> (Option<bool>, String) {
    let (name, n) = (&ctx.params[i].symbol, ctx.names.len());
    let witness = |at: &[Rational], what: &str| match independent_at(ctx, i, at) {
        Some((point, cols, value)) => (
            Some(false),
            format!(
                "{what}: at {}, outside the claim's range, the maximal minor on the monomials {} is {} ≠ 0 (exact): the functions are linearly independent there",
                ctx.point_text(&point),
                cols.iter()
                    .map(|&j| column_text(ctx.matrix.columns[j]))
                    .collect::<Vec<_>>()
                    .join(", "),
                shown(&value)
            ),
        ),
        None => (
            None,
            format!(
                "{what}: no exact point of it was decided (the rank was not computed at the points tried)"
            ),
        ),
    };
    match p {
        Piece::Interval(r) => witness(
            &inside(r),
            &format!("{name} ∈ {r} (declared, outside the claim's range, of positive length)"),
        ),
        Piece::Point(a) => {
            let what = format!(
                "{name} = {} (a declared closed end the claim's range leaves out)",
                ctx.ranges[i].end_text(a)
            );
            if ctx.params.len() == 1 {
                return match ctx.rank_at(std::slice::from_ref(a)) {
                    Ok(at) if at.rank < n => (
                        Some(true),
                        format!(
                            "{what}: the rank there is {} < {n} (exact), so the functions are dependent there{}",
                            at.rank,
                            at.relation.map(|r| format!(": {r}")).unwrap_or_default()
                        ),
                    ),
                    Ok(_) => witness(std::slice::from_ref(a), &what),
                    Err(_) => (
                        None,
                        format!("{what}: the basis is undefined there or not exact"),
                    ),
                };
            }
            // the slab: the matrix with the end substituted, over
            // Q(the other parameters)
            let pname = &ctx.params[i].name;
            if ctx.ranges[i].pi
                || ctx.matrix.rows.iter().flatten().any(|e| {
                    e.variables()
                        .iter()
                        .any(|v| !ctx.params.iter().any(|q| &q.name == v))
                })
            {
                return (
                    None,
                    format!(
                        "{what}: the slab is decided for matrices polynomial in the parameters only"
                    ),
                );
            }
            let rows = ctx.matrix.rows_with(pname, a);
            match echelon_poly(&rows) {
                Ok(e) if e.rank < n => (
                    Some(true),
                    format!(
                        "{what}: with {name} = {a} the rank is {} < {n} over Q(the other parameters) (exact): every maximal minor vanishes on the whole slab, so the functions are dependent at every point of it",
                        e.rank
                    ),
                ),
                Ok(_) => witness(std::slice::from_ref(a), &what),
                Err(_) => (None, format!("{what}: the elimination was not exact")),
            }
        }
    }
}

/// `maximal = true` on `independent`: the functions of `claimed` (the
/// basis with the claim's ranges; the one parameter's range `range` when
/// given) are linearly independent exactly on the claim's range within
/// the declared ranges of `declared` (see the module documentation).
pub fn maximal<B: ExactBasis>(declared: &B, claimed: &B, range: Option<&ParamRange>) -> Verdict {
    let inner = super::independent(claimed, range);
    let d_ranges = ranges(declared);
    let c_ranges: Vec<ParamRange> = ranges(claimed)
        .into_iter()
        .map(|r| range.filter(|_| d_ranges.len() == 1).cloned().unwrap_or(r))
        .collect();
    let mut evidence = inner.evidence.clone();
    evidence.insert(
        0,
        format!(
            "on the claim's range ({}): independence {}",
            c_ranges
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(" × "),
            inner.status
        ),
    );
    if inner.status == Status::Fails {
        return Verdict::new(Status::Fails, MAXIMAL, evidence.into_vec());
    }
    let mut pieces_of = Vec::new();
    for (i, (d, c)) in d_ranges.iter().zip(&c_ranges).enumerate() {
        match pieces(d, c) {
            Ok(ps) => pieces_of.extend(ps.into_iter().map(|p| (i, p))),
            Err(why) => return Verdict::not_checkable(why),
        }
    }
    if pieces_of.is_empty() {
        evidence.push(
            "the claim's range is the whole declared range: nothing lies outside it".to_string(),
        );
    }
    let outside = super::with_context(declared, None, super::inexact_division, |ctx, e| {
        if e.rank < ctx.names.len() {
            // dependent everywhere: the claim's range already fails
            return Verdict::new(Status::Fails, MAXIMAL, Vec::<String>::new());
        }
        let mut status = Status::Holds;
        let mut lines = Vec::new();
        for (i, p) in &pieces_of {
            let (dependent, line) = piece(ctx, *i, p);
            lines.push(line);
            match dependent {
                Some(false) => status = Status::Fails,
                None if status == Status::Holds => status = Status::NotCheckable,
                _ => {}
            }
        }
        Verdict::new(status, MAXIMAL, lines)
    });
    let outside = match outside {
        Ok(v) => v,
        Err(why) => {
            return Verdict::not_checkable(format!(
                "the maximal set of independence is decided by the exact rank, which does not apply: {why}"
            ));
        }
    };
    evidence.extend(outside.evidence.into_vec());
    let status = match (inner.status, outside.status) {
        (_, Status::Fails) => Status::Fails,
        (Status::Holds, Status::Holds) => Status::Holds,
        _ => Status::NotCheckable,
    };
    Verdict::new(status, MAXIMAL, evidence.into_vec())
}
