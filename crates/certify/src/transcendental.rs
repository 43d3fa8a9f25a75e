//! A certified end of a maximal range: the unique root of an exact
//! equation in a rational enclosure, with the proof that admissibility
//! changes exactly there.
//!
//! At a parameter `bad` a function `f` is certified negative and at `ok`
//! every function is `≥ 0`. The factor `h` of `f` whose sign differs
//! between them (the *culprit*, signed so that `h ≥ 0` at `ok`) gives the
//! equation of the end:
//!
//! * `h(p) = 0` when `h` depends on the parameter alone ([`Equation::Parameter`]);
//! * `h(x_e(p), p) = 0` when the minimum of `h` over the domain is at an
//!   end `x_e` of it ([`Equation::EndValue`], the equation printed with the
//!   end substituted exactly); when `h` vanishes identically there (a basis
//!   function interpolating the end), its first derivative into the domain
//!   that does not, which has the sign of `h` next to the end (Taylor);
//! * `h = ∂ₓh = 0` when the minimum is inside the domain — the boundary of
//!   the admissible set, where the minimum over `x` touches 0
//!   ([`Equation::Stationary`]).
//!
//! Its root `r` is certified by the Krawczyk operator ([`crate::krawczyk`])
//! in a tiny box; then, on `P = [a, b] ∋ r` (`a` inside, `b` outside, both
//! rational) and a neighbourhood `T` of the minimiser, the conditions that
//! make `r` the end are proved by enclosures and branch and bound:
//! `dir·∂ₚh < 0` on `T × P` (the minimum decreases through 0 at `r`);
//! for a stationary minimum `∂ₓₓh > 0` on `T × P` and `∂ₓh` of opposite
//! signs at the sides of `T` (one minimiser in `T`), for an end minimum
//! `h` not increasing towards the end on `T` (branch and bound); `h ≥ 0` on the rest of the domain
//! for every `p ∈ P`; the other factors of `f` of one strict sign and the
//! other functions `≥ 0` on `P`. Then `min h(·, p) = m(p)` with `m`
//! strictly monotone and `m(r) = 0`: every `p` between `a` and `r` is
//! admissible (`r` included) and every `p` beyond `r` up to `b` is not —
//! and `b` carries a certified negative value. The end is called exact only
//! when the equation vanishes exactly at a simple value in the enclosure
//! (a rational, a multiple of π/12 on a π axis, a real algebraic root of a
//! polynomial factor).

use rug::Rational;
use trig_core::{Affine, Domain};
use trig_symbolic::Sym;

use crate::algebraic::Algebraic;
use crate::analytic_end::{End, Equation, ExactValue, Outside, Problem, Witness};
use crate::atoms::{d_param, d_variable, param_atoms, value};
use crate::branch::{self, Outcome};
use crate::coordinates::{BoxFunction, Coordinates};
use crate::elimination;
use crate::factors::{self, Sign};
use crate::krawczyk::{Cell, System};
use crate::range::simplest_between;
use crate::sturm::UPoly;

#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Parameter,
    /// The minimum at `τ = 0` (false) or `τ = 1` (true), decided by the
    /// derivative of this order into the domain.
    EndValue(bool, u32),
    Stationary,
}

/// Subdivisions allowed to prove a sign on a small box.
const SIGN_DEPTH: u32 = 6;

fn variable_free(h: &Sym) -> bool {
    !h.variables()
        .iter()
        .any(|v| ["s", "c", "t", "E"].contains(&v.as_str()))
}

/// The culprit factor of `f` between `ok` and `bad` (signed `≥ 0` at
/// `ok`), and the other factors with their multiplicity.
fn culprit(
    problem: &Problem<'_>,
    f: &Sym,
    ok: &Rational,
    bad: &Rational,
) -> Result<(Sym, Vec<(Sym, u32)>), String> {
    let point = |p: &Rational| problem.axis(p, p, false, false);
    let q = Sym::from_poly(f.numerator().clone()).factored();
    let mut found: Vec<Sym> = Vec::new();
    let mut rest: Vec<(Sym, u32)> = Vec::new();
    for (g, e) in &q.num {
        let h = Sym::from_poly(g.clone());
        if e % 2 == 0 {
            rest.push((h, *e));
            continue;
        }
        let at_ok = factors::sign_of(&h, problem.domain, &point(ok), false);
        let at_bad = factors::sign_of(&h, problem.domain, &point(bad), false);
        match (at_ok, at_bad) {
            (Ok((s, _)), Ok((t, _))) if s == t => rest.push((h, *e)),
            (Ok((s, _)), _) => found.push(if s == Sign::Minus { -h } else { h }),
            (Err(why), _) => return Err(format!("the sign of a factor inside: {why}")),
        }
    }
    match <[Sym; 1]>::try_from(found) {
        Ok([h]) => Ok((h, rest)),
        Err(v) if v.is_empty() => Err("no factor changes sign between the bracket's ends".into()),
        Err(_) => Err("two factors change sign in the bracket".into()),
    }
}

