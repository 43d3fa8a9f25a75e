//! `check = "local-control"` both ways on bases outside the catalog, with
//! the results derived independently in examples/independent/README.md,
//! Part D(f) (d-hull-local.py): in the uniform C-B-spline (segment
//! `i = Σ_k b_k P_{i+k}`) `P_j` enters exactly the four segments `j−3 … j`,
//! so "three segments" fails, with the witness in segment `j−3`; its one `α`
//! enters every segment; a parameter with one value per segment (Han's
//! quadratic with `λ_i`) enters its own segment only.

use std::path::PathBuf;

use trig_specfile::Spec;
use trig_verification::{Status, Verdict, spec_audit};

fn example(name: &str) -> Spec {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../examples")
        .join(format!("{name}.toml"));
    Spec::from_file(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// The verdict of claim `id` as the spec audit gives it (witnesses at
/// real points of the basis).
fn decide(spec: &Spec, id: &str) -> Verdict {
    spec_audit::audit(spec)
        .into_iter()
        .find(|e| e.id == id)
        .unwrap_or_else(|| panic!("no claim {id}"))
        .verdict
}

/// The items of a verdict that do not hold, by subject.
fn wrong(v: &Verdict) -> Vec<String> {
    v.evidence
        .iter()
        .filter(|e| e.status.is_some_and(|s| s != Status::Holds))
        .filter_map(|e| e.subject.clone())
        .collect()
}

#[test]
fn a_point_of_the_c_bspline_enters_exactly_four_segments() {
    let cbs = example("c-bspline");
    let four = decide(&cbs, "CBS-local");
    assert_eq!(four.status, Status::Holds, "{four:?}");
    assert!(
        four.evidence
            .iter()
            .any(|e| e.line().contains("P_j enters exactly: j−3, j−2, j−1, j")),
        "{four:?}"
    );
    // every entry is proved by a point where its weight is nonzero
    let proved = four
        .evidence
        .iter()
        .filter(|e| e.status == Some(Status::Holds) && e.witness.is_some())
        .count();
    assert_eq!(proved, 4, "{four:?}");

    let three = decide(&cbs, "CBS-local-three");
    assert_eq!(three.status, Status::Fails, "{three:?}");
    assert_eq!(wrong(&three), ["P_j in segment j−3"]);
    let item = three
        .evidence
        .iter()
        .find(|e| e.status == Some(Status::Fails))
        .expect("the segment left out");
    let w = item.witness.as_ref().expect("an exact witness");
    // b3 = (t − sin t)/K at α = π/2, t = π/4: (π − 2√2)/(4π) ≠ 0
    assert!(w.line().contains("b3"), "{}", w.line());
    assert!(w.values[0].value.unicode != "0", "{}", w.line());
}

#[test]
fn a_whole_curve_parameter_is_not_local_and_a_per_segment_one_is() {
    let cbs = example("c-bspline");
    let alpha = decide(&cbs, "CBS-alpha-local");
    assert_eq!(alpha.status, Status::Fails, "{alpha:?}");
    assert_eq!(wrong(&alpha), ["α in segment j+1"]);
    assert!(
        alpha
            .evidence
            .iter()
            .any(|e| e.line().contains("α enters every segment"))
    );

    // Han's quadratic with one λ_i per segment: λ_i enters segment i only
    let claim = |segments: &str| {
        format!(
            "[[claims]]\nid = \"LOCAL\"\nsource = \"test\"\nstatement = \"local\"\ncheck = \"local-control\"\ncontrol = \"lambda\"\nscope = \"segment\"\nsegments = {segments}\n"
        )
    };
    let han = |segments: &str| {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/han-quadratic.toml");
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
        Spec::from_str_named(&format!("{text}\n{}", claim(segments)), "han-quadratic")
            .unwrap_or_else(|e| panic!("{e}"))
    };
    let own = han("[0]");
    assert_eq!(decide(&own, "LOCAL").status, Status::Holds);
    let two = han("[0, 1]");
    let v = decide(&two, "LOCAL");
    assert_eq!(v.status, Status::Fails, "{v:?}");
    assert_eq!(wrong(&v), ["λ_j in segment j+1"]);
    assert!(
        v.evidence
            .iter()
            .any(|e| e.line().contains("not among the segment's terms"))
    );
}

#[test]
fn a_local_control_claim_names_a_point_or_a_declared_parameter() {
    let text = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/han-quadratic.toml"),
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let with = |fields: &str| {
        Spec::from_str_named(
            &format!(
                "{text}\n[[claims]]\nid = \"L\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"local-control\"\n{fields}\n"
            ),
            "han-quadratic",
        )
    };
    for (fields, message) in [
        (
            "control = \"mu\"\nsegments = [0]",
            "expected `point` or a parameter (lambda)",
        ),
        (
            "control = \"lambda\"\nsegments = [0]",
            "needs the field `scope`",
        ),
        (
            "control = \"lambda\"\nscope = \"local\"\nsegments = [0]",
            "expected `segment`",
        ),
        (
            "control = \"point\"\nscope = \"curve\"\nsegments = [0]",
            "belongs to a parameter",
        ),
        ("control = \"point\"", "needs the field `segments`"),
    ] {
        let e = with(fields).expect_err(fields).to_string();
        assert!(e.contains(message), "{fields}: {e}");
    }
    assert!(with("control = \"point\"\nsegments = [-2, -1, 0]").is_ok());
}

/// The document claims about local control and joins, decided from their
/// data (identities, negated identity parts): seed 002's α_j enters the
/// segments j and j − 1, each shown by a point where ∂Q/∂α ≠ 0; the EH
/// segments join C¹ in t; the thesis's printed G² condition fails while
/// the derived curvature ratio and μ = λ² hold; the C¹ refinement (4.6)
/// moves V1 of the next curve.
#[test]
fn the_local_and_join_claims_of_the_documents_are_decided() {
    let verdict = |id: &str| {
        trig_verification::run(None, Some(id)).expect("the document files")[0]
            .verdict
            .clone()
    };
    let holding = |v: &Verdict| {
        v.evidence
            .iter()
            .filter(|e| e.status == Some(Status::Holds))
            .count()
    };
    let d19 = verdict("D19");
    assert_eq!(d19.status, Status::Holds, "{d19:?}");
    let nonzero: Vec<_> = d19
        .evidence
        .iter()
        .filter(|e| e.status == Some(Status::Fails) && e.witness.is_some())
        .collect();
    assert_eq!(nonzero.len(), 2, "{:?}", d19.evidence);
    for (id, status) in [("D17", Status::Holds), ("E24", Status::Holds)] {
        let v = verdict(id);
        assert_eq!(v.status, status, "{id}: {v:?}");
    }
    let t51 = verdict("T51");
    assert_eq!(t51.status, Status::Fails, "{t51:?}");
    assert_eq!(holding(&t51), 2, "{:?}", t51.evidence);
    let t65 = verdict("T65");
    assert_eq!(t65.status, Status::Fails, "{t65:?}");
    assert_eq!(wrong(&t65).len(), 2, "{:?}", t65.evidence);
    assert!(
        wrong(&t65)[0].contains("V1 of the next curve"),
        "{:?}",
        wrong(&t65)
    );
}
