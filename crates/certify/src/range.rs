//! The maximal interval of a shape parameter on which every function of a
//! basis is nonnegative on its whole domain, with its ends proved.
//!
//! 1. The start must be admissible: a certified point test, else the
//!    search stops with the counterexample ([`MaximalRange::start`]).
//! 2. Every end of the admissible set is a root of a boundary polynomial
//!    ([`crate::boundary`]). Their real roots beyond the start are isolated
//!    exactly (Sturm); between consecutive roots admissibility cannot
//!    change, so one certified point test per gap decides each gap. The
//!    end is the root before the first inadmissible gap: an exact real
//!    algebraic number ([`Algebraic`]), included when it is admissible
//!    (a point test when rational; by closedness when irrational and no
//!    pole enters there). If every gap is admissible, the end is infinite.
//! 3. When no boundary polynomial can be computed, each end is bracketed by
//!    certified point tests and bisection, and reported as a bracket.
//!
//! The closed part of the interval is then certified as a whole by
//! Bernstein subdivision, a cross-check of the gap argument.

use rug::Rational;
use trig_symbolic::Sym;

use crate::algebraic::Algebraic;
use crate::boundary::{Candidate, candidates};
use crate::domain::{Bound, ParamBox};
use crate::nonneg::{Certificate, certify};
use crate::sturm::UPoly;

/// Why a parameter value is not (known to be) admissible.
#[derive(Debug, Clone, PartialEq)]
pub enum Outside {
    /// An exact counterexample `(p, z, value)`, `value < 0`.
    Counterexample(Rational, Rational, Rational),
    /// A function has a pole in the domain at `p` (exact witness text).
    Pole(Rational, String),
    /// Not certified either way at `p` (depth limit).
    Undecided(Rational),
}

/// One end of the maximal interval.
#[derive(Debug, Clone, PartialEq)]
pub enum EndPoint {
    /// The proved end: a root of the boundary polynomial, with a certified
    /// admissible point `inside` before it and the inadmissible `outside`
    /// beyond it (both in the gaps next to the end).
    Exact {
        value: Algebraic,
        closed: bool,
        inside: Rational,
        outside: Outside,
    },
    /// The end lies in `(ok, bad)`; no exact end could be computed (`why`).
    Bracket {
        ok: Rational,
        bad: Rational,
        outside: Outside,
        why: String,
    },
    /// No end: admissible all the way (proved by the gap tests, or by a
    /// certificate on the half-line).
    Unbounded,
    /// The search could not be completed: the decision at `at` failed.
    Undecided { at: Rational, why: String },
}

impl EndPoint {
    /// The end as a bound when it is exact and rational, or infinite.
    pub fn rational_bound(&self) -> Option<Bound> {
        match self {
            EndPoint::Exact {
                value,
                closed: true,
                ..
            } => value.rational.clone().map(Bound::Closed),
            EndPoint::Exact {
                value,
                closed: false,
                ..
            } => value.rational.clone().map(Bound::Open),
            EndPoint::Unbounded => Some(Bound::Infinite),
            _ => None,
        }
    }

    /// True when the end is proved (exact or infinite).
    pub fn is_proved(&self) -> bool {
        matches!(self, EndPoint::Exact { .. } | EndPoint::Unbounded)
    }
}

/// The maximal interval around a starting value, with its certificate.
#[derive(Debug, Clone, PartialEq)]
pub struct MaximalRange {
    pub start: Rational,
    /// `Some` when the start itself is not admissible (then the ends are
    /// `Undecided` and nothing else was searched).
    pub start_outside: Option<Outside>,
    pub lo: EndPoint,
    pub hi: EndPoint,
    /// The boundary polynomials used (empty when they could not be
    /// computed; then the ends are brackets).
    pub boundary: Vec<UPoly>,
    /// The certificate over the closed rational part of the interval.
    pub certificate: Certificate,
}

/// All functions nonnegative at the single parameter value `p`, or why not.
pub fn point(fs: &[Sym], trig: bool, param: &str, p: &Rational) -> Result<(), Outside> {
    for f in fs {
        match certify(f, trig, Some(param), &ParamBox::point(p.clone())) {
            Certificate::NonNegative { .. } => {}
            Certificate::Counterexample { p, z, value } => {
                return Err(Outside::Counterexample(p, z, value));
            }
            Certificate::Pole(why) => return Err(Outside::Pole(p.clone(), why)),
            Certificate::Undecided(_) => return Err(Outside::Undecided(p.clone())),
        }
    }
    Ok(())
}