/// `g` of one strict sign (`positive`) on the cell, by enclosures on at
/// most `2^SIGN_DEPTH` sub-boxes.
fn sign_on(
    coords: &Coordinates<'_>,
    g: &BoxFunction,
    cell: &Cell,
    positive: bool,
    depth: u32,
) -> bool {
    if let Some(v) = coords.enclose(g, cell) {
        if (positive && *v.lo() > 0) || (!positive && *v.hi() < 0) {
            return true;
        }
    }
    if depth == 0 {
        return false;
    }
    let Some(k) = (0..cell.len())
        .filter(|&k| cell[k].0 != cell[k].1)
        .max_by(|&i, &j| {
            let w = |k: usize| Rational::from(&cell[k].1 - &cell[k].0);
            w(i).cmp(&w(j))
        })
    else {
        return false;
    };
    let mid = Rational::from(&cell[k].0 + &cell[k].1) / 2u32;
    [(cell[k].0.clone(), mid.clone()), (mid, cell[k].1.clone())]
        .into_iter()
        .all(|half| {
            let mut c = cell.clone();
            c[k] = half;
            sign_on(coords, g, &c, positive, depth - 1)
        })
}

/// The domain restricted to `τ ∈ [τ₀, τ₁]`.
fn part(domain: &Domain, t0: &Rational, t1: &Rational) -> Domain {
    let at = |t: &Rational| {
        domain
            .start
            .scale(&(1 - t.clone()))
            .plus(&domain.end.scale(t))
    };
    Domain {
        start: at(t0),
        end: at(t1),
        ..domain.clone()
    }
}

/// `h` with the variable at the end `x = e(p)` of the domain, exactly.
fn at_end(h: &Sym, domain: &Domain, end: &Affine) -> Option<Sym> {
    let params: Vec<Sym> = domain.param_names.iter().map(|n| Sym::var(n)).collect();
    let a = domain.atoms_at(end, &Sym::one(), &params)?;
    Some(
        h.subs("s", &Sym::var("__s"))
            .subs("c", &a.c)
            .subs("__s", &a.s)
            .subs("t", &a.t)
            .subs("E", &a.e),
    )
}

/// `F` (in the parameter and its atoms) at the value `v` (× π on a π
/// axis), exactly; `None` when an atom is not exact there.
fn exactly_at(problem: &Problem<'_>, f: &Sym, v: &Rational) -> Option<Sym> {
    let d = problem.domain;
    let p = if problem.pi {
        Sym::rational(v.clone()) * &Sym::pi()
    } else {
        Sym::rational(v.clone())
    };
    let atoms = param_atoms(d);
    let symbols = trig_symbolic::symbolic_atoms();
    let mut out = f.subs(&d.param_names[0], &p);
    for a in &atoms {
        if out.variables().contains(&a.name) {
            out = out.subs(
                &a.name,
                &value(&a.name, d, &symbols, std::slice::from_ref(&p), &atoms)?,
            );
        }
    }
    Some(out)
}

/// The cell `τ = tau` × `[lo, hi]`.
fn bracket_cell(tau: &Rational, lo: &Rational, hi: &Rational) -> Cell {
    vec![(tau.clone(), tau.clone()), (lo.clone(), hi.clone())]
}

/// `(∓∂ₓ)ᵐh` for the least `m ≤ 4` at which it does not vanish
/// identically at the end `τ = 1` (`end`) or `τ = 0` of the domain (the
/// derivative into the domain: `h` has its sign next to the end).
fn into_domain(coords: &Coordinates<'_>, h: &Sym, end: bool, cell: &Cell) -> Option<(Sym, u32)> {
    let tau = &cell[0].0;
    let mut g = h.clone();
    for m in 0..=4 {
        if !coords.zero_on_face(&coords.function(&g), cell, 0, tau) {
            return Some((g, m));
        }
        let d = d_variable(&g, coords.domain);
        g = if end { -d } else { d };
    }
    None
}

