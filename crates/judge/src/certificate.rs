//! Verdicts from certificates: what the report says about nonnegativity
//! and maximal parameter ranges.

use rug::Rational;
use trig_certify::standard::PieceMap;
use trig_certify::{Bound, ParamBox, describe_z};

use crate::exact::ExactBasis;
use crate::exact::basis_of;
use trig_certify::nonneg::{BoxCertificate, Certificate, certify, certify_box};
use trig_certify::range::{EndPoint, MaximalRange, Outside, maximal_range};
use trig_verdict::evidence::EvidenceList;
use trig_verdict::evidence::{Evidence, Kind, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;
use trig_verdict::witness::witness;

/// How nonnegativity is decided, as the report states it.
pub const CERTIFIED: &str = "certified: Weierstrass z = tan(θ/2), exact Bernstein subdivision over (z, parameter) boxes in rational arithmetic (denominators proved of one sign first); counterexamples exact and re-evaluated";

/// How a maximal range is decided, as the report states it.
pub const MAXIMAL: &str = "certified: every end of the admissible set is a root of a boundary polynomial (discriminant in z = tan(θ/2) or t, values at the domain ends); its roots are isolated exactly (Sturm) and one certified point test per gap decides where the set ends; ends are exact real algebraic numbers; the interval is then certified by exact Bernstein subdivision";

/// The witness of a counterexample: the parameters, `z = tan(θ/2)` with
/// `s = sin θ`, `c = cos θ` (or `t`), and the exact value of the tested
/// function there (recorded with the function `f` when it is one, so it
/// can be re-checked by substitution).
pub fn counterexample(
    params: &[(&str, &Rational)],
    z: &Rational,
    value: &Rational,
    trig: bool,
    f: Option<&trig_symbolic::Sym>,
) -> Witness {
    let mut point: Vec<(String, Rational)> = params
        .iter()
        .map(|(n, v)| (n.to_string(), (*v).clone()))
        .collect();
    if trig {
        let d = Rational::from(1) + z.clone() * z;
        point.push(("z".into(), z.clone()));
        point.push(("s".into(), Rational::from(2) * z / d.clone()));
        point.push(("c".into(), (Rational::from(1) - z.clone() * z) / d));
    } else {
        point.push(("t".into(), z.clone()));
    }
    let names: Vec<String> = point.iter().map(|(n, _)| n.clone()).collect();
    let mut w = witness(
        &point,
        &names,
        vec![("value", trig_symbolic::Sym::rational(value.clone()))],
    );
    w.values[0].of = f.map(trig_verdict::evidence::Expr::new);
    if trig {
        w.note = Some(format!(
            "z = tan(θ/2), s = sin θ, c = cos θ; θ ≈ {:.6}",
            2.0 * z.to_f64().atan()
        ));
    }
    w
}

/// The evidence item of a certificate about `what`, with its status.
pub fn describe(
    what: &str,
    f: Option<&trig_symbolic::Sym>,
    cert: &Certificate,
    trig: bool,
    param: Option<&str>,
) -> (Status, Evidence) {
    let (status, text, w) = match cert {
        Certificate::NonNegative { boxes } => (
            Status::Holds,
            format!(
                "certified on the whole domain ({} with all coefficients ≥ 0)",
                trig_verdict::plural(*boxes, "Bernstein box", "Bernstein boxes")
            ),
            None,
        ),
        Certificate::Counterexample { p, z, value } => (
            Status::Fails,
            "violated: negative at the witness point".to_string(),
            Some(counterexample(
                &param.map(|n| (n, p)).into_iter().collect::<Vec<_>>(),
                z,
                value,
                trig,
                f,
            )),
        ),
        Certificate::Pole(why) => (
            Status::Fails,
            format!("not defined on the whole domain: {why}"),
            None,
        ),
        Certificate::Undecided(why) => (Status::NotCheckable, format!("undecided ({why})"), None),
    };
    (
        status,
        Evidence::new(Kind::Certificate, text)
            .about(what, status)
            .witnessed(w),
    )
}

/// True when the functions of `basis` are written in `sin θ`, `cos θ`
/// (the certificates then work in `z = tan(θ/2)`).
fn trigonometric<B: ExactBasis>(basis: &B) -> bool {
    basis.variable().map_or_else(
        || basis.domain().is_trigonometric(),
        |v| v.is_trigonometric(),
    )
}

/// Nonnegativity of the functions `fs` of `basis` (named as the basis
/// names them) on a parameter box, or at fixed parameter values
/// substituted beforehand (`param = None`).
pub fn nonnegative_on<B: ExactBasis>(
    basis: &B,
    fs: &[trig_symbolic::Sym],
    param: Option<&str>,
    bx: &ParamBox,
) -> Verdict {
    nonnegative_named(
        trigonometric(basis),
        fs,
        &basis.function_names(),
        param,
        bx,
        &[],
    )
}

/// The same for functions given with their names (any basis, a spec file's
/// included): holds when every one is certified.
pub fn nonnegative_named(
    trig: bool,
    fs: &[trig_symbolic::Sym],
    names: &[impl AsRef<str>],
    param: Option<&str>,
    bx: &ParamBox,
    maps: &[PieceMap],
) -> Verdict {
    let mut status = Status::Holds;
    let mut evidence = EvidenceList::default();
    for (i, (f, name)) in fs.iter().zip(names).enumerate() {
        let (s, mut line) = describe(
            &format!("{} ≥ 0", name.as_ref()),
            Some(f),
            &certify(f, trig, param, bx),
            trig,
            param,
        );
        // a witness on a piece is in the piece's own variable: say so (the
        // recorded formula is the piece's, so the point re-checks as is)
        if let (Some(w), Some(note)) = (line.witness.as_mut(), maps.get(i).and_then(PieceMap::note))
        {
            if matches!(maps.get(i), Some(PieceMap::Quarter(_))) {
                for a in w.point.iter_mut().filter(|a| a.name == "θ") {
                    a.name = "φ".into();
                    a.latex = a.latex.replacen("\\theta", "\\varphi", 1);
                }
            }
            w.note = Some(match &w.note {
                Some(old) => format!(
                    "{note}; {}",
                    old.replace("z = tan(θ/2), s = sin θ, c = cos θ; θ ≈", "φ ≈")
                ),
                None => note,
            });
        }
        status = Status::conjunction([status, s]);
        evidence.push(line);
    }
    Verdict::new(status, CERTIFIED, evidence)
}

/// Nonnegativity of the functions `fs` of `basis` on a box of several
/// parameters (see [`nonnegative_on_box_named`]).
pub fn nonnegative_on_box<B: ExactBasis>(
    basis: &B,
    fs: &[trig_symbolic::Sym],
    params: &[(&str, ParamBox)],
) -> Verdict {
    nonnegative_on_box_named(trigonometric(basis), fs, &basis.function_names(), params)
}

/// Nonnegativity of every function on a box of several parameters (tensor
/// Bernstein subdivision in `(z, p₁, …, p_d)`): holds when every function
/// is certified, fails with an exact counterexample or pole.
pub fn nonnegative_on_box_named(
    trig: bool,
    fs: &[trig_symbolic::Sym],
    names: &[impl AsRef<str>],
    params: &[(&str, ParamBox)],
) -> Verdict {
    let region: Vec<String> = params.iter().map(|(n, bx)| format!("{n} ∈ {bx}")).collect();
    let mut status = Status::Holds;
    let mut evidence = EvidenceList::from(vec![format!("parameter box {}", region.join(" × "))]);
    for (f, name) in fs.iter().zip(names) {
        let name = name.as_ref();
        let (s, text, w) = match certify_box(f, trig, params) {
            BoxCertificate::NonNegative { boxes } => (
                Status::Holds,
                format!(
                    "certified on the whole domain and box ({} with all coefficients ≥ 0)",
                    trig_verdict::plural(boxes, "Bernstein box", "Bernstein boxes")
                ),
                None,
            ),
            BoxCertificate::Counterexample {
                params: at,
                z,
                value,
            } => {
                let named: Vec<(&str, &Rational)> =
                    params.iter().zip(&at).map(|((n, _), v)| (*n, v)).collect();
                (
                    Status::Fails,
                    "violated: negative at the witness point".to_string(),
                    Some(counterexample(&named, &z, &value, trig, Some(f))),
                )
            }
            BoxCertificate::Pole(why) => (
                Status::Fails,
                format!("not defined on the whole domain and box: {why}"),
                None,
            ),
            BoxCertificate::Undecided(why) => {
                (Status::NotCheckable, format!("undecided ({why})"), None)
            }
        };
        status = Status::conjunction([status, s]);
        evidence.push(
            Evidence::new(Kind::Certificate, text)
                .about(format!("{name} ≥ 0"), s)
                .witnessed(w),
        );
    }
    Verdict::new(status, CERTIFIED, evidence)
}

/// Why a parameter value is outside, as the report shows it.
pub(crate) fn show_outside(o: &Outside, param: &str, trig: bool) -> String {
    match o {
        Outside::Counterexample(p, z, v) => format!(
            "counterexample {param} = {p}, {}: value {v} (exact)",
            describe_z(z, trig)
        ),
        Outside::Pole(p, why) => format!("at {param} = {p} a function is not defined: {why}"),
        Outside::Undecided(p) => format!("{param} = {p} not certified either way"),
    }
}

/// One end of a maximal interval, as the report shows it.
pub fn show_end(e: &EndPoint, param: &str, trig: bool) -> String {
    match e {
        EndPoint::Exact {
            value,
            closed,
            inside,
            outside,
        } => {
            let kind = if value.rational.is_some() {
                "rational"
            } else {
                "irrational"
            };
            format!(
                "exact end {} ({kind}, {}), proved: a root of the boundary polynomial {}; the gaps between boundary roots up to it are admissible (the last certified at {param} = {inside}), the gap beyond it is not: {}",
                value.describe(param, 12),
                if *closed { "included" } else { "excluded" },
                value.poly_text(param),
                show_outside(outside, param, trig)
            )
        }
        EndPoint::Bracket {
            ok,
            bad,
            outside,
            why,
        } => format!(
            "bracket only (not an exact end: {why}): the end lies in ({}, {}); {}",
            trig_certify::algebraic::decimal(ok, 15, false),
            trig_certify::algebraic::decimal(bad, 15, true),
            show_outside(outside, param, trig)
        ),
        EndPoint::Unbounded => {
            "none: admissible on the whole half-line (every gap between boundary roots certified)"
                .into()
        }
        EndPoint::Undecided { at, why } => format!("not decided: {why} ({param} = {at})"),
    }
}

/// The found interval, e.g. `[-2, 1]` or `[0, root of … ]`.
fn show_interval(r: &MaximalRange, param: &str) -> String {
    let end = |e: &EndPoint, lower: bool| match e {
        EndPoint::Exact { value, closed, .. } => {
            let v = match &value.rational {
                Some(q) => q.to_string(),
                None => format!(
                    "≈{}",
                    trig_certify::algebraic::decimal(&value.lo, 12, !lower)
                ),
            };
            let bracket = match (lower, closed) {
                (true, true) => "[",
                (true, false) => "(",
                (false, true) => "]",
                (false, false) => ")",
            };
            if lower {
                format!("{bracket}{v}")
            } else {
                format!("{v}{bracket}")
            }
        }
        EndPoint::Bracket { ok, bad, .. } => {
            let (a, b) = if lower { (bad, ok) } else { (ok, bad) };
            format!("end in ({:.15}, {:.15})", a.to_f64(), b.to_f64())
        }
        EndPoint::Unbounded if lower => "(-inf".into(),
        EndPoint::Unbounded => "+inf)".into(),
        EndPoint::Undecided { .. } => "?".into(),
    };
    let _ = param;
    format!("{}, {}", end(&r.lo, true), end(&r.hi, false))
}

/// The maximal nonnegativity interval of a one-parameter basis, compared
/// with its published range (see [`maximal_against`]).
pub fn maximal_versus_published<B: ExactBasis>(basis: &B) -> (MaximalRange, Verdict) {
    let p = &basis.parameters()[0];
    let published = Published {
        name: &p.name,
        symbol: &p.symbol,
        range: p.range.to_string(),
        set: ParamBox::from_range(&p.range),
        source: &p.source,
    };
    maximal_against(
        &basis_of(basis),
        &basis.function_names(),
        trigonometric(basis),
        &published,
    )
}

/// A published parameter range, as the report cites it.
#[derive(Debug, Clone)]
pub struct Published<'a> {
    pub name: &'a str,
    pub symbol: &'a str,
    /// The range as printed.
    pub range: String,
    /// The range as a set.
    pub set: ParamBox,
    pub source: &'a str,
}