/// The simplest rational (smallest denominator) in `[a, b]`, `a ≤ b`, by
/// the Stern–Brocot descent on continued fractions.
pub fn simplest_between(a: &Rational, b: &Rational) -> Rational {
    if a < &Rational::new() && b > &Rational::new() {
        return Rational::new();
    }
    if b < &Rational::new() {
        return -simplest_between(&-b.clone(), &-a.clone());
    }
    let c = a.clone().ceil();
    if c <= *b {
        return c;
    }
    let fl = a.clone().floor();
    let frac_a = a.clone() - &fl;
    let frac_b = b.clone() - &fl;
    let inner = simplest_between(&(Rational::from(1) / frac_b), &(Rational::from(1) / frac_a));
    fl + Rational::from(1) / inner
}

/// The real roots of the boundary polynomials strictly beyond `start` in
/// direction `dir`, nearest first, as disjoint isolating intervals, each
/// with whether a pole candidate has it.
fn roots_beyond(polys: &[(UPoly, bool)], start: &Rational, dir: i32) -> Vec<(Algebraic, bool)> {
    let mut roots: Vec<(Algebraic, bool)> = Vec::new();
    for (p, pole) in polys {
        let bound = p.root_bound();
        let (a, b) = if dir > 0 {
            (start.clone(), start.clone().abs() + &bound)
        } else {
            (-(start.clone().abs() + &bound), start.clone())
        };
        for (lo, hi) in p.isolate(&a, &b) {
            roots.push((Algebraic::new(p, lo, hi), *pole));
        }
    }
    // distinct polynomials of a coprime basis have distinct roots: refine
    // overlapping intervals until they separate
    loop {
        roots.sort_by(|x, y| x.0.lo.cmp(&y.0.lo));
        let overlap = (1..roots.len()).find(|&i| roots[i].0.lo <= roots[i - 1].0.hi);
        let Some(i) = overlap else { break };
        for k in [i - 1, i] {
            let w = Rational::from(&roots[k].0.hi - &roots[k].0.lo) / 2u32;
            roots[k].0.refine(&w);
        }
    }
    if dir < 0 {
        roots.reverse();
    }
    roots
}

/// A coprime squarefree basis of the boundary polynomials in `param`.
fn coprime_basis(cands: &[Candidate], param: &str) -> Option<Vec<(UPoly, bool)>> {
    let mut basis: Vec<(UPoly, bool)> = Vec::new();
    for c in cands {
        let p = UPoly::from_poly(&c.poly, param)?.squarefree();
        let mut p = p;
        let mut next = Vec::new();
        for (b, pole) in basis {
            let g = p.gcd(&b);
            if g.degree() > 0 {
                p = p.div_rem(&g).0;
                let rest = b.div_rem(&g).0;
                if rest.degree() > 0 {
                    next.push((rest, pole));
                }
                next.push((g, pole || c.pole));
            } else {
                next.push((b, pole));
            }
        }
        if p.degree() > 0 {
            next.push((p, c.pole));
        }
        basis = next;
    }
    Some(basis)
}

/// A rational strictly between two isolated roots (or beyond the last):
/// the simplest one, unless that is a root isolated as a point.
fn gap_point(after: &Algebraic, before: Option<&Algebraic>, dir: i32) -> Rational {
    let Some(b) = before else {
        return if dir > 0 {
            after.hi.clone().ceil() + 1u32
        } else {
            after.lo.clone().floor() - 1u32
        };
    };
    let (lo, hi) = if dir > 0 {
        (&after.hi, &b.lo)
    } else {
        (&b.hi, &after.lo)
    };
    let q = simplest_between(lo, hi);
    let is_root = |x: &Rational| [after, b].iter().any(|r| r.rational.as_ref() == Some(x));
    if is_root(&q) {
        Rational::from(lo + hi) / 2u32
    } else {
        q
    }
}

