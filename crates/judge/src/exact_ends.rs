//! Claims over a range whose ends are printed beyond the rationals
//! (`λ ∈ [−1, 2 + 2√2]`, `α ∈ [1, π]`: [`ExactRange`]), for any check
//! decided over a range.
//!
//! * The printed range rounded **outward** to rationals (10⁻¹² beyond
//!   each such end) contains it: a claim that holds there holds as printed.
//! * Rounded **inward**, it lies inside the printed range: a counterexample
//!   there is one of the printed range.
//! * Otherwise the claim turns on the end itself — typically a paper prints
//!   the exact end of the maximal set. For nonnegativity of a
//!   one-parameter basis taken by the polynomial engine, the maximal
//!   interval's ends are exact real algebraic numbers, and an end
//!   `a + b√k` is compared with them exactly ([`Algebraic::cmp`]): the
//!   printed range lies in the maximal interval (holds) or reaches beyond
//!   it (fails, with a counterexample in the gap beyond the exact end); with
//!   `maximal = true` the ends must be equal and alike included or
//!   excluded. Elsewhere the claim is `not-checkable`, saying so.

use std::cmp::Ordering;

use rug::Rational;
use trig_certify::algebraic::Algebraic;
use trig_certify::domain::ParamBox;
use trig_certify::range::{EndPoint, MaximalRange, simplest_between};
use trig_core::{End, ParamRange};
use trig_specfile::{ExactEnd, ExactRange};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::certificate::{MAXIMAL, Published, maximal_against, show_end};
use crate::exact::ExactBasis;
use crate::nonnegative::pieces;

/// How a claim over such a range is decided, as the report states it.
pub const EXACT_ENDS: &str = "a range with ends beyond the rationals: decided on the rational ranges just outside it (holds there, so as printed) and just inside it (a counterexample there is one of the printed range); at the end itself, for nonnegativity, the printed end a + b√k compared exactly with the exact algebraic end of the maximal interval";

/// How the claim is decided on a range of rationals put in its place.
pub type OnRanges<'a> = dyn Fn(&[(String, ParamRange)]) -> Verdict + 'a;

