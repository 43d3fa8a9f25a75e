//! The maximal interval of one shape parameter on which every function of
//! a basis is `≥ 0` on its whole domain, for bases the polynomial engine
//! ([`crate::range`]) does not take — the variable beside `sin` (C-curves),
//! `sinh`, `exp`, sines of the parameter, domains `[0, α]`, ranges in
//! multiples of π — with typed ends ([`End`]).
//!
//! From an admissible start, each direction is searched on a grid of
//! parameter values up to a limit, each value decided by a certified point
//! test (branch and bound in the variable, factor by factor). The first
//! value with a certified negative value brackets the end; then
//! * a value where the basis is not defined (a denominator vanishing
//!   identically, checked exactly at the simple values of the bracket) is
//!   an exact, open end;
//! * otherwise the end is certified where possible
//!   ([`crate::transcendental`]): the unique root of an exact equation in
//!   a rational enclosure, exact when the equation vanishes exactly at a
//!   simple value inside it;
//! * otherwise it stays a bracket, called so.
//!
//! Finally the part of the interval inside the ends is proved admissible
//! as a whole by branch and bound (open at ends where the basis is not
//! defined). Everything is counted work (boxes), never time.

use rug::Rational;
use trig_core::Domain;
use trig_symbolic::Sym;

use crate::algebraic::{Algebraic, decimal};
use crate::atoms::{param_atoms, reflect, value};
use crate::branch::{Axis, Outcome};
use crate::factors;
use crate::range::simplest_between;
use crate::transcendental::{Equation, certify_end, vanishing_end};

/// A parameter value where a function is certified negative at a point.
#[derive(Debug, Clone, PartialEq)]
pub struct Witness {
    /// The parameter (in units of π on a π axis).
    pub param: Rational,
    /// The function, by its index in the basis.
    pub function: usize,
    /// The point `x = a + Lτ`: `τ` exactly, `x` to f64.
    pub tau: Rational,
    pub x: f64,
    /// A certified enclosure of the value of the function's numerator
    /// (denominators of fixed sign taken out), `hi < 0`.
    pub value: (f64, f64),
}

/// The value of an exact end.
#[derive(Debug, Clone, PartialEq)]
pub enum ExactValue {
    /// A rational (in units of π on a π axis).
    Rational(Rational),
    /// A real algebraic number (a root of a polynomial factor in the
    /// parameter alone).
    Algebraic(Algebraic),
}

/// One end of the maximal interval.
#[derive(Debug, Clone, PartialEq)]
pub enum End {
    /// An exact end: the basis is not defined there (open), or an
    /// equation vanishes exactly there (closed when the functions are `≥ 0`
    /// at it).
    Exact {
        value: ExactValue,
        closed: bool,
        why: String,
        /// An admissible value next to it (proved with the interval).
        inside: Rational,
        /// The certified negative value just beyond it, when found.
        outside: Option<Witness>,
    },
    /// The unique root of `equation` in `[lo, hi]`, certified (a Krawczyk
    /// or interval Newton step), transcendental or at least not found
    /// exact: never called exact. The functions are `≥ 0` at the root
    /// (the end belongs to the interval).
    Certified {
        lo: Rational,
        hi: Rational,
        equation: Equation,
        inside: Rational,
        outside: Witness,
    },
    /// The end lies in `(ok, bad)`; it could not be certified (`why`).
    Bracket {
        ok: Rational,
        bad: Rational,
        outside: Witness,
        why: String,
    },
    /// Admissible at every value tested up to the search limit `upto`
    /// (the interval up to it proved as a whole): no end found.
    Beyond { upto: Rational },
    /// A point test could not be decided.
    Undecided { at: Rational, why: String },
}

