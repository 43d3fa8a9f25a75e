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

/// A big basis that is not totally positive: the Bernstein basis of degree
/// 12 with b1 and b2 exchanged (the 2 × 2 minor of (b1, b2) at two points
/// is negative). Its coefficient matrix is a permutation: no bidiagonal
/// factorisation exists and the enumeration of minors is past its limit,
/// yet a negative collocation minor refutes, exactly.
#[test]
fn a_big_basis_that_is_not_totally_positive_is_refuted() {
    let n = 12;
    let mut text = "id = \"swapped\"\ncitation = \"test\"\nvariable = \"polynomial\"\n".to_string();
    let order: Vec<u64> = (0..=n)
        .map(|i| match i {
            1 => 2,
            2 => 1,
            i => i,
        })
        .collect();
    for (k, i) in order.into_iter().enumerate() {
        text.push_str(&format!(
            "[[functions]]\nname = \"b{k}\"\nformula = \"{}*t^{i}*(1 - t)^{}\"\n",
            binomial(n, i),
            n - i
        ));
    }
    text.push_str("[[claims]]\nid = \"TP\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\n");
    let spec = Spec::from_str_named(&text, "swapped").unwrap_or_else(|e| panic!("{e}"));
    let v = spec_audit::decide(&spec, &spec.claims[0]);
    assert_eq!(v.status, Status::Fails, "{:?}", v.evidence);
    assert!(
        format!("{:?}", v.evidence).contains("minor of the collocation matrix"),
        "{:?}",
        v.evidence
    );
}
