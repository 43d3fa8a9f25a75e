//! Linear independence by the exact rank of the coefficient matrix
//! ([`super::matrix`]): any number of functions and parameters.
//!
//! - generic rank `< n` over `Q(parameters)`: dependent for every value,
//!   the dependence relation from the elimination (exact);
//! - generic rank `n`: the rank drops exactly where every maximal minor
//!   vanishes. Without parameters that never happens (exact). With one
//!   parameter the common zeros of the maximal minors are the real roots
//!   of their gcd: the gcd of the pivot minor and of minors chosen at its
//!   roots, its roots in the range counted and isolated by Sturm
//!   sequences, each rational root decided by the rank there (exact).
//!   Otherwise a rank drop is looked for at exact points of the range (its
//!   closed corners and the rational roots of the minor in one parameter),
//!   and independence is proved by certifying every factor of one maximal
//!   minor (or a sum of squares of several) of one strict sign on the
//!   closed parameter box (interval branch and bound; open ends excluded).

use rug::Rational;
use trig_certify::atoms::{ParamAtom, param_atoms, value};
use trig_certify::branch::{self, Axis, Outcome};
use trig_core::{Domain, End, ParamRange, Parameter};
use trig_symbolic::{Poly, Style, Sym, combine, rational_roots, symbolic_atoms};

use super::matrix::{Coefficients, Echelon, column_text, echelon_poly, minor_on};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How independence is decided by rank, as the report states it.
pub const RANK: &str = "exact rank: the functions over one common denominator, their numerators' coefficients in the independent monomials t^a·c^b·s^e (e ≤ 1) of the normal form, rank by fraction-free (Bareiss) elimination over Q(parameters); dependent for every value when the rank is short (the relation exact); otherwise the rank drops exactly where every maximal minor vanishes: one parameter by the gcd of maximal minors and its real roots in the range (Sturm sequences, exact), several parameters (or their sines) by one maximal minor's factors certified of one strict sign on the closed range (interval branch and bound); refuted at an exact parameter value of the range where the rank drops, with the dependence relation there";

/// Most points of the range where the rank is computed exactly.
const MAX_POINTS: usize = 256;
/// Longest expression printed whole.
const SHOWN: usize = 240;

/// The basis as the rank judge reads it.
pub(super) struct Context<'a> {
    pub names: &'a [String],
    pub fs: &'a [Sym],
    pub params: &'a [Parameter],
    /// The range of each parameter for this claim.
    pub ranges: Vec<ParamRange>,
    pub domain: Domain,
    pub axes: Vec<Axis>,
    /// Notes on the axes (unbounded ranges truncated).
    pub notes: Vec<String>,
    pub matrix: Coefficients,
}

/// Why the rank was not computed at a point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Skip {
    /// A function is undefined there (a denominator vanishes).
    Undefined,
    /// An atom of a parameter is not exact there (`sin 1/2`).
    Inexact,
}

/// A rank at an exact parameter point.
pub(super) struct AtPoint {
    pub rank: usize,
    pub pivots: Vec<usize>,
    /// A dependence relation of the functions there, verified exactly.
    pub relation: Option<String>,
}

/// An expression printed whole when short.
pub(super) fn shown(p: &Poly) -> String {
    let text = if p.len() > 1 && p.len() <= 64 {
        Style::Unicode.factored(&Sym::from_poly(p.clone()).factored())
    } else {
        Sym::from_poly(p.clone()).to_unicode()
    };
    if text.chars().count() <= SHOWN {
        return text;
    }
    match p.as_constant() {
        Some(q) => format!(
            "a nonzero rational of {} digits",
            q.numer().to_string().len()
        ),
        None => format!(
            "a polynomial of {} terms (total degree {})",
            p.len(),
            p.total_degree()
        ),
    }
}

/// `q` or `q·π` as printed.
fn value_text(q: &Rational, pi: bool) -> String {
    if !pi {
        return q.to_string();
    }
    match (q.numer().to_i64(), q.denom().to_i64()) {
        (Some(1), Some(1)) => "π".into(),
        (Some(-1), Some(1)) => "−π".into(),
        (Some(1), Some(d)) => format!("π/{d}"),
        _ => format!("{q}·π"),
    }
}