impl End {
    /// The end as mathematics (no verdict): `symbol` names the parameter,
    /// `names` the functions; values in units of π on a π axis.
    pub fn describe(&self, problem: &Problem<'_>, symbol: &str, names: &[String]) -> String {
        let value = |q: &Rational| value_text(q, problem.pi);
        match self {
            End::Exact {
                value: ExactValue::Rational(v),
                closed,
                why,
                ..
            } => format!(
                "{symbol} = {} exactly ({}; {why})",
                value(v),
                if *closed { "included" } else { "excluded" }
            ),
            End::Exact {
                value: ExactValue::Algebraic(a),
                why,
                ..
            } => format!("{} (exact; {why})", a.describe(symbol, 12)),
            End::Certified {
                lo,
                hi,
                equation,
                inside,
                outside,
            } => {
                let enclosure = if problem.pi {
                    let (a, b) = times_pi(lo, hi);
                    format!(
                        "{symbol}/π ∈ [{}, {}], {symbol} ∈ [{}, {}]",
                        decimal(lo, DIGITS, false),
                        decimal(hi, DIGITS, true),
                        decimal(&a, DIGITS, false),
                        decimal(&b, DIGITS, true)
                    )
                } else {
                    format!(
                        "{symbol} ∈ [{}, {}]",
                        decimal(lo, DIGITS, false),
                        decimal(hi, DIGITS, true)
                    )
                };
                format!(
                    "the unique root of {} with {enclosure} (certified enclosure by a Krawczyk step, transcendental or at least not found exact: not called exact; included); just inside {symbol} = {} is admissible (proved), just outside {symbol} = {} {} < 0 at {} ≈ {:.6} (its numerator in [{:.6e}, {:.6e}], certified)",
                    equation.describe(problem.domain, names),
                    value(inside),
                    value(&outside.param),
                    names[outside.function],
                    problem.domain.name,
                    outside.x,
                    outside.value.0,
                    outside.value.1
                )
            }
            End::Bracket { ok, bad, why, .. } => format!(
                "between {} and {} (a bracket, not certified: {why})",
                value(ok),
                value(bad)
            ),
            End::Beyond { upto } => format!(
                "not below {}: every value up to the search limit {} is admissible",
                value(upto),
                value(upto)
            ),
            End::Undecided { at, why } => {
                format!("not decided (at {symbol} = {}: {why})", value(at))
            }
        }
    }
}

/// Decimal digits of a certified enclosure as printed (rounded outward).
const DIGITS: usize = 24;

/// `[lo·π, hi·π]` enclosed by rationals (π between two 256-bit floats).
fn times_pi(lo: &Rational, hi: &Rational) -> (Rational, Rational) {
    use rug::Float;
    use rug::float::{Constant, Round};
    let bound = |round| {
        Float::with_val_round(256, Constant::Pi, round)
            .0
            .to_rational()
            .expect("π is finite")
    };
    let (p_lo, p_hi) = (bound(Round::Down), bound(Round::Up));
    let products = [
        Rational::from(lo * &p_lo),
        Rational::from(lo * &p_hi),
        Rational::from(hi * &p_lo),
        Rational::from(hi * &p_hi),
    ];
    let min = products.iter().min().cloned().unwrap_or_default();
    let max = products.iter().max().cloned().unwrap_or_default();
    (min, max)
}

/// `q`, or `q·π` on a π axis.
pub fn value_text(q: &Rational, pi: bool) -> String {
    if pi {
        format!("{q}·π")
    } else {
        q.to_string()
    }
}

/// The maximal interval around a start.
#[derive(Debug, Clone, PartialEq)]
pub struct AnalyticRange {
    pub start: Rational,
    /// Why the start is not admissible (then nothing else was searched).
    pub start_outside: Option<Outside>,
    pub lo: End,
    pub hi: End,
    /// The proof of the part inside the ends (all functions, one box of
    /// parameters): `Proved` with its boxes, or why not.
    pub inside: Outcome,
}

/// Why a parameter value is not (known to be) admissible.
#[derive(Debug, Clone, PartialEq)]
pub enum Outside {
    Negative(Witness),
    /// A denominator vanishes identically there: the basis is not defined.
    Undefined,
    Undecided(String),
}

/// What the search works on.
#[derive(Debug)]
pub struct Problem<'a> {
    pub functions: &'a [Sym],
    pub domain: &'a Domain,
    /// The parameter is measured in units of π.
    pub pi: bool,
    /// `mirror[j] = Some(k)`, `k < j`, when `f_j(x) = f_k(a + b − x)`
    /// exactly: the reflection maps the domain onto itself, so `f_j ≥ 0`
    /// exactly when `f_k ≥ 0`, and `f_j` is not decided again.
    mirror: Vec<Option<usize>>,
}

