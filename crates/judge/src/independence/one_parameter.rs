//! Independence with one parameter whose maximal minors are polynomials
//! in it: their gcd and its real roots in the range decide exactly.

use rug::Rational;
use trig_certify::algebraic::Algebraic;
use trig_certify::sturm::UPoly;
use trig_core::End;
use trig_symbolic::{Poly, Style, Sym, combine, rational_roots};

use super::at_root;
use super::matrix::{Echelon, minor_on};
use super::rank::{Context, RANK, Skip, dropped, where_in};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// One parameter, every entry a polynomial in it: the gcd of maximal
/// minors and its real roots in the range decide exactly — a rational root
/// by the rank there (a new minor joins the gcd where it is full), an
/// irrational one by the rank in `Q[p]/(h)` (`at_root.rs`). `None` when
/// the minors are not polynomials in the parameter alone.
pub(super) fn one_parameter(ctx: &Context<'_>, e: &Echelon<Poly>) -> Option<Verdict> {
    let (p, r) = (&ctx.params[0], &ctx.ranges[0]);
    if r.pi {
        return None;
    }
    // every entry a polynomial in the parameter alone: the rank at a
    // rational value is then exact (or the basis undefined there)
    let alone = |q: &Poly| q.variables().iter().all(|v| *v == p.name);
    let in_basis = |f: &Sym| {
        f.variables()
            .iter()
            .all(|v| *v == p.name || super::VARIABLE_ATOMS.contains(&v.as_str()))
    };
    if !ctx.matrix.rows.iter().flatten().all(alone)
        || !ctx.matrix.scales.iter().all(alone)
        || !ctx.fs.iter().all(in_basis)
    {
        return None;
    }
    let rows: Vec<Vec<UPoly>> = ctx
        .matrix
        .rows
        .iter()
        .map(|row| row.iter().map(|x| UPoly::from_poly(x, &p.name)).collect())
        .collect::<Option<_>>()?;
    let n = ctx.names.len();
    let mut g = UPoly::from_poly(&e.minor, &p.name)?.integer_primitive();
    // g without the factors whose roots are decided of full rank
    let mut rest = g.clone();
    let mut cleared: Vec<String> = Vec::new();
    let mut used = 1usize;
    let mut undefined: Vec<Rational> = Vec::new();
    for _ in 0..(4 * n + 16) {
        // rational roots first (the closed ends whatever the search for
        // rational roots could enumerate)
        let mut rational: Vec<Rational> = rational_roots(&to_poly(&rest, &p.name), &p.name).0;
        for end in [&r.lo, &r.hi] {
            if let End::Closed(v) = end
                && rest.sign_at(v) == 0
            {
                rational.push(v.clone());
            }
        }
        rational.retain(|v| r.contains(v) && !undefined.contains(v));
        let bound = rest.root_bound() + Rational::from(1);
        let lo = r.lo.value().cloned().unwrap_or_else(|| -bound.clone());
        let hi = r.hi.value().cloned().unwrap_or(bound);
        let mut roots: Vec<(Rational, Rational)> =
            rational.into_iter().map(|v| (v.clone(), v)).collect();
        if roots.is_empty() && lo < hi {
            roots.extend(rest.isolate(&lo, &hi).into_iter().filter(|(a, b)| {
                !undefined
                    .iter()
                    .any(|u| (a == b && a == u) || (a < u && u < b))
            }));
        }
        let Some((a, b)) = roots.first().cloned() else {
            return Some(one_parameter_holds(ctx, &g, used, &cleared, &undefined));
        };
        if a == b {
            let point = [a.clone()];
            let at = match ctx.rank_at(&point) {
                Ok(at) => at,
                Err(Skip::Undefined) => {
                    undefined.push(a);
                    continue;
                }
                Err(Skip::Inexact) => return None,
            };
            if at.rank < n {
                return Some(dropped(ctx, &point, &at, where_in(&a, r)));
            }
            let minor = minor_on(&ctx.matrix.rows, &at.pivots).ok()?;
            let minor = UPoly::from_poly(&minor, &p.name)?;
            used += 1;
            g = g.gcd(&minor).integer_primitive();
            rest = rest.gcd(&minor).integer_primitive();
            continue;
        }
        // an irrational root in (a, b): the rank in Q[p]/(h)
        let at = at_root::rank_at_root(&rows, rest.squarefree(), &a, &b);
        if at.rank < n {
            return Some(dropped_at_root(ctx, &rows, &at, &a, &b));
        }
        cleared.push(at.h.integer_primitive().display(&p.name));
        while rest.degree() > 0 {
            let (q, remainder) = rest.div_rem(&at.h);
            if !remainder.is_zero() {
                break;
            }
            rest = q;
        }
    }
    Some(Verdict::not_checkable(format!(
        "{}: the gcd of the maximal minors did not settle",
        ctx.header()
    )))
}

