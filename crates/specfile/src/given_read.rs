//! Reading what a claim fixes of the parameters and the ranges it gives
//! (`at`, a one-point `range`, `ranges`, ends linear in other parameters)
//! into a [`Given`], applied before deciding ([`crate::given`]).

use toml::Spanned;
use trig_core::ParamRange;
use trig_symbolic::Sym;

use crate::check::{Between, Check, Fixed, Given};
use crate::error::{Result, SpecError};
use crate::exact_range::ExactRange;
use crate::knots::{KNOT_FAMILIES, Knots};
use crate::raw::{RawClaim, RawKnots};
use crate::source::Source;
use crate::spec::Spec;

/// The `range` of a check decided over a range of the only parameter
/// (`None` when a one-point range fixes its value instead).
pub(crate) fn one_param_range(
    src: &Source<'_>,
    spec: &Spec,
    range: &Option<Spanned<String>>,
) -> Result<Option<ParamRange>> {
    let Some(r) = range else { return Ok(None) };
    if spec.params.len() != 1 {
        return src.invalid(
            r.span(),
            "claims.range",
            "`range` is the range of the only parameter: with several parameters give `ranges = { NAME = \"[a, b]\", … }` (a one-point range `[v, v]` or `at = { NAME = \"v\" }` fixes a value)".into(),
        );
    }
    let range = match ParamRange::parse(r.get_ref()) {
        Ok(range) => range,
        // ends beyond the rationals: decided through [`given`]
        Err(_) if ExactRange::read(spec, &spec.params[0].name, r.get_ref()).is_some() => {
            return Ok(None);
        }
        Err(m) => return src.invalid(r.span(), "claims.range", beyond_rationals(&m)),
    };
    // a one-point range fixes the value ([`given`]): no range is left
    Ok(point_of(&range).is_none().then_some(range))
}

/// A range with ends beyond the rationals that holds no interval.
const EMPTY: &str = "the range is empty: its ends are reversed or nearer than 10⁻¹² (a one-point range [v, v] fixes the value)";

/// The message of an unreadable range, with the exact ends it may have.
fn beyond_rationals(message: &str) -> String {
    format!(
        "{message}; ends may also be exact numbers with square roots or pi, e.g. [-1, 2 + 2*sqrt(2)]"
    )
}

/// `v` for the one-point range `[v, v]`, written as read.
fn point_of(range: &ParamRange) -> Option<String> {
    match (&range.lo, &range.hi) {
        (trig_core::End::Closed(a), trig_core::End::Closed(b)) if a == b => Some(range.end_text(a)),
        _ => None,
    }
}

/// `[lo, hi]` with ends written in the other parameters (closed ends).
fn between(spec: &Spec, name: &str, text: &str) -> Option<Between> {
    let inner = text.trim().strip_prefix('[')?.strip_suffix(']')?;
    let (a, b) = inner.split_once(',')?;
    let end = |e: &str| -> Option<Sym> {
        let v = spec.parse_formula(e, &[]).ok()?;
        let other = |v: &String| spec.params.iter().any(|p| p.name == *v && p.name != name);
        v.variables().iter().all(other).then_some(v)
    };
    Some(Between {
        name: name.to_string(),
        text: text.trim().to_string(),
        lo: end(a)?,
        hi: end(b)?,
    })
}

/// The checks that are decided over a range of the only parameter.
const RANGED: [&str; 6] = [
    "nonnegative",
    "convex-hull",
    "independent",
    "total-positivity",
    "monotone",
    "end-direction",
];

