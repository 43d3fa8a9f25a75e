//! The quoted-figure judge: a figure a document's text quotes, against the
//! value recomputed exactly from its printed tables.
//!
//! A quoted decimal `q` printed with `d` decimals agrees with the exact
//! recomputed value `r` when `q` is `r` rounded to `d` places:
//! `|q − r| ≤ ½·10⁻ᵈ` (at an exact tie either neighbour counts). An
//! integer (`d = 0`) is compared to ½ as well, so a quoted count must be
//! quoted exactly only when the recomputed value is an integer — which
//! counts always are. Every quantity is an exact rational (the printed
//! decimals read exactly), so the comparison is exact.

use rug::ops::Pow;
use rug::{Integer, Rational};

use crate::recomputed::{Recomputed, decimal, witness};
use trig_verdict::evidence::{Evidence, Kind, Relation};
use trig_verdict::status::Status;

/// How a quoted figure is compared, as the report states it.
pub const QUOTED: &str = "exact rational arithmetic on the printed decimals; a quoted figure with d decimals holds when it is the recomputed value rounded to d places (|quoted − recomputed| ≤ ½·10⁻ᵈ)";

/// Half a unit in the last place of a printed decimal (`½·10⁻ᵈ`).
pub fn half_unit(text: &str) -> Rational {
    let d = text.split_once('.').map_or(0, |(_, f)| f.len()) as u32;
    Rational::from((1, 2)) / Rational::from(Integer::from(10).pow(d))
}

/// The item deciding "the text's figure `quoted` is `computed`", where
/// `from` says how `computed` was obtained from the tables (its witness
/// carries the cells and formula of `computed`). A quoted text that is not
/// a decimal is a not-checkable item.
pub fn quoted_figure(
    subject: &str,
    quoted: &str,
    computed: impl Into<Recomputed>,
    from: &str,
) -> Evidence {
    let computed = computed.into();
    let value = match trig_core::parse_exact(quoted) {
        Ok(v) => v,
        Err(e) => {
            return Evidence::note(format!("the quoted figure {quoted} is not a decimal: {e}"))
                .about(subject, Status::NotCheckable);
        }
    };
    let diff = value.clone() - &computed.value;
    let ok = diff.clone().abs() <= half_unit(quoted);
    let text = format!(
        "quoted {quoted}; recomputed {from} = {} ({})",
        decimal(&computed.value),
        if ok {
            "the quoted digits are its rounding".to_string()
        } else {
            format!("differs by {}", decimal(&diff))
        }
    );
    let witness = (!ok).then(|| {
        witness(
            None,
            Relation::Equal,
            &[
                ("quoted", &Recomputed::printed(quoted, &value)),
                ("recomputed", &computed),
            ],
        )
    });
    Evidence::new(Kind::Comparison, text)
        .about(subject, if ok { Status::Holds } else { Status::Fails })
        .witnessed(witness)
}

/// The item deciding "ordered by `what` (smallest first), the entries come
/// in the order `printed`": `entries` are the names with their exact
/// values (with the cells they are read from). Fails at the first printed
/// neighbour pair out of order.
pub fn quoted_order(
    subject: &str,
    what: &str,
    entries: &[(&str, Recomputed)],
    printed: &[&str],
) -> Evidence {
    let value = |name: &str| entries.iter().find(|(n, _)| *n == name).map(|(_, v)| v);
    let mut sorted: Vec<&(&str, Recomputed)> = entries.iter().collect();
    sorted.sort_by(|a, b| a.1.value.cmp(&b.1.value));
    let actual: Vec<String> = sorted
        .iter()
        .map(|(n, v)| format!("{n} {}", decimal(&v.value)))
        .collect();
    let pairs: Option<Vec<(&str, &Recomputed, &str, &Recomputed)>> = printed
        .windows(2)
        .map(|w| Some((w[0], value(w[0])?, w[1], value(w[1])?)))
        .collect();
    let Some(pairs) = pairs.filter(|_| printed.len() == entries.len()) else {
        return Evidence::note(format!(
            "the printed order {} does not name each of the {} entries once",
            printed.join(", "),
            entries.len()
        ))
        .about(subject, Status::NotCheckable);
    };
    let wrong = pairs.iter().find(|(_, a, _, b)| a.value >= b.value);
    let text = format!(
        "printed order {}; by {what}, smallest first: {}",
        printed.join(" < "),
        actual.join(" < ")
    );
    let witness = wrong.map(|(n1, v1, n2, v2)| {
        witness(
            Some(format!("{n1} is printed before {n2}")),
            Relation::Less,
            &[(n1, v1), (n2, v2)],
        )
    });
    Evidence::new(Kind::Comparison, text)
        .about(
            subject,
            if wrong.is_none() {
                Status::Holds
            } else {
                Status::Fails
            },
        )
        .witnessed(witness)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    #[test]
    fn a_quoted_figure_holds_exactly_when_it_is_the_rounding() {
        // 2680.111 quoted as 2680.11: its rounding
        let e = quoted_figure("after", "2680.11", q(2_680_111, 1000), "TOTAL");
        assert_eq!(e.status, Some(Status::Holds));
        // 794.3815 quoted as 794.3715
        let e = quoted_figure(
            "increment",
            "794.3715",
            q(7_943_815, 10_000),
            "after − before",
        );
        assert_eq!(e.status, Some(Status::Fails));
        assert!(e.text.contains("differs by -0.01"), "{}", e.text);
        assert!(e.witness.is_some());
        // 0.0005 away at 3 decimals is a tie: either neighbour
        let e = quoted_figure("x", "1.000", q(10_005, 10_000), "x");
        assert_eq!(e.status, Some(Status::Holds));
        let e = quoted_figure("x", "1.001", q(10_005, 10_000), "x");
        assert_eq!(e.status, Some(Status::Holds));
        let e = quoted_figure("x", "1.002", q(10_005, 10_000), "x");
        assert_eq!(e.status, Some(Status::Fails));
        let e = quoted_figure("x", "one", q(1, 1), "x");
        assert_eq!(e.status, Some(Status::NotCheckable));
    }

    #[test]
    fn an_order_holds_only_when_every_neighbour_pair_increases() {
        let entries = [("a", q(1, 2)), ("b", q(3, 4)), ("c", q(1, 1))].map(|(n, v)| (n, v.into()));
        let e = quoted_order("o", "v", &entries, &["a", "b", "c"]);
        assert_eq!(e.status, Some(Status::Holds));
        let e = quoted_order("o", "v", &entries, &["a", "c", "b"]);
        assert_eq!(e.status, Some(Status::Fails));
        assert_eq!(e.witness.unwrap().note.unwrap(), "c is printed before b");
        let e = quoted_order("o", "v", &entries, &["a", "b"]);
        assert_eq!(e.status, Some(Status::NotCheckable));
    }

    #[test]
    fn half_units_of_printed_decimals() {
        assert_eq!(half_unit("1.25"), q(1, 200));
        assert_eq!(half_unit("7"), q(1, 2));
    }
}
