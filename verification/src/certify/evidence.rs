//! Verdicts from certificates: what the report says about nonnegativity
//! and maximal parameter ranges.

use rug::Rational;
use trig_core::{Bound, Family, Range};

use super::nonneg::{BoxCertificate, Certificate, ParamBox, certify, certify_box, describe_z};
use super::range::{EndPoint, MaximalRange, Outside, certify_all, maximal_range};
use crate::exact::basis;
use crate::verdict::{Status, Verdict};

/// How nonnegativity is decided, as the report states it.
pub const CERTIFIED: &str = "certified: Weierstrass z = tan(θ/2), exact Bernstein subdivision over (z, parameter) boxes in rational arithmetic; counterexamples exact";

/// One line for a certificate about `what`.
pub fn describe(
    what: &str,
    cert: &Certificate,
    trig: bool,
    param: Option<&str>,
) -> (Status, String) {
    match cert {
        Certificate::NonNegative { boxes } => (
            Status::Holds,
            format!(
                "{what}: certified on the whole domain ({boxes} Bernstein boxes with all coefficients ≥ 0)"
            ),
        ),
        Certificate::Counterexample { p, z, value } => (
            Status::Fails,
            format!(
                "{what}: violated at {}{}, where the tested quantity equals {value} (exact)",
                param.map_or(String::new(), |n| format!("{n} = {p}, ")),
                describe_z(z, trig)
            ),
        ),
        Certificate::Undecided(why) => (Status::NotCheckable, format!("{what}: undecided ({why})")),
    }
}

/// Nonnegativity of every function of a family on a parameter box (or at
/// fixed parameter values substituted beforehand, `param = None`).
pub fn nonnegative_on(
    family: Family,
    fs: &[trig_symbolic::Sym],
    param: Option<&str>,
    bx: &ParamBox,
) -> Verdict {
    let info = family.info();
    nonnegative_named(
        info.variable.is_trigonometric(),
        fs,
        info.functions,
        param,
        bx,
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
) -> Verdict {
    let mut status = Status::Holds;
    let mut evidence = Vec::new();
    for (f, name) in fs.iter().zip(names) {
        let (s, line) = describe(
            &format!("{} ≥ 0", name.as_ref()),
            &certify(f, trig, param, bx),
            trig,
            param,
        );
        if s != Status::Holds && status == Status::Holds {
            status = s;
        }
        evidence.push(line);
    }
    Verdict::new(status, CERTIFIED, evidence)
}

/// Nonnegativity of every function of a family on a box of several
/// parameters (tensor Bernstein subdivision in `(z, p₁, …, p_d)`): holds
/// when every function is certified, fails with an exact counterexample.
pub fn nonnegative_on_box(
    family: Family,
    fs: &[trig_symbolic::Sym],
    params: &[(&str, ParamBox)],
) -> Verdict {
    let info = family.info();
    let trig = info.variable.is_trigonometric();
    let show_box = |bx: &ParamBox| match bx {
        ParamBox::Interval(a, b) => format!("[{a}, {b}]"),
        ParamBox::FromTo(a) => format!("[{a}, ∞)"),
    };
    let region: Vec<String> = params
        .iter()
        .map(|(n, bx)| format!("{n} ∈ {}", show_box(bx)))
        .collect();
    let mut status = Status::Holds;
    let mut evidence = vec![format!("parameter box {}", region.join(" × "))];
    for (f, name) in fs.iter().zip(info.functions) {
        let (s, line) = match certify_box(f, trig, params) {
            BoxCertificate::NonNegative { boxes } => (
                Status::Holds,
                format!(
                    "{name} ≥ 0: certified on the whole domain and box ({boxes} Bernstein boxes with all coefficients ≥ 0)"
                ),
            ),
            BoxCertificate::Counterexample {
                params: at,
                z,
                value,
            } => {
                let ps: Vec<String> = params
                    .iter()
                    .zip(&at)
                    .map(|((n, _), v)| format!("{n} = {v}"))
                    .collect();
                (
                    Status::Fails,
                    format!(
                        "{name} ≥ 0: violated at {}, {}, where it equals {value} (exact)",
                        ps.join(", "),
                        describe_z(&z, trig)
                    ),
                )
            }
            BoxCertificate::Undecided(why) => (
                Status::NotCheckable,
                format!("{name} ≥ 0: undecided ({why})"),
            ),
        };
        if s != Status::Holds && status == Status::Holds {
            status = s;
        }
        evidence.push(line);
    }
    Verdict::new(status, CERTIFIED, evidence)
}

/// One end of a maximal interval, as the report shows it.
pub fn show_end(e: &EndPoint, param: &str, trig: bool) -> String {
    let outside = |o: &Outside| match o {
        Outside::Counterexample(p, z, v) => {
            format!(
                "counterexample {param} = {p}, {}: value {v}",
                describe_z(z, trig)
            )
        }
        Outside::Undecided(p) => format!("{param} = {p} not certified either way"),
    };
    match e {
        EndPoint::Exact { value, outside: o } => {
            format!("exact end {value}; just beyond, {}", outside(o))
        }
        EndPoint::Bracket {
            ok,
            bad,
            outside: o,
        } => {
            format!(
                "end in ({:.15}, {:.15}); {}",
                ok.to_f64(),
                bad.to_f64(),
                outside(o)
            )
        }
        EndPoint::Unbounded => "unbounded".into(),
    }
}

/// The maximal nonnegativity interval of a one-parameter family, compared
/// with its published range. Holds when they coincide (ends and their
/// inclusion), fails otherwise; the interval and certificates are evidence.
pub fn maximal_versus_published(family: Family) -> (MaximalRange, Verdict) {
    let info = family.info();
    let spec = info.params[0];
    let start = match (spec.range.lo.value(), spec.range.hi.value()) {
        (Some(a), Some(b)) => (a + b) / 2u32,
        (Some(a), None) => a + 1u32,
        (None, Some(b)) => b - 1u32,
        (None, None) => Rational::new(),
    };
    let published = Published {
        name: spec.name,
        symbol: spec.symbol,
        range: spec.range.to_string(),
        source: spec.range_source,
    };
    maximal_against(
        &basis(family),
        info.variable.is_trigonometric(),
        &published,
        &start,
        |r| {
            let found = Range {
                lo: end_bound(&r.lo),
                hi: end_bound(&r.hi),
            };
            (found.to_string(), found == spec.range)
        },
    )
}

/// A published parameter range, as the report cites it.
#[derive(Debug, Clone)]
pub struct Published<'a> {
    pub name: &'a str,
    pub symbol: &'a str,
    /// The range as printed.
    pub range: String,
    pub source: &'a str,
}

