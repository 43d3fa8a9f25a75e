//! The claims of a spec file, read into checks the audit can decide
//! ([`crate::check`]), after the functions ([`crate::spec`]).

use toml::Spanned;
use trig_symbolic::Names;

use crate::check::{Check, Printed, RationalCurve, SpecClaim, Varied};
use crate::error::{Result, SpecError};
use crate::fields::{
    data_file, end_field, file_field, formula_in, function_index, need, order_field, wrt_field,
};
use crate::given_read::{given, one_param_range};
use crate::property_read::{conic, monotone, shape_effect, symmetry};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;
use std::path::Path;

use trig_interp::{DataSet, Scheme};

impl Spec {
    /// The names a reader sees in this spec's formulas: the parameters
    /// (names and printed symbols), the functions and definitions; tool
    /// symbols drawn from it read like none of them.
    pub fn names(&self) -> Names {
        let mut names = Names::of_parameters(
            self.params
                .iter()
                .map(|p| (p.name.as_str(), p.symbol.as_str())),
        );
        for f in self.functions.iter().chain(&self.definitions) {
            names.user(&f.name, "a function or definition");
        }
        names
    }

    /// The names of the `G¹`/`G²` factors: `alpha`, `beta`, or the first
    /// pair of (`gamma`, `delta`), (`kappa`, `nu`), … whose names and
    /// letters no parameter, symbol or function takes.
    pub fn join_factors(&self) -> [String; 2] {
        self.names().factors().map(|f| f.to_string())
    }
}

/// `name = formula` entries.
fn printed(src: &Source<'_>, spec: &Spec, items: &[Spanned<String>]) -> Result<Vec<Printed>> {
    items
        .iter()
        .map(|item| {
            let Some((name, formula)) = item.get_ref().split_once('=') else {
                return src.invalid(
                    item.span(),
                    "claims.values",
                    format!("`{}`: expected `NAME = VALUE`", item.get_ref()),
                );
            };
            let function = function_index(src, spec, item, name)?;
            let value = formula_in(src, spec, item, &format!("{name}="), formula, &[])?;
            Ok(Printed {
                function,
                text: item.get_ref().trim().to_string(),
                value,
            })
        })
        .collect()
}

/// Reads the claims of the file into `spec`, whose functions are read;
/// an id used twice is an error.
pub(crate) fn attach(src: &Source<'_>, spec: &mut Spec, raw: &[RawClaim]) -> Result<()> {
    for c in raw {
        if let Some(basis) = &c.basis {
            return src.invalid(
                basis.span(),
                "claims.basis",
                "a spec file states one basis: `basis` names one of a document file's `[bases]`"
                    .into(),
            );
        }
        let claim = claim(src, spec, c)?;
        if spec.claims.iter().any(|d| d.id == claim.id) {
            return Err(SpecError::Invalid {
                at: src.at(0),
                field: "claims.id".into(),
                message: format!("`{}` is used twice", claim.id),
            });
        }
        spec.claims.push(claim);
    }
    umbrellas(src, spec)
}

/// The claims an umbrella (`check = "all"`) lists exist, and no umbrella
/// lists itself through others.
pub(crate) fn umbrellas(src: &Source<'_>, spec: &Spec) -> Result<()> {
    let ids: Vec<&str> = spec.claims.iter().map(|c| c.id.as_str()).collect();
    umbrellas_among(src, &ids, |id| {
        match spec.claims.iter().find(|c| c.id == id).map(|c| &c.check) {
            Some(Check::All { claims, .. }) => Some(claims.clone()),
            _ => None,
        }
    })
}