/// The end certified from the bracket `(ok, w.param)` in direction `dir`.
pub fn certify_end(
    problem: &Problem<'_>,
    ok: &Rational,
    w: &Witness,
    dir: i32,
) -> Result<End, String> {
    let f = &problem.functions[w.function];
    let bad = &w.param;
    let (h, rest) = culprit(problem, f, ok, bad)?;
    let (lo, hi) = if ok < bad { (ok, bad) } else { (bad, ok) };
    let bracket = problem.axis(lo, hi, false, false);
    let coords = Coordinates::new(problem.domain, &bracket);
    // the function whose sign decides next to the end: h itself, or at an
    // end of the domain where h vanishes identically its first derivative
    // into the domain that does not (Taylor: h has its sign there)
    let (kind, g) = if variable_free(&h) {
        (Kind::Parameter, h.clone())
    } else {
        let negative_at = |end: bool| -> Option<(Sym, u32)> {
            let tau = Rational::from(u32::from(end));
            let (g, m) = into_domain(&coords, &h, end, &bracket_cell(&tau, lo, hi))?;
            let cell: Cell = vec![(tau.clone(), tau), (bad.clone(), bad.clone())];
            coords
                .enclose(&coords.function(&g), &cell)
                .is_some_and(|v| *v.hi() < 0)
                .then_some((g, m))
        };
        let near = |end: bool| {
            if end {
                w.tau >= Rational::from((7, 8))
            } else {
                w.tau <= Rational::from((1, 8))
            }
        };
        match [true, false].into_iter().find_map(|end| {
            near(end)
                .then(|| negative_at(end))
                .flatten()
                .map(|g| (end, g))
        }) {
            Some((end, (g, m))) => (Kind::EndValue(end, m), g),
            None => (Kind::Stationary, h.clone()),
        }
    };
    let hf = coords.function(&g);
    // the root, certified
    let tau0 = match kind {
        Kind::EndValue(true, _) => Rational::from(1),
        Kind::EndValue(false, _) | Kind::Parameter => Rational::new(),
        Kind::Stationary => w.tau.clone(),
    };
    let (system, unknowns) = match kind {
        Kind::Stationary => (
            System::new(
                &coords,
                vec![hf.clone(), coords.derivative(&hf, 0)],
                vec![0, 1],
            ),
            2,
        ),
        _ => (System::new(&coords, vec![hf.clone()], vec![1]), 1),
    };
    let width = Rational::from(hi - lo);
    let mid = Rational::from(lo + hi) / 2u32;
    let start: Cell = vec![(tau0.clone(), tau0.clone()), (mid.clone(), mid)];
    let within: Cell = vec![
        (Rational::new(), Rational::from(1)),
        (Rational::from(lo - &width), Rational::from(hi + &width)),
    ];
    let guess = system
        .guess(&start, &within, 60)
        .ok_or("Newton's method did not converge to the end")?;
    let r = Rational::from((1, 1u64 << 62)) * Rational::from((1, 1u64 << 30));
    let cell: Cell = guess
        .iter()
        .enumerate()
        .map(|(k, (x, _))| {
            if unknowns == 2 || k == 1 {
                (Rational::from(x - &r), Rational::from(x + &r))
            } else {
                (x.clone(), x.clone())
            }
        })
        .collect();
    let root = system
        .certify(&cell, 4)
        .ok_or("the Krawczyk test did not certify a unique root near the end")?;
    let (r_lo, r_hi) = root[1].clone();
    let tau = root[0].clone();
    let equation = match kind {
        Kind::Parameter => Equation::Parameter {
            function: w.function,
            factor: h.clone(),
        },
        Kind::EndValue(e, order) => {
            let end = if e {
                &problem.domain.end
            } else {
                &problem.domain.start
            };
            Equation::EndValue {
                function: w.function,
                factor: h.clone(),
                order,
                at_end: e,
                value: at_end(&g, problem.domain, end).ok_or("the end's atoms are not exact")?,
            }
        }
        Kind::Stationary => Equation::Stationary {
            function: w.function,
            factor: h.clone(),
            derivative: d_variable(&h, problem.domain),
            tau: tau.clone(),
        },
    };
    let exact = exact_root(problem, &equation, &r_lo, &r_hi);
    // the conditions that make the root the end, on P = [a, b]
    let scale = Rational::from(&width * (1u32 << 12));
    for k in [3u32, 6, 9, 12, 15] {
        let rho = Rational::from(&scale / (1u64 << k));
        let half = Rational::from(&rho / 2u32);
        let below = simplest_between(
            &Rational::from(&r_lo - &rho),
            &Rational::from(&r_lo - &half),
        );
        let above = simplest_between(
            &Rational::from(&r_hi + &half),
            &Rational::from(&r_hi + &rho),
        );
        let (inside, outside) = if dir > 0 {
            (below, above)
        } else {
            (above, below)
        };
        let Err(Outside::Negative(witness)) = problem.admissible(&outside) else {
            continue;
        };
        let (a, b) = if inside < outside {
            (inside.clone(), outside.clone())
        } else {
            (outside.clone(), inside.clone())
        };
        if !conditions(
            problem,
            w.function,
            (&h, &g),
            &rest,
            kind,
            &tau,
            &a,
            &b,
            dir,
        ) {
            continue;
        }
        return Ok(match &exact {
            Some(value) => End::Exact {
                value: value.clone(),
                closed: true,
                why: if matches!(equation, Equation::Stationary { .. }) {
                    elimination::WHY.into()
                } else {
                    "the equation of the end vanishes exactly there".into()
                },
                inside,
                outside: Some(witness),
            },
            None => End::Certified {
                lo: r_lo,
                hi: r_hi,
                equation,
                inside,
                outside: witness,
            },
        });
    }
    Err("the conditions that make the certified root the end were not proved".into())
}

