//! Inequalities of bases that are not polynomial in sin, cos or the
//! variable on a standard domain (C-curves, hyperbolic and exponential
//! bases, half angles, parameter-dependent domains): decided by the
//! interval engine ([`trig_certify::branch`]). Every `holds` is a proof;
//! witnesses are rational points with certified enclosures of the value;
//! maximal ranges are bracketed (an end found this way is never called
//! exact unless the basis is undefined there).

use rug::Rational;
use trig_certify::branch::{Axis, Outcome};
use trig_core::{End, ParamRange};
use trig_symbolic::Sym;

use super::analytic;
use crate::exact::ExactBasis;
use crate::exact::basis_of;
use crate::memo::Memo;
use trig_verdict::real_witness::context_key;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// How the interval method decides, as the report states it.
pub const INTERVAL: &str = "certified: branch and bound over (variable, parameters) with Taylor models in 128-bit MPFR (a polynomial and a rigorous remainder) and interval arithmetic with outward rounding; products and quotients factor by factor (denominators of one strict sign); next to the domain's ends and the range ends by exact derivatives (a zero of order m on a face has the sign of the m-th derivative into the box; otherwise ≥ 0 on the face and a derivative ≥ 0 into the box); counterexamples are boxes where the value is certified negative";

/// Width kept of an unbounded range (the search is then partial).
const TRUNCATE: i64 = 64;

/// The axes of the parameters for a claim: the declared ranges, `range`
/// replacing the only parameter's; unbounded ranges truncated (noted).
pub fn axes<B: ExactBasis>(basis: &B, range: Option<&ParamRange>) -> (Vec<Axis>, Vec<String>) {
    let mut notes = Vec::new();
    let params = basis.parameters();
    let axes = params
        .iter()
        .map(|p| {
            let r = range.filter(|_| params.len() == 1).unwrap_or(&p.range);
            Axis::from_range(r).unwrap_or_else(|| {
                let (lo, hi, lo_open, hi_open) = match (r.lo.value(), r.hi.value()) {
                    (Some(a), None) => (
                        a.clone(),
                        a.clone() + TRUNCATE,
                        matches!(r.lo, End::Open(_)),
                        false,
                    ),
                    (None, Some(b)) => (
                        b.clone() - TRUNCATE,
                        b.clone(),
                        false,
                        matches!(r.hi, End::Open(_)),
                    ),
                    _ => (
                        Rational::from(-TRUNCATE),
                        Rational::from(TRUNCATE),
                        false,
                        false,
                    ),
                };
                notes.push(format!(
                    "the range {r} of {} is unbounded: only [{lo}, {hi}] was searched",
                    p.symbol
                ));
                Axis {
                    lo,
                    hi,
                    lo_open,
                    hi_open,
                    pi: r.pi,
                }
            })
        })
        .collect();
    (axes, notes)
}

/// `q`, or `q·π` on an axis in multiples of π.
fn value_text(q: &Rational, pi: bool) -> String {
    if pi {
        format!("{q}·π")
    } else {
        q.to_string()
    }
}

fn describe_point<B: ExactBasis>(basis: &B, axes: &[Axis], params: &[Rational], x: f64) -> String {
    let mut parts: Vec<String> = basis
        .parameters()
        .iter()
        .zip(params)
        .zip(axes)
        .map(|((p, v), a)| format!("{} = {}", p.symbol, value_text(v, a.pi)))
        .collect();
    parts.push(format!("{} ≈ {x:.6}", basis.variable_name()));
    parts.join(", ")
}

/// `f ≥ 0` on the domain for the parameters in `axes`, decided factor by
/// factor by the engine ([`trig_certify::factors::nonnegative`]).
pub fn nonnegative<B: ExactBasis>(
    basis: &B,
    name: &str,
    f: &Sym,
    axes: &[Axis],
) -> (Status, String) {
    outcome_line(
        basis,
        (name, "its numerator"),
        axes,
        trig_certify::factors::nonnegative(f, &basis.domain(), axes),
    )
}

/// The status and evidence line of the engine's outcome for `name ≥ 0`
/// (`what` was enclosed at a counterexample: the function's numerator, or
/// its value).
fn outcome_line<B: ExactBasis>(
    basis: &B,
    (name, what): (&str, &str),
    axes: &[Axis],
    outcome: Outcome,
) -> (Status, String) {
    match outcome {
        Outcome::Proved { boxes } => (
            Status::Holds,
            format!("{name} ≥ 0: certified on the whole domain ({boxes} interval boxes)"),
        ),
        Outcome::Negative {
            params, x, value, ..
        } => (
            Status::Fails,
            format!(
                "{name} ≥ 0: violated at {} ({what} lies in [{:.6e}, {:.6e}] there, certified)",
                describe_point(basis, axes, &params, x),
                value.0,
                value.1
            ),
        ),
        Outcome::Undecided(why) => (
            Status::NotCheckable,
            format!("{name} ≥ 0: undecided ({why})"),
        ),
    }
}

