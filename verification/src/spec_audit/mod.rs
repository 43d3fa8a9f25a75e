//! The audit of a spec file (crate `trig-specfile`): a standard battery —
//! partition of unity, the maximal certified nonnegativity range against
//! the declared one, symmetry (with the parameters exchanged when that is
//! what holds), endpoint interpolation, the exact derivative tables, the
//! C¹/C² join conditions — plus every claim the file lists, decided by the
//! same exact and certified methods as the built-in claims and reported in
//! the same format ([`Entry`]).
//!
//! The checkers take the spec's exact functions, domain and declared
//! parameters instead of a catalog [`trig_core::Family`]; on the thesis
//! cubic they reproduce the built-in verdicts and evidence line for line
//! (test `spec_thesis_cubic_matches_builtin`).

mod joins;
mod negation;
mod umbrella;

pub use umbrella::umbrella_verdict;

use std::sync::Arc;
use std::time::Duration;

use trig_deriv::Wrt;
use trig_specfile::{Check, Spec, SpecClaim, Varied};

use crate::budget::{Stopped, bounded};
use crate::entry::{Document, Entry};
use trig_judge::endpoint::TABLE_ORDERS;
use trig_judge::local_control::Control;
use trig_verdict::evidence::Evidence;
use trig_verdict::real_witness::{RealPoints, with_real_points};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// The report document of a spec: the claims its file lists.
pub fn document(spec: &Spec) -> Document {
    Document {
        heading: format!("Spec {}", spec.id),
        id: spec.id.clone(),
        title: if spec.title.is_empty() {
            spec.citation.clone()
        } else {
            format!("{} ({})", spec.title, spec.citation)
        },
        file: spec.file.clone(),
        location: spec.file.clone(),
        order: usize::MAX - 1,
        battery: false,
    }
}

/// The report document of a spec's standard battery: the tool's own
/// checks of the basis, after the file's claims and counted apart.
pub fn battery_document(spec: &Spec) -> Document {
    Document {
        heading: format!("Standard battery of {}", spec.id),
        id: format!("{} battery", spec.id),
        title: "checks the tool runs on every basis, not claims of the paper (counted apart)"
            .into(),
        file: spec.file.clone(),
        location: spec.file.clone(),
        order: usize::MAX,
        battery: true,
    }
}

/// The opening sentences of a spec report (`battery`: the standard
/// battery was run).
pub fn intro(spec: &Spec, battery: bool) -> String {
    let mut intro = format!(
        "Every verdict below is computed by `trig-audit audit --spec {}` from the formulas of the spec file; identities are decided exactly in the symbolic ring, inequalities by certified Bernstein subdivision, counterexamples in 256-bit MPFR.",
        spec.file
    );
    if battery {
        intro.push_str(" The standard battery (the tool's own checks of every basis, not claims of the file) is counted apart: the total (all) counts the file's claims only.");
    }
    intro
}

/// The file's claims, then the standard battery.
pub fn audit(spec: &Spec) -> Vec<Entry> {
    audit_within(spec, None, None, true).entries
}

/// The real points of the basis for its witnesses: the domain and the
/// declared parameter sets (unbounded ones truncated as for the interval
/// engine).
fn real_points(spec: &Spec) -> RealPoints {
    RealPoints {
        domain: spec.domain.clone(),
        axes: trig_judge::by_intervals::axes(spec, None).0,
        symbols: spec.params.iter().map(|p| p.symbol.clone()).collect(),
    }
}

/// A decision of the audit, run on the spec.
type Decision<T> = Box<dyn FnOnce(&Spec) -> T + Send>;

/// An audit whose decisions had a time limit.
#[derive(Debug, Clone)]
pub struct Audit {
    /// The claims, with their verdicts; a claim the time limit cut off is
    /// `not-checkable` with the limit as the reason.
    pub entries: Vec<Entry>,
    /// The ids of the claims the time limit cut off.
    pub cut_off: Vec<String>,
}