/// Independence on the range when no common zero of the maximal minors
/// lies in it.
fn one_parameter_holds(
    ctx: &Context<'_>,
    g: &UPoly,
    used: usize,
    cleared: &[String],
    undefined: &[Rational],
) -> Verdict {
    let (p, r, n) = (&ctx.params[0], &ctx.ranges[0], ctx.names.len());
    let roots = if cleared.is_empty() {
        format!("with no root in the range {r}")
    } else {
        format!(
            "whose only roots in the range {r} are roots of {}, where the rank is {n} (elimination in Q[{}]/(h), exact)",
            cleared.join(", "),
            p.name
        )
    };
    let mut evidence = vec![format!(
        "{}: rank {n} over Q({}); the gcd of {used} maximal minor{} is {} (exact), {roots} (Sturm sequences): a maximal minor is nonzero at every {} there, so the functions are linearly independent",
        ctx.header(),
        p.symbol,
        if used == 1 { "" } else { "s" },
        g.display(&p.name),
        p.symbol
    )];
    if !undefined.is_empty() {
        evidence.push(format!(
            "the basis is undefined at {} = {} (a denominator vanishes), which is left out",
            p.symbol,
            undefined
                .iter()
                .map(Rational::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    Verdict::new(Status::Holds, RANK, evidence)
}

/// The refutation at an irrational root of the minors' gcd.
fn dropped_at_root(
    ctx: &Context<'_>,
    rows: &[Vec<UPoly>],
    at: &at_root::AtRoot,
    lo: &Rational,
    hi: &Rational,
) -> Verdict {
    let (p, n) = (&ctx.params[0], ctx.names.len());
    let mut root = Algebraic::new(&at.h, lo.clone(), hi.clone());
    root.refine(&Rational::from((1, 1_000_000_000_000u64)));
    let value = root.describe(&p.name, 12);
    let mut evidence = vec![format!(
        "{}: rank {n} over Q({}), but at {} = {value}, inside the range, every maximal minor vanishes: the rank there is {} < {n} (elimination in Q[{}]/({}), exact), so the functions are linearly dependent at that {}",
        ctx.header(),
        p.symbol,
        p.symbol,
        at.rank,
        p.name,
        at.h.display(&p.name),
        p.symbol
    )];
    // the relation of the rows, checked modulo h, for the functions
    // (times their denominators in the parameter)
    if let Some(k) = &at.relation {
        let holds = (0..rows.first().map_or(0, Vec::len)).all(|j| {
            let sum = k
                .iter()
                .zip(rows)
                .fold(UPoly::new(vec![]), |acc, (c, row)| acc.add(&c.mul(&row[j])));
            sum.div_rem(&at.h).1.is_zero()
        });
        let scales: Option<Vec<UPoly>> = ctx
            .matrix
            .scales
            .iter()
            .map(|s| UPoly::from_poly(s, &p.name))
            .collect();
        if let (true, Some(scales)) = (holds, scales) {
            let mut cs: Vec<UPoly> = k
                .iter()
                .zip(&scales)
                .map(|(c, d)| c.mul(d).div_rem(&at.h).1)
                .collect();
            if cs
                .iter()
                .find(|c| !c.is_zero())
                .is_some_and(|c| c.leading() < 0)
            {
                cs = cs.iter().map(|c| UPoly::new(vec![]).sub(c)).collect();
            }
            let parts: Vec<(String, String)> = cs
                .into_iter()
                .zip(ctx.names)
                .filter(|(c, _)| !c.is_zero())
                .map(|(c, name)| {
                    (
                        Style::Unicode.sym(&Sym::from_poly(to_poly(&c, &p.name))),
                        name.clone(),
                    )
                })
                .collect();
            evidence.push(format!(
                "there: {} ≡ 0 with {} that root (dependence, exact modulo {})",
                combine(&parts, Style::Unicode),
                p.name,
                at.h.display(&p.name)
            ));
        }
    }
    Verdict::new(Status::Fails, RANK, evidence)
}

/// The univariate `g` as a polynomial in `name`.
fn to_poly(g: &UPoly, name: &str) -> Poly {
    g.coeffs()
        .iter()
        .enumerate()
        .fold(Poly::zero(), |acc, (i, a)| {
            acc + &(Poly::var(name).pow(i as u32).scale(a))
        })
}
