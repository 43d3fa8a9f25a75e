//! The claims of the shape properties, read: a conic the span reproduces
//! (`conic`), monotone functions (`monotone`), the effect of a shape
//! parameter (`shape-effect`) and symmetry (`symmetry`).

use rug::Rational;
use toml::Spanned;
use trig_core::{Affine, ParamRange, parse_exact};
use trig_symbolic::Sym;

use crate::check::{Check, Direction, Monotone, Polygons, Quantifier, Target};
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

/// `parameter = "lambda"` (or `parameters = ["lambda", "mu"]`, changed
/// concurrently), `direction = "towards-polygon"` or `"away-from-polygon"`
/// (or `onto = ["b0", "b2"]`, the functions whose weights rise), optional
/// `either = true` ("increases (or decreases)") and `range` (of the one
/// parameter).
pub(crate) fn shape_effect(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let parameters = match &c.parameters {
        Some(names) => {
            if let Some(p) = &c.parameter {
                return src.invalid(
                    p.span(),
                    "claims.parameter",
                    "`parameter` and `parameters` exclude each other".into(),
                );
            }
            let mut found = Vec::new();
            for name in names {
                let p = parameter_of(src, spec, name)?;
                if found.contains(&p.name) {
                    return src.invalid(
                        name.span(),
                        "claims.parameters",
                        format!("`{}` listed twice", name.get_ref()),
                    );
                }
                found.push(p.name.clone());
            }
            if found.len() < 2 {
                return src.invalid(
                    c.check.span(),
                    "claims.parameters",
                    "`parameters` lists the parameters changed concurrently (two or more; one is `parameter`)".into(),
                );
            }
            found
        }
        None => vec![parameter_named(src, spec, c)?.name.clone()],
    };
    let target = match (&c.direction, &c.onto) {
        (Some(_), Some(o)) => {
            return src.invalid(
                o.first().map_or(c.check.span(), Spanned::span),
                "claims.onto",
                "`direction` and `onto` exclude each other".into(),
            );
        }
        (None, Some(onto)) => {
            let mut indices = Vec::new();
            for f in onto {
                indices.push(function_index(src, spec, f, f.get_ref())?);
            }
            if indices.is_empty() || indices.len() == spec.functions.len() {
                return src.invalid(
                    c.check.span(),
                    "claims.onto",
                    "`onto` names some of the functions, not none or all".into(),
                );
            }
            Target::Onto(indices)
        }
        (_, None) => {
            let dir = need(src, c, &c.direction, "direction")?;
            Target::Polygon(match dir.get_ref().trim() {
                "towards-polygon" => Direction::TowardsPolygon,
                "away-from-polygon" => Direction::AwayFromPolygon,
                other => {
                    return src.invalid(
                        dir.span(),
                        "claims.direction",
                        format!("`{other}`: expected `towards-polygon` or `away-from-polygon`"),
                    );
                }
            })
        }
    };
    let range = match &c.range {
        Some(r) if parameters.len() > 1 => {
            return src.invalid(
                r.span(),
                "claims.range",
                "`range` is the range of one parameter (`parameter`)".into(),
            );
        }
        Some(r) => Some(
            ParamRange::parse(r.get_ref()).or_else(|m| src.invalid(r.span(), "claims.range", m))?,
        ),
        None => None,
    };
    let polygons = polygons(src, spec, c)?;
    if polygons.is_some() && parameters.len() > 1 {
        return src.invalid(
            c.check.span(),
            "claims.polygons",
            "printed `polygons` are shown at values of one parameter (`parameter`)".into(),
        );
    }
    Ok(Check::ShapeEffect {
        parameters,
        target,
        either: c.either == Some(true),
        range,
        polygons,
    })
}

/// The basis's parameter `parameter = "m"` names (by name or symbol).
pub(crate) fn parameter_named<'a>(
    src: &Source<'_>,
    spec: &'a Spec,
    c: &RawClaim,
) -> Result<&'a trig_core::Parameter> {
    parameter_of(src, spec, need(src, c, &c.parameter, "parameter")?)
}

/// The basis's parameter `name` names (by name or symbol).
fn parameter_of<'a>(
    src: &Source<'_>,
    spec: &'a Spec,
    name: &Spanned<String>,
) -> Result<&'a trig_core::Parameter> {
    let found = spec
        .params
        .iter()
        .find(|p| p.name == name.get_ref().trim() || p.symbol == name.get_ref().trim());
    found.map_or_else(
        || {
            src.invalid(
                name.span(),
                "claims.parameter",
                format!("`{}`: not a parameter of the basis", name.get_ref()),
            )
        },
        Ok,
    )
}