impl Context<'_> {
    pub(super) fn header(&self) -> String {
        format!(
            "coefficient matrix of {} times their common denominator (each row also times its function's denominator factors free of the variable; the minors below are of this matrix) in the {} monomials t^a·c^b·s^e (e ≤ 1) of their numerators ({} × {})",
            self.names.join(", "),
            self.matrix.columns.len(),
            self.names.len(),
            self.matrix.columns.len()
        )
    }

    pub(super) fn columns_text(&self, cols: &[usize]) -> String {
        cols.iter()
            .map(|&j| column_text(self.matrix.columns[j]))
            .collect::<Vec<_>>()
            .join(", ")
    }

    fn point_value(&self, i: usize, q: &Rational) -> Sym {
        if self.axes.get(i).is_some_and(|a| a.pi) || self.ranges[i].pi {
            Sym::rational(q.clone()) * &Sym::pi()
        } else {
            Sym::rational(q.clone())
        }
    }

    pub(super) fn point_text(&self, point: &[Rational]) -> String {
        self.params
            .iter()
            .zip(point)
            .enumerate()
            .map(|(i, (p, q))| format!("{} = {}", p.symbol, value_text(q, self.ranges[i].pi)))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// `f` at the parameter values `point` (atoms of the parameters exact
    /// there).
    fn at(&self, f: &Sym, point: &[Sym], atoms: &[ParamAtom]) -> Result<Sym, Skip> {
        let symbols = symbolic_atoms();
        let mut g = f.clone();
        for a in atoms {
            if g.variables().contains(&a.name) {
                let v =
                    value(&a.name, &self.domain, &symbols, point, atoms).ok_or(Skip::Inexact)?;
                g = g.try_subs(&a.name, &v).map_err(|_| Skip::Undefined)?;
            }
        }
        for (p, v) in self.params.iter().zip(point) {
            g = g.try_subs(&p.name, v).map_err(|_| Skip::Undefined)?;
        }
        Ok(g)
    }

    /// A polynomial entry at the point (a polynomial again).
    fn entry_at(&self, e: &Poly, point: &[Sym], atoms: &[ParamAtom]) -> Result<Poly, Skip> {
        let v = self.at(&Sym::from_poly(e.clone()), point, atoms)?;
        if v.denominator().is_empty() {
            Ok(v.numerator().clone())
        } else {
            Err(Skip::Inexact)
        }
    }

    /// The coefficient matrix at an exact point.
    fn rows_at(&self, values: &[Sym], atoms: &[ParamAtom]) -> Result<Vec<Vec<Poly>>, Skip> {
        self.matrix
            .rows
            .iter()
            .map(|row| {
                row.iter()
                    .map(|e| self.entry_at(e, values, atoms))
                    .collect::<Result<Vec<Poly>, Skip>>()
            })
            .collect()
    }

    fn values(&self, point: &[Rational]) -> Vec<Sym> {
        point
            .iter()
            .enumerate()
            .map(|(i, q)| self.point_value(i, q))
            .collect()
    }

    /// The maximal minor on the columns `cols` at an exact point.
    pub(super) fn minor_at(&self, point: &[Rational], cols: &[usize]) -> Result<Poly, Skip> {
        let rows = self.rows_at(&self.values(point), &param_atoms(&self.domain))?;
        minor_on(&rows, cols).map_err(|_| Skip::Inexact)
    }

    /// The rank at an exact point, with the relation where it drops.
    pub(super) fn rank_at(&self, point: &[Rational]) -> Result<AtPoint, Skip> {
        let values = self.values(point);
        let atoms = param_atoms(&self.domain);
        let fs: Vec<Sym> = self
            .fs
            .iter()
            .map(|f| self.at(f, &values, &atoms))
            .collect::<Result<_, _>>()?;
        let rows = self.rows_at(&values, &atoms)?;
        let e = echelon_poly(&rows).map_err(|_| Skip::Inexact)?;
        let relation = if e.rank < self.names.len() {
            let scales: Vec<Poly> = self
                .matrix
                .scales
                .iter()
                .map(|s| self.entry_at(s, &values, &atoms))
                .collect::<Result<_, _>>()?;
            self.relation(&e, &scales, &fs)
        } else {
            None
        };
        Ok(AtPoint {
            rank: e.rank,
            pivots: e.pivots,
            relation,
        })
    }

    /// The relations of the elimination as `Σ cⱼbⱼ ≡ 0` (at most four,
    /// fewest terms first), each checked exactly against the functions
    /// `fs` (`None` if a check fails).
    fn relation(&self, e: &Echelon<Poly>, scales: &[Poly], fs: &[Sym]) -> Option<String> {
        let mut ks: Vec<&Vec<Poly>> = e.relations.iter().collect();
        ks.sort_by_key(|k| k.iter().filter(|x| !x.is_zero()).count());
        let mut out = Vec::new();
        for k in ks.into_iter().take(4) {
            let cs = simplify(k.iter().zip(scales).map(|(x, d)| x * d).collect());
            let combination = cs.iter().zip(fs).fold(Sym::zero(), |acc, (c, f)| {
                acc + &(Sym::from_poly(c.clone()) * f)
            });
            if !combination.is_zero() {
                return None;
            }
            let parts: Vec<(String, String)> = cs
                .iter()
                .zip(self.names)
                .filter(|(c, _)| !c.is_zero())
                .map(|(c, n)| (Style::Unicode.sym(&Sym::from_poly(c.clone())), n.clone()))
                .collect();
            out.push(format!("{} ≡ 0", combine(&parts, Style::Unicode)));
        }
        (!out.is_empty()).then(|| out.join(", "))
    }
}