/// An exact end where a function vanishes identically: a simple value `q`
/// strictly between `ok` and the witness's parameter (a multiple of π/12
/// on a π axis, or the simplest rational) where some function is exactly
/// 0 for every `x`, with every function `≥ 0` on `[ok, q]` (branch and
/// bound) and, at a fixed point of the domain, that function strictly
/// decreasing beyond `q` up to the witness (`dir·∂ₚf < 0` there, so
/// `f < 0` on `(q, bad]`): `q` is the end, included.
pub fn vanishing_end(
    problem: &Problem<'_>,
    ok: &Rational,
    w: &Witness,
    dir: i32,
    candidates: &[Rational],
) -> Option<End> {
    let bad = &w.param;
    for q in candidates {
        let vanishing: Vec<usize> = problem
            .functions
            .iter()
            .enumerate()
            .filter(|(_, f)| {
                exactly_at(problem, &Sym::from_poly(f.numerator().clone()), q)
                    .is_some_and(|v| v.is_zero())
            })
            .map(|(j, _)| j)
            .collect();
        if vanishing.is_empty() {
            continue;
        }
        let (lo, hi) = if q < bad { (q, bad) } else { (bad, q) };
        let beyond = problem.axis(lo, hi, false, false);
        let coords = Coordinates::new(problem.domain, &beyond);
        let decreasing = vanishing.iter().find_map(|&j| {
            let f = &problem.functions[j];
            let num = coords.function(&Sym::from_poly(f.numerator().clone()));
            let dp = coords.derivative(&num, 1);
            let down = if dir > 0 { dp.negated() } else { dp };
            // denominators of one strict sign on the bracket beyond
            let signs: Option<Vec<Sign>> = f
                .denominator()
                .keys()
                .map(|g| {
                    factors::sign_of(&Sym::from_poly(g.clone()), problem.domain, &beyond, true)
                        .ok()
                        .map(|(s, _)| s)
                })
                .collect();
            let negative = signs?.iter().filter(|s| **s == Sign::Minus).count() % 2 == 1;
            let down = if negative { down.negated() } else { down };
            [
                w.tau.clone(),
                Rational::from((1, 2)),
                Rational::from((1, 3)),
            ]
            .into_iter()
            .find(|tau| {
                let cell: Cell = vec![(tau.clone(), tau.clone()), (lo.clone(), hi.clone())];
                sign_on(&coords, &down, &cell, true, SIGN_DEPTH)
            })
            .map(|tau| (j, tau))
        });
        let Some((j, tau)) = decreasing else {
            continue;
        };
        if !admissible_up_to(problem, ok, q, dir, &vanishing) {
            continue;
        }
        let var = &problem.domain.name;
        return Some(End::Exact {
            value: ExactValue::Rational(q.clone()),
            closed: true,
            why: format!(
                "a basis function (number {}) vanishes identically there and, at {var} = a + {tau}·(b − a), decreases through 0 beyond it: its derivative in the parameter is certified of one sign up to the witness",
                j + 1
            ),
            inside: ok.clone(),
            outside: Some(w.clone()),
        });
    }
    None
}