impl Published<'_> {
    /// A point strictly inside the range, where the search starts.
    fn start(&self) -> Rational {
        match (self.set.lo.value(), self.set.hi.value()) {
            (Some(a), Some(b)) => Rational::from(a + b) / 2u32,
            (Some(a), None) => a.clone() + 1u32,
            (None, Some(b)) => b.clone() - 1u32,
            (None, None) => Rational::new(),
        }
    }
}

/// The maximal nonnegativity interval of `fs` around a point inside the
/// published range, compared with it. Holds when both ends are proved and
/// equal to the published ones (value and inclusion); fails when they are
/// proved different, when the start is not admissible, or when a bracket
/// excludes the published end; not-checkable when a decision could not be
/// completed.
pub fn maximal_against(
    fs: &[trig_symbolic::Sym],
    names: &[impl AsRef<str>],
    trig: bool,
    published: &Published<'_>,
) -> (MaximalRange, Verdict) {
    let name = published.name;
    let start = published.start();
    let names: Vec<&str> = names.iter().map(AsRef::as_ref).collect();
    let r = maximal_range(fs, &names, trig, name, &start);
    let mut evidence = EvidenceList::from(vec![format!(
        "published range of {}: {} ({})",
        published.symbol, published.range, published.source
    )]);
    if let Some(o) = &r.start_outside {
        evidence.push(format!(
            "the search starts inside the published range at {name} = {start}, which is not admissible: {}",
            show_outside(o, name, trig)
        ));
        let status = match o {
            Outside::Undecided(_) => Status::NotCheckable,
            _ => Status::Fails,
        };
        return (r, Verdict::new(status, MAXIMAL, evidence));
    }
    evidence.push(format!(
        "maximal interval containing {start} on which every function is ≥ 0: {}",
        show_interval(&r, name)
    ));
    evidence.push(format!("lower end: {}", show_end(&r.lo, name, trig)));
    evidence.push(format!("upper end: {}", show_end(&r.hi, name, trig)));
    let (cs, cline) = describe(
        "cross-check, every function ≥ 0 on the closed rational part of the interval",
        None,
        &r.certificate,
        trig,
        Some(name),
    );
    evidence.push(cline);
    let ends = [
        (&r.lo, &published.set.lo, true),
        (&r.hi, &published.set.hi, false),
    ];
    let mut status = Status::conjunction(
        ends.into_iter()
            .map(|(found, printed, lower)| end_status(found, printed, lower)),
    );
    let bracketed =
        matches!(r.lo, EndPoint::Bracket { .. }) || matches!(r.hi, EndPoint::Bracket { .. });
    if cs == Status::Fails || (bracketed && cs != Status::Holds) {
        evidence
            .push("the certificate of the interval is missing or contradicts the ends: no verdict");
        status = Status::NotCheckable;
    }
    (r, Verdict::new(status, MAXIMAL, evidence))
}