/// The coefficients of a relation divided by their common factor (the
/// rational content, and a polynomial gcd where one is defined), the first
/// nonzero one with a positive leading coefficient.
fn simplify(cs: Vec<Poly>) -> Vec<Poly> {
    let nonzero: Vec<&Poly> = cs.iter().filter(|c| !c.is_zero()).collect();
    let Some(first) = nonzero.first() else {
        return cs;
    };
    let mut g = (*first).clone();
    for c in &nonzero[1..] {
        match trig_symbolic::gcd::gcd(&g, c) {
            Some(h) => g = h,
            None => {
                g = Poly::one();
                break;
            }
        }
    }
    let mut unit = (*first).canonical().0;
    if g.as_constant().is_none() {
        let divided: Option<Vec<Poly>> = cs.iter().map(|c| c.exact_div(&g)).collect();
        if let Some(d) = divided {
            let u = d.iter().find(|c| !c.is_zero()).map(|c| c.canonical().0);
            return d
                .iter()
                .map(|c| c.scale(&u.clone().unwrap_or_else(|| Rational::from(1)).recip()))
                .collect();
        }
    }
    if unit == 0 {
        unit = Rational::from(1);
    }
    // the content of all the coefficients together
    let content = nonzero.iter().fold(Rational::new(), |acc, c| {
        let k = c.content();
        if acc == 0 {
            k
        } else {
            Rational::from((
                acc.numer().clone().gcd(k.numer()),
                acc.denom().clone().lcm(k.denom()),
            ))
        }
    });
    let scale = if unit < 0 { -content } else { content };
    cs.iter().map(|c| c.scale(&scale.clone().recip())).collect()
}

/// Generic rank `< n`: dependent for every parameter value.
pub(super) fn short_rank(ctx: &Context<'_>, e: &Echelon<Poly>) -> Verdict {
    let n = ctx.names.len();
    let relation = ctx.relation(e, &ctx.matrix.scales, ctx.fs);
    let mut evidence = vec![format!(
        "{}: rank {} < {n} over Q(parameters) (fraction-free elimination, exact), so the functions are linearly dependent for every parameter value",
        ctx.header(),
        e.rank
    )];
    match relation {
        Some(r) => evidence.push(format!("dependence (exact): {r}")),
        None => {
            return Verdict::not_checkable(format!(
                "{}: rank {} < {n}, but the dependence relation of the elimination did not check exactly",
                ctx.header(),
                e.rank
            ));
        }
    }
    Verdict::new(Status::Fails, RANK, evidence)
}