/// Every function `≥ 0` for the parameter between `ok` and `q`: by branch
/// and bound, or — for a function vanishing identically at `q` — because
/// its numerator `N`, signed by its denominator (`σ`), does not increase
/// towards `q` at any fixed fraction `τ` of the domain
/// (`x = a(p) + L(p)·τ`): `−dir·σ·∂ₚ|_τ N ≥ 0`, so `σN ≥ σN(·, q) = 0`.
/// With `∂ₚ|_τ = ∂ₚ|ₓ + (a′ + L′·τ)·∂ₓ` and `L > 0`, the sign is that of
/// `L·∂ₚ|ₓN + (a′·L + L′·(x − a))·∂ₓN`, an exact function on the domain.
fn admissible_up_to(
    problem: &Problem<'_>,
    ok: &Rational,
    q: &Rational,
    dir: i32,
    vanishing: &[usize],
) -> bool {
    let d = problem.domain;
    let (lo, hi) = if ok < q { (ok, q) } else { (q, ok) };
    let axis = problem.axis(lo, hi, false, false);
    let atoms = param_atoms(d);
    let p: Vec<Sym> = d.param_names.iter().map(|n| Sym::var(n)).collect();
    let a = d.start.eval(&Sym::one(), &p);
    let length = d.end.eval(&Sym::one(), &p) - &a;
    let da = d_param(&a, d, 0, &atoms);
    let dl = d_param(&length, d, 0, &atoms);
    // the variable `t` may enter the derivative along τ
    let with_t = Domain {
        uses_variable: true,
        ..d.clone()
    };
    // a function vanishing at `q`: the derivative first (branch and bound
    // on the function itself is slow next to the face where it is ≡ 0)
    let decreasing_towards = |f: &Sym| {
        let mut negative = dir > 0;
        for g in f.denominator().keys() {
            match factors::sign_of(&Sym::from_poly(g.clone()), d, &axis, true) {
                Ok((Sign::Minus, _)) => negative = !negative,
                Ok(_) => {}
                Err(_) => return false,
            }
        }
        let n = Sym::from_poly(f.numerator().clone());
        let along = length.clone() * &d_param(&n, d, 0, &atoms)
            + &((da.clone() * &length + &(dl.clone() * &(Sym::var("t") - &a)))
                * &d_variable(&n, d));
        let g = if negative { -along } else { along };
        matches!(
            factors::nonnegative(&g, &with_t, &axis),
            Outcome::Proved { .. }
        )
    };
    problem.decided().all(|(j, f)| {
        (vanishing.contains(&j) && decreasing_towards(f))
            || matches!(factors::nonnegative(f, d, &axis), Outcome::Proved { .. })
    })
}

/// The root as an exact value, when the equation vanishes exactly at a
/// simple value of the enclosure (or is a polynomial in the parameter).
fn exact_root(
    problem: &Problem<'_>,
    equation: &Equation,
    lo: &Rational,
    hi: &Rational,
) -> Option<ExactValue> {
    let f = match equation {
        Equation::Parameter { factor, .. } => factor,
        Equation::EndValue { value, .. } => value,
        Equation::Stationary {
            factor, derivative, ..
        } => return elimination::exact_root(problem, factor, derivative, lo, hi),
    };
    let name = &problem.domain.param_names[0];
    if !problem.pi && f.variables().iter().all(|v| v == name) {
        let p = UPoly::from_poly(f.numerator(), name)?.squarefree();
        let (a, b) = p.isolate(lo, hi).into_iter().next()?;
        let root = Algebraic::new(&p, a, b);
        return Some(match &root.rational {
            Some(q) => ExactValue::Rational(q.clone()),
            None => ExactValue::Algebraic(root),
        });
    }
    let mut candidates = Vec::new();
    if problem.pi {
        let k = Rational::from(lo * 12u32).ceil();
        if Rational::from(&k / 12u32) <= *hi {
            candidates.push(Rational::from(&k / 12u32));
        }
    }
    candidates.push(simplest_between(lo, hi));
    candidates
        .into_iter()
        .find(|v| exactly_at(problem, f, v).is_some_and(|x| x.is_zero()))
        .map(ExactValue::Rational)
}