/// Whether a found end matches the printed one: proved equal (holds),
/// proved different (fails), or not decided.
fn end_status(found: &EndPoint, printed: &Bound, lower: bool) -> Status {
    match found {
        EndPoint::Exact { .. } | EndPoint::Unbounded => {
            if found.rational_bound().as_ref() == Some(printed) {
                Status::Holds
            } else {
                Status::Fails
            }
        }
        EndPoint::Bracket { ok, bad, .. } => match printed.value() {
            // the end lies strictly between ok and bad
            Some(v) if (lower && (v > ok || v <= bad)) || (!lower && (v < ok || v >= bad)) => {
                Status::Fails
            }
            None => Status::Fails,
            Some(_) => Status::NotCheckable,
        },
        EndPoint::Undecided { .. } => Status::NotCheckable,
    }
}

/// Monotonicity of function `index` of `basis` on its whole domain for
/// every parameter in the box: the sign of its derivative, certified.
pub fn monotone<B: ExactBasis>(
    basis: &B,
    index: usize,
    increasing: bool,
    param: Option<&str>,
    bx: &ParamBox,
) -> Verdict {
    monotone_named(
        &basis_of(basis)[index],
        &basis.function_names()[index],
        trigonometric(basis),
        increasing,
        param,
        bx,
    )
}