/// Every function `≥ 0` for the parameters of `axes`.
pub fn all_nonnegative<B: ExactBasis>(
    basis: &B,
    fs: &[(String, Sym)],
    axes: &[Axis],
    notes: &[String],
) -> Verdict {
    if let Some(v) = on_half_line(basis, fs, axes, notes) {
        return v;
    }
    if let Some(v) = refuted_by_probe(basis, fs, axes, notes) {
        return v;
    }
    let partners: Vec<Option<usize>> = fs
        .iter()
        .enumerate()
        .map(|(k, (_, f))| (0..fs.len()).find(|&j| j != k && mirrors(basis, f, &fs[j].1)))
        .collect();
    // the functions without an earlier mirror image, certified on every
    // core at once (into the memo; the loop below reads them in order)
    let first: Vec<usize> = (0..fs.len())
        .filter(|&k| partners[k].is_none_or(|j| j > k))
        .collect();
    trig_core::parallel::map(&first, |&k| memo(basis, &fs[k].0, &fs[k].1, axes));
    let mut status = Status::Holds;
    let mut evidence: Vec<String> = notes.to_vec();
    let mut done: Vec<Option<Status>> = vec![None; fs.len()];
    for (k, (name, f)) in fs.iter().enumerate() {
        // f(x) = g(a + b − x) exactly for a decided g: f ≥ 0 follows from g ≥ 0
        let partner = partners[k];
        if let Some(j) = partner.filter(|&j| done[j] == Some(Status::Holds)) {
            evidence.push(format!(
                "{name} ≥ 0 follows from {} ≥ 0: {name}(x) = {}(a + b − x) exactly and the reflection maps the domain onto itself",
                fs[j].0, fs[j].0
            ));
            done[k] = Some(Status::Holds);
            continue;
        }
        let (mut s, mut line) = memo(basis, name, f, axes);
        if s == Status::NotCheckable {
            if let Some(j) = partner.filter(|&j| done[j].is_none()) {
                let (s2, line2) = memo(basis, &fs[j].0, &fs[j].1, axes);
                if s2 == Status::Holds {
                    (s, line) = (
                        s2,
                        format!(
                            "{line2}; {name} ≥ 0 follows: {name}(x) = {}(a + b − x) exactly",
                            fs[j].0
                        ),
                    );
                    done[j] = Some(Status::Holds);
                }
            }
        }
        if s == Status::NotCheckable {
            if let Some((inner, text)) = away_from_open_ends(axes) {
                let (s2, line2) = memo(basis, name, f, &inner);
                if s2 != Status::NotCheckable {
                    line = format!("{line}; on the inner range {text}: {line2}");
                    if s2 == Status::Fails {
                        s = s2;
                    }
                }
            }
        }
        done[k] = Some(s);
        status = Status::conjunction([status, s]);
        evidence.push(line);
    }
    if status == Status::Holds && !notes.is_empty() {
        status = Status::NotCheckable;
    }
    Verdict::new(status, INTERVAL, evidence)
}

/// The claim refuted before any certificate when the search's first probe
/// (a few points per axis) finds a function `< 0` at a point, certified:
/// one violation decides the claim, so the functions it did not catch are
/// not certified (that is where the time goes); `None` when the probe
/// finds none.
fn refuted_by_probe<B: ExactBasis>(
    basis: &B,
    fs: &[(String, Sym)],
    axes: &[Axis],
    notes: &[String],
) -> Option<Verdict> {
    let domain = basis.domain();
    let violations: Vec<String> = fs
        .iter()
        .filter_map(|(name, f)| {
            let negative = trig_certify::branch::probe_negative(f, &domain, axes)?;
            Some(outcome_line(basis, (name, "its value"), axes, negative).1)
        })
        .collect();
    if violations.is_empty() {
        return None;
    }
    let mut evidence: Vec<String> = notes.to_vec();
    evidence.extend(violations);
    evidence.push(
        "the other functions are not certified: a certified violation decides the claim".into(),
    );
    Some(Verdict::new(Status::Fails, INTERVAL, evidence))
}

/// How an unbounded range of an exponential basis is decided.
const HALF_LINE: &str = "certified for every parameter of the unbounded range: on [0, p] the atoms y = exp(κx), Y = exp(κp) satisfy 1 ≤ y ≤ Y; with y = 1 + u, Y = 1 + u + v (u, v ≥ 0) every factor of odd multiplicity has coefficients of one sign in u, v (exact rational arithmetic)";