/// [`audit`], each decision limited to `budget` of time: a decision that
/// runs over gets no verdict and is listed in [`Audit::cut_off`] (see
/// [`crate::budget`]), so every verdict printed is the one any machine
/// computes. With `only`, just the entry of that id (case-insensitive) is
/// decided — the others are not computed at all. Without `battery`, the
/// standard battery is not run.
pub fn audit_within(
    spec: &Spec,
    budget: Option<Duration>,
    only: Option<&str>,
    battery: bool,
) -> Audit {
    let (paper, checks) = (document(spec), battery_document(spec));
    let shared = Arc::new(spec.clone());
    let wanted = |id: &str| only.is_none_or(|c| id.eq_ignore_ascii_case(c));
    // every witness at a real point of the basis, within the budget
    let run = |f: Decision<(String, Verdict)>| -> Option<(String, Verdict)> {
        let f: Decision<(String, Verdict)> =
            Box::new(move |s: &Spec| with_real_points(real_points(s), || f(s)));
        match budget {
            None => Some(f(spec)),
            Some(limit) => {
                let s = Arc::clone(&shared);
                decided(bounded(limit, move || f(&s)), |v| (String::new(), v))
            }
        }
    };
    let mut audit = Audit {
        entries: Vec::new(),
        cut_off: Vec::new(),
    };
    // an entry whose statement the decision may state (symmetry names the
    // exchange it found); `statement` is used when it does not
    let mut entry = |doc: &Document,
                     id: &str,
                     source: &str,
                     statement: String,
                     decide: Decision<(String, Verdict)>| {
        if !wanted(id) || (doc.battery && !battery) {
            return;
        }
        match run(decide) {
            Some((stated, verdict)) => audit.entries.push(Entry {
                id: id.to_string(),
                document: doc.clone(),
                source: source.to_string(),
                statement: if stated.is_empty() { statement } else { stated },
                verdict,
                figure: None,
            }),
            None => {
                audit.cut_off.push(id.to_string());
                audit.entries.push(Entry {
                    id: id.to_string(),
                    document: doc.clone(),
                    source: source.to_string(),
                    statement,
                    verdict: Verdict::not_checkable(cut_off_reason(budget)),
                    figure: None,
                });
            }
        }
    };
    let plain = |f: fn(&Spec) -> Verdict| -> Decision<(String, Verdict)> {
        Box::new(move |s: &Spec| (String::new(), f(s)))
    };
    let names = spec
        .functions
        .iter()
        .map(|f| f.name.as_str())
        .collect::<Vec<_>>()
        .join(", ");
    entry(
        &checks,
        "unity",
        BATTERY,
        format!(
            "partition of unity: {}",
            trig_judge::unity::sum_label(
                &spec
                    .functions
                    .iter()
                    .map(|f| f.name.clone())
                    .collect::<Vec<_>>()
            )
        ),
        plain(trig_judge::unity::unity),
    );
    entry(
        &checks,
        "nonnegativity",
        BATTERY,
        format!("{names} ≥ 0 on the domain exactly for the declared parameter ranges"),
        plain(trig_judge::nonnegative::nonnegativity),
    );
    entry(
        &checks,
        "symmetry",
        BATTERY,
        "symmetry of the functions".into(),
        Box::new(|s: &Spec| trig_judge::symmetry::battery_symmetry(s)),
    );
    entry(&checks, "interpolation", BATTERY, "endpoint interpolation: only the first function is nonzero at the start (value 1), only the last at the end (value 1)".into(), plain(trig_judge::endpoint::interpolation));
    entry(
        &checks,
        "derivatives",
        BATTERY,
        format!(
            "exact endpoint derivatives of orders 0–{} {}, by jets and by symbolic differentiation",
            TABLE_ORDERS - 1,
            trig_judge::domain::describe_wrt(spec, table_wrt(spec))
        ),
        plain(|s| trig_judge::endpoint::derivative_table(s, table_wrt(s))),
    );
    for order in [1, 2] {
        entry(
            &checks,
            &format!("join-C{order}"),
            BATTERY,
            format!(
                "C{order} join of Σ b_i P_i (end) and Σ b_i Q_i (start): derived conditions on Q"
            ),
            Box::new(move |s: &Spec| (String::new(), trig_judge::join::derived_join(s, order))),
        );
    }
    for c in &spec.claims {
        let claim = c.clone();
        entry(
            &paper,
            &c.id,
            &c.source,
            c.statement.clone(),
            Box::new(move |s: &Spec| (String::new(), decide(s, &claim))),
        );
    }
    // the file's claims first, the battery after them, each claim with the
    // figure its file gives (from the current directory)
    audit.entries.sort_by_key(|e| e.document.battery);
    for e in audit.entries.iter_mut().filter(|e| !e.document.battery) {
        let claim = spec.claims.iter().find(|c| c.id == e.id);
        e.figure = claim
            .and_then(|c| c.figure.as_ref())
            .map(|f| crate::figures::Figure::of(f, std::path::Path::new("")));
    }
    audit
}

