//! Reading a `check = "join"` claim into a [`Check::Join`]: the kind, the
//! convention, the two segments' control points and parameters as the
//! paper names them, and the printed conditions as printed terms over
//! their denominators.
//!
//! By default the first segment is `Σ bᵢPᵢ` and the second `Σ bᵢQᵢ`; with
//! `different = true` each parameter `p` is `p1` on the first and `p2` on
//! the second. A paper that names them otherwise — the thesis's `P0…P3`
//! and `P4…P7`, with `m2` on the first curve and `m1` on the second — says
//! so with `points = [["P0", …], ["P4", …]]` and `segment-params =
//! [{ m = "m2" }, { m = "m1" }]`, and writes its conditions in those names.

use std::collections::BTreeMap;

use toml::Spanned;
use trig_core::{End, ParamRange};
use trig_deriv::JoinKind;
use trig_symbolic::Sym;

use crate::check::{Check, Condition, JoinSegments};
use crate::error::{Result, SpecError};
use crate::fields::{need, wrt_field};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

/// `wrt` of a join whose paper does not say with respect to what it
/// differentiates: judged in the default convention, a formula that holds
/// in another one holding after that correction.
const UNSTATED: &str = "unstated";

pub(crate) fn join(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let kind_field = need(src, c, &c.join, "join")?;
    let kind: JoinKind = kind_field
        .get_ref()
        .trim()
        .parse()
        .map_err(|_| SpecError::Invalid {
            at: src.at(kind_field.span().start),
            field: "claims.join".into(),
            message: format!(
                "`{}`: expected C0, C1, C2, C3, G1 or G2",
                kind_field.get_ref().trim()
            ),
        })?;
    let different = c.different.unwrap_or(false);
    let n = spec.functions.len();
    // the names a printed condition may use, each reading as one thing
    let mut names = spec.names();
    let clash = |e: trig_symbolic::NameClash| SpecError::Invalid {
        at: src.at(c.check.span().start),
        field: "claims".into(),
        message: format!("claim `{}`: {e}", c.id.get_ref().trim()),
    };
    let points = point_names(src, n, c)?;
    let mut extra = Vec::new();
    for point in points.iter().flatten() {
        names.fixed(point, "a control point").map_err(clash)?;
        extra.push(point.clone());
    }
    let factors = match &c.factors {
        Some(given) => printed_factors(src, c, given, &mut names)?,
        None => names.factors().map(|f| f.to_string()),
    };
    extra.extend(factors.iter().cloned());
    let reversed = orientation(src, c, kind)?;
    let printed = printed_params(src, spec, c, different)?;
    let segments = JoinSegments {
        points: points.clone(),
        printed,
        also: None,
    };
    let params = segments.param_copies(spec);
    let mut segment_ranges = Vec::new();
    if different {
        for (k, segment) in params.iter().enumerate() {
            for (p, s) in spec.params.iter().zip(segment) {
                let copy = s.to_string();
                let what = format!("`{}` on segment {}", p.name, k + 1);
                names.fixed(&copy, &what).map_err(clash)?;
                extra.push(copy.clone());
                segment_ranges.push((copy, p.range.clone()));
            }
        }
    }
    if matches!(kind, JoinKind::G1 | JoinKind::G2) {
        // the tangents point the same way: the first G factor is positive
        let positive = ParamRange {
            lo: End::Open(rug::Rational::new()),
            hi: End::Unbounded,
            pi: false,
        };
        segment_ranges.push((factors[0].clone(), positive));
    }
    let all_points: Vec<String> = points.iter().flatten().cloned().collect();
    let second = &points[1];
    let conditions = need(src, c, &c.conditions, "conditions")?
        .iter()
        .map(|item| {
            let text = item.get_ref();
            let expected = format!("{}…{}", second[0], second[n - 1]);
            let Some((lhs, rhs)) = text.split_once('=') else {
                return src.invalid(item.span(), "claims.conditions", format!("`{text}`: expected `{} = formula in {}…{}, {expected}`", second[0], points[0][0], points[0][n - 1]));
            };
            let Some(point) = second.iter().position(|q| q == lhs.trim()) else {
                return src.invalid(item.span(), "claims.conditions", format!("`{}`: expected a control point {expected} of the second segment on the left", lhs.trim()));
            };
            let (value, singular) = spec
                .parse_claim_formula(rhs, &extra, &segment_ranges)
                .map_err(|mut e| {
                    e.position += lhs.chars().count() + 1;
                    src.formula_error(item, e)
                })?;
            if different {
                if let Some((i, p)) = spec.params.iter().enumerate().find(|(_, p)| value.variables().contains(&p.name)) {
                    return src.invalid(item.span(), "claims.conditions", format!("`{text}`: with different parameters write {} (first segment) or {} (second), not {}", params[0][i], params[1][i], p.name));
                }
            }
            let printed = spec
                .printed_terms(rhs, &extra, &all_points)
                .map_err(|e| src.formula_error(item, e))?;
            Ok(Condition { point, text: text.trim().to_string(), value, terms: printed.terms, denominator: printed.denominator, brackets: printed.brackets, singular })
        })
        .collect::<Result<Vec<_>>>()?;
    let unstated = c.wrt.as_ref().filter(|w| w.get_ref().trim() == UNSTATED);
    let also = c
        .also_params
        .as_ref()
        .map(|tables| param_tables(src, spec, c, tables, "also-params"))
        .transpose()?;
    Ok(Check::Join {
        kind,
        wrt: wrt_field(
            src,
            spec,
            if unstated.is_some() {
                None
            } else {
                c.wrt.as_ref()
            },
        )?,
        declared: unstated.is_none(),
        different,
        factors,
        reversed,
        conditions,
        segments: JoinSegments { also, ..segments },
    })
}