/// Every function `≥ 0` for a range unbounded above (the interval engine
/// would only search a truncation of it), by the positive-coefficient
/// certificate of [`trig_certify::exp_half_line`]; `None` when it does not
/// decide every function.
fn on_half_line<B: ExactBasis>(
    basis: &B,
    fs: &[(String, Sym)],
    axes: &[Axis],
    notes: &[String],
) -> Option<Verdict> {
    let [axis] = axes else {
        return None;
    };
    let p = basis.parameters().into_iter().next()?;
    let unbounded_above = p.range.lo.value().is_some() && !notes.is_empty();
    if !unbounded_above || axis.pi {
        return None;
    }
    let evidence: Vec<String> = fs
        .iter()
        .map(|(name, f)| {
            trig_certify::exp_half_line::nonnegative(f, &basis.domain(), &axis.lo).map(|_| {
                format!(
                    "{name} ≥ 0: certified for every {} in {} (positive coefficients in u, v)",
                    p.symbol, p.range
                )
            })
        })
        .collect::<Option<_>>()?;
    Some(Verdict::new(Status::Holds, HALF_LINE, evidence))
}

/// [`nonnegative`], remembered across the claims of one run (the battery
/// and the file's claims ask the same questions).
fn memo<B: ExactBasis>(basis: &B, name: &str, f: &Sym, axes: &[Axis]) -> (Status, String) {
    static DECIDED: Memo<(Status, String)> = Memo::new();
    let key = format!("{}|{:?}|{name}|{f}|{axes:?}", basis.id(), basis.domain());
    DECIDED.get_or_compute(key, || nonnegative(basis, name, f, axes))
}

/// True when `f(x) = g(a + b − x)` exactly (same parameters).
fn mirrors<B: ExactBasis>(basis: &B, f: &Sym, g: &Sym) -> bool {
    let a = basis.domain().reflection();
    let params = super::domain::param_symbols(basis);
    super::symmetry::reflect(basis, g, &a, &params).is_ok_and(|r| (r - f).is_zero())
}

/// The axes with every open end moved inward by an eighth of the width
/// (a partial search when the whole one is undecided), with its text.
fn away_from_open_ends(axes: &[Axis]) -> Option<(Vec<Axis>, String)> {
    if !axes.iter().any(|a| a.lo_open || a.hi_open) {
        return None;
    }
    let mut texts = Vec::new();
    let inner = axes
        .iter()
        .map(|a| {
            let step = Rational::from(&a.hi - &a.lo) / 8u32;
            let mut b = a.clone();
            if a.lo_open {
                b.lo = Rational::from(&a.lo + &step);
                b.lo_open = false;
            }
            if a.hi_open {
                b.hi = Rational::from(&a.hi - &step);
                b.hi_open = false;
            }
            texts.push(format!(
                "[{}, {}]",
                value_text(&b.lo, b.pi),
                value_text(&b.hi, b.pi)
            ));
            b
        })
        .collect();
    Some((inner, texts.join(" × ")))
}

/// The functions of `basis` with their names.
pub fn functions<B: ExactBasis>(basis: &B) -> Vec<(String, Sym)> {
    basis
        .function_names()
        .into_iter()
        .zip(basis_of(basis))
        .collect()
}

/// The declared (or claimed) range against the maximal one, for one
/// parameter: containment is proved; an end is exact only where the basis
/// is undefined (a denominator vanishes identically there); otherwise a
/// point just beyond it decides: admissible refutes maximality, a
/// certified counterexample brackets the end.
pub fn maximal<B: ExactBasis>(basis: &B, range: &ParamRange) -> Verdict {
    static DECIDED: Memo<Verdict> = Memo::new();
    let key = format!(
        "{:?}",
        (
            functions(basis),
            basis.domain(),
            basis.parameters(),
            range,
            context_key()
        )
    );
    DECIDED.get_or_compute(key, || maximal_uncached(basis, range))
}