/// The source of the standard battery's entries.
const BATTERY: &str = "standard battery";

/// Why a claim cut off by the time limit has no decision: the limit, and
/// that it is the one `not-checkable` that depends on the machine.
fn cut_off_reason(budget: Option<Duration>) -> String {
    format!(
        "cut off by the time limit of {} s per claim (--time-limit): the decision did not finish in time on this machine, so it reached no verdict; a longer limit may decide it",
        budget.map_or(0.0, |b| b.as_secs_f64())
    )
}

/// The verdict of a decision that ran with a time limit: `None` when the
/// limit cut it off, `not-checkable` when it could not run.
fn decided<T>(result: Result<T, Stopped>, failed: impl FnOnce(Verdict) -> T) -> Option<T> {
    match result {
        Ok(v) => Some(v),
        Err(Stopped::CutOff) => None,
        Err(Stopped::Failed(why)) => Some(failed(Verdict::not_checkable(why))),
    }
}

/// [`decide`] with every witness at a real point of the basis, as the
/// audit of a file decides each claim: a claim of a document file.
pub fn decide_in(spec: &Spec, claim: &SpecClaim) -> Verdict {
    with_real_points(real_points(spec), || decide(spec, claim))
}

/// The verdict of one claim of the file: the values it fixes substituted
/// and the ranges it gives put in place first (`trig_specfile::Given`); a
/// claim stated as the negation of its check holds where the check fails.
/// The file's notes follow the evidence.
pub fn decide(spec: &Spec, claim: &SpecClaim) -> Verdict {
    let v = decide_stated(spec, claim);
    let mut v = if claim.negated {
        negation::negation(v, || negation::instance(spec, claim))
    } else {
        v
    };
    v.evidence.extend(claim.notes.iter().map(String::as_str));
    v
}

/// The verdict of an umbrella over parts about several bases (a document
/// file's `[[claims.parts]]`): each part decided on its own basis as it is
/// stated and shown under its statement; the umbrella holds when every
/// counted part holds, fails when one fails, otherwise it is not-checkable.
/// A part shown for information (`shown = true`) keeps its own verdict in
/// its label and never decides. The notes follow the evidence.
pub fn decide_parts(parts: &[(&Spec, &trig_specfile::Part)], notes: &[String]) -> Verdict {
    let decided: Vec<(String, bool, Verdict)> = parts
        .iter()
        .map(|(spec, part)| {
            let v = decide_in(spec, &part.claim);
            (part.claim.statement.clone(), part.shown, v)
        })
        .collect();
    let status = Status::conjunction(
        decided
            .iter()
            .filter(|(_, shown, _)| !shown)
            .map(|(_, _, v)| v.status),
    );
    let evidence: Vec<Evidence> = decided
        .into_iter()
        .flat_map(|(name, shown, v)| {
            let name = if shown {
                format!("{name} (shown, not a condition of the claim)")
            } else {
                name
            };
            v.into_part(&name)
        })
        .collect();
    let mut v = Verdict::new(status, PARTS, evidence);
    v.evidence.extend(notes.iter().map(String::as_str));
    v
}

const PARTS: &str = "every part decided on its own basis as it is stated: the claim holds when every part holds, fails when one fails";

fn decide_stated(spec: &Spec, claim: &SpecClaim) -> Verdict {
    if claim.given.is_empty() {
        return decide_check(spec, &claim.check);
    }
    if !claim.given.exact.is_empty() {
        return exact_ends(spec, claim);
    }
    let given = claim.given.describe(spec);
    if let Check::Independent { maximal: true, .. } = claim.check
        && !claim.given.ranges.is_empty()
    {
        return maximal_independent(spec, claim, &given);
    }
    match claim.given.apply(spec, &claim.check) {
        Ok((fixed, check)) => {
            let mut v = with_real_points(real_points(&fixed), || decide_check(&fixed, &check));
            v.evidence.insert(
                0,
                format!(
                    "decided at {given}, as the claim states: {}",
                    if claim.given.knots.is_some() && claim.given.ranges.is_empty() && claim.given.fixed.is_empty() {
                        "the segment functions of that span formed from the basis's functions before deciding"
                    } else if claim.given.fixed.is_empty() && claim.given.between.is_empty() {
                        "these ranges in place of the declared ones"
                    } else {
                        "the values substituted into the formulas of the basis and of the claim before deciding"
                    }
                ),
            );
            v
        }
        // the printed construction on the claim's knots is undefined: the
        // claim about it is refuted by the knots it names
        Err(e @ trig_specfile::GivenError::Coefficients { .. }) => {
            Verdict::new(Status::Fails, KNOTS, vec![e.to_string()])
        }
        Err(e) => Verdict::not_checkable(format!("the claim fixes {given}, where {e}")),
    }
}