/// The end in direction `dir` from an admissible `start`, by gap tests.
fn exact_end(
    fs: &[Sym],
    trig: bool,
    param: &str,
    start: &Rational,
    basis: &[(UPoly, bool)],
    dir: i32,
) -> EndPoint {
    let roots = roots_beyond(basis, start, dir);
    // The start may itself be a boundary root (a function identically zero
    // there, as (1 + λ)(…) at λ = −1): admissibility may change at the
    // start, so the gap just beyond it is tested first.
    if let Some((p, _)) = basis.iter().find(|(p, _)| p.sign_at(start) == 0) {
        let at_start = Algebraic::new(p, start.clone(), start.clone());
        let q = gap_point(&at_start, roots.first().map(|r| &r.0), dir);
        match point(fs, trig, param, &q) {
            Ok(()) => {}
            Err(Outside::Undecided(at)) => {
                return EndPoint::Undecided {
                    at,
                    why: "the point test next to the start (a boundary root) was not decided"
                        .into(),
                };
            }
            Err(outside) => {
                return EndPoint::Exact {
                    value: at_start,
                    closed: true,
                    inside: start.clone(),
                    outside,
                };
            }
        }
    }
    let mut inside = start.clone();
    for (k, (root, pole)) in roots.iter().enumerate() {
        // the gap before this root was admissible; test the one after it
        let q = gap_point(root, roots.get(k + 1).map(|r| &r.0), dir);
        match point(fs, trig, param, &q) {
            Ok(()) => inside = q,
            Err(Outside::Undecided(at)) => {
                return EndPoint::Undecided {
                    at,
                    why: "the point test beyond a boundary root was not decided".into(),
                };
            }
            Err(outside) => {
                let mut value = root.clone();
                value.refine(&Rational::from((1, 1_000_000_000_000_000i64)));
                let closed = match &value.rational {
                    Some(r) => point(fs, trig, param, r).is_ok(),
                    None if *pole => {
                        return EndPoint::Undecided {
                            at: value.lo.clone(),
                            why: "a pole may enter at the irrational end".into(),
                        };
                    }
                    None => true,
                };
                // the witnesses are the gap points: the simplest rationals of
                // the gaps next to the end, where admissibility is constant
                return EndPoint::Exact {
                    value,
                    closed,
                    inside,
                    outside,
                };
            }
        }
    }
    EndPoint::Unbounded
}

/// The end by bracketing and bisection (no boundary polynomial): a
/// counterexample far out comes from a certificate on the half-line.
fn bracketed_end(
    fs: &[Sym],
    trig: bool,
    param: &str,
    start: &Rational,
    dir: i32,
    why: &str,
) -> EndPoint {
    let half_line = if dir > 0 {
        ParamBox::from_closed(start.clone())
    } else {
        ParamBox::up_to(start.clone())
    };
    let mut bad = None;
    for f in fs {
        match certify(f, trig, Some(param), &half_line) {
            Certificate::NonNegative { .. } => {}
            Certificate::Counterexample { p, .. } => {
                bad = Some(p);
                break;
            }
            Certificate::Pole(_) | Certificate::Undecided(_) => {
                return EndPoint::Undecided {
                    at: start.clone(),
                    why: format!("the half-line from {start} was not decided"),
                };
            }
        }
    }
    let Some(mut bad) = bad else {
        return EndPoint::Unbounded;
    };
    let mut ok = start.clone();
    let tiny = Rational::from((1, 10_000_000_000_000i64));
    while Rational::from(&bad - &ok).abs() > tiny {
        let mid = Rational::from(&ok + &bad) / 2u32;
        match point(fs, trig, param, &mid) {
            Ok(()) => ok = mid,
            Err(Outside::Undecided(at)) => {
                return EndPoint::Undecided {
                    at,
                    why: "bisection met an undecided point".into(),
                };
            }
            Err(_) => bad = mid,
        }
    }
    match point(fs, trig, param, &bad) {
        Err(outside) => EndPoint::Bracket {
            ok,
            bad,
            outside,
            why: why.to_string(),
        },
        Ok(()) => EndPoint::Undecided {
            at: bad,
            why: "the bracket's outer end re-tested admissible".into(),
        },
    }
}