/// `polygons = [["(0, 0)", "(1, 2)", …], …]` with `curve-at = { s = "4/5",
/// c = "3/5" }` (the atoms of the variable; `s² + c² = 1`) and `values`
/// (the varied parameter's values): each exact.
fn polygons(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Option<Polygons>> {
    let Some(printed) = &c.polygons else {
        if let Some(at) = c.curve_at.as_ref().and_then(|m| m.values().next()) {
            return src.invalid(
                at.span(),
                "claims.curve-at",
                "`curve-at` places the curve point of printed `polygons`".into(),
            );
        }
        if let Some(v) = c.values.as_ref().and_then(|v| v.first()) {
            return src.invalid(
                v.span(),
                "claims.values",
                "`values` of a shape-effect claim are the parameter values of printed `polygons`"
                    .into(),
            );
        }
        return Ok(None);
    };
    let number =
        |item: &Spanned<String>, text: &str, field: &str| rational_in(src, spec, item, text, field);
    let polygons = printed_polygons(src, spec, c, printed)?;
    let atoms: Vec<String> = spec
        .functions
        .iter()
        .flat_map(|f| f.value.variables())
        .filter(|v| !spec.params.iter().any(|p| &p.name == v))
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    let mut at = Vec::new();
    for (name, value) in need(src, c, &c.curve_at, "curve-at")? {
        if !atoms.contains(name) {
            return src.invalid(
                value.span(),
                "claims.curve-at",
                format!(
                    "`{name}`: not an atom of the functions ({})",
                    atoms.join(", ")
                ),
            );
        }
        at.push((name.clone(), number(value, value.get_ref(), "curve-at")?));
    }
    // the sine before the cosine, as a point of the angle is written
    at.sort_by_key(|(name, _)| (name != "s", name != "c"));
    let value = |n: &str| at.iter().find(|(a, _)| a == n).map(|(_, v)| v.clone());
    if let (Some(s), Some(cos)) = (value("s"), value("c"))
        && Rational::from(&s * &s) + Rational::from(&cos * &cos) != 1
    {
        return src.invalid(
            c.check.span(),
            "claims.curve-at",
            format!("s = {s}, c = {cos} is not a point of the angle (s² + c² ≠ 1)"),
        );
    }
    let values = need(src, c, &c.values, "values")?
        .iter()
        .map(|v| number(v, v.get_ref(), "values"))
        .collect::<Result<Vec<_>>>()?;
    Ok(Some(Polygons {
        polygons,
        at,
        values,
    }))
}

/// A rational number of the formula language in `item` (the text `text`
/// of it), for `claims.{field}`.
pub(crate) fn rational_in(
    src: &Source<'_>,
    spec: &Spec,
    item: &Spanned<String>,
    text: &str,
    field: &str,
) -> Result<Rational> {
    let value = formula_in(src, spec, item, "", text, &[])?;
    value.as_rational().map_or_else(
        || {
            src.invalid(
                item.span(),
                &format!("claims.{field}"),
                format!("`{}`: expected a rational number", text.trim()),
            )
        },
        Ok,
    )
}

/// `polygons = [["(0, 0)", "(1, 2)", …], …]`: each polygon's vertices,
/// exact, at least two.
pub(crate) fn printed_polygons(
    src: &Source<'_>,
    spec: &Spec,
    c: &RawClaim,
    printed: &[Vec<Spanned<String>>],
) -> Result<Vec<Vec<(Rational, Rational)>>> {
    let mut polygons = Vec::new();
    for polygon in printed {
        let mut vertices = Vec::new();
        for item in polygon {
            let text = item.get_ref();
            let pair = text
                .trim()
                .strip_prefix('(')
                .and_then(|r| r.strip_suffix(')'));
            let Some((x, y)) = pair.and_then(|p| p.split_once(',')) else {
                return src.invalid(
                    item.span(),
                    "claims.polygons",
                    format!("`{text}`: expected a point `(x, y)`"),
                );
            };
            vertices.push((
                rational_in(src, spec, item, x, "polygons")?,
                rational_in(src, spec, item, y, "polygons")?,
            ));
        }
        if vertices.len() < 2 {
            return src.invalid(
                c.check.span(),
                "claims.polygons",
                "a polygon has at least two points".into(),
            );
        }
        polygons.push(vertices);
    }
    Ok(polygons)
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

#[cfg(test)]
mod tests {
    use rug::Rational;

    use crate::check::{Check, Target};
    use crate::spec::Spec;

    fn thesis_cubic_with(claim: &str) -> crate::error::Result<Spec> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog/thesis-cubic.toml");
        let text = std::fs::read_to_string(path).unwrap();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"e\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"shape-effect\"\nparameter = \"m\"\ndirection = \"towards-polygon\"\n{claim}\n"
            ),
            "thesis-cubic.toml",
        )
    }

    #[test]
    fn printed_polygons_are_read_exactly_with_their_curve_point() {
        let spec = thesis_cubic_with(
            "polygons = [[\"(0, 0)\", \"(10.5, 8)\"]]\ncurve-at = { c = \"3/5\", s = \"4/5\" }\nvalues = [\"-1\", \"1/2\"]",
        )
        .unwrap();
        let Check::ShapeEffect {
            polygons: Some(p), ..
        } = &spec.claims[0].check
        else {
            panic!("a shape-effect claim with polygons");
        };
        let q = |n: i64, d: i64| Rational::from((n, d));
        assert_eq!(p.polygons, [vec![(q(0, 1), q(0, 1)), (q(21, 2), q(8, 1))]]);
        // the sine first, as a point of the angle is written
        assert_eq!(
            p.at,
            [("s".to_string(), q(4, 5)), ("c".to_string(), q(3, 5))]
        );
        assert_eq!(p.values, [q(-1, 1), q(1, 2)]);
    }

    #[test]
    fn a_curve_point_off_the_angle_or_a_stray_field_is_refused() {
        let off = "polygons = [[\"(0, 0)\", \"(1, 2)\"]]\ncurve-at = { s = \"1/2\", c = \"1/2\" }\nvalues = [\"0\"]";
        let e = thesis_cubic_with(off).unwrap_err();
        assert!(e.to_string().contains("s² + c² ≠ 1"), "{e}");
        let e = thesis_cubic_with("polygons = [[\"(0, 0)\", \"1, 2\"]]\ncurve-at = { s = \"4/5\", c = \"3/5\" }\nvalues = [\"0\"]").unwrap_err();
        assert!(e.to_string().contains("expected a point"), "{e}");
        let e = thesis_cubic_with("values = [\"0\"]").unwrap_err();
        assert!(e.to_string().contains("printed `polygons`"), "{e}");
        let e = thesis_cubic_with(
            "polygons = [[\"(0, 0)\", \"(1, 2)\"]]\ncurve-at = { q = \"1\" }\nvalues = [\"0\"]",
        )
        .unwrap_err();
        assert!(e.to_string().contains("not an atom"), "{e}");
    }

    fn eh_with(claim: &str) -> crate::error::Result<Spec> {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/catalog/eh.toml");
        let text = std::fs::read_to_string(path).unwrap();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"e\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"shape-effect\"\n{claim}\n"
            ),
            "eh.toml",
        )
    }

    #[test]
    fn onto_named_points_concurrent_parameters_and_either_are_read() {
        let spec = eh_with("parameter = \"mu\"\nonto = [\"b0\", \"b2\"]\neither = true").unwrap();
        let Check::ShapeEffect {
            parameters,
            target,
            either,
            ..
        } = &spec.claims[0].check
        else {
            panic!("a shape-effect claim");
        };
        assert_eq!(parameters, &["mu"]);
        assert_eq!(target, &Target::Onto(vec![0, 2]));
        assert!(*either);
        let spec =
            eh_with("parameters = [\"λ\", \"mu\"]\ndirection = \"towards-polygon\"").unwrap();
        let Check::ShapeEffect {
            parameters, either, ..
        } = &spec.claims[0].check
        else {
            panic!("a shape-effect claim");
        };
        assert_eq!(parameters, &["lambda", "mu"]);
        assert!(!*either);
        for (bad, says) in [
            (
                "parameter = \"mu\"\nonto = [\"b0\"]\ndirection = \"towards-polygon\"",
                "exclude each other",
            ),
            ("parameter = \"mu\"\nonto = [\"b7\"]", "unknown function"),
            (
                "parameters = [\"mu\"]\ndirection = \"towards-polygon\"",
                "two or more",
            ),
            (
                "parameters = [\"mu\", \"μ\"]\ndirection = \"towards-polygon\"",
                "listed twice",
            ),
            (
                "parameters = [\"lambda\", \"mu\"]\ndirection = \"towards-polygon\"\nrange = \"[0, 1]\"",
                "one parameter",
            ),
        ] {
            let e = eh_with(bad).unwrap_err();
            assert!(e.to_string().contains(says), "{bad}: {e}");
        }
    }
}