impl<'a> Problem<'a> {
    /// The functions of a basis on `domain`, one parameter (in units of π
    /// when `pi`).
    pub fn new(functions: &'a [Sym], domain: &'a Domain, pi: bool) -> Problem<'a> {
        let mirror = (0..functions.len())
            .map(|j| {
                let r = reflect(&functions[j], domain)?;
                (0..j).find(|&k| r == functions[k])
            })
            .collect();
        Problem {
            functions,
            domain,
            pi,
            mirror,
        }
    }

    /// The parameter value where the domain shrinks to a point
    /// (`b(p) − a(p) = 0`), when it depends on the parameter and the value
    /// is exact in the axis' units.
    pub fn empty_domain_at(&self) -> Option<Rational> {
        let d = self.domain;
        let length = d.end.plus(&d.start.scale(&Rational::from(-1)));
        let q = length.params.iter().find(|(i, _)| *i == 0)?.1.clone();
        if q == 0 {
            return None;
        }
        // length = constant + π·pi + q·p, p = π·y on a π axis
        let root = if self.pi {
            (length.constant == 0).then(|| -Rational::from(&length.pi / &q))
        } else {
            (length.pi == 0).then(|| -Rational::from(&length.constant / &q))
        }?;
        Some(root)
    }

    /// The functions to decide (a mirror image of an earlier one is not).
    pub(crate) fn decided(&self) -> impl Iterator<Item = (usize, &Sym)> {
        self.functions
            .iter()
            .enumerate()
            .filter(|(j, _)| self.mirror[*j].is_none())
    }

    /// The single-parameter axis `[lo, hi]`.
    pub fn axis(&self, lo: &Rational, hi: &Rational, lo_open: bool, hi_open: bool) -> Vec<Axis> {
        vec![Axis {
            lo: lo.clone(),
            hi: hi.clone(),
            lo_open,
            hi_open,
            pi: self.pi,
        }]
    }

    /// All functions `≥ 0` at the parameter value `p`, or why not.
    pub fn admissible(&self, p: &Rational) -> Result<(), Outside> {
        if self.undefined_at(p) {
            return Err(Outside::Undefined);
        }
        let axis = self.axis(p, p, false, false);
        for (i, f) in self.decided() {
            match factors::nonnegative(f, self.domain, &axis) {
                Outcome::Proved { .. } => {}
                Outcome::Negative { tau, x, value, .. } => {
                    return Err(Outside::Negative(Witness {
                        param: p.clone(),
                        function: i,
                        tau,
                        x,
                        value,
                    }));
                }
                Outcome::Undecided(why) => return Err(Outside::Undecided(why)),
            }
        }
        Ok(())
    }

    /// True when a denominator factor of some function vanishes
    /// identically at `p` (the parameter and its atoms substituted
    /// exactly; `false` when an atom is not exact there).
    pub fn undefined_at(&self, p: &Rational) -> bool {
        let atoms = param_atoms(self.domain);
        let at = [if self.pi {
            Sym::rational(p.clone()) * &Sym::pi()
        } else {
            Sym::rational(p.clone())
        }];
        let symbols = trig_symbolic::symbolic_atoms();
        let name = &self.domain.param_names[0];
        self.functions.iter().any(|f| {
            f.denominator().keys().any(|factor| {
                let mut v = Sym::from_poly(factor.clone()).subs(name, &at[0]);
                for a in atoms.iter().filter(|a| a.param == 0) {
                    if !v.variables().contains(&a.name) {
                        continue;
                    }
                    match value(&a.name, self.domain, &symbols, &at, &atoms) {
                        Some(e) => v = v.subs(&a.name, &e),
                        None => return false,
                    }
                }
                v.is_zero()
            })
        })
    }

    /// The proof that every function is `≥ 0` for the parameter in the
    /// axis (factor by factor), with the total boxes.
    pub fn prove(&self, axis: &[Axis]) -> Outcome {
        let mut boxes = 0;
        for (_, f) in self.decided() {
            match factors::nonnegative(f, self.domain, axis) {
                Outcome::Proved { boxes: b } => boxes += b,
                other => return other,
            }
        }
        Outcome::Proved { boxes }
    }
}