/// How a claim on knots where the printed coefficient formulas are
/// undefined is decided.
const KNOTS: &str = "the printed coefficient formulas evaluated exactly on the claim's knots";

/// `maximal = true` on `independent` with the claim's own ranges: the
/// declared ranges (with the claim's fixed values, if any) against the
/// claim's.
fn maximal_independent(spec: &Spec, claim: &SpecClaim, given: &str) -> Verdict {
    if !claim.given.between.is_empty() {
        return Verdict::not_checkable(
            "a maximal set of independence against a region bounded by lines is not decided (own ranges of the parameters only)",
        );
    }
    let mut fixed_only = claim.given.clone();
    fixed_only.ranges.clear();
    let applied = claim
        .given
        .apply(spec, &claim.check)
        .and_then(|(claimed, _)| Ok((fixed_only.apply(spec, &claim.check)?.0, claimed)));
    match applied {
        Ok((declared, claimed)) => {
            let mut v = trig_judge::independence::maximal(&declared, &claimed, None);
            v.evidence.insert(
                0,
                format!("decided at {given}, as the claim states, within the declared ranges"),
            );
            v
        }
        Err(e) => Verdict::not_checkable(format!("the claim fixes {given}, where {e}")),
    }
}

/// A claim over ranges with ends beyond the rationals
/// (`trig_judge::exact_ends`): decided over rational ranges put in their
/// place, and for nonnegativity (the convex hull's part of it with unity
/// beside) at the printed end exactly.
fn exact_ends(spec: &Spec, claim: &SpecClaim) -> Verdict {
    let with = |check: Check| {
        move |ranges: &[(String, trig_core::ParamRange)]| {
            let mut c = claim.clone();
            c.check = check.clone();
            c.given.exact.clear();
            c.given.ranges.extend(ranges.iter().cloned());
            decide(spec, &c)
        }
    };
    // the functions and margin of a nonnegativity claim (all, none for the
    // convex hull's)
    let (functions, margin) = match &claim.check {
        Check::Nonnegative {
            functions, margin, ..
        } => (functions.clone(), margin.clone()),
        _ => (Vec::new(), None),
    };
    let narrowed = spec.narrowed(&functions, margin.as_ref());
    let nonnegativity = |maximal: bool| {
        trig_judge::exact_ends::decide(
            &narrowed,
            &claim.given.exact,
            Some(maximal),
            &with(Check::Nonnegative {
                range: None,
                maximal,
                functions: functions.clone(),
                margin: margin.clone(),
            }),
        )
    };
    match &claim.check {
        Check::Nonnegative { maximal, .. } => nonnegativity(*maximal),
        Check::ConvexHull { maximal, .. } => Verdict::all(
            trig_judge::certificate::CERTIFIED,
            vec![
                ("partition of unity".into(), trig_judge::unity::unity(spec)),
                ("nonnegativity".into(), nonnegativity(*maximal)),
            ],
        ),
        Check::TotalPositivity { maximal: true, .. } => Verdict::not_checkable(
            "a maximal set of total positivity against a printed end beyond the rationals is not decided (exact ends are compared for nonnegativity only)",
        ),
        Check::Independent { maximal: true, .. } => Verdict::not_checkable(
            "a maximal set of independence against a printed end beyond the rationals is not decided (exact ends are compared for nonnegativity only)",
        ),
        check => {
            trig_judge::exact_ends::decide(spec, &claim.given.exact, None, &with(check.clone()))
        }
    }
}

