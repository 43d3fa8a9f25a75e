//! Bases of many functions: the Bernstein bases of degree 3–20 on [0, 1]
//! and C(n, i)·sin²ⁱt·cos²⁽ⁿ⁻ⁱ⁾t on [0, π/2] (the Bernstein basis of sin²t,
//! an increasing change of variable) satisfy every property the audit
//! checks — the standard battery, linear independence, total positivity and
//! the convex hull hold by the textbook — and none ends `not-checkable` or
//! panics (issue 38: from 7 functions on independence was not checkable,
//! total positivity of degree 15 and 20 was cut off, the sin² basis from
//! degree 10 on panicked). Timings are in BENCHMARKS.md (`bench/scale.py`).

use trig_specfile::Spec;
use trig_verification::{Status, spec_audit};

fn binomial(n: u64, k: u64) -> u64 {
    (0..k).fold(1, |acc, i| acc * (n - i) / (i + 1))
}

fn bernstein(n: u64, sin2: bool) -> Spec {
    let mut text = format!(
        "id = \"b{n}\"\ncitation = \"textbook\"\nvariable = \"{}\"\n",
        if sin2 { "angle" } else { "polynomial" }
    );
    for i in 0..=n {
        let c = binomial(n, i);
        let f = if sin2 {
            format!("{c}*s^{}*c^{}", 2 * i, 2 * (n - i))
        } else {
            format!("{c}*t^{i}*(1 - t)^{}", n - i)
        };
        text.push_str(&format!(
            "[[functions]]\nname = \"b{i}\"\nformula = \"{f}\"\n"
        ));
    }
    for (id, check) in [
        ("IND", "independent"),
        ("TP", "total-positivity"),
        ("HULL", "convex-hull"),
    ] {
        text.push_str(&format!(
            "[[claims]]\nid = \"{id}\"\nsource = \"textbook\"\nstatement = \"{check}\"\ncheck = \"{check}\"\n"
        ));
    }
    Spec::from_str_named(&text, "bernstein").unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn bernstein_bases_of_degree_3_to_20_hold_every_property() {
    for n in [3, 6, 10, 15, 20] {
        for sin2 in [false, true] {
            let entries = spec_audit::audit(&bernstein(n, sin2));
            assert_eq!(entries.len(), 10, "degree {n}");
            for e in &entries {
                assert_eq!(
                    e.verdict.status,
                    Status::Holds,
                    "degree {n}, sin² {sin2}, {}: {:?}",
                    e.id,
                    e.verdict.evidence
                );
            }
        }
    }
}