/// The maximal nonnegativity interval of `fs` around `start`, compared with
/// the published range: `found` shows the interval and says whether it is the
/// published one. Holds when it is and both ends are exact (or unbounded),
/// fails otherwise; the interval and certificates are evidence.
pub fn maximal_against(
    fs: &[trig_symbolic::Sym],
    trig: bool,
    published: &Published<'_>,
    start: &Rational,
    found: impl Fn(&MaximalRange) -> (String, bool),
) -> (MaximalRange, Verdict) {
    let name = published.name;
    let r = maximal_range(fs, trig, name, start);
    let (cs, cline) = describe(
        "every function ≥ 0 on the maximal interval",
        &r.certificate,
        trig,
        Some(name),
    );
    let (found_text, equal) = found(&r);
    let same = matches!(r.lo, EndPoint::Exact { .. } | EndPoint::Unbounded)
        && matches!(r.hi, EndPoint::Exact { .. } | EndPoint::Unbounded)
        && equal;
    let status = if cs != Status::Holds {
        cs
    } else if same {
        Status::Holds
    } else {
        Status::Fails
    };
    let evidence = vec![
        format!(
            "published range of {}: {} ({})",
            published.symbol, published.range, published.source
        ),
        format!("maximal interval containing {start} on which every function is ≥ 0: {found_text}"),
        format!("lower end: {}", show_end(&r.lo, name, trig)),
        format!("upper end: {}", show_end(&r.hi, name, trig)),
        cline,
    ];
    let verdict = Verdict::new(status, CERTIFIED, evidence);
    (r, verdict)
}

/// A found end as a bound: exact ends are included (closed), brackets are
/// shown by their certified side, unbounded ends are open.
fn end_bound(e: &EndPoint) -> Bound {
    let small =
        |q: &Rational| -> Option<(i64, i64)> { Some((q.numer().to_i64()?, q.denom().to_i64()?)) };
    match e {
        EndPoint::Exact { value, .. } | EndPoint::Bracket { ok: value, .. } => match small(value) {
            Some((n, d)) => Bound::Closed(n, d),
            None => Bound::Unbounded,
        },
        EndPoint::Unbounded => Bound::Unbounded,
    }
}

/// Certifies a whole family on its published parameter range (closed
/// hull of it; open ends are approached from inside, so the closure is
/// a stronger statement).
pub fn on_published_range(family: Family) -> Verdict {
    let info = family.info();
    let spec = info.params[0];
    let bx = match (spec.range.lo.value(), spec.range.hi.value()) {
        (Some(a), Some(b)) => ParamBox::Interval(a, b),
        (Some(a), None) => ParamBox::FromTo(a),
        _ => return Verdict::not_checkable("a range unbounded below is not supported"),
    };
    let trig = info.variable.is_trigonometric();
    let cert = certify_all(&basis(family), trig, spec.name, &bx);
    let (status, line) = describe(
        &format!("all functions, {} ∈ closure of {}", spec.symbol, spec.range),
        &cert,
        trig,
        Some(spec.name),
    );
    Verdict::new(status, CERTIFIED, vec![line])
}

/// Monotonicity of function `index` of `family` on its whole domain for
/// every parameter in the box: the sign of its derivative, certified.
pub fn monotone(
    family: Family,
    index: usize,
    increasing: bool,
    param: Option<&str>,
    bx: &ParamBox,
) -> Verdict {
    let info = family.info();
    monotone_named(
        &basis(family)[index],
        info.functions[index],
        info.variable.is_trigonometric(),
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
    let what = if increasing {
        format!("{name}' ≥ 0 ({name} increasing)")
    } else {
        format!("−{name}' ≥ 0 ({name} decreasing)")
    };
    let (status, line) = describe(&what, &certify(&g, trig, param, bx), trig, param);
    Verdict::new(status, CERTIFIED, vec![line])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn monotonicity_is_proved_or_refuted() {
        let range = ParamBox::Interval(Rational::from(-2), Rational::from(1));
        assert_eq!(
            monotone(Family::ThesisCubic, 0, false, Some("m"), &range).status,
            Status::Holds
        );
        assert_eq!(
            monotone(Family::ThesisCubic, 0, true, Some("m"), &range).status,
            Status::Fails
        );
        assert_eq!(
            monotone(Family::ThesisCubic, 2, true, Some("m"), &range).status,
            Status::Fails
        );
    }
}