/// The umbrellas among the claims `ids` (`parts`: the claims an umbrella
/// lists, `None` for a claim that is not one) list claims of `ids`, at
/// least one, and none lists itself through others.
pub(crate) fn umbrellas_among(
    src: &Source<'_>,
    ids: &[&str],
    parts: impl Fn(&str) -> Option<Vec<String>>,
) -> Result<()> {
    let invalid = |message: String| {
        Err(SpecError::Invalid {
            at: src.at(0),
            field: "claims.claims".into(),
            message,
        })
    };
    for &id in ids {
        let Some(listed) = parts(id) else {
            continue;
        };
        if listed.is_empty() {
            return invalid(format!("`{id}` lists no claim"));
        }
        if let Some(missing) = listed.iter().find(|l| !ids.contains(&l.as_str())) {
            return invalid(format!(
                "`{id}` lists `{missing}`, which is not a claim of the file"
            ));
        }
        // every claim reached from `id` through umbrellas
        let (mut seen, mut todo) = (Vec::<String>::new(), listed);
        while let Some(part) = todo.pop() {
            if part == id {
                return invalid(format!("`{id}` lists itself (through the claims it lists)"));
            }
            if !seen.contains(&part) {
                todo.extend(parts(&part).unwrap_or_default());
                seen.push(part);
            }
        }
    }
    Ok(())
}

