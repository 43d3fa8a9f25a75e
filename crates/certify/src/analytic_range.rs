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

pub use crate::analytic_end::{End, Equation, ExactValue, Outside, Problem, Witness, value_text};
use crate::branch::Outcome;
use crate::coordinates::Axis;
use crate::range::simplest_between;
use crate::transcendental::{certify_end, vanishing_end};

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
    /// The part of the inside that the caller had proved already (then
    /// `inside` counts the boxes of the rest only).
    pub inside_given: Option<Axis>,
}

/// Grid steps from the start to each limit.
const STEPS: u32 = 16;
/// Bisections of a bracket before the end is certified.
const BISECTIONS: usize = 12;

/// The maximal interval containing `start` on which every function is
/// `≥ 0`, searched down to `lo_limit` and up to `hi_limit`. `proved`: a
/// parameter interval on which the caller has proved every function `≥ 0`
/// already (the printed range): only the part of the inside beyond it is
/// proved again.
pub fn maximal_range(
    problem: &Problem<'_>,
    start: &Rational,
    lo_limit: &Rational,
    hi_limit: &Rational,
    proved: Option<&Axis>,
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
            inside_given: None,
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
    let (inside, inside_given) = match (inner(&lo), inner(&hi)) {
        (Some((a, a_open)), Some((b, b_open))) => {
            let whole = &problem.axis(&a, &b, a_open, b_open)[0];
            match proved.filter(|p| covers_most(whole, p)) {
                Some(p) => (prove_beyond(problem, whole, p), Some(p.clone())),
                None => (problem.prove(std::slice::from_ref(whole)), None),
            }
        }
        _ => (Outcome::Undecided("an end was not decided".into()), None),
    };
    AnalyticRange {
        start: start.clone(),
        start_outside: None,
        lo,
        hi,
        inside,
        inside_given,
    }
}

/// True when `given` covers most of `whole`: they share an interval wider
/// than the rest of `whole` (else proving the rest is no cheaper than
/// proving the whole).
fn covers_most(whole: &Axis, given: &Axis) -> bool {
    let top = (&whole.hi).min(&given.hi);
    let bottom = (&whole.lo).max(&given.lo);
    let shared = Rational::from(top - bottom);
    let rest = Rational::from(&whole.hi - &whole.lo) - &shared;
    whole.pi == given.pi && shared > 0 && shared > rest
}

/// The proof of `whole` where `given` (proved, overlapping it) does not
/// reach: the pieces below and above `given`, each closed where it meets
/// `given` (a shared end point is proved twice, never missed).
fn prove_beyond(problem: &Problem<'_>, whole: &Axis, given: &Axis) -> Outcome {
    let mut pieces = Vec::new();
    if whole.lo < given.lo || (whole.lo == given.lo && given.lo_open && !whole.lo_open) {
        pieces.push((whole.lo.clone(), given.lo.clone(), whole.lo_open, false));
    }
    if whole.hi > given.hi || (whole.hi == given.hi && given.hi_open && !whole.hi_open) {
        pieces.push((given.hi.clone(), whole.hi.clone(), false, whole.hi_open));
    }
    let mut boxes = 0;
    for (lo, hi, lo_open, hi_open) in pieces {
        match problem.prove(&problem.axis(&lo, &hi, lo_open, hi_open)) {
            Outcome::Proved { boxes: b } => boxes += b,
            other => return other,
        }
    }
    Outcome::Proved { boxes }
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
    use trig_core::{Affine, Domain};
    use trig_symbolic::Sym;

    #[test]
    fn an_end_at_a_tangency_is_certified_and_an_exact_end_is_exact() {
        // b0 = 1 − λ t sin t, b1 = λ t sin t on [0, π]: admissible exactly
        // for λ ∈ [0, 1/M], M = max t sin t = t* sin t*, tan t* = −t*
        // (examples/independent/transcendental-end.py: 1/M = 0.5495393…)
        let d = zero_to_pi();
        let g = Sym::var("lambda") * &Sym::var("t") * &Sym::var("s");
        let fs = [Sym::one() - &g, g];
        let p = Problem::new(&fs, &d, false);
        let r = maximal_range(&p, &q(1, 4), &q(-1, 1), &q(1, 1), None);
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
        let r = maximal_range(&p, &q(1, 1), &q(1, 2), &q(6, 1), None);
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
        let r = maximal_range(&p, &q(1, 2), &q(0, 1), &q(2, 1), None);
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
        // with the printed range (0, π] proved by the caller, the inside
        // is not proved again; with a proved part smaller than the rest,
        // the whole is proved
        let given = |lo: (i64, i64), hi: (i64, i64)| Axis {
            lo: q(lo.0, lo.1),
            hi: q(hi.0, hi.1),
            lo_open: true,
            hi_open: false,
            pi: true,
        };
        let printed = given((0, 1), (1, 1));
        let reused = maximal_range(&p, &q(1, 2), &q(0, 1), &q(2, 1), Some(&printed));
        assert_eq!(reused.inside, Outcome::Proved { boxes: 0 });
        assert_eq!(reused.inside_given, Some(printed));
        assert_eq!((reused.lo, reused.hi), (r.lo.clone(), r.hi.clone()));
        let narrow = maximal_range(
            &p,
            &q(1, 2),
            &q(0, 1),
            &q(2, 1),
            Some(&given((1, 4), (1, 2))),
        );
        assert_eq!((narrow.inside, narrow.inside_given), (r.inside, None));
    }

    #[test]
    fn the_rest_beyond_a_proved_interval_is_proved_piece_by_piece() {
        // b = α − t on t ∈ [0, 1]: ≥ 0 exactly for α ≥ 1; with [1, 3] proved
        // the rest of [2, 4] is [3, 4] (proved), of [1/2, 2] it is [1/2, 1] (refuted)
        let d = Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::rational(q(1, 1)),
            angle: None,
            uses_variable: true,
            exp: None,
            param_angles: Vec::new(),
            param_exps: Vec::new(),
        };
        let fs = [v("alpha") - &v("t")];
        let p = Problem::new(&fs, &d, false);
        let axis = |a: (i64, i64), b: (i64, i64)| Axis {
            lo: q(a.0, a.1),
            hi: q(b.0, b.1),
            lo_open: false,
            hi_open: false,
            pi: false,
        };
        let whole = axis((2, 1), (4, 1));
        assert!(matches!(
            prove_beyond(&p, &whole, &axis((1, 1), (3, 1))),
            Outcome::Proved { boxes } if boxes > 0
        ));
        assert_eq!(
            prove_beyond(&p, &whole, &axis((1, 1), (5, 1))),
            Outcome::Proved { boxes: 0 }
        );
        assert!(!matches!(
            prove_beyond(&p, &axis((1, 2), (2, 1)), &axis((1, 1), (3, 1))),
            Outcome::Proved { .. }
        ));
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
        let r = maximal_range(&p, &q(1, 2), &q(0, 1), &q(4, 1), None);
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
