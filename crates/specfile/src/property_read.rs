//! The claims of the shape properties, read: a conic the span reproduces
//! (`conic`), monotone functions (`monotone`), the effect of a shape
//! parameter (`shape-effect`) and symmetry (`symmetry`).

use rug::Rational;
use trig_core::{Affine, ParamRange, parse_exact};
use trig_symbolic::Sym;

use crate::check::{Check, Direction, Monotone, Quantifier};
use crate::error::{Result, SpecError};
use crate::fields::{formula_in, function_index, need};
use crate::given_read::one_param_range;
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

/// `values = ["P0 = (x, y)", …]` (one point per function, in order) and
/// `value = "equation in X, Y"`.
pub(crate) fn conic(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    if spec.params.iter().any(|p| p.name == "X" || p.name == "Y") {
        return src.invalid(
            c.check.span(),
            "claims.check",
            "`conic` writes its equation in X and Y, which are parameter names here".into(),
        );
    }
    let items = need(src, c, &c.values, "values")?;
    if items.len() != spec.functions.len() {
        return src.invalid(
            c.check.span(),
            "claims.values",
            format!(
                "expected one control point per function ({}), found {}",
                spec.functions.len(),
                items.len()
            ),
        );
    }
    let (mut points, mut points_text, mut singular) = (Vec::new(), Vec::new(), Vec::new());
    for item in items {
        let text = item.get_ref();
        let malformed = || {
            src.invalid(
                item.span(),
                "claims.values",
                format!("`{text}`: expected `NAME = (X, Y)`"),
            )
        };
        let Some((_, pair)) = text.split_once('=') else {
            return malformed();
        };
        let inner = pair.trim();
        let Some(inner) = inner.strip_prefix('(').and_then(|r| r.strip_suffix(')')) else {
            return malformed();
        };
        let mut depth = 0i32;
        let split = inner.char_indices().find(|&(_, ch)| {
            depth += match ch {
                '(' => 1,
                ')' => -1,
                _ => 0,
            };
            ch == ',' && depth == 0
        });
        let Some((at, _)) = split else {
            return malformed();
        };
        // errors point into the item: the offset of each coordinate in it
        let start = text.len() - pair.trim_start().len() + 1;
        let mut coordinate = |part: &str, offset: usize| -> Result<Sym> {
            let (value, why) = spec.parse_claim_formula(part, &[], &[]).map_err(|mut e| {
                e.position += text[..offset].chars().count();
                src.formula_error(item, e)
            })?;
            singular.extend(why);
            Ok(value)
        };
        let x = coordinate(&inner[..at], start)?;
        let y = coordinate(&inner[at + 1..], start + at + 1)?;
        points.push((x, y));
        points_text.push(text.trim().to_string());
    }
    let item = need(src, c, &c.value, "value")?;
    let extra = ["X".to_string(), "Y".to_string()];
    let equation = formula_in(src, spec, item, "", item.get_ref(), &extra)?;
    let quantifier = match &c.quantifier {
        None => None,
        Some(q) => match q.get_ref().trim() {
            "every value" => None,
            "some value" => Some(Quantifier::Some),
            "no value" => Some(Quantifier::No),
            other => {
                return src.invalid(
                    q.span(),
                    "claims.for",
                    format!("`{other}`: expected `every value`, `some value` or `no value`"),
                );
            }
        },
    };
    Ok(Check::Conic {
        points,
        points_text,
        equation,
        equation_text: item.get_ref().trim().to_string(),
        singular,
        quantifier,
    })
}

