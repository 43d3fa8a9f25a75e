//! Queries on the printed values of a data table (`check = "data-values"`):
//! "a point lying on the zero axis at x = 1" is `f(1) = 0`, "several data
//! points lie exactly on the zero axis" is `count(f = 0) >= 2`. The table's
//! decimals are read as exact rationals, so every comparison is exact; a
//! value that differs is witnessed by its printed cell against the stated
//! value.

use trig_interp::DataSet;
use trig_specfile::data_query::{DataQuery, QueryKind};
use trig_verdict::evidence::{Evidence, Kind, Relation};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use crate::recomputed::{self, Cell, Recomputed, decimal};

fn status(ok: bool) -> Status {
    if ok { Status::Holds } else { Status::Fails }
}

/// The item of one query on `data`.
fn item(data: &DataSet, q: &DataQuery) -> Evidence {
    let caption = &data.table.caption;
    match &q.kind {
        QueryKind::ValueAt { x, value } => {
            let Some(i) = data.x.iter().position(|k| k == x) else {
                return Evidence::note(format!("{caption} has no knot x = {}", decimal(x)))
                    .about(q.text.as_str(), Status::NotCheckable);
            };
            let f = &data.f[i];
            let ok = f == value;
            Evidence::new(
                Kind::Comparison,
                format!(
                    "{caption}, row {}: x = {}, f = {}",
                    i + 1,
                    decimal(x),
                    decimal(f)
                ),
            )
            .about(q.text.as_str(), status(ok))
            .witnessed((!ok).then(|| {
                // the printed cell f_i against the stated value
                let cell = Cell::new(format!("f{i}"), &decimal(f), f);
                recomputed::witness(
                    Some(format!(
                        "{caption} at x = {}: f{i} is its f, row {}",
                        decimal(x),
                        i + 1
                    )),
                    Relation::Equal,
                    &[
                        ("printed f", &Recomputed::cell(cell)),
                        ("stated", &Recomputed::from(value.clone())),
                    ],
                )
            }))
        }
        QueryKind::CountAtLeast { value, least } => {
            let k = data.f.iter().filter(|f| *f == value).count();
            let values: Vec<String> = data.f.iter().map(decimal).collect();
            Evidence::new(
                Kind::Comparison,
                format!(
                    "{caption}: f = {}; {k} of {} exactly {}",
                    values.join(", "),
                    data.f.len(),
                    decimal(value)
                ),
            )
            // the query as math: `count(f = 0) ≥ 2`
            .about(
                format!("count(f = {}) ≥ {least}", decimal(value)),
                status(k >= *least),
            )
        }
    }
}

/// Every query on the printed values of `data`.
pub fn decide(data: &DataSet, queries: &[DataQuery]) -> Verdict {
    let items: Vec<Evidence> = queries.iter().map(|q| item(data, q)).collect();
    Verdict::new(
        Status::conjunction(items.iter().filter_map(|e| e.status)),
        format!(
            "the printed data values of {}, read exactly",
            data.table.caption
        ),
        items,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_specfile::data_query::parse;

    fn run(data: &str, queries: &[&str]) -> Verdict {
        let data = DataSet::named(data).unwrap();
        let queries: Vec<DataQuery> = queries.iter().map(|q| parse(q).unwrap()).collect();
        decide(&data, &queries)
    }

    #[test]
    fn values_are_compared_exactly() {
        // Table 4.6 prints f = 12, 0.1, 1, 13
        assert_eq!(
            run("thesis-table-4.6", &["f(1) = 0.1"]).status,
            Status::Holds
        );
        let off = run("thesis-table-4.6", &["f(1) = 0"]);
        assert_eq!(off.status, Status::Fails);
        assert!(off.evidence[0].witness.is_some());
        assert_eq!(
            run("thesis-table-4.6", &["f(7) = 0"]).status,
            Status::NotCheckable
        );
        assert_eq!(
            run("thesis-table-4.6", &["count(f = 1) >= 1"]).status,
            Status::Holds
        );
        assert_eq!(
            run("thesis-table-4.6", &["count(f = 1) >= 2"]).status,
            Status::Fails
        );
    }
}