/// The verdict of one check on the spec as it is.
fn decide_check(spec: &Spec, check: &Check) -> Verdict {
    match check {
        Check::Unity => trig_judge::unity::unity(spec),
        Check::Nonnegative {
            range,
            maximal,
            functions,
            margin,
        } => trig_judge::nonnegative::nonnegative_claim(
            &spec.narrowed(functions, margin.as_ref()),
            range.as_ref(),
            *maximal,
        ),
        Check::ConvexHull { range, maximal } => {
            trig_judge::nonnegative::convex_hull_claim(spec, range.as_ref(), *maximal)
        }
        Check::Conic {
            points,
            points_text,
            equation,
            equation_text,
            singular,
            quantifier,
        } => {
            let mut v = match quantifier {
                None => trig_judge::span::conic(spec, points, equation, equation_text),
                Some(q) => trig_judge::exceptional::quantified(
                    spec,
                    &trig_judge::span::conic_label(equation_text),
                    &trig_judge::span::conic_residual(spec, points, equation),
                    *q,
                ),
            };
            v.evidence.insert(
                0,
                format!("control points as printed: {}", points_text.join("; ")),
            );
            for why in singular {
                v.evidence.push(format!(
                    "the printed points are singular inside the ranges: {why}"
                ));
            }
            v
        }
        Check::Independent {
            range,
            maximal: false,
        } => trig_judge::independence::independent(spec, range.as_ref()),
        Check::Independent {
            range,
            maximal: true,
        } => trig_judge::independence::maximal(spec, spec, range.as_ref()),
        Check::TotalPositivity {
            range,
            maximal: false,
        } => trig_judge::total_positivity::normalized_totally_positive(spec, range.as_ref()),
        Check::TotalPositivity {
            range,
            maximal: true,
        } => trig_judge::tp_maximal::maximal_totally_positive(spec, range.as_ref()),
        Check::Monotone { items, range } => {
            trig_judge::nonnegative::monotone_claim(spec, items, range.as_ref())
        }
        Check::EndCurvature {
            curve,
            polygon,
            curves,
        } => trig_judge::end_curvature::end_curvature(
            curve,
            polygon,
            &trig_judge::end_curvature::curves_of(spec, curves),
        ),
        Check::ShapeEffect {
            parameters,
            target,
            either,
            range,
            polygons,
        } => {
            let mut v = trig_judge::shape_effect::shape_effect(
                spec,
                parameters,
                target,
                *either,
                range.as_ref(),
            );
            if let (Some(p), [parameter]) = (polygons, parameters.as_slice()) {
                let at: Vec<(&str, rug::Rational)> =
                    p.at.iter().map(|(n, x)| (n.as_str(), x.clone())).collect();
                v.evidence.extend(p.polygons.iter().map(|q| {
                    trig_judge::shape_effect::polygon_distances(spec, q, &at, parameter, &p.values)
                }));
            }
            v
        }
        Check::Symmetry {
            map_text,
            map,
            index_text,
            offset,
            at,
            params,
            params_text,
        } => trig_judge::symmetry::symmetry_claim(
            spec,
            &trig_judge::symmetry::PrintedSymmetry {
                map_text,
                map,
                index_text,
                offset: *offset,
                at,
                params,
                params_text,
            },
        ),
        Check::EndpointValues { end, values } => {
            trig_judge::endpoint::endpoint_values(spec, *end, values)
        }
        Check::EndpointDerivatives {
            wrt,
            values,
            curves,
        } => trig_judge::endpoint::endpoint_derivative_values(spec, *wrt, values, curves),
        Check::CurveDerivative {
            end,
            order,
            wrt,
            text,
            value,
        } => trig_judge::curve::curve_derivative(spec, *end, *order, *wrt, text, value),
        Check::Join {
            kind,
            wrt,
            declared,
            different,
            factors,
            reversed,
            conditions,
            segments,
        } => joins::printed_join(
            spec,
            joins::Stated {
                kind: *kind,
                wrt: *wrt,
                declared: *declared,
                different: *different,
                reversed: *reversed,
                segments,
            },
            factors,
            conditions,
        ),
        Check::JoinSingular {
            wrt,
            copies,
            values,
        } => joins::join_singular(spec, *wrt, copies, values),
        Check::Continuity { order, of } => continuity_of(spec, *order, of),
        Check::All { claims, brief } => umbrella_verdict(
            claims
                .iter()
                .filter_map(|id| spec.claims.iter().find(|c| &c.id == id))
                .map(|c| (c.id.clone(), decide(spec, c)))
                .collect(),
            *brief,
        ),
        Check::NotPrinted { reason } => Verdict::not_checkable(reason.clone()),
        Check::InterpolantNonnegative { data, scheme, .. } => {
            trig_judge::interpolant::nonnegative(spec, data, *scheme)
        }
        Check::InterpolantContinuity {
            data,
            scheme,
            order,
            ..
        } => trig_judge::interpolant_jumps::continuity(spec, data, *scheme, *order),
        Check::TableArithmetic { text, .. } => trig_judge::table_arithmetic::decide(text),
        Check::TableQuotes { text, quotes, .. } => trig_judge::table_quotes::decide(text, quotes),
        Check::TableCompare { text, quotes, .. } => trig_judge::table_compare::decide(text, quotes),
        Check::TableCount { text, counts, .. } => trig_judge::table_count::decide(text, counts),
        Check::DataValues { data, queries, .. } => trig_judge::data_values::decide(data, queries),
        Check::InterpolantMaximum {
            data,
            scheme,
            queries,
            ..
        } => trig_judge::interpolant_maximum::maximum(spec, data, *scheme, queries),
        Check::FourierSpan { span } => trig_judge::fourier::in_span(spec, span),
        Check::KnotCoefficients { knots, matrix } => {
            trig_judge::knot_coefficients::knot_coefficients(spec, knots, matrix)
        }
        Check::SurfaceJoin {
            path,
            kind,
            wrt,
            nets,
            seams,
        } => trig_judge::surface_join::surface_join(spec, *kind, *wrt, path, nets, seams),
        Check::Cylinder { net, radius, .. } => {
            trig_judge::surface::net_cylinder_distance(spec, net, radius)
        }
        Check::LeavesHull {
            parameter,
            values,
            polygons,
            net,
        } => trig_judge::leaves_hull::leaves_hull(spec, parameter, values, polygons, net.as_ref()),
        Check::OneMaximum => {
            trig_judge::maxima::exactly_one_maximum(spec, &trig_judge::exact::basis_of(spec))
        }
        Check::Identity { .. } => trig_judge::identity::printed_identities(
            spec,
            &trig_judge::identity::Printed::of(check).expect("an identity check"),
        ),
        Check::EndDirection {
            end,
            order,
            wrt,
            along,
            positive,
            range,
            limit,
        } => trig_judge::end_direction::end_direction(
            spec,
            &trig_judge::end_direction::Direction {
                end: *end,
                order: *order,
                wrt: *wrt,
                along: *along,
                sign: if *positive {
                    trig_judge::end_direction::FactorSign::Positive
                } else {
                    trig_judge::end_direction::FactorSign::Nonzero
                },
                range: range.as_ref(),
                limit: limit.as_deref(),
            },
        ),
        Check::SameBasis {
            other,
            params,
            params_text,
            ..
        } => trig_judge::same_basis::same_basis(spec, other.as_ref(), params, params_text),
        Check::LocalControl {
            rational: Some(curve),
            segments,
            first,
            ..
        } => trig_judge::local_control::rational_local_control(
            spec,
            &curve.curve,
            &curve.point,
            *first,
            segments,
        ),
        Check::LocalControl {
            varied,
            segments,
            also,
            first,
            rational: None,
        } => {
            let control = |varied: &Varied| match varied {
                Varied::Point => Control::Point,
                Varied::Parameter {
                    name,
                    per_segment: true,
                } => Control::SegmentParameter {
                    name: name.clone(),
                    shift: 0,
                },
                Varied::Parameter { name, .. } => Control::CurveParameter { name: name.clone() },
            };
            let mut v =
                trig_judge::local_control::local_control(spec, &control(varied), *first, segments);
            if let Some(also) = also {
                v.evidence.push(trig_judge::local_control::other_reading(
                    spec,
                    &control(also),
                    segments,
                ));
            }
            v
        }
    }
}

/// The convention of the standard table: the angle for formulas in
/// `s`, `c` alone, the variable otherwise.
fn table_wrt(spec: &Spec) -> Wrt {
    let declared_angle = spec.shorthand.is_none_or(|k| k == 1);
    if (spec.domain.is_pure_trigonometric() || spec.legacy.is_some()) && declared_angle {
        Wrt::Angle
    } else {
        Wrt::Variable
    }
}

/// `check = "continuity"` on what the claim names ([`Continuous`]).
fn continuity_of(spec: &Spec, order: usize, of: &trig_specfile::Continuous) -> Verdict {
    use trig_judge::continuity::{bspline_continuity, curve_continuity, knot_continuity};
    use trig_specfile::Continuous;
    match of {
        Continuous::Bspline => bspline_continuity(spec, order),
        Continuous::Curve {
            point,
            weights,
            segments,
        } => curve_continuity(spec, order, point, *weights, segments),
        Continuous::Knots(knots) => knot_continuity(spec, order, knots),
    }
}