/// The parameter values a claim fixes and the ranges it narrows: `at`
/// (except for `symmetry`, whose `at` places its numeric counterexample),
/// a one-point `range` of the only parameter, `ranges` by name (a
/// one-point one fixes the value).
pub(crate) fn given(src: &Source<'_>, spec: &Spec, c: &RawClaim, kind: &str) -> Result<Given> {
    let mut out = Given::default();
    let param = |name: &str, span: std::ops::Range<usize>, field: &str| {
        spec.params
            .iter()
            .find(|p| p.name == name.trim() || p.symbol == name.trim())
            .map(|p| p.name.clone())
            .ok_or_else(|| SpecError::Invalid {
                at: src.at(span.start),
                field: format!("claims.{field}"),
                message: format!("`{}`: not a parameter of the basis", name.trim()),
            })
    };
    let fix = |out: &mut Given,
               name: String,
               text: &str,
               span: std::ops::Range<usize>,
               field: &str|
     -> Result<()> {
        if out.fixed.iter().any(|f| f.name == name) {
            return src.invalid(
                span,
                &format!("claims.{field}"),
                format!("`{name}` is fixed twice"),
            );
        }
        let value = spec
            .parse_formula(text, &[])
            .map_err(|e| SpecError::Invalid {
                at: src.at(span.start),
                field: format!("claims.{field}"),
                message: format!("`{}`: {}", text.trim(), e.message),
            })?;
        // a number, or (a line of the parameter plane) an expression in the
        // other parameters: `beta = "3 - 3*alpha"`
        let other = |v: &String| spec.params.iter().any(|p| p.name == *v && p.name != name);
        if value
            .variables()
            .iter()
            .any(|v| v != "pi" && !v.starts_with("sqrt(") && !other(v))
        {
            return src.invalid(
                span,
                &format!("claims.{field}"),
                format!("`{}`: a fixed value is a number (rationals, pi and square roots: 0, 1/2, sqrt(2)/2, pi/3) or an expression in the other parameters (3 - 3*alpha)", text.trim()),
            );
        }
        out.fixed.push(Fixed {
            name,
            text: text.trim().to_string(),
            value,
        });
        Ok(())
    };
    if let Some(k) = c
        .knots
        .as_ref()
        .filter(|_| !["knot-coefficients", "continuity"].contains(&kind))
    {
        out.knots = Some(knots(src, spec, k)?);
    }
    if kind != "symmetry" {
        for (name, v) in c.at.iter().flatten() {
            let name = param(name, v.span(), "at")?;
            fix(&mut out, name, v.get_ref(), v.span(), "at")?;
        }
    }
    if let Some(r) = c.range.as_ref().filter(|_| kind != "shape-effect") {
        let [p] = spec.params.as_slice() else {
            return one_param_range(src, spec, &c.range).map(|_| out);
        };
        let range = match ParamRange::parse(r.get_ref()) {
            Ok(range) => Some(range),
            Err(m) => {
                match ExactRange::read(spec, &p.name, r.get_ref()) {
                    Some(exact) if exact.point().is_some() => {
                        let point = exact.point().unwrap_or_default();
                        fix(&mut out, p.name.clone(), &point, r.span(), "range")?;
                        None
                    }
                    Some(exact) if exact.rounded(false).is_none() => {
                        return src.invalid(r.span(), "claims.range", EMPTY.into());
                    }
                    Some(exact) if RANGED.contains(&kind) && c.quantifier.is_none() => {
                        out.exact.push(exact);
                        None
                    }
                    Some(_) => {
                        return src.invalid(
                        r.span(),
                        "claims.range",
                        format!("a range with ends beyond the rationals is taken by {} (without `for`)", RANGED.join(", ")),
                    );
                    }
                    None => return src.invalid(r.span(), "claims.range", beyond_rationals(&m)),
                }
            }
        };
        match range.as_ref().map(|r| (r, point_of(r))) {
            None => {}
            Some((_, Some(point))) => fix(&mut out, p.name.clone(), &point, r.span(), "range")?,
            // a quantified claim (`for = "some value"`) is about its range
            Some((range, None)) if c.quantifier.is_some() => {
                out.ranges.push((p.name.clone(), range.clone()));
            }
            Some((_, None)) if !RANGED.contains(&kind) => {
                return src.invalid(
                    r.span(),
                    "claims.range",
                    format!("`{kind}` takes no range of values (but with `for = \"some value\"` or `\"no value\"`); a one-point range `[v, v]` fixes the value"),
                );
            }
            Some((_, None)) => {}
        }
    }
    // `ranges` as written, then those a `region` of inequalities states
    let mut ranges: Vec<(String, String, std::ops::Range<usize>, &str)> = Vec::new();
    for (name, r) in c.ranges.iter().flatten() {
        let name = param(name, r.span(), "ranges")?;
        ranges.push((name, r.get_ref().clone(), r.span(), "ranges"));
    }
    if let Some(r) = &c.region {
        if c.range.is_some() {
            return src.invalid(
                r.span(),
                "claims.region",
                "a claim gives its parameters either a `region` or a `range`, not both".into(),
            );
        }
        if !RANGED.contains(&kind) && c.quantifier.is_none() {
            return src.invalid(
                r.span(),
                "claims.region",
                format!("`{kind}` takes no region of values (but with `for = \"some value\"` or `\"no value\"`): it is an identity, decided for every value or at the values `at` fixes"),
            );
        }
        // values the claim fixes are substituted into the inequalities first
        let fixed: Vec<(String, Sym)> = out
            .fixed
            .iter()
            .map(|f| (f.name.clone(), f.value.clone()))
            .collect();
        let stated = crate::region_read::region_ranges(spec, r.get_ref(), &fixed)
            .or_else(|m| src.invalid(r.span(), "claims.region", m))?;
        for (name, text) in stated {
            if ranges.iter().any(|(n, ..)| *n == name) {
                return src.invalid(
                    r.span(),
                    "claims.region",
                    format!("`{name}` is given a range and a region"),
                );
            }
            ranges.push((name, text, r.span(), "region"));
        }
    }
    // a parameter map (an exchange symmetry) or the copies of a join's two
    // segments would be rewritten by the change of parameters of a range
    // with ends in other parameters: such claims take boxes only
    let mapped = (kind == "symmetry" && c.params.as_ref().is_some_and(|m| !m.is_empty()))
        || (kind == "join" && c.different == Some(true));
    for (name, text, span, field) in ranges {
        let range = match ParamRange::parse(&text) {
            Ok(range) => range,
            Err(_) if mapped && between(spec, &name, &text).is_some() => {
                return src.invalid(
                    span,
                    &format!("claims.{field}"),
                    format!("`{kind}` with exchanged parameters or two segments takes boxes of parameters (numbers as ends), not ends in other parameters: `{name}` ∈ {text}"),
                );
            }
            Err(m) => match between(spec, &name, &text) {
                Some(b) => {
                    out.between.push(b);
                    continue;
                }
                None => match ExactRange::read(spec, &name, &text) {
                    Some(exact) if exact.point().is_some() => {
                        let point = exact.point().unwrap_or_default();
                        fix(&mut out, name, &point, span, field)?;
                        continue;
                    }
                    Some(exact) if exact.rounded(false).is_none() => {
                        return src.invalid(span, &format!("claims.{field}"), EMPTY.into());
                    }
                    Some(exact) if RANGED.contains(&kind) && c.quantifier.is_none() => {
                        out.exact.push(exact);
                        continue;
                    }
                    _ => {
                        return src.invalid(
                            span,
                            &format!("claims.{field}"),
                            format!(
                                "{m}; or ends linear in the other parameters, e.g. [0, 4 - lambda], or exact numbers with square roots or pi (for {}), e.g. [-1, 2 + 2*sqrt(2)]",
                                RANGED.join(", ")
                            ),
                        );
                    }
                },
            },
        };
        match point_of(&range) {
            Some(point) => fix(&mut out, name, &point, span, field)?,
            None if out.fixed.iter().any(|f| f.name == name) => {
                return src.invalid(
                    span,
                    &format!("claims.{field}"),
                    format!("`{name}` is fixed and given a range"),
                );
            }
            None => out.ranges.push((name, range)),
        }
    }
    Ok(out)
}