fn maximal_uncached<B: ExactBasis>(basis: &B, range: &ParamRange) -> Verdict {
    let (ax, notes) = axes(basis, Some(range));
    let fs = functions(basis);
    let inside = all_nonnegative(basis, &fs, &ax, &notes);
    if inside.status != Status::Holds {
        return inside;
    }
    let p = &basis.parameters()[0];
    let mut status = Status::Holds;
    let mut evidence = inside.evidence;
    let width = Rational::from(&ax[0].hi - &ax[0].lo);
    let step = width / 64u32;
    // the maximal interval by the analytic engine (bounded printed ranges)
    let values: Vec<Sym> = fs.iter().map(|(_, f)| f.clone()).collect();
    let found = notes
        .is_empty()
        .then(|| analytic::search(basis, &values, &ax[0], true));
    if let Some(r) = &found {
        evidence.push(analytic::describe(basis, &values, &ax[0], r));
    }
    let ends = [
        (range.lo.value(), -1, matches!(range.lo, End::Open(_))),
        (range.hi.value(), 1, matches!(range.hi, End::Open(_))),
    ];
    for (end, outward, open) in ends {
        let Some(v) = end else {
            continue;
        };
        let decided = found.as_ref().and_then(|r| {
            let proved = matches!(r.inside, Outcome::Proved { .. });
            let e = if outward < 0 { &r.lo } else { &r.hi };
            analytic::decide_end(v, open, outward, e, proved, range.pi)
        });
        if let Some(d) = decided {
            status = Status::conjunction([status, d.status]);
            evidence.push(d.line);
            continue;
        }
        let shown = value_text(v, range.pi);
        if undefined_at(basis, &fs, v, range.pi) {
            evidence.push(format!(
                "the end {} = {shown} is exact: a denominator vanishes identically there, so the basis is not defined at it",
                p.symbol
            ));
            continue;
        }
        let w: Rational = v.clone() + step.clone() * Rational::from(outward);
        let point = vec![Axis {
            lo: w.clone(),
            hi: w.clone(),
            lo_open: false,
            hi_open: false,
            pi: range.pi,
        }];
        let beyond = all_nonnegative(basis, &fs, &point, &[]);
        match beyond.status {
            Status::Holds => {
                status = Status::Fails;
                evidence.push(format!(
                    "not maximal: beyond the end {shown}, at {} = {}, every function is certified ≥ 0",
                    p.symbol,
                    value_text(&w, range.pi)
                ));
            }
            Status::Fails => {
                status = Status::conjunction([status, Status::NotCheckable]);
                evidence.push(format!(
                    "the end {shown} is bracketed, not exact: at {} = {} a function is certified negative ({}), so the maximal range ends in [{}, {}]",
                    p.symbol,
                    value_text(&w, range.pi),
                    beyond.evidence.iter().find(|l| l.contains("violated")).map(ToString::to_string).unwrap_or_default(),
                    value_text(if outward < 0 { &w } else { v }, range.pi),
                    value_text(if outward < 0 { v } else { &w }, range.pi)
                ));
            }
            _ => {
                status = Status::conjunction([status, Status::NotCheckable]);
                evidence.push(format!(
                    "beyond the end {shown} (at {} = {}) the search was not decided",
                    p.symbol,
                    value_text(&w, range.pi)
                ));
            }
        }
    }
    let method = if found.is_some() {
        format!("{INTERVAL}; {}", analytic::ANALYTIC)
    } else {
        INTERVAL.to_string()
    };
    Verdict::new(status, method, evidence)
}

/// True when some denominator factor is identically zero at `p = v` (its
/// atoms of the parameter substituted when they are exact there).
fn undefined_at<B: ExactBasis>(basis: &B, fs: &[(String, Sym)], v: &Rational, pi: bool) -> bool {
    use trig_certify::atoms::{param_atoms, value};
    let d = &basis.domain();
    let name = &basis.parameters()[0].name;
    let atoms = param_atoms(d);
    let params = [if pi {
        Sym::rational(v.clone()) * &Sym::pi()
    } else {
        Sym::rational(v.clone())
    }];
    let symbols = trig_symbolic::symbolic_atoms();
    fs.iter().any(|(_, f)| {
        f.denominator().keys().any(|factor| {
            let mut at = Sym::from_poly(factor.clone()).subs(name, &params[0]);
            for a in atoms.iter().filter(|a| a.param == 0) {
                match value(&a.name, d, &symbols, &params, &atoms) {
                    Some(e) => at = at.subs(&a.name, &e),
                    None => return false,
                }
            }
            at.is_zero()
        })
    })
}

/// Monotonicity by the sign of the derivative in the variable.
pub fn monotone<B: ExactBasis>(
    basis: &B,
    name: &str,
    f: &Sym,
    increasing: bool,
    range: Option<&ParamRange>,
) -> Verdict {
    let d = trig_certify::atoms::d_variable(f, &basis.domain());
    let g = if increasing { d } else { -d };
    let (ax, notes) = axes(basis, range);
    let what = if increasing {
        format!("{name}' ≥ 0 ({name} increasing)")
    } else {
        format!("−{name}' ≥ 0 ({name} decreasing)")
    };
    all_nonnegative(basis, &[(what, g)], &ax, &notes)
}
