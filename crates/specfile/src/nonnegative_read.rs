//! `check = "nonnegative"`, read: the range, `maximal`, and the options
//! that narrow it to some of the functions (`functions = ["F1", "F2"]`) and
//! ask for a strict bound (`margin = "1/200"`: `f ≥ 1/200`, hence `f > 0`).

use trig_core::parse_exact;

use crate::check::{Check, Margin};
use crate::error::Result;
use crate::given_read::one_param_range;
use crate::knots::Knots;
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

/// The nonnegativity claim of `c`. The names of `functions` are those of
/// the basis the claim is about: on a knot vector, the knot family's
/// segment functions.
pub(crate) fn nonnegative(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let maximal = c.maximal.unwrap_or(false);
    let names: Vec<String> = match c
        .knots
        .as_ref()
        .and_then(|k| Knots::family(&k.get_ref().coefficients))
    {
        Some((names, _)) => names.iter().map(|n| n.to_string()).collect(),
        None => spec.functions.iter().map(|f| f.name.clone()).collect(),
    };
    let mut functions = Vec::new();
    for name in c.functions.iter().flatten() {
        match names.iter().position(|n| n == name.get_ref().trim()) {
            Some(i) if !functions.contains(&i) => functions.push(i),
            Some(_) => {
                return src.invalid(
                    name.span(),
                    "claims.functions",
                    format!("`{}` is listed twice", name.get_ref().trim()),
                );
            }
            None => {
                return src.invalid(
                    name.span(),
                    "claims.functions",
                    format!(
                        "`{}`: unknown function (expected one of {})",
                        name.get_ref().trim(),
                        names.join(", ")
                    ),
                );
            }
        }
    }
    let margin = match &c.margin {
        None => None,
        Some(m) if maximal => {
            return src.invalid(
                m.span(),
                "claims.margin",
                "`margin` bounds the functions below on the claim's range; the maximal range of `f ≥ margin` is not decided (give `margin` or `maximal`, not both)".into(),
            );
        }
        Some(m) => match parse_exact(m.get_ref().trim()) {
            Ok(value) => Some(Margin {
                text: m.get_ref().trim().to_string(),
                value,
            }),
            Err(e) => {
                return src.invalid(
                    m.span(),
                    "claims.margin",
                    format!("expected an exact number (`1/200`, `0.005`): {e}"),
                );
            }
        },
    };
    Ok(Check::Nonnegative {
        range: one_param_range(src, spec, &c.range)?,
        maximal,
        functions,
        margin,
    })
}