pub(crate) fn claim(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<SpecClaim> {
    let id = c.id.get_ref().trim().to_string();
    if id.is_empty() {
        return src.invalid(c.id.span(), "claims.id", "expected a nonempty id".into());
    }
    if let Err(e) = trig_tex::marked::check(c.statement.get_ref()) {
        return src.invalid(
            c.statement.span(),
            "claims.statement",
            format!("math marks ⟪…⟫ (character positions counted from the statement's first): {e}"),
        );
    }
    if c.parts.is_some() || c.shown.is_some() {
        return src.invalid(
            c.id.span(),
            "claims.parts",
            "`parts` and `shown` belong to a document file's umbrella (`check = \"all\"` with `[[claims.parts]]`, parts about several bases), not to a claim of one basis".into(),
        );
    }
    let check = match c.check.get_ref().trim() {
        "unity" => Check::Unity,
        "nonnegative" => crate::nonnegative_read::nonnegative(src, spec, c)?,
        "convex-hull" => Check::ConvexHull {
            range: one_param_range(src, spec, &c.range)?,
            maximal: c.maximal.unwrap_or(false),
        },
        "conic" => conic(src, spec, c)?,
        "independent" => Check::Independent {
            range: one_param_range(src, spec, &c.range)?,
            maximal: c.maximal.unwrap_or(false),
        },
        "total-positivity" => Check::TotalPositivity {
            range: one_param_range(src, spec, &c.range)?,
            maximal: c.maximal.unwrap_or(false),
        },
        "monotone" => monotone(src, spec, c)?,
        "shape-effect" => shape_effect(src, spec, c)?,
        "end-curvature" => crate::curvature_read::end_curvature(src, spec, c)?,
        "symmetry" => symmetry(src, spec, c)?,
        "endpoint-values" => Check::EndpointValues {
            end: end_field(src, need(src, c, &c.end, "end")?)?,
            values: printed(src, spec, need(src, c, &c.values, "values")?)?,
        },
        "endpoint-derivatives" => crate::derivative_read::endpoint_derivatives(src, spec, c)?,
        "curve-derivative" => {
            let item = need(src, c, &c.value, "value")?;
            let mut names = spec.names();
            let mut points = Vec::new();
            for i in 0..spec.functions.len() {
                let point = format!("P{i}");
                names
                    .fixed(&point, "a control point")
                    .map_err(|e| SpecError::Invalid {
                        at: src.at(item.span().start),
                        field: "claims.value".into(),
                        message: e.to_string(),
                    })?;
                points.push(point);
            }
            Check::CurveDerivative {
                end: end_field(src, need(src, c, &c.end, "end")?)?,
                order: order_field(src, c, need(src, c, &c.order, "order")?)?,
                wrt: wrt_field(src, spec, c.wrt.as_ref())?,
                text: item.get_ref().trim().to_string(),
                value: formula_in(src, spec, item, "", item.get_ref(), &points)?,
            }
        }
        "join" => crate::join_read::join(src, spec, c)?,
        "join-singular" => crate::join_read::join_singular(src, spec, c)?,
        "continuity" => {
            if spec.functions.len() < 2 {
                return src.invalid(c.check.span(), "claims.check", "continuity at knots needs at least two segment functions (piece k of the B-spline is function n − 1 − k)".into());
            }
            Check::Continuity {
                order: order_field(src, c, need(src, c, &c.order, "order")?)?,
                of: crate::given_read::continuous(src, spec, c)?,
            }
        }
        "local-control" => local_control(src, spec, c)?,
        "identity" => crate::identity_read::identity(src, spec, c)?,
        "one-maximum" => Check::OneMaximum,
        "fourier-span" => Check::FourierSpan {
            span: need(src, c, &c.span, "span")?
                .iter()
                .map(|item| {
                    let text = item.get_ref().trim().to_string();
                    formula_in(src, spec, item, "", &text, &[]).map(|v| (text, v))
                })
                .collect::<Result<_>>()?,
        },
        "surface-join" => crate::listing::surface_join(src, spec, c)?,
        "cylinder" => crate::listing::cylinder(src, spec, c)?,
        "leaves-hull" => crate::listing::leaves_hull(src, spec, c)?,
        "knot-coefficients" => crate::given_read::knot_coefficients(src, spec, c)?,
        "all" => Check::All {
            claims: need(src, c, &c.claims, "claims")?
                .iter()
                .map(|id| id.get_ref().trim().to_string())
                .collect(),
            brief: c.brief == Some(true),
        },
        "not-printed" => {
            let reason = need(src, c, &c.reason, "reason")?;
            if reason.get_ref().trim().is_empty() {
                return src.invalid(
                    reason.span(),
                    "claims.reason",
                    "say what the copy does not print".into(),
                );
            }
            Check::NotPrinted {
                reason: reason.get_ref().trim().to_string(),
            }
        }
        "interpolant-nonnegative" => {
            let (path, data, scheme) = interpolant(src, c)?;
            Check::InterpolantNonnegative { path, data, scheme }
        }
        "interpolant-continuity" => {
            let (path, data, scheme) = interpolant(src, c)?;
            let order = order_field(src, c, need(src, c, &c.order, "order")?)?;
            Check::InterpolantContinuity {
                path,
                data,
                scheme,
                order,
            }
        }
        "table-arithmetic" => {
            let (path, text) = data_file(src, c)?;
            Check::TableArithmetic { path, text }
        }
        "same-basis" => same_basis(src, spec, c)?,
        "end-direction" => crate::direction_read::end_direction(src, spec, c)?,
        "table-quotes" => {
            let (path, text) = data_file(src, c)?;
            let (quotes_path, quotes) =
                file_field(src, need(src, c, &c.quotes, "quotes")?, "quotes")?;
            Check::TableQuotes {
                path,
                text,
                quotes_path,
                quotes,
            }
        }
        "table-compare" => {
            let (path, text) = data_file(src, c)?;
            let (quotes_path, quotes) =
                file_field(src, need(src, c, &c.quotes, "quotes")?, "quotes")?;
            Check::TableCompare {
                path,
                text,
                quotes_path,
                quotes,
            }
        }
        "data-values" => {
            let (path, data, _) = interpolant(src, c)?;
            let queries = need(src, c, &c.values, "values")?
                .iter()
                .map(|q| {
                    crate::data_query::parse(q.get_ref())
                        .or_else(|e| src.invalid(q.span(), "claims.values", e))
                })
                .collect::<Result<_>>()?;
            Check::DataValues {
                path,
                data,
                queries,
            }
        }
        "interpolant-maximum" => {
            let (path, data, scheme) = interpolant(src, c)?;
            let queries = need(src, c, &c.values, "values")?
                .iter()
                .map(|q| {
                    crate::data_query::maximum(q.get_ref())
                        .or_else(|e| src.invalid(q.span(), "claims.values", e))
                })
                .collect::<Result<_>>()?;
            Check::InterpolantMaximum {
                path,
                data,
                scheme,
                queries,
            }
        }
        "table-count" => {
            let (path, text) = data_file(src, c)?;
            let (counts_path, counts) =
                file_field(src, need(src, c, &c.quotes, "quotes")?, "quotes")?;
            Check::TableCount {
                path,
                text,
                counts_path,
                counts,
            }
        }
        other => {
            return src.invalid(
                c.check.span(),
                "claims.check",
                format!("`{other}`: expected unity, nonnegative, convex-hull, conic, independent, total-positivity, monotone, shape-effect, symmetry, endpoint-values, endpoint-derivatives, curve-derivative, join, join-singular, continuity, local-control, identity, one-maximum, fourier-span, all, not-printed, interpolant-nonnegative, interpolant-continuity, table-arithmetic, table-quotes, table-compare, table-count, data-values, interpolant-maximum, same-basis, end-direction, surface-join, cylinder, knot-coefficients, leaves-hull or end-curvature"),
            );
        }
    };
    for (field, given, taken) in [
        (
            "claims",
            c.claims
                .as_ref()
                .map(|v| v.first().map_or(c.check.span(), Spanned::span)),
            matches!(check, Check::All { .. }),
        ),
        (
            "reason",
            c.reason.as_ref().map(Spanned::span),
            matches!(check, Check::NotPrinted { .. }),
        ),
        (
            "brief",
            c.brief.as_ref().map(|_| c.check.span()),
            matches!(check, Check::All { .. }),
        ),
        (
            "data",
            c.data.as_ref().map(Spanned::span),
            matches!(
                check,
                Check::InterpolantNonnegative { .. }
                    | Check::InterpolantContinuity { .. }
                    | Check::TableArithmetic { .. }
                    | Check::TableQuotes { .. }
                    | Check::TableCompare { .. }
                    | Check::TableCount { .. }
                    | Check::DataValues { .. }
                    | Check::InterpolantMaximum { .. }
                    | Check::SurfaceJoin { .. }
                    | Check::Cylinder { .. }
                    | Check::LeavesHull { .. }
            ),
        ),
        (
            "quotes",
            c.quotes.as_ref().map(Spanned::span),
            matches!(
                check,
                Check::TableQuotes { .. } | Check::TableCompare { .. } | Check::TableCount { .. }
            ),
        ),
        (
            "scheme",
            c.scheme.as_ref().map(Spanned::span),
            matches!(
                check,
                Check::InterpolantNonnegative { .. }
                    | Check::InterpolantContinuity { .. }
                    | Check::InterpolantMaximum { .. }
            ),
        ),
        (
            "other",
            c.other.as_ref().map(Spanned::span),
            matches!(check, Check::SameBasis { .. }),
        ),
        (
            "curves",
            c.curves
                .as_ref()
                .map(|v| v.first().map_or(c.check.span(), |k| k.name.span())),
            matches!(
                check,
                Check::EndpointDerivatives { .. } | Check::Identity { .. }
            ),
        ),
        (
            "polygons",
            c.polygons.as_ref().map(|_| c.check.span()),
            matches!(
                check,
                Check::ShapeEffect { .. } | Check::LeavesHull { .. } | Check::EndCurvature { .. }
            ),
        ),
        (
            "correction",
            c.correction.as_ref().map(|k| k.says.span()),
            matches!(check, Check::Identity { .. }),
        ),
        (
            "positive",
            c.positive.as_ref().map(|_| c.check.span()),
            matches!(check, Check::Identity { .. }),
        ),
        (
            "along",
            [&c.along, &c.sign, &c.limit]
                .into_iter()
                .flatten()
                .next()
                .map(Spanned::span),
            matches!(check, Check::EndDirection { .. }),
        ),
        (
            "onto",
            c.onto
                .as_ref()
                .map(|v| v.first().map_or(c.check.span(), Spanned::span)),
            matches!(check, Check::ShapeEffect { .. }),
        ),
        (
            "parameters",
            c.parameters
                .as_ref()
                .map(|v| v.first().map_or(c.check.span(), Spanned::span)),
            matches!(check, Check::ShapeEffect { .. }),
        ),
        (
            "either",
            c.either.map(|_| c.check.span()),
            matches!(check, Check::ShapeEffect { .. }),
        ),
        (
            "curvatures",
            c.curvatures.as_ref().map(|_| c.check.span()),
            matches!(check, Check::EndCurvature { .. }),
        ),
    ] {
        if let (Some(span), false) = (given, taken) {
            return src.invalid(
                span,
                &format!("claims.{field}"),
                format!(
                    "`{field}` belongs to `check = \"{}\"`",
                    match field {
                        "claims" | "brief" => "all",
                        "reason" => "not-printed",
                        "data" => "interpolant-nonnegative`, `check = \"interpolant-continuity`, `check = \"table-arithmetic`, `check = \"table-quotes`, `check = \"table-compare`, `check = \"table-count`, `check = \"data-values`, `check = \"interpolant-maximum`, `check = \"surface-join`, `check = \"cylinder` or `check = \"leaves-hull",
                        "other" => "same-basis",
                        "polygons" => "shape-effect`, `check = \"leaves-hull` or `check = \"end-curvature",
                        "quotes" => "table-quotes`, `check = \"table-compare` or `check = \"table-count",
                        "curves" => "identity` or `check = \"endpoint-derivatives",
                        "correction" | "positive" => "identity",
                        "along" => "end-direction",
                        "onto" | "parameters" | "either" => "shape-effect",
                        "curvatures" => "end-curvature",
                        _ => "interpolant-nonnegative` or `check = \"interpolant-continuity",
                    }
                ),
            );
        }
    }
    let with_maximal = matches!(
        check,
        Check::Nonnegative { .. }
            | Check::ConvexHull { .. }
            | Check::TotalPositivity { .. }
            | Check::Independent { .. }
    );
    if let (Some(true), false) = (c.maximal, with_maximal) {
        return src.invalid(
            c.check.span(),
            "claims.maximal",
            format!(
                "`maximal = true` asks for the maximal set of nonnegativity, of the convex-hull property, of independence or of total positivity; it is not decided for `{}` (the claim would be decided without it)",
                c.check.get_ref().trim()
            ),
        );
    }
    if let (Some(q), false) = (&c.quantifier, matches!(check, Check::Conic { .. })) {
        return src.invalid(
            q.span(),
            "claims.for",
            format!(
                "`for` (some value, no value) is decided for `conic` claims, not for `{}`",
                c.check.get_ref().trim()
            ),
        );
    }
    let given = given(src, spec, c, c.check.get_ref().trim())?;
    if matches!(check, Check::All { .. } | Check::NotPrinted { .. }) && !given.is_empty() {
        return src.invalid(
            c.check.span(),
            "claims.at",
            "an umbrella or a claim the copy does not print fixes no values (its parts fix their own)".into(),
        );
    }
    if matches!(
        check,
        Check::InterpolantNonnegative { .. }
            | Check::InterpolantContinuity { .. }
            | Check::TableArithmetic { .. }
            | Check::TableQuotes { .. }
            | Check::TableCompare { .. }
            | Check::TableCount { .. }
            | Check::DataValues { .. }
            | Check::InterpolantMaximum { .. }
    ) && !given.is_empty()
    {
        return src.invalid(
            c.check.span(),
            "claims.at",
            "a claim about a printed table takes its values from the table: it fixes no values"
                .into(),
        );
    }
    if c.maximal == Some(true) && spec.params.is_empty() {
        return src.invalid(
            c.check.span(),
            "claims.maximal",
            "`maximal = true` on a basis without parameters: there is no set of parameters to be maximal (drop `maximal`)".into(),
        );
    }
    if c.maximal == Some(true) && !spec.params.is_empty() && given.fixed.len() == spec.params.len()
    {
        return src.invalid(
            c.check.span(),
            "claims.maximal",
            "`maximal = true` with every parameter fixed: no range is left to be maximal (drop `maximal`, or leave a parameter free)".into(),
        );
    }
    let varied: &[String] = match &check {
        Check::ShapeEffect { parameters, .. } => parameters,
        Check::LocalControl {
            varied: Varied::Parameter { name, .. },
            ..
        } => std::slice::from_ref(name),
        _ => &[],
    };
    if let Some(p) = varied
        .iter()
        .find(|p| given.fixed.iter().any(|f| &f.name == *p))
    {
        return src.invalid(
            c.check.span(),
            "claims.at",
            format!("the claim is about varying `{p}`, which it also fixes"),
        );
    }
    Ok(SpecClaim {
        id,
        source: c.source.clone(),
        statement: c.statement.get_ref().clone(),
        check,
        given,
        negated: c.negated == Some(true),
        notes: c.notes.clone().unwrap_or_default(),
        figure: crate::fields::figure_field(src, c)?,
    })
}

/// `data = "table-4.1.tsv"` (a table file, relative to the claim's file:
/// read here, so a missing or malformed table is an error of the file) and
/// `scheme` (the table's own unless given): the path as written, the table,
/// the scheme.
fn interpolant(src: &Source<'_>, c: &RawClaim) -> Result<(String, DataSet, Scheme)> {
    let (path, text) = data_file(src, c)?;
    let data = match DataSet::parse(&text) {
        Ok(data) => data,
        Err(e) => {
            let span = need(src, c, &c.data, "data")?.span();
            return src.invalid(span, "claims.data", format!("{path}: {e}"));
        }
    };
    let scheme = match &c.scheme {
        None => data.table.scheme,
        Some(s) => match s.get_ref().trim().parse::<Scheme>() {
            Ok(scheme) => scheme,
            Err(e) => return src.invalid(s.span(), "claims.scheme", e.to_string()),
        },
    };
    Ok((path, data, scheme))
}

/// `other = "han.toml"` (a spec file, relative to the claim's file: read
/// here, its basis only) and `params = { lambda = "m" }`: each of its
/// parameters as a formula in this basis's parameters.
fn same_basis(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let path = need(src, c, &c.other, "other")?;
    let dir = Path::new(src.file).parent().unwrap_or(Path::new(""));
    let other = Spec::basis_from_file(&dir.join(path.get_ref().trim())).map_err(|e| {
        SpecError::Invalid {
            at: src.at(path.span().start),
            field: "claims.other".into(),
            message: e.to_string(),
        }
    })?;
    let empty = std::collections::BTreeMap::new();
    let map = c.params.as_ref().unwrap_or(&empty);
    if let Some((name, value)) = map
        .iter()
        .find(|(name, _)| !other.params.iter().any(|p| &p.name == *name))
    {
        return src.invalid(
            value.span(),
            "claims.params",
            format!("`{name}`: not a parameter of {}", other.id),
        );
    }
    let mut params = Vec::new();
    let mut shown = Vec::new();
    for p in &other.params {
        let Some(value) = map.get(&p.name) else {
            return src.invalid(
                path.span(),
                "claims.params",
                format!(
                    "`{}` of {} needs a value in `params` (a formula in this basis's parameters)",
                    p.name, other.id
                ),
            );
        };
        params.push((
            p.name.clone(),
            formula_in(src, spec, value, "", value.get_ref(), &[])?,
        ));
        shown.push(format!("{} = {}", p.symbol, value.get_ref().trim()));
    }
    Ok(Check::SameBasis {
        path: path.get_ref().trim().to_string(),
        other: Box::new(other),
        params,
        params_text: shown.join(", "),
    })
}

/// `control = "point"` (the control point `P_j`) or a parameter's name
/// with `scope = "segment"` (one value per segment) or `"curve"` (one for
/// the whole curve); `segments = [-3, -2, -1, 0]`, the printed segments
/// `j + o`.
fn local_control(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let control = need(src, c, &c.control, "control")?;
    let segments = need(src, c, &c.segments, "segments")?.clone();
    let name = control.get_ref().trim();
    let varied = if name == "point" {
        if let Some(scope) = &c.scope {
            return src.invalid(
                scope.span(),
                "claims.scope",
                "`scope` belongs to a parameter (`control = \"point\"` varies a control point)"
                    .into(),
            );
        }
        Varied::Point
    } else {
        if !spec.params.iter().any(|p| p.name == name) {
            let names: Vec<&str> = spec.params.iter().map(|p| p.name.as_str()).collect();
            return src.invalid(
                control.span(),
                "claims.control",
                format!(
                    "`{name}`: expected `point` or a parameter ({})",
                    if names.is_empty() {
                        "none declared".to_string()
                    } else {
                        names.join(", ")
                    }
                ),
            );
        }
        Varied::Parameter {
            name: name.to_string(),
            per_segment: scope_field(src, need(src, c, &c.scope, "scope")?, "scope")?,
        }
    };
    let also = match (&c.also_scope, &varied) {
        (None, _) => None,
        (Some(scope), Varied::Parameter { name, .. }) => Some(Varied::Parameter {
            name: name.clone(),
            per_segment: scope_field(src, scope, "also-scope")?,
        }),
        (Some(scope), Varied::Point) => {
            return src.invalid(
                scope.span(),
                "claims.also-scope",
                "`also-scope` belongs to a parameter".into(),
            );
        }
    };
    let rational = match (c.weights, &c.curve, &c.point) {
        (Some(true), curve, point) => {
            if varied != Varied::Point {
                return src.invalid(
                    c.check.span(),
                    "claims.weights",
                    "`weights = true` (a rational curve) is decided for `control = \"point\"`: the control point and its weight".into(),
                );
            }
            let curve = curve.as_ref().map_or("r", |n| n.get_ref().trim());
            let point = point.as_ref().map_or("P", |n| n.get_ref().trim());
            let mut names = spec.names();
            for (prefix, what) in [(point, "a control point"), ("w", "a weight")] {
                for i in 0..spec.functions.len() {
                    names
                        .fixed(&format!("{prefix}{i}"), what)
                        .map_err(|e| SpecError::Invalid {
                            at: src.at(c.check.span().start),
                            field: "claims.point".into(),
                            message: e.to_string(),
                        })?;
                }
            }
            Some(RationalCurve {
                curve: curve.to_string(),
                point: point.to_string(),
            })
        }
        (_, None, None) => None,
        _ => {
            return src.invalid(
                c.check.span(),
                "claims.curve",
                "`curve` and `point` name the parts of a rational curve (`weights = true`)".into(),
            );
        }
    };
    Ok(Check::LocalControl {
        varied,
        segments,
        also,
        first: c.first_point.unwrap_or(0),
        rational,
    })
}

/// `segment` (one value per segment: true) or `curve` (one value for the
/// whole curve).
fn scope_field(src: &Source<'_>, scope: &Spanned<String>, field: &str) -> Result<bool> {
    match scope.get_ref().trim() {
        "segment" => Ok(true),
        "curve" => Ok(false),
        other => src.invalid(
            scope.span(),
            &format!("claims.{field}"),
            format!("`{other}`: expected `segment` (one value per segment) or `curve` (one value for the whole curve)"),
        ),
    }
}
