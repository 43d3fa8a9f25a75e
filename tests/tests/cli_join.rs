//! `trig-audit join`: snapshots of every derived join formula (every family,
//! C⁰–C³, G¹, G², same and different parameters, each convention), formats,
//! and one-line errors for bad requests.

use trig_e2e::{FAMILIES, assert_errors, stdout_ok};

const KINDS: [&str; 6] = ["c0", "c1", "c2", "c3", "g1", "g2"];
const WRT: [&str; 3] = ["angle", "u", "x"];

#[test]
fn every_derived_join_formula() {
    for family in FAMILIES {
        let mut all = String::new();
        for kind in KINDS {
            for params in ["same", "different"] {
                for wrt in WRT {
                    let args = [
                        "join", family, "--kind", kind, "--params", params, "--wrt", wrt,
                    ];
                    let out = trig_e2e::run(&args);
                    all.push_str(&format!("$ trig-audit {}\n", args.join(" ")));
                    if out.status.success() {
                        all.push_str(&String::from_utf8_lossy(&out.stdout));
                    } else {
                        // an inconsistent system is reported, not solved
                        all.push_str(&String::from_utf8_lossy(&out.stderr));
                    }
                    all.push('\n');
                }
            }
        }
        insta::assert_snapshot!(format!("join_{family}"), all);
    }
}

#[test]
fn thesis_c1_formula_and_its_singularity() {
    let out = stdout_ok(&[
        "join",
        "thesis-cubic",
        "--kind",
        "c1",
        "--params",
        "different",
    ]);
    assert!(
        out.contains("Q₁ = (−m₁ − 2)/(m₂ + 2)·P₂ + (m₁ + m₂ + 4)/(m₂ + 2)·P₃"),
        "{out}"
    );
    assert!(out.contains("singular where m₂ = −2"), "{out}");
}

#[test]
fn formats_render() {
    let tex = stdout_ok(&["join", "bernstein3", "--kind", "c2", "--format", "tex"]);
    assert!(
        tex.contains("\\begin{align*}") && tex.contains("Q_{2} &="),
        "{tex}"
    );
    let json = stdout_ok(&["join", "thesis-cubic", "--kind", "g1", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("valid JSON");
    assert_eq!(v["forced"].as_array().map(Vec::len), Some(2));
    assert_eq!(v["forced"][1]["singular_where"][0], "m = −2");
}

#[test]
fn bad_join_requests_are_one_line_errors() {
    assert_errors(&[
        (
            &["join", "thesis-cubic", "--kind", "c9"][..],
            "unknown join kind",
        ),
        (
            &["join", "no-such-family", "--kind", "c1"][..],
            "unknown family",
        ),
        (&["join", "seed003", "--kind", "c1"][..], "no formulas"),
        (
            &[
                "join",
                "thesis-cubic",
                "--kind",
                "c3",
                "--params",
                "different",
            ][..],
            "cannot be met",
        ),
    ]);
}