/// The conditions of the module docs on `P = [a, b]`.
#[allow(clippy::too_many_arguments)]
fn conditions(
    problem: &Problem<'_>,
    function: usize,
    (h, g): (&Sym, &Sym),
    rest: &[(Sym, u32)],
    kind: Kind,
    tau: &(Rational, Rational),
    a: &Rational,
    b: &Rational,
    dir: i32,
) -> bool {
    let axis = problem.axis(a, b, false, false);
    let coords = Coordinates::new(problem.domain, &axis);
    let hf = coords.function(g);
    let dp = coords.derivative(&hf, 1);
    let down = if dir > 0 { dp.negated() } else { dp };
    let p = (a.clone(), b.clone());
    let domain_ok = |t0: &Rational, t1: &Rational| -> bool {
        t0 >= t1
            || matches!(
                branch::nonnegative(h, &part(problem.domain, t0, t1), &axis),
                Outcome::Proved { .. }
            )
    };
    let zero = Rational::new();
    let one = Rational::from(1);
    // the slab of the domain × P where the minimum lives, when the local
    // conditions hold there
    let slab: Option<Cell> = match kind {
        Kind::Parameter => {
            let c: Cell = vec![(zero.clone(), zero.clone()), p.clone()];
            sign_on(&coords, &down, &c, true, SIGN_DEPTH)
                .then(|| vec![(one.clone() / 2u32, one.clone() / 2u32), p.clone()])
        }
        Kind::EndValue(end, _) => [8u32, 32, 128].iter().find_map(|&n| {
            let delta = Rational::from((1, n));
            let (t0, t1, te) = if end {
                (1 - delta.clone(), one.clone(), one.clone())
            } else {
                (zero.clone(), delta.clone(), zero.clone())
            };
            // h does not increase towards the end on the slab (its
            // derivative may vanish at the end: branch and bound)
            let dx = d_variable(g, problem.domain);
            let towards = if end { -dx } else { dx };
            let slab: Cell = vec![(t0.clone(), t1.clone()), p.clone()];
            let edge: Cell = vec![(te.clone(), te.clone()), p.clone()];
            (matches!(
                branch::nonnegative(&towards, &part(problem.domain, &t0, &t1), &axis),
                Outcome::Proved { .. }
            ) && sign_on(&coords, &down, &edge, true, SIGN_DEPTH)
                && if end {
                    domain_ok(&zero, &t0)
                } else {
                    domain_ok(&t1, &one)
                })
            .then_some(slab)
        }),
        Kind::Stationary => [16u32, 64, 256, 1024].iter().find_map(|&n| {
            let delta = Rational::from((1, n));
            let t0 = Rational::from(&tau.0 - &delta).max(zero.clone());
            let t1 = Rational::from(&tau.1 + &delta).min(one.clone());
            let dt = coords.derivative(&hf, 0);
            let dtt = coords.derivative(&dt, 0);
            let slab: Cell = vec![(t0.clone(), t1.clone()), p.clone()];
            (t0 > zero
                && t1 < one
                && sign_on(&coords, &dtt, &slab, true, SIGN_DEPTH)
                && sign_on(&coords, &down, &slab, true, SIGN_DEPTH)
                && sign_on(
                    &coords,
                    &dt,
                    &vec![(t0.clone(), t0.clone()), p.clone()],
                    false,
                    SIGN_DEPTH,
                )
                && sign_on(
                    &coords,
                    &dt,
                    &vec![(t1.clone(), t1.clone()), p.clone()],
                    true,
                    SIGN_DEPTH,
                )
                && domain_ok(&zero, &t0)
                && domain_ok(&t1, &one))
            .then_some(slab)
        }),
    };
    let Some(slab) = slab else {
        return false;
    };
    // the other factors of one sign on the domain and nonzero where the
    // minimum lives (so f < 0 there beyond the root), the denominators of
    // one strict sign, the other functions ≥ 0
    let f = &problem.functions[function];
    let signed = |g: &Sym| match factors::sign_of(g, problem.domain, &axis, false) {
        Ok((sign, _)) => sign_on(
            &coords,
            &coords.function(g),
            &slab,
            sign == Sign::Plus,
            SIGN_DEPTH,
        ),
        Err(_) => false,
    };
    rest.iter().all(|(g, _)| signed(g))
        && f.denominator().keys().all(|g| {
            factors::sign_of(&Sym::from_poly(g.clone()), problem.domain, &axis, true).is_ok()
        })
        && problem
            .decided()
            .filter(|(j, _)| *j != function)
            .all(|(_, g)| {
                matches!(
                    factors::nonnegative(g, problem.domain, &axis),
                    Outcome::Proved { .. }
                )
            })
}
