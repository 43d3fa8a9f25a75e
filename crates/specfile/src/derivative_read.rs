//! Reading `check = "endpoint-derivatives"`: printed derivatives at the
//! ends of the domain, as a paper lists them — several orders at both
//! ends, of the functions and of curves `Σ bᵢPᵢ` it names:
//!
//! ```toml
//! check = "endpoint-derivatives"
//! wrt = "u"
//! curves = [{ name = "P", points = ["V0", "V1", "V2", "V3"] }]
//! values = ["b0'(0) = -pi - m*pi/2", "b2''(1) = -pi^2 - m*pi^2", "P'(1) = (-pi - m*pi/2)*V2 + (pi + m*pi/2)*V3"]
//! ```
//!
//! Each value is `NAME'…'(END) = formula` (the primes the order, `END` the
//! domain's start or end as a number of the formula language), optionally
//! named for the report (`"Condition 1, Q2(0): Q2(0) = P4"`, the text before
//! the first `: `). A curve names one control point per function. Where the
//! paper prints the parameters with a value, `Q2'(0; m1)` is the derivative
//! with the basis at `m = m1` (one value per parameter, in order; new names
//! such as `m1` listed in `symbols = ["m1"]`). The older form of one order at
//! one end, `end`, `order` and `values = ["b0 = formula"]`, is read too.

use toml::Spanned;
use trig_deriv::End;

use crate::check::{Check, Differentiated, NamedCurve, PrintedDerivative};
use crate::error::{Result, SpecError};
use crate::fields::{formula_in, function_index, need, wrt_field};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::{MAX_ORDER, Spec};

pub(crate) fn endpoint_derivatives(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let wrt = wrt_field(src, spec, c.wrt.as_ref())?;
    let items = need(src, c, &c.values, "values")?;
    let values = match (&c.end, &c.order) {
        (Some(end), Some(order)) => {
            if let Some(curves) = &c.curves {
                let span = curves.first().map_or(c.check.span(), |k| k.name.span());
                return src.invalid(span, "claims.curves", "curves are named in values of the form `NAME'(END) = formula`, not with `end` and `order`".into());
            }
            let end = crate::fields::end_field(src, end)?;
            let order = crate::fields::order_field(src, c, order)?;
            one_order(src, spec, items, end, order)?
        }
        (None, None) => {
            let (curves, extra) = curves(src, spec, c)?;
            let values = items
                .iter()
                .map(|item| listed(src, spec, c, item, &curves, &extra))
                .collect::<Result<Vec<_>>>()?;
            if values.is_empty() {
                return src.invalid(
                    c.check.span(),
                    "claims.values",
                    "list at least one value".into(),
                );
            }
            return Ok(Check::EndpointDerivatives {
                wrt,
                values,
                curves,
            });
        }
        _ => {
            return src.invalid(
                c.check.span(),
                "claims.end",
                "give `end` and `order` together (values `NAME = formula`), or neither (values `NAME'(END) = formula`)".into(),
            );
        }
    };
    Ok(Check::EndpointDerivatives {
        wrt,
        values,
        curves: Vec::new(),
    })
}

/// `values = ["b0 = formula"]` of one order at one end.
fn one_order(
    src: &Source<'_>,
    spec: &Spec,
    items: &[Spanned<String>],
    end: End,
    order: usize,
) -> Result<Vec<PrintedDerivative>> {
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
            Ok(PrintedDerivative {
                of: Differentiated::Function(function_index(src, spec, item, name)?),
                order,
                end,
                label: None,
                params: None,
                printed: formula.trim().to_string(),
                value: formula_in(src, spec, item, &format!("{name}="), formula, &[])?,
            })
        })
        .collect()
}

