//! End-to-end tests of `trig-audit interp`: each table with the scheme of its
//! section (text snapshots), the corrected variants, Markdown and JSON, and
//! one-line errors for bad input.

use trig_e2e::{assert_errors, stdout_ok};

const EXAMPLES: [(&str, &str); 6] = [
    ("thesis-table-4.1", "c1"),
    ("thesis-table-4.2", "c2"),
    ("thesis-table-4.3", "g1"),
    ("thesis-table-4.4", "g2"),
    ("thesis-table-4.5", "g2"),
    ("thesis-table-4.6", "g1"),
];

#[test]
fn every_example_with_its_scheme() {
    for (data, scheme) in EXAMPLES {
        let out = stdout_ok(&["interp", "--data", data, "--scheme", scheme]);
        assert!(out.contains("certified minimum per piece"), "{data}");
        insta::assert_snapshot!(format!("interp_{data}_{scheme}"), out);
    }
}

#[test]
fn corrected_schemes_and_formats() {
    for (data, scheme) in [("thesis-table-4.2", "c2"), ("thesis-table-4.4", "g2")] {
        let out = stdout_ok(&[
            "interp",
            "--data",
            data,
            "--scheme",
            scheme,
            "--variant",
            "corrected",
            "--format",
            "md",
        ]);
        insta::assert_snapshot!(format!("interp_{data}_{scheme}_corrected_md"), out);
    }
    let json: serde_json::Value = serde_json::from_str(&stdout_ok(&[
        "interp",
        "--data",
        "thesis-table-4.2",
        "--scheme",
        "c2",
        "--format",
        "json",
    ]))
    .expect("valid JSON");
    assert_eq!(json["pieces"].as_array().map(Vec::len), Some(4));
    assert_eq!(json["knots"][0]["continuity"], "C1");
    assert_eq!(json["positivity"], "certified ≥ 0 on the whole interval");
    // the corrected C² scheme is C² at every knot
    let corrected: serde_json::Value = serde_json::from_str(&stdout_ok(&[
        "interp",
        "--data",
        "thesis-table-4.2",
        "--scheme",
        "c2",
        "--variant",
        "corrected",
        "--format",
        "json",
    ]))
    .expect("valid JSON");
    for k in corrected["knots"].as_array().expect("knots") {
        assert_eq!(k["continuity"], "C2");
    }
}

#[test]
fn bad_input_is_a_one_line_error() {
    assert_errors(&[
        (
            &["interp", "--data", "thesis-table-9", "--scheme", "c1"],
            "unknown data set `thesis-table-9`",
        ),
        (
            &["interp", "--data", "thesis-table-4.1", "--scheme", "c3"],
            "unknown scheme `c3`",
        ),
        (
            &["interp", "--data", "thesis-table-4.1", "--scheme", "g1"],
            "has no `n` column",
        ),
        (
            &["interp", "--data", "thesis-table-4.2", "--scheme", "g2"],
            "has no `alpha` column",
        ),
    ]);
}
