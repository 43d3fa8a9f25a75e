//! Every witness of a claim that does not hold can be re-checked from the
//! JSON report alone, by substitution: some value records the expression it
//! is the value of (`of`, whose symbols the point names), or the item has an
//! expression labelled like a value, or a residual (or jump) the values are
//! the two sides of — the routes `scripts/recheck_witnesses.py` takes. A
//! witness that gives values only (a printed total, a certified bound with
//! no formula) leaves the reader nothing to substitute into.

use serde_json::Value;

/// Why the witness of `item` cannot be re-checked by substitution, if it
/// cannot.
fn not_recheckable(item: &Value) -> Option<String> {
    let w = &item["witness"];
    let values = w["values"].as_array()?;
    let labels: Vec<&str> = values.iter().filter_map(|v| v["label"].as_str()).collect();
    let exprs: Vec<&str> = item["exprs"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|x| x["label"].as_str())
        .collect();
    let of = values.iter().any(|v| v.get("of").is_some());
    let labelled = exprs.iter().any(|l| labels.contains(l));
    let residual = exprs
        .iter()
        .any(|l| l.contains("residual") || l.contains("jump"))
        || (exprs.len() == 1 && values.len() == 1);
    (!(of || labelled || residual)).then(|| {
        format!(
            "values {labels:?} with no expression to substitute into: {}",
            item["text"].as_str().unwrap_or_default()
        )
    })
}

/// The witnesses of the claims that do not hold which give values only.
fn values_only(report: &Value) -> (usize, Vec<String>) {
    let mut total = 0;
    let mut found = Vec::new();
    for claim in report["claims"].as_array().into_iter().flatten() {
        if claim["verdict"] == "holds" {
            continue;
        }
        for item in claim["evidence"].as_array().into_iter().flatten() {
            if item.get("witness").is_none() {
                continue;
            }
            total += 1;
            if let Some(why) = not_recheckable(item) {
                found.push(format!("{}: {why}", claim["id"]));
            }
        }
    }
    (total, found)
}

#[test]
fn every_failing_witness_has_an_expression_to_substitute_into() {
    let report = serde_json::to_value(crate::audit::json()).expect("JSON");
    let (total, found) = values_only(&report);
    assert!(total > 100, "{total} witnesses of claims that do not hold");
    assert!(
        found.is_empty(),
        "{} of {total} witnesses give values only:\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The scan finds a witness of values only, and accepts each route.
#[test]
fn a_witness_of_values_only_is_found() {
    let item = |values: Value, exprs: Value| serde_json::json!({"text": "t", "exprs": exprs, "witness": {"values": values}});
    let printed = serde_json::json!([{"label": "printed"}, {"label": "computed"}]);
    assert!(not_recheckable(&item(printed.clone(), serde_json::json!([]))).is_some());
    let of = serde_json::json!([{"label": "printed"}, {"label": "computed", "of": {}}]);
    assert!(not_recheckable(&item(of, serde_json::json!([]))).is_none());
    let residual = serde_json::json!([{"label": "residual", "expr": {}}]);
    assert!(not_recheckable(&item(printed.clone(), residual)).is_none());
    let labelled = serde_json::json!([{"label": "computed", "expr": {}}]);
    assert!(not_recheckable(&item(printed, labelled)).is_none());
    let report = serde_json::json!({"claims": [
        {"id": "A", "verdict": "fails", "evidence": [item(serde_json::json!([{"label": "v"}]), serde_json::json!([]))]},
        {"id": "B", "verdict": "holds", "evidence": [item(serde_json::json!([{"label": "v"}]), serde_json::json!([]))]},
    ]});
    let (total, found) = values_only(&report);
    assert_eq!((total, found.len()), (1, 1));
}
