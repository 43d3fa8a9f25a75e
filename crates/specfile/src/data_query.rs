//! Queries on the values of a printed data table (`check = "data-values"`,
//! `values = ["f(1) = 0", "count(f = 0) >= 2"]`), read from the claim's
//! `values`: each decided exactly on the table's `f` column.

use rug::Rational;

/// One query, as written and as read (numbers exact: decimals read exactly).
#[derive(Debug, Clone, PartialEq)]
pub struct DataQuery {
    pub text: String,
    pub kind: QueryKind,
}

/// What a [`DataQuery`] asks.
#[derive(Debug, Clone, PartialEq)]
pub enum QueryKind {
    /// `f(X) = V`: the data value at the knot `x = X` is exactly `V`.
    ValueAt { x: Rational, value: Rational },
    /// `count(f = V) >= K`: at least `K` data values are exactly `V`.
    CountAtLeast { value: Rational, least: usize },
}

fn number(text: &str) -> Result<Rational, String> {
    trig_core::parse_exact(text.trim()).map_err(|e| format!("`{}`: {e}", text.trim()))
}

/// Reads one query; the error says what was expected.
pub fn parse(text: &str) -> Result<DataQuery, String> {
    let t = text.trim();
    let expected = || format!("`{t}`: expected `f(X) = V` or `count(f = V) >= K`");
    let kind = if let Some(rest) = t.strip_prefix("count(f =") {
        let (value, least) = rest.split_once(")").ok_or_else(expected)?;
        let least = least.trim().strip_prefix(">=").ok_or_else(expected)?;
        QueryKind::CountAtLeast {
            value: number(value)?,
            least: least.trim().parse().map_err(|_| expected())?,
        }
    } else if let Some(rest) = t.strip_prefix("f(") {
        let (x, value) = rest.split_once(")").ok_or_else(expected)?;
        let value = value.trim().strip_prefix('=').ok_or_else(expected)?;
        QueryKind::ValueAt {
            x: number(x)?,
            value: number(value)?,
        }
    } else {
        return Err(expected());
    };
    Ok(DataQuery {
        text: t.to_string(),
        kind,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn queries_read_exactly() {
        let q = parse("f(1) = 0.1").unwrap();
        assert_eq!(
            q.kind,
            QueryKind::ValueAt {
                x: Rational::from(1),
                value: Rational::from((1, 10))
            }
        );
        let q = parse("count(f = 0) >= 2").unwrap();
        assert_eq!(
            q.kind,
            QueryKind::CountAtLeast {
                value: Rational::new(),
                least: 2
            }
        );
        assert!(parse("g(1) = 0").is_err());
        assert!(parse("count(f = 0) > 2").is_err());
        assert!(matches!(
            maximum("rises to about 55"),
            Ok(MaximumQuery::About { printed, .. }) if printed == "55"
        ));
        assert!(matches!(
            maximum("near x = 4.5"),
            Ok(MaximumQuery::Near { .. })
        ));
        assert!(matches!(
            maximum("then drops"),
            Ok(MaximumQuery::Drops { .. })
        ));
        assert!(maximum("peaks").is_err());
    }
}

/// What a text says about the maximum of an interpolant
/// (`check = "interpolant-maximum"`, `values` as printed, recognised by
/// their words).
#[derive(Debug, Clone, PartialEq)]
pub enum MaximumQuery {
    /// `… about V`: the maximum rounds to `V` at `V`'s last printed digit.
    About { text: String, printed: String },
    /// `near x = X`: the maximum lies on the piece that contains `X`,
    /// certified above every other piece.
    Near { text: String, x: Rational },
    /// `… drops …` ("then drops towards the endpoint"): the maximum lies on
    /// the last piece and the last data value is below it.
    Drops { text: String },
}

/// Reads what a text says about a maximum; the error says what was expected.
pub fn maximum(text: &str) -> Result<MaximumQuery, String> {
    let t = text.trim().to_string();
    if let Some((_, v)) = t.split_once("about ") {
        let printed = v.trim().to_string();
        number(&printed)?;
        Ok(MaximumQuery::About { text: t, printed })
    } else if let Some((_, x)) = t.split_once("near x = ") {
        let x = number(x)?;
        Ok(MaximumQuery::Near { text: t, x })
    } else if t.contains("drops") {
        Ok(MaximumQuery::Drops { text: t })
    } else {
        Err(format!(
            "`{t}`: expected `… about V`, `near x = X` or `… drops …`"
        ))
    }
}