pub(crate) fn monotone(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let items = need(src, c, &c.functions, "functions")?
        .iter()
        .map(|item| {
            let text = item.get_ref();
            let (name, dir) = text.trim().rsplit_once(' ').unwrap_or((text, ""));
            let increasing = match dir {
                "increasing" => true,
                "decreasing" => false,
                _ => {
                    return src.invalid(
                        item.span(),
                        "claims.functions",
                        format!("`{text}`: expected `NAME increasing` or `NAME decreasing`"),
                    );
                }
            };
            Ok(Monotone {
                function: function_index(src, spec, item, name)?,
                increasing,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Check::Monotone {
        items,
        range: one_param_range(src, spec, &c.range)?,
    })
}

/// `parameter = "lambda"`, `direction = "towards-polygon"` or
/// `"away-from-polygon"`, optional `range` (of that parameter).
pub(crate) fn shape_effect(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let name = need(src, c, &c.parameter, "parameter")?;
    let Some(p) = spec
        .params
        .iter()
        .find(|p| p.name == name.get_ref().trim() || p.symbol == name.get_ref().trim())
    else {
        return src.invalid(
            name.span(),
            "claims.parameter",
            format!("`{}`: not a parameter of the basis", name.get_ref()),
        );
    };
    let dir = need(src, c, &c.direction, "direction")?;
    let direction = match dir.get_ref().trim() {
        "towards-polygon" => Direction::TowardsPolygon,
        "away-from-polygon" => Direction::AwayFromPolygon,
        other => {
            return src.invalid(
                dir.span(),
                "claims.direction",
                format!("`{other}`: expected `towards-polygon` or `away-from-polygon`"),
            );
        }
    };
    let range = match &c.range {
        Some(r) => Some(
            ParamRange::parse(r.get_ref()).or_else(|m| src.invalid(r.span(), "claims.range", m))?,
        ),
        None => None,
    };
    Ok(Check::ShapeEffect {
        parameter: p.name.clone(),
        direction,
        range,
    })
}

pub(crate) fn symmetry(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let map = need(src, c, &c.map, "map")?;
    let expected = format!(
        "`{}`: expected a reflection `A - {}` with A a number, pi or the parameters (e.g. 1 - u, pi/2 - t, alpha - t)",
        map.get_ref(),
        spec.var_name
    );
    let l = spec
        .parse_linear(map.get_ref(), "a symmetry map")
        .map_err(|e| src.formula_error(map, e))?;
    if l.x != Affine::rational(Rational::from(-1)) {
        return src.invalid(map.span(), "claims.map", expected);
    }
    let index = need(src, c, &c.index, "index")?;
    let compact: String = index
        .get_ref()
        .chars()
        .filter(|ch| !ch.is_whitespace())
        .collect();
    let offset = compact
        .strip_suffix("-i")
        .and_then(|a| a.parse::<i64>().ok())
        .ok_or_else(|| SpecError::Invalid {
            at: src.at(index.span().start),
            field: "claims.index".into(),
            message: format!("`{}`: expected `N - i` with an integer N", index.get_ref()),
        })?;
    let mut at = Vec::new();
    for p in &spec.params {
        let value = match c.at.as_ref().and_then(|m| m.get(&p.name)) {
            Some(v) => parse_exact(v.get_ref()).map_err(|e| SpecError::Invalid {
                at: src.at(v.span().start),
                field: "claims.at".into(),
                message: e.to_string(),
            })?,
            None => p.range.interior_point(),
        };
        at.push(value);
    }
    let mut params: Vec<Sym> = spec.params.iter().map(|p| Sym::var(&p.name)).collect();
    let mut shown = Vec::new();
    if let Some(map) = &c.params {
        for (name, value) in map {
            let Some(i) = spec.params.iter().position(|p| &p.name == name) else {
                return src.invalid(
                    value.span(),
                    "claims.params",
                    format!("`{name}`: not a parameter of the basis"),
                );
            };
            params[i] = formula_in(src, spec, value, "", value.get_ref(), &[])?;
            shown.push(format!("{name} ↦ {}", value.get_ref().trim()));
        }
    }
    Ok(Check::Symmetry {
        map_text: map.get_ref().trim().to_string(),
        map: l.rest,
        index_text: index.get_ref().trim().to_string(),
        offset,
        at,
        params,
        params_text: shown.join(", "),
    })
}
