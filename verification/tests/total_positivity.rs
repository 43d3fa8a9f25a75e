//! `check = "total-positivity"` both ways, on bases outside the catalog,
//! with the results derived independently in examples/independent/README.md,
//! Part D(d) (script d-total-positivity.py): Han's quadratic is totally
//! positive on [−1, 1], Yan & Liang's cubic on [−3, 1]; the squared Han
//! basis is nonnegative on [−1, 2 + 2√2] but totally positive only on
//! [−1, 1] — at λ = 5/4 a 2×2 collocation minor is negative. And the
//! catalog claims D14, D16 (seed 002), T42, T70 (thesis), S4 (seed 003).

use std::path::PathBuf;

use crate::common::evidence_lines;

use rug::Rational;
use trig_specfile::Spec;
use trig_verification::{Status, Verdict, run, spec_audit};

/// An example spec file with a total-positivity claim on `range` appended.
fn decide(name: &str, range: Option<&str>) -> Verdict {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../examples")
        .join(format!("{name}.toml"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
    let range = range.map_or(String::new(), |r| format!("range = \"{r}\"\n"));
    let claim = format!(
        "[[claims]]\nid = \"TP\"\nsource = \"test\"\nstatement = \"normalized totally positive\"\ncheck = \"total-positivity\"\n{range}"
    );
    let spec =
        Spec::from_str_named(&format!("{text}\n{claim}"), name).unwrap_or_else(|e| panic!("{e}"));
    spec_audit::decide(&spec, &spec.claims[spec.claims.len() - 1])
}

#[test]
fn han_and_yan_liang_are_totally_positive_on_their_ranges() {
    for (name, set) in [
        ("han-quadratic", "λ ∈ [-1, 1]"),
        ("yan-liang-cubic", "λ ∈ [-3, 1]"),
    ] {
        let v = decide(name, None);
        assert_eq!(v.status, Status::Holds, "{name}: {}", evidence_lines(&v));
        assert!(
            evidence_lines(&v).contains(set),
            "{name}: {}",
            evidence_lines(&v)
        );
        assert!(
            evidence_lines(&v).contains("convexity preservation"),
            "{}",
            evidence_lines(&v)
        );
    }
}

/// Beyond the nonnegativity range a negative value is a negative 1×1 minor.
#[test]
fn beyond_the_nonnegativity_range_total_positivity_fails() {
    for name in ["han-quadratic", "yan-liang-cubic"] {
        let v = decide(name, Some("[-1, 2]"));
        assert_eq!(v.status, Status::Fails, "{name}: {}", evidence_lines(&v));
        assert!(
            evidence_lines(&v).contains("not totally positive at λ ="),
            "{}",
            evidence_lines(&v)
        );
    }
}

/// Nonnegative on [−1, 2 + 2√2] but TP only on [−1, 1]: the refuting
/// minor is exact and negative, and re-checks as a determinant of the
/// witness's values.
#[test]
fn squares_han_is_totally_positive_only_on_minus_one_to_one() {
    let inside = decide("squares-han", None);
    assert_eq!(inside.status, Status::Holds, "{}", evidence_lines(&inside));
    let v = decide("squares-han", Some("[-1, 9/2]"));
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    let all = evidence_lines(&v);
    assert!(all.contains("all ≥ 0 exactly for λ ∈ [-1, 1]"), "{all}");
    let witness = v
        .evidence
        .clone()
        .into_vec()
        .into_iter()
        .find_map(|e| e.witness)
        .expect("a witness");
    let value = |label: &str| -> Rational {
        let v = witness
            .values
            .iter()
            .find(|x| x.label == label)
            .unwrap_or_else(|| panic!("{label}: {witness:?}"));
        v.value.plain.parse().unwrap_or_else(|_| panic!("{v:?}"))
    };
    let minor = value("minor");
    assert!(minor < 0, "{witness:?}");
    // the 2×2 case: re-check the determinant by hand
    let labels: Vec<&str> = witness.values.iter().map(|x| x.label.as_str()).collect();
    if labels.len() == 5 {
        let det = value(labels[0]) * value(labels[3]) - value(labels[1]) * value(labels[2]);
        assert_eq!(det, minor, "{witness:?}");
    }
}

#[test]
fn catalog_claims_of_total_positivity() {
    let status = |id: &str| {
        let entries = run(None, Some(id)).expect("the document files");
        assert_eq!(entries.len(), 1, "{id}");
        entries[0].verdict.status
    };
    for id in ["D14", "D16", "T42", "T70"] {
        assert_eq!(status(id), Status::Holds, "{id}");
    }
    assert_eq!(status("S4"), Status::NotCheckable);
}

/// `maximal = true` on total positivity (one parameter): Han's quadratic
/// is totally positive on [−1, 1] and nonnegative exactly there, so the
/// range is exactly the maximal set; on the narrower [−1, 1/2] the
/// certificate proves total positivity beyond 1/2 (fails); the squared Han
/// basis is totally positive on [−1, 1] but nonnegative up to 2 + 2√2: its
/// maximal set of total positivity is exactly [−1, 1], strictly smaller
/// (examples/independent/, Part D(d)) — beyond 1, b0 = (1 − s)²(1 − λs)²
/// vanishes inside the domain and rises again, which a variation
/// diminishing basis with b0 = 1 at the start cannot do; on [−1, 1/2] the
/// certificate reaches beyond the printed end, and [−1, 2] is not totally
/// positive (both fail).
#[test]
fn the_maximal_set_of_total_positivity() {
    let claim = |range: &str| {
        format!(
            "[[claims]]\nid = \"TPMAX\"\nsource = \"test\"\nstatement = \"TP exactly\"\ncheck = \"total-positivity\"\nmaximal = true\n{range}"
        )
    };
    let decide_in = |name: &str, range: &str| {
        let spec = crate::common::example_with(name, &claim(range));
        spec_audit::decide(&spec, spec.claims.last().expect("claim"))
    };
    let v = decide_in("han-quadratic", "");
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("exactly the maximal set"),
        "{}",
        evidence_lines(&v)
    );
    let v = decide_in("han-quadratic", "range = \"[-1, 1/2]\"");
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("outside the printed range, the basis is totally positive too"),
        "{}",
        evidence_lines(&v)
    );
    let v = decide_in("squares-han", "");
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    for end in ["the end 1 is exact", "the end -1 is exact"] {
        assert!(evidence_lines(&v).contains(end), "{}", evidence_lines(&v));
    }
    for range in ["range = \"[-1, 1/2]\"", "range = \"[-1, 2]\""] {
        let v = decide_in("squares-han", range);
        assert_eq!(v.status, Status::Fails, "{range}: {}", evidence_lines(&v));
    }
}