/// A claim's knot vector (`knots = { … }`, [`crate::knots`]): a knot family
/// of the catalog, each knot a number, the knots non-decreasing.
pub(crate) fn knots(src: &Source<'_>, spec: &Spec, k: &Spanned<RawKnots>) -> Result<Knots> {
    let raw = k.get_ref();
    let bad = |message: String| src.invalid(k.span(), "claims.knots", message);
    if Knots::family(&raw.coefficients).is_none() {
        return bad(format!(
            "`{}`: not a knot family (expected one of {})",
            raw.coefficients,
            KNOT_FAMILIES.join(", ")
        ));
    }
    let mut values = Vec::new();
    for text in &raw.values {
        let value = match spec.parse_formula(text, &[]) {
            Ok(v) if v.variables().is_empty() => v,
            _ => return bad(format!("`{text}`: a knot is a rational number")),
        };
        values.push(value);
    }
    let increasing = values.windows(2).all(|w| {
        matches!(
            (w[0].as_rational(), w[1].as_rational()),
            (Some(a), Some(b)) if a <= b
        )
    });
    if !increasing {
        return bad("the knots are rational numbers in non-decreasing order".into());
    }
    if usize::try_from(raw.span).map_or(true, |j| j + 1 >= values.len()) {
        return bad(format!(
            "span {}: the span [n_j, n_(j+1)) lies inside the {} knots",
            raw.span,
            values.len()
        ));
    }
    Ok(Knots {
        coefficients: raw.coefficients.clone(),
        texts: raw.values.iter().map(|t| t.trim().to_string()).collect(),
        values,
        span: raw.span,
    })
}

