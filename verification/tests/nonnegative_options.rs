//! `check = "nonnegative"` with `functions` (some of the functions, named
//! as in the basis the claim is about, on a knot vector its segment
//! functions) and `margin` (`f ≥ margin`, a positive margin proving
//! `f > 0`): read, refused where meaningless, and decided; seed 000's M11
//! as the document file states it.

use std::path::PathBuf;

use trig_specfile::{Check, Spec};
use trig_verification::{Status, run, spec_audit};

/// The seed 000 uniform basis (F0…F3 on ζ ∈ [0, 4]) with one claim.
fn uniform(extra: &str) -> Result<Spec, String> {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples/catalog/seed000-uniform.toml");
    let base = std::fs::read_to_string(&path).expect("the catalog file");
    let text = format!(
        "{base}\n[[claims]]\nid = \"X\"\nsource = \"s\"\nstatement = \"x\"\ncheck = \"nonnegative\"\n{extra}\n"
    );
    Spec::from_str_named(&text, &path.display().to_string()).map_err(|e| e.to_string())
}

fn verdict(extra: &str) -> trig_verification::Entry {
    let spec = uniform(extra).expect("a nonnegativity claim");
    spec_audit::audit(&spec)
        .into_iter()
        .find(|e| e.id == "X")
        .expect("the claim")
}

#[test]
fn functions_and_margin_are_read() {
    let spec = uniform("functions = [\"F2\", \"F1\"]\nmargin = \"1/200\"").unwrap();
    let Check::Nonnegative {
        functions, margin, ..
    } = &spec.claims[0].check
    else {
        panic!("{:?}", spec.claims[0].check)
    };
    assert_eq!(functions, &[2, 1]);
    let m = margin.as_ref().expect("the margin");
    assert_eq!(
        (m.text.as_str(), m.value.to_string()),
        ("1/200", "1/200".into())
    );
    let narrowed = spec.narrowed(functions, Some(m));
    let names: Vec<&str> = narrowed.functions.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(names, ["F2 − 1/200", "F1 − 1/200"]);
}

#[test]
fn unknown_or_repeated_functions_and_a_margin_with_maximal_are_refused() {
    for (extra, says) in [
        ("functions = [\"F7\"]", "`F7`: unknown function"),
        ("functions = [\"F1\", \"F1\"]", "listed twice"),
        (
            "margin = \"1/200\"\nmaximal = true",
            "give `margin` or `maximal`",
        ),
        ("margin = \"zeta\"", "expected an exact number"),
    ] {
        let e = uniform(extra).expect_err(extra);
        assert!(e.contains(says), "{extra}: {e}");
    }
}

/// The middle pieces are bounded below by 1/200 on ζ ∈ [0, 4], not by
/// 1/2 (F1 = s(ζ)/(2(3ζ² − 3ζ + 5)) < 1/2 at t = π/2); the end pieces are
/// negative somewhere (M2), so all four fail where the middle two hold.
#[test]
fn the_margin_and_the_functions_decide() {
    let middle = verdict("functions = [\"F1\", \"F2\"]\nmargin = \"1/200\"");
    assert_eq!(middle.verdict.status, Status::Holds, "{:?}", middle.verdict);
    assert!(
        middle
            .verdict
            .evidence
            .iter()
            .any(|e| e.line().contains("F1 − 1/200 ≥ 0"))
    );
    let half = verdict("functions = [\"F1\"]\nmargin = \"1/2\"");
    assert_eq!(half.verdict.status, Status::Fails, "{:?}", half.verdict);
    let all = verdict("margin = \"1/200\"");
    assert_eq!(all.verdict.status, Status::Fails);
    let both = verdict("functions = [\"F1\", \"F2\"]");
    assert_eq!(both.verdict.status, Status::Holds);
}

/// M11: the printed y_6 is wrong (the corrected one holds), the middle
/// pieces of the uniform basis are > 0, and piece 2 of F_8 on the
/// printed non-uniform coefficients is negative at z = 1.
#[test]
fn m11_fails_on_y6_and_the_nonuniform_piece() {
    let entries = run(None, Some("M11")).expect("the document files");
    let v = &entries[0].verdict;
    assert_eq!(v.status, Status::Fails);
    let status = |part: &str| {
        v.evidence
            .iter()
            .find(|e| e.parts.iter().any(|p| p.name.starts_with(part)))
            .and_then(|e| e.parts.iter().find(|p| p.name.starts_with(part)))
            .map(|p| p.status)
    };
    assert_eq!(status("the printed y_0"), Some(Status::Fails));
    assert_eq!(status("uniform knots"), Some(Status::Holds));
    assert_eq!(
        status("non-uniform knots (those of M3), ζ = 2: piece 1"),
        Some(Status::Holds)
    );
    assert_eq!(
        status("non-uniform knots (those of M3), ζ = 2: piece 2"),
        Some(Status::Fails)
    );
    let lines: Vec<String> = v.evidence.iter().map(|e| e.line()).collect();
    assert!(
        lines
            .iter()
            .any(|l| l.contains("y_6 = S(b0 + b2) + 4(S + 1)b3") && l.contains("holds")),
        "{lines:?}"
    );
}