/// The claim's curves and the symbols its values may use (control
/// points, the printed parameters' names of `symbols`), each a name of
/// its own.
fn curves(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<(Vec<NamedCurve>, Vec<String>)> {
    let mut names = spec.names();
    let (mut out, mut extra) = (Vec::new(), Vec::new());
    let n = spec.functions.len();
    for raw in c.curves.iter().flatten() {
        let at = raw.name.span();
        let invalid =
            |message: String| -> Result<()> { src.invalid(at.clone(), "claims.curves", message) };
        let name = raw.name.get_ref().trim().to_string();
        if raw.change.is_some() {
            invalid(format!(
                "curve `{name}`: a curve's own `change` belongs to `check = \"identity\"`"
            ))?;
        }
        if !ascii_name(&name) || out.iter().any(|k: &NamedCurve| k.name == name) {
            invalid(format!(
                "`{name}`: a curve is named once, by ASCII letters and digits"
            ))?;
        }
        if spec.functions.iter().any(|f| f.name == name) {
            invalid(format!("`{name}`: a function of the basis, not a curve"))?;
        }
        let points: Vec<String> = raw
            .points
            .iter()
            .map(|p| p.get_ref().trim().to_string())
            .collect();
        if points.len() != n || points.iter().any(|p| !ascii_name(p)) {
            invalid(format!(
                "curve `{name}`: expected {n} control points (one per function), each named by ASCII letters and digits"
            ))?;
        }
        for p in &points {
            if !extra.contains(p) {
                fixed(
                    src,
                    &mut names,
                    p,
                    &format!("a control point of `{name}`"),
                    at.clone(),
                )?;
                extra.push(p.clone());
            }
        }
        out.push(NamedCurve { name, points });
    }
    for symbol in c.symbols.iter().flatten() {
        let name = symbol.get_ref().trim().to_string();
        if !extra.contains(&name) {
            fixed(
                src,
                &mut names,
                &name,
                "a printed parameter's name",
                symbol.span(),
            )?;
            extra.push(name);
        }
    }
    Ok((out, extra))
}

fn fixed(
    src: &Source<'_>,
    names: &mut trig_symbolic::Names,
    name: &str,
    what: &str,
    at: std::ops::Range<usize>,
) -> Result<()> {
    names
        .fixed(name, what)
        .map(|_| ())
        .map_err(|e| SpecError::Invalid {
            at: src.at(at.start),
            field: "claims.curves".into(),
            message: e.to_string(),
        })
}

/// The claim fixes no values and gives no ranges.
fn given_free(c: &RawClaim) -> bool {
    c.at.is_none() && c.ranges.is_none() && c.region.is_none() && c.range.is_none()
}

fn ascii_name(name: &str) -> bool {
    name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// One listed value `[label: ]NAME'…'(END) = formula`.
fn listed(
    src: &Source<'_>,
    spec: &Spec,
    c: &RawClaim,
    item: &Spanned<String>,
    curves: &[NamedCurve],
    extra: &[String],
) -> Result<PrintedDerivative> {
    let text = item.get_ref();
    let (label, body) = match text.split_once(": ") {
        Some((label, body)) => (Some(label.trim()), body),
        None => (None, text.as_str()),
    };
    let expected = || {
        src.invalid(
            item.span(),
            "claims.values",
            format!("`{text}`: expected `NAME'…'(END) = formula` (a function or a curve of the claim, primes for the order, END the start or the end of the domain)"),
        )
    };
    let Some((lhs, formula)) = body.split_once('=') else {
        return expected();
    };
    let lhs = lhs.trim();
    let (Some(open), true) = (lhs.find('('), lhs.ends_with(')')) else {
        return expected();
    };
    let head = &lhs[..open];
    let name = head.trim_end_matches('\'');
    let order = head.len() - name.len();
    let of = match (
        spec.functions.iter().position(|f| f.name == name),
        curves.iter().position(|k| k.name == name),
    ) {
        (Some(i), _) => Differentiated::Function(i),
        (None, Some(k)) => Differentiated::Curve(k),
        (None, None) => {
            return src.invalid(
                item.span(),
                "claims.values",
                format!("`{name}`: neither a function of the basis nor a curve of the claim"),
            );
        }
    };
    if order > MAX_ORDER {
        return src.invalid(
            item.span(),
            "claims.values",
            format!("`{lhs}`: derivative order {order} above {MAX_ORDER}"),
        );
    }
    let (argument, params) = match lhs[open + 1..lhs.len() - 1].split_once(';') {
        Some((argument, params)) => (argument, Some(params)),
        None => (&lhs[open + 1..lhs.len() - 1], None),
    };
    let params = match params {
        None => None,
        Some(_) if !given_free(c) => {
            return src.invalid(
                item.span(),
                "claims.values",
                format!("`{lhs}`: a value with printed parameters takes no fixed values or ranges"),
            );
        }
        Some(list) => {
            let list: Vec<&str> = list.split(',').collect();
            if list.len() != spec.params.len() {
                return src.invalid(item.span(), "claims.values", format!("`{lhs}`: expected {} parameter value(s) after `;`, one per parameter of the basis", spec.params.len()));
            }
            let values = list
                .iter()
                .map(|p| {
                    spec.parse_formula(p, extra)
                        .map_err(|e| src.formula_error(item, e))
                })
                .collect::<Result<Vec<_>>>()?;
            Some(values)
        }
    };
    let point = spec
        .parse_linear(argument, "the end of the domain")
        .map_err(|e| src.formula_error(item, e))?;
    let end = match point.rest {
        _ if point.x != trig_core::Affine::default() => None,
        ref a if *a == spec.domain.start => Some(End::Start),
        ref a if *a == spec.domain.end => Some(End::End),
        _ => None,
    };
    let Some(end) = end else {
        return src.invalid(
            item.span(),
            "claims.values",
            format!(
                "`{lhs}`: `{}` is neither end of the domain",
                argument.trim()
            ),
        );
    };
    let prefix = &text[..text.len() - formula.len()];
    Ok(PrintedDerivative {
        of,
        order,
        end,
        label: Some(label.unwrap_or(lhs).to_string()),
        params,
        printed: formula.trim().to_string(),
        value: formula_in(src, spec, item, prefix, formula, extra)?,
    })
}

#[cfg(test)]
mod tests {
    use crate::check::{Check, Differentiated};
    use crate::spec::Spec;
    use trig_deriv::End;

    fn cubic_with(claim: &str) -> crate::error::Result<Spec> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog/thesis-cubic.toml");
        let text = std::fs::read_to_string(path).unwrap();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"d\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"endpoint-derivatives\"\n{claim}\n"
            ),
            "thesis-cubic.toml",
        )
    }

    #[test]
    fn listed_values_name_their_order_end_and_curve() {
        let spec = cubic_with(
            "curves = [{ name = \"Q2\", points = [\"P4\", \"P5\", \"P6\", \"P7\"] }]\nsymbols = [\"m1\"]\nvalues = [\"b2''(1) = -pi^2\", \"Condition 2, Q2'(0): Q2'(0; m1) = (m1 + 2)*(P5 - P4)\"]",
        )
        .unwrap();
        let Check::EndpointDerivatives { values, curves, .. } = &spec.claims[0].check else {
            panic!("an endpoint-derivatives claim");
        };
        assert_eq!(
            (values[0].of, values[0].order, values[0].end),
            (Differentiated::Function(2), 2, End::End)
        );
        assert_eq!(values[0].label.as_deref(), Some("b2''(1)"));
        assert_eq!(
            (values[1].of, values[1].order, values[1].end),
            (Differentiated::Curve(0), 1, End::Start)
        );
        assert_eq!(values[1].label.as_deref(), Some("Condition 2, Q2'(0)"));
        assert_eq!(curves[0].points[1], "P5");
        assert_eq!(
            (values[0].params.as_ref(), values[1].params.as_deref()),
            (None, Some(&[trig_symbolic::Sym::var("m1")][..]))
        );
    }

    #[test]
    fn malformed_values_are_refused_with_the_reason() {
        let e = cubic_with("values = [\"b0'(1/2) = 0\"]").unwrap_err();
        assert!(e.to_string().contains("neither end of the domain"), "{e}");
        let e = cubic_with("values = [\"R'(0) = 0\"]").unwrap_err();
        assert!(e.to_string().contains("neither a function"), "{e}");
        let e = cubic_with("end = \"start\"\nvalues = [\"b0 = 0\"]").unwrap_err();
        assert!(e.to_string().contains("together"), "{e}");
        let e =
            cubic_with("curves = [{ name = \"Q\", points = [\"P0\"] }]\nvalues = [\"Q(0) = P0\"]")
                .unwrap_err();
        assert!(e.to_string().contains("expected 4 control points"), "{e}");
        // a point may not read as a parameter
        let e = cubic_with("curves = [{ name = \"Q\", points = [\"m\", \"P1\", \"P2\", \"P3\"] }]\nvalues = [\"Q(0) = m\"]")
            .unwrap_err();
        assert!(e.to_string().contains("`m`"), "{e}");
        // a printed parameter's name is declared, and one per parameter
        assert!(cubic_with("values = [\"b0(0; m1) = 1\"]").is_err());
        let e = cubic_with("symbols = [\"m1\"]\nvalues = [\"b0(0; m1, m1) = 1\"]").unwrap_err();
        assert!(e.to_string().contains("one per parameter"), "{e}");
    }
}