/// The `G` factors as printed (`factors = ["omega", "beta"]`): two names,
/// each reading as nothing else of the file.
fn printed_factors(
    src: &Source<'_>,
    c: &RawClaim,
    given: &[Spanned<String>],
    names: &mut trig_symbolic::Names,
) -> Result<[String; 2]> {
    let [first, second] = given else {
        return src.invalid(
            c.check.span(),
            "claims.factors",
            format!(
                "expected the two G factors as printed, found {}",
                given.len()
            ),
        );
    };
    let mut out = [first, second].map(|f| f.get_ref().trim().to_string());
    for (name, item) in out.iter_mut().zip([first, second]) {
        names
            .fixed(name, "a G factor")
            .map_err(|e| SpecError::Invalid {
                at: src.at(item.span().start),
                field: "claims.factors".into(),
                message: e.to_string(),
            })?;
    }
    Ok(out)
}

/// `orientation = "reversed"`: the printed `G` factors give the first
/// segment's derivatives from the second's (`P'(1) = ωQ'(0)`); only for
/// `G¹`, `G²`.
fn orientation(src: &Source<'_>, c: &RawClaim, kind: JoinKind) -> Result<bool> {
    let Some(given) = &c.orientation else {
        return Ok(false);
    };
    if given.get_ref().trim() != "reversed" {
        return src.invalid(
            given.span(),
            "claims.orientation",
            format!("`{}`: expected \"reversed\"", given.get_ref().trim()),
        );
    }
    if !matches!(kind, JoinKind::G1 | JoinKind::G2) {
        return src.invalid(
            given.span(),
            "claims.orientation",
            "`orientation` orients the factors of a G¹ or G² join".into(),
        );
    }
    Ok(true)
}

/// The two segments' control points: `points` as printed, else `P0…`,
/// `Q0…`. Each segment names one point per function, all names distinct.
fn point_names(src: &Source<'_>, n: usize, c: &RawClaim) -> Result<[Vec<String>; 2]> {
    let Some(given) = &c.points else {
        return Ok(["P", "Q"].map(|p| (0..n).map(|i| format!("{p}{i}")).collect()));
    };
    let span = c.check.span();
    let names: Vec<Vec<String>> = given
        .iter()
        .map(|segment| {
            segment
                .iter()
                .map(|p| p.get_ref().trim().to_string())
                .collect()
        })
        .collect();
    let mut all: Vec<&String> = names.iter().flatten().collect();
    all.sort();
    all.dedup();
    let valid = |p: &str| {
        p.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
            && p.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    };
    if names.len() != 2 || names.iter().any(|s| s.len() != n) || all.len() != 2 * n {
        return src.invalid(span, "claims.points", format!("expected two lists of {n} distinct control point names (the first segment's, then the second's), one per function"));
    }
    if let Some(bad) = all.iter().find(|p| !valid(p)) {
        return src.invalid(
            span,
            "claims.points",
            format!("`{bad}`: a control point is named by ASCII letters and digits"),
        );
    }
    Ok([names[0].clone(), names[1].clone()])
}

