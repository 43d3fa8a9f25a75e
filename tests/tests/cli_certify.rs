//! The certification engine on published bases that are not in the catalog
//! (spec files under `examples/`), end to end through `audit --spec`.
//!
//! The expected results were derived independently of the tool (SymPy,
//! `examples/independent/*.py`, results in its `README.md`, and by
//! hand in each file's header): exact range ends, quotient bases, regions
//! of two parameters, exact counterexamples re-checkable by hand.

use std::path::PathBuf;

use trig_e2e::{example, stdout_ok};

/// The verdict and evidence of one claim of a spec file.
fn claim(file: &str, id: &str) -> (String, Vec<String>) {
    let text = stdout_ok(&[
        "audit",
        "--spec",
        &example(file),
        "--claim",
        id,
        "--format",
        "json",
    ]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    let c = &json["claims"][0];
    // each structured evidence item as the text of its string fields
    let evidence = c["evidence"]
        .as_array()
        .expect("evidence")
        .iter()
        .map(|e| {
            let mut text = Vec::new();
            strings(e, &mut text);
            text.join(" ")
        })
        .collect();
    (
        c["verdict"].as_str().unwrap_or_default().to_string(),
        evidence,
    )
}

/// Every string inside `v`, in order.
fn strings(v: &serde_json::Value, out: &mut Vec<String>) {
    match v {
        serde_json::Value::String(s) => out.push(s.clone()),
        serde_json::Value::Array(a) => a.iter().for_each(|x| strings(x, out)),
        serde_json::Value::Object(o) => o.values().for_each(|x| strings(x, out)),
        _ => {}
    }
}

fn has(evidence: &[String], needle: &str) -> bool {
    evidence.iter().any(|e| e.contains(needle))
}

#[test]
fn one_parameter_trigonometric_and_polynomial_ranges_are_exact() {
    // Han 2002: λ ∈ [−1, 1] exactly; a printed [−2, 1] is refuted at λ = −2,
    // t with tan(t/2) = 1/2 (sin t = 4/5, cos t = 3/5): b1 = (−1)(4/5 + 3/5 − 1) = −2/5
    let (v, e) = claim("han-quadratic.toml", "HQ-range");
    assert_eq!(v, "holds", "{e:?}");
    assert!(
        has(&e, "exact end -1 (rational, included)") && has(&e, "exact end 1 (rational, included)"),
        "{e:?}"
    );
    let (v, e) = claim("han-quadratic.toml", "HQ-wider");
    assert_eq!(v, "fails");
    assert!(has(&e, "value") || has(&e, "equals -2/5"), "{e:?}");
    // Yan & Liang 2011: λ ∈ [−3, 1] exactly; b0'(0) = −(3 + λ)
    let (v, e) = claim("yan-liang-cubic.toml", "YL-range");
    assert_eq!(v, "holds", "{e:?}");
    assert!(
        has(&e, "exact end -3 (rational, included)") && has(&e, "exact end 1 (rational, included)"),
        "{e:?}"
    );
    assert_eq!(claim("yan-liang-cubic.toml", "YL-tangent").0, "holds");
}

#[test]
fn quotient_bases_are_certified_on_half_lines_and_refuted_exactly() {
    // w ∈ [0, ∞): the end 0 is included (b1 = 0 there), no upper end
    let (v, e) = claim("rational-quadratic.toml", "RQ-range");
    assert_eq!(v, "holds", "{e:?}");
    assert!(has(&e, "exact end 0 (rational, included)"), "{e:?}");
    assert!(has(&e, "upper end: none"), "{e:?}");
    // w = −1/10: the denominator is (1 + w)/2 at t = 1/2, b1 = w/(1 + w) = −1/9
    let (v, e) = claim("rational-quadratic.toml", "RQ-wide");
    assert_eq!(v, "fails");
    // the witness of b1 ≥ 0: point w = −1/10, t = 1/2 (name, value), value −1/9
    assert!(
        e.iter().any(|x| x.contains("b1 ≥ 0")
            && x.contains("w -1/10")
            && x.contains("t 1/2")
            && x.contains("value")
            && x.contains("-1/9")),
        "{e:?}"
    );
    assert_eq!(claim("rational-quadratic.toml", "RQ-unity").0, "holds");
}

#[test]
fn two_parameter_regions_are_decided_as_equalities() {
    // separable: the product of two exact intervals [−2, 1]
    let (v, e) = claim("han-ma-huang-cubic.toml", "HMH-region");
    assert_eq!(v, "holds", "{e:?}");
    assert!(has(&e, "depends on one parameter at most"), "{e:?}");
    // coupled (b1 depends on α and β): the necessary end conditions cut
    // out the box
    let (v, e) = claim("bashir-quadratic.toml", "QTB-nonneg");
    assert_eq!(v, "holds", "{e:?}");
    // a two-parameter quotient basis on [0, ∞)²
    let (v, e) = claim("rational-cubic.toml", "RC-region");
    assert_eq!(v, "holds", "{e:?}");
    assert!(has(&e, "3*w1 ≥ 0") && has(&e, "3*w2 ≥ 0"), "{e:?}");
}

#[test]
fn a_region_that_is_not_a_box_refutes_maximality_with_a_certified_cell() {
    // f0 = (1 − t)(1 − (λ + μ)t), f1 = 1 − f0: nonnegative exactly on the
    // strip −1 ≤ λ + μ ≤ 1, which is larger than the box [−1/2, 1/2]²
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_certify");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("strip.toml");
    std::fs::write(
        &path,
        r#"id = "strip"
citation = "constructed"
variable = "polynomial"
[[parameters]]
name = "lambda"
range = "[-1/2, 1/2]"
[[parameters]]
name = "mu"
range = "[-1/2, 1/2]"
[[functions]]
name = "f0"
formula = "(1 - t)*(1 - (lambda + mu)*t)"
[[functions]]
name = "f1"
formula = "t*(1 + (lambda + mu)*(1 - t))"
[[claims]]
id = "box"
source = "test"
statement = "f_i ≥ 0 for λ, μ ∈ [−1/2, 1/2]"
check = "nonnegative"
[[claims]]
id = "maximal"
source = "test"
statement = "f_i ≥ 0 exactly for λ, μ ∈ [−1/2, 1/2]"
check = "nonnegative"
maximal = true
"#,
    )
    .expect("write spec");
    let file = path.display().to_string();
    let get = |id: &str| {
        let text = stdout_ok(&["audit", "--spec", &file, "--claim", id, "--format", "json"]);
        let json: serde_json::Value = serde_json::from_str(&text).expect("json");
        (
            json["claims"][0]["verdict"]
                .as_str()
                .unwrap_or_default()
                .to_string(),
            json["claims"][0]["evidence"].to_string(),
        )
    };
    assert_eq!(get("box").0, "holds");
    let (v, e) = get("maximal");
    assert_eq!(v, "fails", "{e}");
    // the face λ = 1/2 lies on no boundary polynomial (the edge is λ + μ = ±1);
    // the section μ = 0 extends to λ ∈ [−1, 1]
    assert!(e.contains("is not on the region's edge"), "{e}");
    assert!(e.contains("exact end 1 (rational, included)"), "{e}");
}

#[test]
fn an_irrational_end_is_an_exact_algebraic_number_not_a_rational_guess() {
    // ends 2 ∓ 2√2, roots of λ² − 4λ − 4; at λ = 7, t = 1/2:
    // k = 21/4, b0 = (1/4)(1 − 21/16) = −5/64
    let (v, e) = claim("irrational-end.toml", "IE-maximal");
    assert_eq!(v, "fails", "{e:?}");
    assert!(
        has(
            &e,
            "lambda^2 - 4*lambda - 4 = 0 in [4.828427124746, 4.828427124747] (minimal polynomial) (irrational, included)"
        ),
        "{e:?}"
    );
    assert!(
        has(&e, "counterexample lambda = 7, t = 1/2: value -5/64"),
        "{e:?}"
    );
    assert_eq!(claim("irrational-end.toml", "IE-inside").0, "holds");
}
