//! The maximal nonnegativity interval of a one-parameter spec basis that
//! the polynomial engine does not take, found by the analytic engine
//! ([`trig_certify::analytic_range`]), set against a printed range end by
//! end.
//!
//! An end is *exact* (the basis is undefined there, or its equation
//! vanishes exactly at a simple value), *certified* (the unique root of an
//! exact equation in a rational enclosure, proved by a Krawczyk step —
//! never called exact), a *bracket* (a proved admissible value and a
//! certified negative one), or not found within the search limits.

use rug::Rational;
use trig_certify::analytic_range::{AnalyticRange, End, ExactValue, Problem, maximal_range};
use trig_certify::branch::{Axis, Outcome};
use trig_certify::range::simplest_between;
use trig_symbolic::Sym;

use crate::exact::ExactBasis;
use trig_verdict::status::Status;

/// The analytic engine, as the report states it.
pub const ANALYTIC: &str = "the maximal interval by the analytic engine: a grid of certified point tests from a value inside the printed range and bisection bracket each end; an end is exact where the basis is undefined or its equation vanishes exactly, or where, at a stationary minimum of a trigonometric basis, eliminating the variable by resultants leaves exactly one root in the certified enclosure of the end, certified where a Krawczyk step proves the unique root of the equation of the end (the factor that changes sign, at the end of the domain or at a stationary minimum) and branch and bound proves that admissibility changes exactly there, a bracket otherwise; the part inside the ends is proved as a whole";

/// The decision for one printed end against the maximal interval.
#[derive(Debug)]
pub struct EndDecision {
    pub status: Status,
    pub line: String,
}

/// The maximal interval containing a value inside `printed` (searched one
/// printed width beyond each end), with the functions' names; `proved`
/// when every function is proved `≥ 0` on the printed range already.
pub fn search<B: ExactBasis>(basis: &B, fs: &[Sym], printed: &Axis, proved: bool) -> AnalyticRange {
    let domain = basis.domain();
    let problem = Problem::new(fs, &domain, printed.pi);
    let width = Rational::from(&printed.hi - &printed.lo).max(Rational::from(1));
    // a simple value well inside (the printed ends may be open)
    let quarter = Rational::from(&printed.hi - &printed.lo) / 4u32;
    let start = simplest_between(
        &Rational::from(&printed.lo + &quarter),
        &Rational::from(&printed.hi - &quarter),
    );
    let lo_limit = Rational::from(&printed.lo - &width);
    let hi_limit = Rational::from(&printed.hi + &width);
    maximal_range(
        &problem,
        &start,
        &lo_limit,
        &hi_limit,
        proved.then_some(printed),
    )
}

/// The whole interval as one line of evidence.
pub fn describe<B: ExactBasis>(basis: &B, fs: &[Sym], printed: &Axis, r: &AnalyticRange) -> String {
    let domain = basis.domain();
    let problem = Problem::new(fs, &domain, printed.pi);
    let names = basis.function_names();
    let symbol = &basis.parameters()[0].symbol;
    let inside = match &r.inside {
        Outcome::Proved { boxes } => match (&r.inside_given, boxes) {
            (Some(_), 0) => {
                "the part inside the ends proved: it lies in the printed range, proved above".into()
            }
            (Some(_), _) => format!(
                "the part inside the ends proved: the printed range above, the rest here ({boxes} interval boxes)"
            ),
            (None, _) => format!("the part inside the ends proved ({boxes} interval boxes)"),
        },
        Outcome::Negative { .. } => "the part inside the ends not proved (a negative value)".into(),
        Outcome::Undecided(why) => format!("the part inside the ends not proved ({why})"),
    };
    format!(
        "maximal interval of {symbol} containing {symbol} = {} on which every function is ≥ 0: lower end {}; upper end {}; {inside}",
        value_text(&r.start, printed.pi),
        r.lo.describe(&problem, symbol, &names),
        r.hi.describe(&problem, symbol, &names),
    )
}

fn value_text(q: &Rational, pi: bool) -> String {
    trig_certify::analytic_range::value_text(q, pi)
}

/// The printed end `v` (`open` when excluded) in direction `dir` against
/// the end `found` of the maximal interval; `None` when the engine says
/// nothing about it. `inside_proved`: the part inside the ends is proved.
pub fn decide_end(
    v: &Rational,
    open: bool,
    dir: i32,
    found: &End,
    inside_proved: bool,
    pi: bool,
) -> Option<EndDecision> {
    let shown = value_text(v, pi);
    // `q` lies strictly beyond the printed end (outside the printed range)
    let beyond = |q: &Rational| if dir > 0 { q > v } else { q < v };
    let decision = |status, line: String| Some(EndDecision { status, line });
    match found {
        End::Exact {
            value: ExactValue::Rational(q),
            closed,
            ..
        } if q == v => {
            if *closed != open {
                decision(
                    Status::Holds,
                    format!("the printed end {shown} is the exact end of the maximal interval"),
                )
            } else if *closed {
                decision(
                    Status::Fails,
                    format!(
                        "not maximal: the printed range excludes {shown}, but every function is ≥ 0 there (the maximal interval includes it)"
                    ),
                )
            } else {
                decision(
                    Status::Fails,
                    format!("the printed range includes {shown}, where the basis is not defined"),
                )
            }
        }
        End::Exact {
            value: ExactValue::Rational(q),
            inside,
            ..
        } if inside_proved && beyond(q) => decision(
            Status::Fails,
            format!(
                "not maximal: the maximal interval extends beyond the printed end {shown} to the exact end {} (every function is ≥ 0 up to {} by the proof of the interval)",
                value_text(q, pi),
                value_text(inside, pi)
            ),
        ),
        End::Exact {
            value: ExactValue::Algebraic(a),
            inside,
            ..
        } if inside_proved && a.rational.is_none() && beyond(inside) => decision(
            Status::Fails,
            format!(
                "not maximal: the maximal interval extends beyond the printed end {shown} to an irrational algebraic end (every function is ≥ 0 up to {} by the proof of the interval)",
                value_text(inside, pi)
            ),
        ),
        End::Certified { lo, hi, inside, .. } => {
            if (v >= lo && v <= hi) || !inside_proved {
                decision(
                    Status::NotCheckable,
                    format!(
                        "the printed end {shown} lies in the certified enclosure of the end: not decided"
                    ),
                )
            } else if beyond(inside) {
                decision(
                    Status::Fails,
                    format!(
                        "not maximal: the maximal interval extends beyond the printed end {shown} to a certified end that is not the printed value (every function is ≥ 0 up to {} by the proof of the interval)",
                        value_text(inside, pi)
                    ),
                )
            } else {
                None
            }
        }
        End::Bracket { ok, .. } | End::Exact { inside: ok, .. } if inside_proved && beyond(ok) => {
            decision(
                Status::Fails,
                format!(
                    "not maximal: every function is ≥ 0 up to {} beyond the printed end {shown} (proved with the interval)",
                    value_text(ok, pi)
                ),
            )
        }
        End::Beyond { upto } if inside_proved && beyond(upto) => decision(
            Status::Fails,
            format!(
                "not maximal: every function is ≥ 0 up to the search limit {} beyond the printed end {shown} (proved)",
                value_text(upto, pi)
            ),
        ),
        _ => None,
    }
}
