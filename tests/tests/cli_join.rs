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

/// A G² join whose order-2 condition involves no free control point of the
/// second segment is met by the factor β alone: the join says which β
/// instead of failing. The quartic trigonometric basis with two shape
/// parameters (b₀ = (1 − s)²(1 − λs)², b₂ = (1 − c)²(1 − μc)², b₁ the rest),
/// checked independently in SymPy (a new user's derivation):
/// β = −α[α(μ₁² + 4μ₁ + 1)/(μ₁ + 1) + (λ₂² + 4λ₂ + 1)/(λ₂ + 1)].
#[test]
fn a_g2_condition_without_a_free_point_fixes_the_factor() {
    let spec = crate::cli_spec_features::spec_file(
        "quartic-two-shape.toml",
        "id = \"quartic-two-shape\"\ncitation = \"test\"\nvariable = \"angle\"\n[[parameters]]\nname = \"lambda\"\nsymbol = \"λ\"\nrange = \"[-1, 1]\"\n[[parameters]]\nname = \"mu\"\nsymbol = \"μ\"\nrange = \"[-1, 1]\"\n[[functions]]\nname = \"b0\"\nformula = \"(1 - s)^2*(1 - lambda*s)^2\"\n[[functions]]\nname = \"b2\"\nformula = \"(1 - c)^2*(1 - mu*c)^2\"\n[[functions]]\nname = \"b1\"\nformula = \"1 - b0 - b2\"\n",
    );
    let g2 = |extra: &[&str]| {
        let args = [
            &[
                "join",
                "--spec",
                &spec,
                "--kind",
                "g2",
                "--params",
                "different",
            ][..],
            extra,
        ]
        .concat();
        stdout_ok(&args)
    };
    let text = g2(&[]);
    assert!(
        text.contains("β = −α·(α·λ₂·μ₁² + 4·α·λ₂·μ₁ + α·μ₁² + λ₂²·μ₁ + α·λ₂ + 4·α·μ₁ + λ₂² + 4·λ₂·μ₁ + α + 4·λ₂ + μ₁ + 1)/((λ₂ + 1)·(μ₁ + 1))"),
        "{text}"
    );
    let json = g2(&["--format", "json"]);
    let value: serde_json::Value = serde_json::from_str(&json).expect("json");
    assert_eq!(value["factor"]["symbol"], "beta", "{json}");
    // a C² join has no factor to take up the condition: it cannot be met
    let c2 = trig_e2e::error_line(&[
        "join",
        "--spec",
        &spec,
        "--kind",
        "c2",
        "--params",
        "different",
    ]);
    assert!(c2.contains("cannot be met"), "{c2}");
}