/// The maximal interval containing `start` on which every function in `fs`
/// (of one parameter `param`) is nonnegative on its whole domain.
pub fn maximal_range(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    param: &str,
    start: &Rational,
) -> MaximalRange {
    if let Err(o) = point(fs, trig, param, start) {
        let why = "the start is not admissible".to_string();
        let und = EndPoint::Undecided {
            at: start.clone(),
            why: why.clone(),
        };
        return MaximalRange {
            start: start.clone(),
            start_outside: Some(o),
            lo: und.clone(),
            hi: und,
            boundary: Vec::new(),
            certificate: Certificate::Undecided(why),
        };
    }
    let basis = candidates(fs, names, trig).and_then(|c| {
        coprime_basis(&c, param)
            .ok_or_else(|| "a boundary polynomial depends on other symbols".to_string())
    });
    let (lo, hi, boundary) = match basis {
        Ok(b) => (
            exact_end(fs, trig, param, start, &b, -1),
            exact_end(fs, trig, param, start, &b, 1),
            b.into_iter().map(|(p, _)| p).collect(),
        ),
        Err(why) => (
            bracketed_end(fs, trig, param, start, -1, &why),
            bracketed_end(fs, trig, param, start, 1, &why),
            Vec::new(),
        ),
    };
    let certificate = match certified_part(&lo, &hi) {
        Some(bx) => certify_all(fs, trig, param, &bx),
        None => Certificate::Undecided("an end was not decided".into()),
    };
    MaximalRange {
        start: start.clone(),
        start_outside: None,
        lo,
        hi,
        boundary,
        certificate,
    }
}

/// The closed rational part of the found interval (exact rational ends,
/// the inner side of irrational ends and brackets, half-lines).
fn certified_part(lo: &EndPoint, hi: &EndPoint) -> Option<ParamBox> {
    let inner = |e: &EndPoint| -> Option<Bound> {
        match e {
            EndPoint::Exact {
                value,
                closed,
                inside,
                ..
            } => Some(match (&value.rational, closed) {
                (Some(r), true) => Bound::Closed(r.clone()),
                _ => Bound::Closed(inside.clone()),
            }),
            EndPoint::Bracket { ok, .. } => Some(Bound::Closed(ok.clone())),
            EndPoint::Unbounded => Some(Bound::Infinite),
            EndPoint::Undecided { .. } => None,
        }
    };
    Some(ParamBox {
        lo: inner(lo)?,
        hi: inner(hi)?,
    })
}