/// The same for one function `f` named `name` (any basis).
pub fn monotone_named(
    f: &trig_symbolic::Sym,
    name: &str,
    trig: bool,
    increasing: bool,
    param: Option<&str>,
    bx: &ParamBox,
) -> Verdict {
    let d = if trig { f.d_angle() } else { f.d_t() };
    let g = if increasing { d } else { -d };
    // the variable of differentiation: the angle θ of s = sin θ, c = cos θ
    // (θ = πu/2 for a variable u: the same sign), or t
    let dx = if trig { "dθ" } else { "dt" };
    let what = if increasing {
        format!("d{name}/{dx} ≥ 0 ({name} increasing)")
    } else {
        format!("−d{name}/{dx} ≥ 0 ({name} decreasing)")
    };
    let (status, line) = describe(&what, Some(&g), &certify(&g, trig, param, bx), trig, param);
    Verdict::new(status, CERTIFIED, vec![line])
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    #[test]
    fn undecided_ends_are_never_failures() {
        let q = |a: i64, b: i64| Rational::from((a, b));
        let undecided = EndPoint::Undecided {
            at: q(1, 1),
            why: "depth".into(),
        };
        assert_eq!(
            end_status(&undecided, &Bound::Closed(q(1, 1)), false),
            Status::NotCheckable
        );
        let bracket = EndPoint::Bracket {
            ok: q(1, 1),
            bad: q(11, 10),
            outside: Outside::Undecided(q(11, 10)),
            why: "no boundary polynomial".into(),
        };
        // the printed end 21/20 lies in the bracket: not decided
        assert_eq!(
            end_status(&bracket, &Bound::Closed(q(21, 20)), false),
            Status::NotCheckable
        );
        // the printed end 2 lies beyond the inadmissible 11/10: refuted
        assert_eq!(
            end_status(&bracket, &Bound::Closed(q(2, 1)), false),
            Status::Fails
        );
        assert_eq!(
            end_status(&EndPoint::Unbounded, &Bound::Infinite, false),
            Status::Holds
        );
    }

    #[test]
    fn monotonicity_is_proved_or_refuted() {
        let range = ParamBox::closed(Rational::from(-2), Rational::from(1));
        assert_eq!(
            monotone(&Family::ThesisCubic, 0, false, Some("m"), &range).status,
            Status::Holds
        );
        assert_eq!(
            monotone(&Family::ThesisCubic, 0, true, Some("m"), &range).status,
            Status::Fails
        );
        assert_eq!(
            monotone(&Family::ThesisCubic, 2, true, Some("m"), &range).status,
            Status::Fails
        );
    }
}