/// Grid steps from the start to each limit.
const STEPS: u32 = 16;
/// Bisections of a bracket before the end is certified.
const BISECTIONS: usize = 12;

/// The maximal interval containing `start` on which every function is
/// `≥ 0`, searched down to `lo_limit` and up to `hi_limit`.
pub fn maximal_range(
    problem: &Problem<'_>,
    start: &Rational,
    lo_limit: &Rational,
    hi_limit: &Rational,
) -> AnalyticRange {
    if let Err(o) = problem.admissible(start) {
        let und = End::Undecided {
            at: start.clone(),
            why: "the start is not admissible".into(),
        };
        return AnalyticRange {
            start: start.clone(),
            start_outside: Some(o),
            lo: und.clone(),
            hi: und,
            inside: Outcome::Undecided("the start is not admissible".into()),
        };
    }
    // the search stops where the domain shrinks to a point
    let empty = problem.empty_domain_at();
    let clamp = |limit: &Rational, dir: i32| -> (Rational, bool) {
        match &empty {
            Some(e)
                if (dir < 0 && e > limit && e < start) || (dir > 0 && e < limit && e > start) =>
            {
                (e.clone(), true)
            }
            _ => (limit.clone(), false),
        }
    };
    let (lo_limit, lo_empty) = clamp(lo_limit, -1);
    let (hi_limit, hi_empty) = clamp(hi_limit, 1);
    let lo = search(problem, start, &lo_limit, -1, lo_empty);
    let hi = search(problem, start, &hi_limit, 1, hi_empty);
    let inside = match (inner(&lo), inner(&hi)) {
        (Some((a, a_open)), Some((b, b_open))) => {
            problem.prove(&problem.axis(&a, &b, a_open, b_open))
        }
        _ => Outcome::Undecided("an end was not decided".into()),
    };
    AnalyticRange {
        start: start.clone(),
        start_outside: None,
        lo,
        hi,
        inside,
    }
}

/// The inner bound of an end for the final proof: `(value, open)`.
fn inner(e: &End) -> Option<(Rational, bool)> {
    match e {
        End::Exact {
            value: ExactValue::Rational(v),
            closed,
            ..
        } => Some((v.clone(), !closed)),
        End::Exact { inside, .. } | End::Certified { inside, .. } => Some((inside.clone(), false)),
        End::Bracket { ok, .. } => Some((ok.clone(), false)),
        End::Beyond { upto } => Some((upto.clone(), false)),
        End::Undecided { .. } => None,
    }
}

/// The grid value `k` of `STEPS` from `start` to `limit`.
fn grid(start: &Rational, limit: &Rational, k: u32) -> Rational {
    start.clone() + Rational::from(limit - start) * Rational::from((k, STEPS))
}

/// The end in direction `dir` (−1 down, +1 up), searched up to `limit`
/// (where the domain shrinks to a point when `empty`).
fn search(problem: &Problem<'_>, start: &Rational, limit: &Rational, dir: i32, empty: bool) -> End {
    let mut ok = start.clone();
    for k in 1..=STEPS {
        let q = grid(start, limit, k);
        if empty && k == STEPS {
            return End::Exact {
                value: ExactValue::Rational(q),
                closed: false,
                why: "the domain shrinks to a point there (and is reversed beyond)".into(),
                inside: ok,
                outside: None,
            };
        }
        match problem.admissible(&q) {
            Ok(()) => ok = q,
            Err(Outside::Negative(w)) => return refine(problem, ok, w, dir),
            Err(Outside::Undefined) => {
                let beyond = grid(start, limit, k) + Rational::from((dir, 1_000_000));
                return End::Exact {
                    value: ExactValue::Rational(q),
                    closed: false,
                    why: "the basis is not defined there (a denominator vanishes identically)"
                        .into(),
                    inside: ok,
                    outside: match problem.admissible(&beyond) {
                        Err(Outside::Negative(w)) => Some(w),
                        _ => None,
                    },
                };
            }
            Err(Outside::Undecided(why)) => return End::Undecided { at: q, why },
        }
    }
    End::Beyond {
        upto: limit.clone(),
    }
}