/// Certifies every function on the box (the first failure is returned).
pub fn certify_all(fs: &[Sym], trig: bool, param: &str, bx: &ParamBox) -> Certificate {
    let mut boxes = 0;
    for f in fs {
        match certify(f, trig, Some(param), bx) {
            Certificate::NonNegative { boxes: b } => boxes += b,
            other => return other,
        }
    }
    Certificate::NonNegative { boxes }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Rational {
        Rational::from((a, b))
    }

    #[test]
    fn simplest_rationals() {
        assert_eq!(simplest_between(&q(3, 10), &q(4, 10)), q(1, 3));
        assert_eq!(simplest_between(&q(-21, 10), &q(-19, 10)), q(-2, 1));
        assert_eq!(simplest_between(&q(1, 2), &q(1, 2)), q(1, 2));
        assert_eq!(simplest_between(&q(-1, 2), &q(1, 3)), q(0, 1));
    }

    /// The thesis cubic basis (3.7): b0 = (1 − s)²(1 − m s), …
    fn thesis_cubic() -> Vec<Sym> {
        let (s, c, m) = (Sym::var("s"), Sym::var("c"), Sym::var("m"));
        let one = Sym::one();
        let sq = |x: &Sym| x.clone() * x;
        vec![
            sq(&(one.clone() - &s)) * &(one.clone() - &(m.clone() * &s)),
            m.clone() * &s * &sq(&(one.clone() - &s)) - &(Sym::int(2) * &s * &(s.clone() - &one)),
            m.clone() * &c * &sq(&(one.clone() - &c)) - &(Sym::int(2) * &c * &(c.clone() - &one)),
            sq(&(one.clone() - &c)) * &(one.clone() - &(m * &c)),
        ]
    }

    #[test]
    fn thesis_cubic_maximal_range_is_minus_two_to_one() {
        let names = ["b0", "b1", "b2", "b3"];
        let r = maximal_range(&thesis_cubic(), &names, true, "m", &Rational::new());
        for (end, v) in [(&r.lo, -2), (&r.hi, 1)] {
            match end {
                EndPoint::Exact {
                    value,
                    closed: true,
                    outside: Outside::Counterexample(_, _, neg),
                    ..
                } => {
                    assert_eq!(value.rational, Some(Rational::from(v)));
                    assert!(*neg < 0);
                }
                other => panic!("{other:?}"),
            }
        }
        assert!(
            matches!(r.certificate, Certificate::NonNegative { .. }),
            "{:?}",
            r.certificate
        );
    }

    /// A basis of squares (examples/independent/README.md C7):
    /// b0 = (1 − s)²(1 − λs)², b2 = (1 − c)²(1 − λc)², b1 = 1 − b0 − b2;
    /// the discriminants of b0, b2 vanish identically (squares), yet the
    /// maximal range is exactly [−1, 2 + 2√2] (λ² − 4λ − 4 = 0).
    #[test]
    fn squares_have_exact_ends_after_squarefree_decomposition() {
        let (s, c, l) = (Sym::var("s"), Sym::var("c"), Sym::var("lambda"));
        let one = Sym::one();
        let sq = |x: Sym| x.clone() * &x;
        let b0 = sq((one.clone() - &s) * &(one.clone() - &(l.clone() * &s)));
        let b2 = sq((one.clone() - &c) * &(one.clone() - &(l.clone() * &c)));
        let b1 = one - &b0 - &b2;
        let names = ["b0", "b1", "b2"];
        let r = maximal_range(&[b0, b1, b2], &names, true, "lambda", &Rational::new());
        match &r.lo {
            EndPoint::Exact {
                value,
                closed: true,
                ..
            } => {
                assert_eq!(value.rational, Some(Rational::from(-1)));
            }
            other => panic!("{other:?}"),
        }
        match &r.hi {
            EndPoint::Exact {
                value,
                closed: true,
                ..
            } => {
                assert!(value.rational.is_none());
                // 2 + 2√2 = 4.828427124746…
                let (lo, hi) = (value.lo.to_f64(), value.hi.to_f64());
                assert!(
                    lo <= 4.828_427_124_746_2 && 4.828_427_124_746_1 <= hi,
                    "{lo} {hi}"
                );
            }
            other => panic!("{other:?}"),
        }
    }

    /// Han's quadratic basis (CAGD 19 (2002)): b0 = (1 − s)(1 − λs),
    /// b1 = (1 + λ)(s + c − 1), b2 = (1 − c)(1 − λc); admissible exactly for
    /// λ ∈ [−1, 1] (b1 < 0 inside for λ < −1; b0 < 0 near s = 1 for λ > 1).
    /// Started at λ = −1, where b1 ≡ 0, the search must not step past it.
    #[test]
    fn a_start_where_a_function_vanishes_identically_is_an_end() {
        let (s, c, l) = (Sym::var("s"), Sym::var("c"), Sym::var("lambda"));
        let one = Sym::one();
        let fs = vec![
            (one.clone() - &s) * &(one.clone() - &(l.clone() * &s)),
            (one.clone() + &l) * &(s.clone() + &c - &one),
            (one.clone() - &c) * &(one.clone() - &(l.clone() * &c)),
        ];
        let r = maximal_range(&fs, &["b0", "b1", "b2"], true, "lambda", &q(-1, 1));
        for (end, v) in [(&r.lo, -1), (&r.hi, 1)] {
            match end {
                EndPoint::Exact {
                    value,
                    closed: true,
                    outside: Outside::Counterexample(..),
                    ..
                } => assert_eq!(value.rational, Some(Rational::from(v))),
                other => panic!("{other:?}"),
            }
        }
    }

    #[test]
    fn an_irrational_end_is_exact_and_a_bad_start_is_caught() {
        // f = 1 − (p² − 4p)·t(1 − t) on t ∈ [0, 1]; t(1 − t) ≤ 1/4 with
        // equality at t = 1/2, so f ≥ 0 ⇔ p² − 4p − 4 ≤ 0 ⇔ p ∈ [2 − 2√2, 2 + 2√2]
        let (t, p) = (Sym::var("t"), Sym::var("p"));
        let w = t.clone() * &(Sym::one() - &t);
        let f = Sym::one() - &(p.clone() * &p * &w) + &(Sym::int(4) * &p * &w);
        let r = maximal_range(
            std::slice::from_ref(&f),
            &["f"],
            false,
            "p",
            &Rational::new(),
        );
        match &r.hi {
            EndPoint::Exact {
                value,
                closed: true,
                ..
            } => {
                assert!(value.rational.is_none() && value.minimal);
                assert_eq!(value.poly_text("p"), "p^2 - 4*p - 4");
                assert!((value.to_f64() - (2.0 + 2.0 * 2f64.sqrt())).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
        assert!(matches!(&r.lo, EndPoint::Exact { value, .. } if value.rational.is_none()));
        let bad = maximal_range(&[f], &["f"], false, "p", &Rational::from(10));
        assert!(matches!(
            bad.start_outside,
            Some(Outside::Counterexample(..))
        ));
    }
}
