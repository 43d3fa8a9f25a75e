//! The curvature at a common end point of rational curves on different
//! bases, read (`check = "end-curvature"`): one printed or exemplary
//! polygon, the curves of the claim's basis with their weights, and the
//! compared curves, each on a basis of its own spec file.

use std::path::Path;

use rug::Rational;

use crate::check::{Check, WeightedCurve};
use crate::error::{Result, SpecError};
use crate::fields::need;
use crate::property_read::{printed_polygons, rational_in};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

/// `curve = "RQTB"` (the printed name of the claim's curves),
/// `polygons = [["(0, 0)", "(1, 0)", …]]` (one polygon, as long as the
/// largest basis), `curvatures = [{ label, weights }, { label, name, basis }]`:
/// at least one curve of the claim's basis (no `basis`) and one compared.
pub(crate) fn end_curvature(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let curve = need(src, c, &c.curve, "curve")?
        .get_ref()
        .trim()
        .to_string();
    let printed = need(src, c, &c.polygons, "polygons")?;
    let mut polygons = printed_polygons(src, spec, c, printed)?;
    let (Some(polygon), true) = (polygons.pop(), polygons.is_empty()) else {
        return src.invalid(
            c.check.span(),
            "claims.polygons",
            "an end-curvature claim compares curves on one polygon".into(),
        );
    };
    let dir = Path::new(src.file).parent().unwrap_or(Path::new(""));
    let mut curves = Vec::new();
    for raw in need(src, c, &c.curvatures, "curvatures")? {
        let basis = match &raw.basis {
            None => None,
            Some(path) => Some(Box::new(
                Spec::basis_from_file(&dir.join(path.get_ref().trim())).map_err(|e| {
                    SpecError::Invalid {
                        at: src.at(path.span().start),
                        field: "claims.curvatures".into(),
                        message: e.to_string(),
                    }
                })?,
            )),
        };
        let n = basis
            .as_ref()
            .map_or(spec.functions.len(), |b| b.functions.len());
        if n > polygon.len() {
            return src.invalid(
                c.check.span(),
                "claims.curvatures",
                format!(
                    "`{}`: {n} functions, but the polygon has {} points",
                    raw.label,
                    polygon.len()
                ),
            );
        }
        let weights = match &raw.weights {
            None => vec![Rational::from(1); n],
            Some(items) if items.len() == n => items
                .iter()
                .map(|w| rational_in(src, spec, w, w.get_ref(), "curvatures"))
                .collect::<Result<_>>()?,
            Some(_) => {
                return src.invalid(
                    c.check.span(),
                    "claims.curvatures",
                    format!("`{}`: one weight per function ({n})", raw.label),
                );
            }
        };
        if weights.iter().any(|w| *w <= 0) {
            return src.invalid(
                c.check.span(),
                "claims.curvatures",
                format!(
                    "`{}`: the weights of a rational curve are positive",
                    raw.label
                ),
            );
        }
        curves.push(WeightedCurve {
            name: raw.name.clone().unwrap_or_else(|| raw.label.clone()),
            label: raw.label.clone(),
            basis,
            weights,
        });
    }
    if !curves.iter().any(|k| k.basis.is_none()) || curves.iter().all(|k| k.basis.is_none()) {
        return src.invalid(
            c.check.span(),
            "claims.curvatures",
            "list curves of the claim's basis (no `basis`) and compared curves (a `basis` each)"
                .into(),
        );
    }
    Ok(Check::EndCurvature {
        curve,
        polygon,
        curves,
    })
}

#[cfg(test)]
mod tests {
    use crate::check::Check;
    use crate::spec::Spec;

    /// The cubic Bernstein basis compared with itself from its spec file.
    fn bernstein_with(curvatures: &str) -> crate::error::Result<Spec> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/catalog");
        let text = std::fs::read_to_string(dir.join("bernstein3.toml")).unwrap();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"k\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"end-curvature\"\ncurve = \"C\"\npolygons = [[\"(0, 0)\", \"(1, 0)\", \"(1, 1)\", \"(2, 1)\"]]\ncurvatures = {curvatures}\n"
            ),
            dir.join("bernstein3.toml").to_str().unwrap(),
        )
    }

    #[test]
    fn curves_of_the_claims_basis_and_compared_ones_are_read() {
        let spec = bernstein_with("[{ label = \"w1 = 2\", weights = [\"1\", \"2\", \"1\", \"1\"] }, { label = \"the cubic\", name = \"cubic\", basis = \"bernstein3.toml\" }]").unwrap();
        let Check::EndCurvature {
            curves, polygon, ..
        } = &spec.claims[0].check
        else {
            panic!("an end-curvature claim");
        };
        assert_eq!(polygon.len(), 4);
        assert_eq!(curves[0].weights[1], 2);
        assert_eq!(curves[0].name, "w1 = 2");
        assert_eq!(curves[1].name, "cubic");
        assert!(curves[1].basis.is_some());
        for (bad, says) in [
            (
                "[{ label = \"a\", weights = [\"1\", \"0\", \"1\", \"1\"] }, { label = \"b\", basis = \"bernstein3.toml\" }]",
                "positive",
            ),
            (
                "[{ label = \"a\", weights = [\"1\"] }, { label = \"b\", basis = \"bernstein3.toml\" }]",
                "one weight per function",
            ),
            ("[{ label = \"a\" }]", "compared curves"),
        ] {
            let e = bernstein_with(bad).unwrap_err();
            assert!(e.to_string().contains(says), "{bad}: {e}");
        }
    }
}