/// Simple values in the open interval between `a` and `b`: the simplest
/// rational and, on a π axis, the multiples of 1/12 (π/12).
fn simple_values(a: &Rational, b: &Rational, pi: bool) -> Vec<Rational> {
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    let mut out = Vec::new();
    if pi {
        let mut k = Rational::from(lo * 12u32).floor() + 1u32;
        while Rational::from(&k / 12u32) < *hi && out.len() < 64 {
            out.push(Rational::from(&k / 12u32));
            k += 1u32;
        }
    }
    let s = simplest_between(lo, hi);
    if s > *lo && s < *hi && !out.contains(&s) {
        out.push(s);
    }
    out
}

/// The end inside the bracket `(ok, bad)` (`bad` with its witness).
fn refine(problem: &Problem<'_>, mut ok: Rational, mut w: Witness, dir: i32) -> End {
    // a value where the basis is not defined is the end, exactly
    if let Some(q) = simple_values(&ok, &w.param, problem.pi)
        .into_iter()
        .find(|q| problem.undefined_at(q))
    {
        return End::Exact {
            value: ExactValue::Rational(q),
            closed: false,
            why: "the basis is not defined there (a denominator vanishes identically)".into(),
            inside: ok,
            outside: Some(w),
        };
    }
    for _ in 0..BISECTIONS {
        let mid = Rational::from(&ok + &w.param) / 2u32;
        match problem.admissible(&mid) {
            Ok(()) => ok = mid,
            Err(Outside::Negative(v)) => w = v,
            Err(Outside::Undefined) => {
                return End::Exact {
                    value: ExactValue::Rational(mid),
                    closed: false,
                    why: "the basis is not defined there (a denominator vanishes identically)"
                        .into(),
                    inside: ok,
                    outside: Some(w),
                };
            }
            Err(Outside::Undecided(_)) => break,
        }
    }
    let candidates = simple_values(&ok, &w.param, problem.pi);
    if let Some(end) = vanishing_end(problem, &ok, &w, dir, &candidates) {
        return end;
    }
    match certify_end(problem, &ok, &w, dir) {
        Ok(end) => end,
        Err(why) => End::Bracket {
            bad: w.param.clone(),
            ok,
            outside: w,
            why,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{q, zero_to_pi};
    use crate::transcendental::Equation;
    use trig_core::Affine;

    #[test]
    fn an_end_at_a_tangency_is_certified_and_an_exact_end_is_exact() {
        // b0 = 1 − λ t sin t, b1 = λ t sin t on [0, π]: admissible exactly
        // for λ ∈ [0, 1/M], M = max t sin t = t* sin t*, tan t* = −t*
        // (examples/independent/transcendental-end.py: 1/M = 0.5495393…)
        let d = zero_to_pi();
        let g = Sym::var("lambda") * &Sym::var("t") * &Sym::var("s");
        let fs = [Sym::one() - &g, g];
        let p = Problem::new(&fs, &d, false);
        let r = maximal_range(&p, &q(1, 4), &q(-1, 1), &q(1, 1));
        assert!(matches!(r.inside, Outcome::Proved { .. }), "{:?}", r.inside);
        match &r.hi {
            End::Certified {
                lo, hi, outside, ..
            } => {
                assert!(lo.to_f64() < 0.549_539_4 && hi.to_f64() > 0.549_539_3);
                assert!(Rational::from(hi - lo) < q(1, 1_000_000_000));
                assert!(outside.value.1 < 0.0 && outside.param > *hi);
            }
            other => panic!("{other:?}"),
        }
        match &r.lo {
            End::Exact { value, closed, .. } => {
                assert_eq!(value, &ExactValue::Rational(q(0, 1)));
                assert!(closed);
            }
            other => panic!("{other:?}"),
        }
    }

    /// `t ∈ [0, α]` with `s, c = sin t, cos t` and `sin α`, `cos α`.
    fn c_curve() -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: Some(Affine::rational(q(1, 1))),
            uses_variable: true,
            exp: None,
            param_angles: vec![(0, q(1, 1))],
            param_exps: Vec::new(),
        }
    }

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    #[test]
    fn an_end_value_is_certified_where_tan_alpha_equals_alpha() {
        // sin t − t cos α ≥ 0 on [0, α] until sin α = α cos α: α* = 4.4934094579…
        // (examples/independent/transcendental-end.py)
        let d = c_curve();
        let f = v("s") - &(v("t") * &v("cos(alpha)"));
        let fs = [f];
        let p = Problem::new(&fs, &d, false);
        let r = maximal_range(&p, &q(1, 1), &q(1, 2), &q(6, 1));
        assert!(matches!(r.inside, Outcome::Proved { .. }), "{:?}", r.inside);
        match &r.hi {
            End::Certified {
                lo,
                hi,
                equation: Equation::EndValue { value, at_end, .. },
                ..
            } => {
                assert!(lo.to_f64() < 4.493_409_458 && hi.to_f64() > 4.493_409_457);
                assert!(*at_end);
                assert_eq!(value.to_string(), "-alpha*cos(alpha) + sin(alpha)");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn quadratic_c_bezier_ends_exactly_at_pi_where_b1_vanishes() {
        // BVP 2022 eq. (2); examples/independent/README.md C2: (0, π], b1 ≡ 0 at π
        let d = c_curve();
        let (sa, ca) = (v("sin(alpha)"), v("cos(alpha)"));
        let (s, c) = (v("s"), v("c"));
        let one = Sym::one();
        let c_at = ca.clone() * &c + &(sa.clone() * &s);
        let den = one.clone() - &ca;
        let fs = [
            (one.clone() - &c_at) / &den,
            -((one.clone() - &c + &ca - &c_at) / &den),
            (one.clone() - &c) / &den,
        ];
        let p = Problem::new(&fs, &d, true);
        let r = maximal_range(&p, &q(1, 2), &q(0, 1), &q(2, 1));
        assert!(matches!(r.inside, Outcome::Proved { .. }), "{:?}", r.inside);
        match &r.hi {
            End::Exact {
                value,
                closed: true,
                outside: Some(w),
                ..
            } => {
                assert_eq!(value, &ExactValue::Rational(q(1, 1)));
                assert!(w.value.1 < 0.0 && w.param > q(1, 1));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn c_bezier_cubic_is_admissible_exactly_on_zero_two_pi() {
        // Zhang 1996; examples/independent/c-bezier-cubic.py (B1): (0, 2π)
        let d = c_curve();
        let (a, sa, ca) = (v("alpha"), v("sin(alpha)"), v("cos(alpha)"));
        let (t, s, c) = (v("t"), v("s"), v("c"));
        let one = Sym::one();
        // sin(α − t), cos(α − t)
        let s_at = sa.clone() * &c - &(ca.clone() * &s);
        let c_at = ca.clone() * &c + &(sa.clone() * &s);
        let big_a = a.clone() - &sa;
        let g = Sym::int(2) - &(Sym::int(2) * &ca) - &(a.clone() * &sa);
        let n = |cos_tau: &Sym, tau: &Sym, sin_tau: &Sym| {
            big_a.clone() * &(one.clone() - cos_tau)
                - &((one.clone() - &ca) * &(tau.clone() - sin_tau))
        };
        let u = a.clone() - &t;
        let fs = [
            (u.clone() - &s_at) / &big_a,
            (one.clone() - &ca) * &n(&c_at, &u, &s_at) / &(big_a.clone() * &g),
            (one.clone() - &ca) * &n(&c, &t, &s) / &(big_a.clone() * &g),
            (t.clone() - &s) / &big_a,
        ];
        let p = Problem::new(&fs, &d, true);
        let r = maximal_range(&p, &q(1, 2), &q(0, 1), &q(4, 1));
        assert!(matches!(r.inside, Outcome::Proved { .. }), "{:?}", r.inside);
        for (end, at) in [(&r.lo, q(0, 1)), (&r.hi, q(2, 1))] {
            match end {
                End::Exact {
                    value,
                    closed: false,
                    ..
                } => assert_eq!(value, &ExactValue::Rational(at)),
                other => panic!("{other:?}"),
            }
        }
        // beyond 2π a certified negative value
        assert!(matches!(&r.hi, End::Exact { outside: Some(w), .. } if w.value.1 < 0.0));
    }
}