/// `check = "knot-coefficients"`: the claim's knots (taken by the check,
/// not formed into the basis: the check is about the coefficients) and the
/// printed matrix, a row of one formula per basis function for each
/// segment function of the knot family.
pub(crate) fn knot_coefficients(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let field = "claims.knots";
    let Some(k) = &c.knots else {
        return src.invalid(
            c.check.span(),
            field,
            "`knot-coefficients` needs `knots`".into(),
        );
    };
    let knots = knots(src, spec, k)?;
    let Some(rows) = &c.matrix else {
        return src.invalid(
            c.check.span(),
            "claims.matrix",
            "`knot-coefficients` needs `matrix`, the printed coefficients".into(),
        );
    };
    let (names, _) = Knots::family(&knots.coefficients).unwrap_or_default();
    if rows.len() != names.len() || rows.iter().any(|r| r.len() != spec.functions.len()) {
        return src.invalid(
            c.check.span(),
            "claims.matrix",
            format!(
                "expected {} rows (the segment functions {}) of {} coefficients (of {})",
                names.len(),
                names.join(", "),
                spec.functions.len(),
                spec.functions
                    .iter()
                    .map(|f| f.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        );
    }
    let matrix = rows
        .iter()
        .map(|row| {
            row.iter()
                .map(|item| {
                    let text = item.get_ref().trim().to_string();
                    match spec.parse_formula(&text, &[]) {
                        Ok(v)
                            if !v.variables().iter().any(|n| {
                                !spec.params.iter().any(|p| &p.name == n) && n != "pi"
                            }) =>
                        {
                            Ok((text, v))
                        }
                        // the formula's own error (a division by a divisor
                        // that vanishes in the range) is the reason
                        Err(e) => {
                            src.invalid(item.span(), "claims.matrix", format!("`{text}`: {e}"))
                        }
                        Ok(_) => src.invalid(
                            item.span(),
                            "claims.matrix",
                            format!("`{text}`: a coefficient is a formula in the parameters"),
                        ),
                    }
                })
                .collect::<Result<Vec<_>>>()
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Check::KnotCoefficients { knots, matrix })
}

/// What a `continuity` claim examines: the B-spline on its `knots`, the
/// curve of its control points `point` on consecutive `segments` (with
/// `weights`), or the uniform B-spline of the basis.
pub(crate) fn continuous(
    src: &Source<'_>,
    spec: &Spec,
    c: &RawClaim,
) -> Result<crate::check::Continuous> {
    use crate::check::Continuous;
    if let Some(k) = &c.knots {
        return Ok(Continuous::Knots(knots(src, spec, k)?));
    }
    let Some(point) = &c.point else {
        return Ok(Continuous::Bspline);
    };
    let segments = c.segments.clone().unwrap_or_default();
    if segments.len() < 2 || segments.windows(2).any(|w| w[1] != w[0] + 1) || segments[0] < 0 {
        return src.invalid(
            point.span(),
            "claims.segments",
            "a curve's continuity needs `segments`, at least two consecutive spans from 0 up (the knots between them are examined)".into(),
        );
    }
    Ok(Continuous::Curve {
        point: point.get_ref().trim().to_string(),
        weights: c.weights.unwrap_or(false),
        segments,
    })
}

#[cfg(test)]
mod tests {
    use crate::spec::Spec;

    /// The catalog's blending functions with a `knot-coefficients` claim
    /// whose printed coefficient of `F0` is `row0`.
    fn blending_with(row0: &str) -> crate::error::Result<Spec> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog/seed000-blending.toml");
        let text = std::fs::read_to_string(path).unwrap();
        let knots: Vec<String> = (0..=20).map(|k| format!("\"{k}\"")).collect();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"k\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"knot-coefficients\"\nknots = {{ coefficients = \"seed000-nonuniform\", values = [{}], span = 10 }}\nmatrix = [[\"{row0}\", \"0\", \"0\", \"0\"], [\"0\", \"1\", \"0\", \"0\"], [\"0\", \"0\", \"1\", \"0\"], [\"0\", \"0\", \"0\", \"1\"]]\n",
                knots.join(", ")
            ),
            "k.toml",
        )
    }

    #[test]
    fn a_refused_coefficient_names_its_reason() {
        assert!(blending_with("1/(6*zeta^2 - 6*zeta + 10)").is_ok());
        // 2ζ − 1 vanishes at ζ = 1/2 ∈ [0, 4]: the division is the reason
        // (it was reported as "a coefficient is a formula in the parameters")
        let e = blending_with("1/(2*zeta - 1)").unwrap_err().to_string();
        assert!(e.contains("division by"), "{e}");
        let e = blending_with("t*zeta").unwrap_err().to_string();
        assert!(
            e.contains("a coefficient is a formula in the parameters"),
            "{e}"
        );
    }
}