/// The claim over `ranges` (their ends beyond the rationals), decided by
/// `on` over rational ranges; `nonnegativity`: `Some(maximal)` when the
/// claim is nonnegativity (or its part of the convex hull), whose end is
/// then compared exactly.
pub fn decide<B: ExactBasis>(
    basis: &B,
    ranges: &[ExactRange],
    nonnegativity: Option<bool>,
    on: &OnRanges<'_>,
) -> Verdict {
    let rounded = |outward: bool| -> Option<Vec<(String, ParamRange)>> {
        ranges
            .iter()
            .map(|r| Some((r.name.clone(), r.rounded(outward)?)))
            .collect()
    };
    let (outer, inner) = (rounded(true), rounded(false));
    let shown = |rs: &[(String, ParamRange)]| {
        rs.iter()
            .map(|(n, r)| format!("{} ∈ {r}", symbol(basis, n)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut evidence = vec![format!(
        "the printed range {} has an end beyond the rationals: decided on rational ranges next to it (ends on a grid of 10⁻¹²){}",
        ranges
            .iter()
            .map(|r| format!("{} ∈ {}", symbol(basis, &r.name), r.text))
            .collect::<Vec<_>>()
            .join(", "),
        if nonnegativity.is_some() {
            ", and at the end itself exactly"
        } else {
            ""
        }
    )];
    // the claim turns on the end itself when it fails just outside and
    // holds just inside; it is decided where it holds outside (a superset)
    // or fails inside (a subset)
    let mut turns = [false, false];
    if nonnegativity != Some(true) {
        let sides = [
            (
                &outer,
                Status::Holds,
                Status::Fails,
                "which contains the printed range",
            ),
            (
                &inner,
                Status::Fails,
                Status::Holds,
                "which lies inside the printed range",
            ),
        ];
        for (k, (side, decides, turning, relation)) in sides.into_iter().enumerate() {
            let Some(rs) = side else { continue };
            let v = on(rs);
            turns[k] = v.status == turning;
            if v.status == decides {
                evidence.push(format!("{} on {}, {relation}:", v.status, shown(rs)));
                return with_lines(v, evidence);
            }
            evidence.push(format!("on {}, {relation}: {}", shown(rs), v.status));
        }
    }
    match (nonnegativity, ranges, inner) {
        (Some(maximal), [range], Some(inner)) if basis.parameters().len() == 1 => {
            at_the_ends(basis, range, &inner[0].1, maximal, on, evidence)
        }
        _ => {
            evidence.push(if turns == [true, true] {
                "the claim turns on the end itself, which is decided exactly for the nonnegativity of a one-parameter basis only".into()
            } else {
                "neither rational range decides the claim".into()
            });
            Verdict::new(Status::NotCheckable, EXACT_ENDS, evidence)
        }
    }
}

/// The parameter's printed symbol.
fn symbol<B: ExactBasis>(basis: &B, name: &str) -> String {
    basis
        .parameters()
        .into_iter()
        .find(|p| p.name == name)
        .map_or(name.to_string(), |p| p.symbol)
}

/// `v` with `lines` before its own evidence.
fn with_lines(mut v: Verdict, lines: Vec<String>) -> Verdict {
    for (k, l) in lines.into_iter().enumerate() {
        v.evidence.insert(k, l);
    }
    v
}

/// The printed ends against the exact ends of the maximal nonnegativity
/// interval (searched from inside `inner`).
fn at_the_ends<B: ExactBasis>(
    basis: &B,
    range: &ExactRange,
    inner: &ParamRange,
    maximal: bool,
    on: &OnRanges<'_>,
    mut evidence: Vec<String>,
) -> Verdict {
    let p = &basis.parameters()[0];
    let Ok((trig, fs, names)) = pieces(basis) else {
        evidence.push("the exact ends of the maximal interval are found by the polynomial engine only (not this basis): the claim turns on the end itself".into());
        return Verdict::new(Status::NotCheckable, MAXIMAL, evidence);
    };
    let published = Published {
        name: &p.name,
        symbol: &p.symbol,
        range: range.text.clone(),
        set: ParamBox::from_range(inner),
        source: "as claimed",
    };
    let (found, _) = maximal_against(&fs, &names, trig, &published);
    let mut status = Status::Holds;
    for (printed, lower) in [(&range.lo, true), (&range.hi, false)] {
        let end = if lower { &found.lo } else { &found.hi };
        let (s, line) = compare(printed, end, lower, maximal, &p.name, trig);
        status = Status::conjunction([status, s]);
        evidence.push(line);
    }
    if status == Status::Fails && !maximal {
        // a counterexample in the gap beyond the exact end, inside the print
        if let Some((q, v)) = beyond_the_end(&found, range, on, &p.name) {
            evidence.push(format!(
                "at {} = {q}, between the exact end and the printed one:",
                p.symbol
            ));
            return with_lines(v, evidence);
        }
    }
    Verdict::new(status, MAXIMAL, evidence)
}

/// One printed end against the found one: the status (`maximal`: equal
/// ends; otherwise the printed end inside) and the line saying why.
fn compare(
    printed: &ExactEnd,
    found: &EndPoint,
    lower: bool,
    maximal: bool,
    param: &str,
    trig: bool,
) -> (Status, String) {
    let side = if lower { "lower" } else { "upper" };
    let found_text = show_end(found, param, trig);
    let (printed_text, open) = match printed {
        ExactEnd::Unbounded => ("infinite".to_string(), false),
        ExactEnd::Finite { text, open, .. } => (text.clone(), *open),
    };
    let line = |verdict: &str| {
        format!(
            "the printed {side} end {printed_text} against the maximal interval's {side} end ({found_text}): {verdict}"
        )
    };
    // inside: the printed end lies on the admissible side of the found one
    let inside = |o: Ordering| {
        if lower {
            o == Ordering::Greater
        } else {
            o == Ordering::Less
        }
    };
    match (printed, found) {
        (ExactEnd::Unbounded, EndPoint::Unbounded) => (Status::Holds, line("both infinite")),
        (_, EndPoint::Unbounded) => (
            if maximal {
                Status::Fails
            } else {
                Status::Holds
            },
            line("inside (the maximal interval is unbounded)"),
        ),
        (ExactEnd::Unbounded, _) => (Status::Fails, line("the printed range reaches beyond")),
        (_, EndPoint::Exact { value, closed, .. }) => {
            let Some(mut mine) = printed.algebraic() else {
                return (
                    Status::NotCheckable,
                    line(
                        "the printed end is not of the form a + b√k, so it is not compared exactly",
                    ),
                );
            };
            let mut theirs = value.clone();
            match mine.cmp(&mut theirs) {
                Ordering::Equal => {
                    let alike = *closed != open;
                    let verdict = match (maximal, alike, *closed) {
                        (true, true, _) => (
                            Status::Holds,
                            "the same number, exactly, and alike included or excluded",
                        ),
                        (true, false, _) => (
                            Status::Fails,
                            "the same number, exactly, but included in one and excluded in the other",
                        ),
                        (false, _, true) | (false, true, _) => {
                            (Status::Holds, "the same number, exactly: inside")
                        }
                        (false, false, false) => (
                            Status::Fails,
                            "the same number, exactly, included in the print but excluded from the maximal interval",
                        ),
                    };
                    (verdict.0, line(verdict.1))
                }
                o if inside(o) => (
                    if maximal {
                        Status::Fails
                    } else {
                        Status::Holds
                    },
                    line("strictly inside, exactly"),
                ),
                _ => (Status::Fails, line("beyond it, exactly")),
            }
        }
        (_, EndPoint::Bracket { .. } | EndPoint::Undecided { .. }) => (
            Status::NotCheckable,
            line("the maximal interval's end is not exact, so the ends are not compared"),
        ),
    }
}

/// A counterexample at a rational point between an exact end of the
/// maximal interval and the printed end beyond it (the gap beyond an exact
/// end is inadmissible up to the next boundary root).
fn beyond_the_end(
    found: &MaximalRange,
    range: &ExactRange,
    on: &OnRanges<'_>,
    name: &str,
) -> Option<(Rational, Verdict)> {
    for (printed, end, lower) in [(&range.lo, &found.lo, true), (&range.hi, &found.hi, false)] {
        let (EndPoint::Exact { value, .. }, Some(mut mine)) = (end, printed.algebraic()) else {
            continue;
        };
        let mut theirs: Algebraic = value.clone();
        if mine.cmp(&mut theirs) == Ordering::Equal {
            continue;
        }
        // both intervals are now apart: a rational between them
        let (a, b) = if lower {
            (&mine.hi, &theirs.lo)
        } else {
            (&theirs.hi, &mine.lo)
        };
        let q = simplest_between(a, b);
        if q <= *a || q >= *b {
            continue;
        }
        let point = ParamRange {
            lo: End::Closed(q.clone()),
            hi: End::Closed(q.clone()),
            pi: false,
        };
        let v = on(&[(name.to_string(), point)]);
        if v.status == Status::Fails {
            return Some((q, v));
        }
    }
    None
}