/// Each segment's parameters as printed (`segment-params`), with
/// `different` only; `None` where not printed.
fn printed_params(
    src: &Source<'_>,
    spec: &Spec,
    c: &RawClaim,
    different: bool,
) -> Result<Option<[Vec<Sym>; 2]>> {
    if c.segment_params.is_none() && c.also_params.is_none() {
        return Ok(None);
    }
    let field = if c.segment_params.is_some() {
        "segment-params"
    } else {
        "also-params"
    };
    if !different {
        return src.invalid(
            c.check.span(),
            &format!("claims.{field}"),
            format!("`{field}` (each segment's own parameters) needs `different = true`"),
        );
    }
    if c.at.is_some() || c.ranges.is_some() || c.region.is_some() || c.range.is_some() {
        return src.invalid(
            c.check.span(),
            &format!("claims.{field}"),
            format!("`{field}` takes no fixed values or ranges"),
        );
    }
    c.segment_params
        .as_ref()
        .map(|tables| param_tables(src, spec, c, tables, "segment-params"))
        .transpose()
}

/// Two tables `{ p = "name" }`, one per segment, naming every declared
/// parameter: the names of each segment's copies.
fn param_tables(
    src: &Source<'_>,
    spec: &Spec,
    c: &RawClaim,
    tables: &[BTreeMap<String, Spanned<String>>],
    field: &str,
) -> Result<[Vec<Sym>; 2]> {
    let span = c.check.span();
    if tables.len() != 2 {
        return src.invalid(
            span,
            &format!("claims.{field}"),
            "expected two tables, the first segment's parameters then the second's".into(),
        );
    }
    let mut out = [Vec::new(), Vec::new()];
    for (k, table) in tables.iter().enumerate() {
        if let Some(unknown) = table
            .keys()
            .find(|key| spec.params.iter().all(|p| &p.name != *key))
        {
            return src.invalid(
                span,
                &format!("claims.{field}"),
                format!("`{unknown}`: not a parameter of the basis"),
            );
        }
        for p in &spec.params {
            let Some(name) = table.get(&p.name) else {
                return src.invalid(
                    span,
                    &format!("claims.{field}"),
                    format!("segment {}: no name for `{}`", k + 1, p.name),
                );
            };
            let name = name.get_ref().trim();
            if !name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                || spec.params.iter().any(|q| q.name == name)
            {
                return src.invalid(span, &format!("claims.{field}"), format!("`{name}`: a segment's copy of `{}` is a new ASCII name, not a declared parameter", p.name));
            }
            out[k].push(Sym::var(name));
        }
    }
    Ok(out)
}

/// `check = "join-singular"`: `values = ["m = -2"]`, the printed parameter
/// values where the joins break; each segment's copies as printed
/// (`segment-params`) or `p1`, `p2`.
pub(crate) fn join_singular(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    if c.at.is_some() || c.ranges.is_some() || c.region.is_some() || c.range.is_some() {
        return src.invalid(
            c.check.span(),
            "claims.check",
            "`join-singular` is about the whole declared range: no fixed values or ranges".into(),
        );
    }
    let copies = match &c.segment_params {
        Some(tables) => param_tables(src, spec, c, tables, "segment-params")?,
        None => JoinSegments {
            points: [Vec::new(), Vec::new()],
            printed: None,
            also: None,
        }
        .param_copies(spec),
    };
    let values = need(src, c, &c.values, "values")?
        .iter()
        .map(|item| {
            let text = item.get_ref();
            let parsed = text.split_once('=').and_then(|(name, value)| {
                spec.params
                    .iter()
                    .position(|p| p.name == name.trim() || p.symbol == name.trim())
                    .map(|i| (i, value))
            });
            let Some((i, value)) = parsed else {
                return src.invalid(
                    item.span(),
                    "claims.values",
                    format!("`{text}`: expected `parameter = value`"),
                );
            };
            let value = spec
                .parse_formula(value, &[])
                .map_err(|e| src.formula_error(item, e))?;
            if !value.variables().is_empty() {
                return src.invalid(
                    item.span(),
                    "claims.values",
                    format!("`{text}`: the value is a number"),
                );
            }
            Ok((i, value))
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Check::JoinSingular {
        wrt: wrt_field(src, spec, c.wrt.as_ref())?,
        copies,
        values,
    })
}