/// The refutation at `point` where the rank drops.
pub(super) fn dropped(ctx: &Context<'_>, point: &[Rational], at: &AtPoint, how: &str) -> Verdict {
    let n = ctx.names.len();
    let mut evidence = vec![format!(
        "{}: rank {n} over Q(parameters), but at {}{how} the rank is {} < {n} (exact): the functions are linearly dependent at {}",
        ctx.header(),
        ctx.point_text(point),
        at.rank,
        ctx.point_text(point)
    )];
    if let Some(r) = &at.relation {
        evidence.push(format!(
            "at {}: {r} (dependence, exact)",
            ctx.point_text(point)
        ));
    }
    Verdict::new(Status::Fails, RANK, evidence)
}

const CLOSED_END: &str = ", a closed end of the range,";

/// Where `q` lies in `r`: at a closed end, or inside.
pub(super) fn where_in(q: &Rational, r: &ParamRange) -> &'static str {
    let at = |e: &End| matches!(e, End::Closed(v) if v == q);
    if at(&r.lo) || at(&r.hi) {
        CLOSED_END
    } else {
        ", inside the range,"
    }
}

/// Where `point` lies in the parameter box: at a closed end (one
/// parameter), a corner, or in it.
pub(super) fn how_in(ctx: &Context<'_>, point: &[Rational]) -> &'static str {
    let corner = point
        .iter()
        .zip(&ctx.ranges)
        .all(|(q, r)| where_in(q, r) == CLOSED_END);
    match (ctx.params.len(), corner) {
        (1, _) => where_in(&point[0], &ctx.ranges[0]),
        (_, true) => ", a corner of the range,",
        _ => ", in the range,",
    }
}

/// Generic rank `n` without any parameter in the pivot minor.
pub(super) fn constant_minor(ctx: &Context<'_>, e: &Echelon<Poly>) -> Verdict {
    let n = ctx.names.len();
    let every = if ctx.params.is_empty() {
        ""
    } else {
        " for every parameter value"
    };
    Verdict::new(
        Status::Holds,
        RANK,
        vec![format!(
            "{}: rank {n} (fraction-free elimination, exact): the {n} × {n} minor on the monomials {} is {} ≠ 0{every}, so the functions are linearly independent",
            ctx.header(),
            ctx.columns_text(&e.pivots),
            shown(&e.minor)
        )],
    )
}

/// Candidate values of parameter `i`: its closed ends, the rational roots
/// of `minor` in it (where it vanishes whatever the others are), else a
/// point inside.
fn candidates(ctx: &Context<'_>, i: usize, minor: &Poly) -> Vec<Rational> {
    let (p, r, axis) = (&ctx.params[i], &ctx.ranges[i], &ctx.axes[i]);
    let mut out: Vec<Rational> = [&r.lo, &r.hi]
        .into_iter()
        .filter_map(|e| match e {
            End::Closed(v) => Some(v.clone()),
            _ => None,
        })
        .collect();
    if !r.pi {
        let (roots, _) = rational_roots(minor, &p.name);
        out.extend(roots.into_iter().filter(|v| r.contains(v)));
    }
    if out.is_empty() {
        out.push(Rational::from(&axis.lo + &axis.hi) / 2u32);
    }
    out.sort();
    out.dedup();
    out
}

/// Every point of the product of the candidates (at most [`MAX_POINTS`]).
fn grid(lists: &[Vec<Rational>]) -> Vec<Vec<Rational>> {
    let mut out: Vec<Vec<Rational>> = vec![Vec::new()];
    for list in lists {
        out = out
            .iter()
            .flat_map(|prefix| {
                list.iter().map(move |v| {
                    let mut p = prefix.clone();
                    p.push(v.clone());
                    p
                })
            })
            .take(MAX_POINTS)
            .collect();
    }
    out
}

/// Several parameters (or their atoms, or a range in multiples of π):
/// exact points of the range refute; certified minors prove.
pub(super) fn general(ctx: &Context<'_>, e: &Echelon<Poly>) -> Verdict {
    let n = ctx.names.len();
    let lists: Vec<Vec<Rational>> = (0..ctx.params.len())
        .map(|i| candidates(ctx, i, &e.minor))
        .collect();
    let mut others: Vec<Vec<usize>> = Vec::new();
    let mut decided = 0;
    for point in grid(&lists) {
        let Ok(at) = ctx.rank_at(&point) else {
            continue;
        };
        decided += 1;
        if at.rank < n {
            return dropped(ctx, &point, &at, how_in(ctx, &point));
        }
        if at.pivots != e.pivots && !others.contains(&at.pivots) && others.len() < 3 {
            others.push(at.pivots);
        }
    }
    let header = format!(
        "{}: rank {n} over Q(parameters); no rank drop at the {decided} exact point{} tried (closed ends, rational roots of the pivot minor, else a middle point)",
        ctx.header(),
        if decided == 1 { "" } else { "s" }
    );
    if !ctx.notes.is_empty() {
        let mut evidence = ctx.notes.clone();
        evidence.push(format!(
            "{header}; a maximal minor is certified nonzero only on a bounded range"
        ));
        return Verdict::new(Status::NotCheckable, RANK, evidence);
    }
    let free = |v: &String| v == "pi" || v.starts_with("sqrt(");
    let factored = e.minor.factor();
    let mut unproved = None;
    for (h, _) in &factored.factors {
        if h.variables().iter().all(free) {
            continue;
        }
        if let Err(why) = strict_sign(ctx, &Sym::from_poly(h.clone())) {
            unproved = Some((h.clone(), why));
            break;
        }
    }
    let Some((h, why)) = unproved else {
        return Verdict::new(
            Status::Holds,
            RANK,
            vec![format!(
                "{header}: the {n} × {n} minor on the monomials {} is {}; each of its factors is certified of one strict sign for {} (interval branch and bound), so the functions are linearly independent there",
                ctx.columns_text(&e.pivots),
                shown(&e.minor),
                ctx.point_ranges()
            )],
        );
    };
    // a sum of squares of maximal minors
    let mut sum = e.minor.clone() * &e.minor;
    for cols in &others {
        if let Ok(d) = minor_on(&ctx.matrix.rows, cols) {
            sum = sum + &(d.clone() * &d);
        }
    }
    if !others.is_empty() && strict_sign(ctx, &Sym::from_poly(sum)).is_ok() {
        return Verdict::new(
            Status::Holds,
            RANK,
            vec![format!(
                "{header}: the sum of the squares of the {} maximal minors on the monomials {{{}}} and {} is certified positive for {} (interval branch and bound), so the functions are linearly independent there",
                others.len() + 1,
                ctx.columns_text(&e.pivots),
                others
                    .iter()
                    .map(|c| format!("{{{}}}", ctx.columns_text(c)))
                    .collect::<Vec<_>>()
                    .join(", "),
                ctx.point_ranges()
            )],
        );
    }
    Verdict::new(
        Status::NotCheckable,
        RANK,
        vec![format!(
            "{header}: the factor {} of the maximal minor on the monomials {} is not certified of one strict sign on the range ({why}), and no rank drop was found",
            shown(&h),
            ctx.columns_text(&e.pivots)
        )],
    )
}

impl Context<'_> {
    pub(super) fn point_ranges(&self) -> String {
        self.params
            .iter()
            .zip(&self.ranges)
            .map(|(p, r)| format!("{} ∈ {r}", p.symbol))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// `f > 0` or `f < 0` on the parameter box, certified; the reason when
/// neither is.
pub(super) fn strict_sign(ctx: &Context<'_>, f: &Sym) -> Result<(), String> {
    let mut why = String::new();
    for g in [f.clone(), -f.clone()] {
        match branch::positive(&g, &ctx.domain, &ctx.axes) {
            Outcome::Proved { .. } => return Ok(()),
            Outcome::Negative { .. } => why = "it changes sign or vanishes".into(),
            Outcome::Undecided(w) if why.is_empty() => why = w,
            Outcome::Undecided(_) => {}
        }
    }
    Err(why)
}
