//! Reading `check = "end-direction"`: the curve `Σ bᵢPᵢ` at one end along
//! a printed difference of two control points, with a factor of a stated
//! sign (and optionally tending to 0):
//!
//! ```toml
//! check = "end-direction"
//! end = "start"
//! order = 1              # 0: the end point, 1: the end tangent, …
//! along = "P1 - P0"
//! sign = "positive"      # or "nonzero"
//! range = "(-2, 1]"      # optional: the claim's range of the parameter
//! limit = "inf"          # optional: the factor → 0 as the parameter → ∞
//! ```

use crate::check::Check;
use crate::error::Result;
use crate::fields::{end_field, need, order_field, wrt_field};
use crate::given_read::one_param_range;
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

pub(crate) fn end_direction(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let along = need(src, c, &c.along, "along")?;
    let n = spec.functions.len();
    let point = |text: &str| {
        text.trim()
            .strip_prefix('P')
            .and_then(|i| i.parse::<usize>().ok())
            .filter(|i| *i < n)
    };
    let pair = along
        .get_ref()
        .replace('−', "-")
        .split_once('-')
        .and_then(|(a, b)| Some((point(a)?, point(b)?)))
        .filter(|(a, b)| a != b);
    let Some(pair) = pair else {
        return src.invalid(
            along.span(),
            "claims.along",
            format!(
                "`{}`: expected a difference of two control points `Pa - Pb` (P0 … P{})",
                along.get_ref(),
                n - 1
            ),
        );
    };
    let positive = match c.sign.as_ref().map(|s| s.get_ref().trim()) {
        None | Some("positive") => true,
        Some("nonzero") => false,
        Some(other) => {
            return src.invalid(
                c.sign.as_ref().map_or(c.check.span(), |s| s.span()),
                "claims.sign",
                format!("`{other}`: expected `positive` or `nonzero`"),
            );
        }
    };
    let limit = match c.limit.as_ref().map(|l| (l, l.get_ref().trim())) {
        None => None,
        Some((_, "inf")) => Some("∞".to_string()),
        Some((_, "-inf")) => Some("−∞".to_string()),
        Some((l, other)) => {
            return src.invalid(
                l.span(),
                "claims.limit",
                format!("`{other}`: expected `inf` or `-inf` (the factor tends to 0 there)"),
            );
        }
    };
    Ok(Check::EndDirection {
        end: end_field(src, need(src, c, &c.end, "end")?)?,
        order: order_field(src, c, need(src, c, &c.order, "order")?)?,
        wrt: wrt_field(src, spec, c.wrt.as_ref())?,
        along: pair,
        positive,
        range: one_param_range(src, spec, &c.range)?,
        limit,
    })
}

#[cfg(test)]
mod tests {
    use crate::check::Check;
    use crate::spec::Spec;

    fn cubic_with(claim: &str) -> crate::error::Result<Spec> {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/catalog/thesis-cubic.toml");
        let text = std::fs::read_to_string(path).unwrap();
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"d\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"end-direction\"\nend = \"end\"\norder = 1\n{claim}\n"
            ),
            "d.toml",
        )
    }

    #[test]
    fn the_difference_sign_and_limit_are_read() {
        let spec = cubic_with(
            "along = \"P3 − P2\"\nsign = \"nonzero\"\nrange = \"(-2, 1]\"\nlimit = \"-inf\"",
        )
        .unwrap();
        let Check::EndDirection {
            along,
            positive,
            range,
            limit,
            ..
        } = &spec.claims[0].check
        else {
            panic!("an end-direction claim");
        };
        assert_eq!((*along, *positive), ((3, 2), false));
        assert_eq!(
            range.as_ref().map(ToString::to_string).as_deref(),
            Some("(-2, 1]")
        );
        assert_eq!(limit.as_deref(), Some("−∞"));
        for (bad, why) in [
            ("along = \"P4 - P0\"", "expected a difference"),
            ("along = \"P1 - P1\"", "expected a difference"),
            (
                "along = \"P1 - P0\"\nsign = \"negative\"",
                "expected `positive` or `nonzero`",
            ),
            (
                "along = \"P1 - P0\"\nlimit = \"0\"",
                "expected `inf` or `-inf`",
            ),
        ] {
            let e = cubic_with(bad).unwrap_err();
            assert!(e.to_string().contains(why), "{bad}: {e}");
        }
    }
}
