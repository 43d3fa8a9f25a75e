//! Total positivity with two and three shape parameters, decided both
//! ways on bases outside the catalog (expected results derived by hand
//! below and independently in examples/independent/issue38-total-positivity.py).

use trig_specfile::Spec;

use crate::common::{evidence_lines, example_text};
use trig_verification::{Status, Verdict, spec_audit};

/// A polynomial spec on `[0, 1]` with the given parameters (`name range`)
/// and functions, and one total-positivity claim.
fn tp(params: &[(&str, &str)], functions: &[&str]) -> Verdict {
    let mut text = "id = \"several\"\ncitation = \"test\"\nvariable = \"polynomial\"\n".to_string();
    for (name, range) in params {
        text.push_str(&format!(
            "[[parameters]]\nname = \"{name}\"\nrange = \"{range}\"\n"
        ));
    }
    for (i, f) in functions.iter().enumerate() {
        text.push_str(&format!(
            "[[functions]]\nname = \"b{i}\"\nformula = \"{f}\"\n"
        ));
    }
    text.push_str(
        "[[claims]]\nid = \"TP\"\nsource = \"test\"\nstatement = \"TP\"\ncheck = \"total-positivity\"\n",
    );
    let spec = Spec::from_str_named(&text, "several").unwrap_or_else(|e| panic!("{e}"));
    spec_audit::decide(&spec, &spec.claims[0])
}

/// `b0 = B0 + a·B1`, `b1 = (1 − a − b)·B1`, `b2 = B2 + b·B1` (quadratic
/// Bernstein `Bₖ`): coefficient matrix `[[1, a, 0], [0, 1 − a − b, 0],
/// [0, b, 1]]`, whose minors `a`, `b`, `1 − a − b`, … are all `≥ 0` exactly
/// on the triangle `a, b ≥ 0`, `a + b ≤ 1`; outside it `b1 < 0` (when
/// `a + b > 1`) or `b0 < 0` near `t = 1` (when `a < 0`), so a `1 × 1`
/// collocation minor is negative.
const TRIANGLE: [&str; 3] = [
    "(1 - t)^2 + 2*a*t*(1 - t)",
    "2*(1 - a - b)*t*(1 - t)",
    "t^2 + 2*b*t*(1 - t)",
];

#[test]
fn two_parameters_both_ways() {
    let v = tp(&[("a", "[0, 1/2]"), ("b", "[0, 1/2]")], &TRIANGLE);
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("each a polynomial in a, b"),
        "{}",
        evidence_lines(&v)
    );
    let v = tp(&[("a", "[0, 1]"), ("b", "[0, 1]")], &TRIANGLE);
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("not totally positive at a = "),
        "{}",
        evidence_lines(&v)
    );
    let v = tp(&[("a", "[-1/2, 0]"), ("b", "[0, 1/2]")], &TRIANGLE);
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
}

/// The cubic version with three parameters: `b0 = B0 + a·B1`,
/// `b1 = (1 − a)·B1 + g·B2`, `b2 = (1 − b − g)·B2`, `b3 = B3 + b·B2`; the
/// coefficient matrix `[[1, a, 0, 0], [0, 1 − a, g, 0], [0, 0, 1 − b − g, 0],
/// [0, 0, b, 1]]` has the minors `a`, `1 − a`, `b`, `g`, `1 − b − g`, `ag`,
/// `(1 − a)b`, `(1 − a)(1 − b − g)`, …: all `≥ 0` for `a ∈ [0, 1]`,
/// `b, g ∈ [0, 1/2]`; at `b = g = 1`, `b2 = −B2 < 0`.
#[test]
fn three_parameters_both_ways() {
    let cubic = [
        "(1 - t)^3 + 3*a*t*(1 - t)^2",
        "3*(1 - a)*t*(1 - t)^2 + 3*g*t^2*(1 - t)",
        "3*(1 - b - g)*t^2*(1 - t)",
        "t^3 + 3*b*t^2*(1 - t)",
    ];
    let v = tp(
        &[("a", "[0, 1]"), ("b", "[0, 1/2]"), ("g", "[0, 1/2]")],
        &cubic,
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    let v = tp(&[("a", "[0, 1]"), ("b", "[0, 1]"), ("g", "[0, 1]")], &cubic);
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("not totally positive at a = "),
        "{}",
        evidence_lines(&v)
    );
}

/// A spec text with one claim appended, decided.
fn decide_text(text: &str, claim: &str) -> Verdict {
    let spec = Spec::from_str_named(
        &format!(
            "{text}\n[[claims]]\nid = \"X\"\nsource = \"test\"\nstatement = \"test\"\n{claim}\n"
        ),
        "several",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    spec_audit::decide(&spec, spec.claims.last().expect("claim"))
}

/// Constructed in examples/independent/issue38.md, section 3, item 6:
/// nonnegative on [0, 2]² (b0, b2 squares, b1 = t(1 − t)·Q with Q > 0) but
/// totally positive exactly on [0, 1]²: at (λ, μ) = (2, 0) the 2×2
/// collocation minor of (b0, b1) at t = 1/2 < 3/4 is det[[0, 3/4],
/// [1/64, 27/64]] = −3/256.
const NONNEGATIVE_NOT_TP: &str = "id = \"b6\"\ncitation = \"constructed\"\nvariable = \"polynomial\"\n\
[[parameters]]\nname = \"lambda\"\nsymbol = \"λ\"\nrange = \"[0, 2]\"\n\
[[parameters]]\nname = \"mu\"\nsymbol = \"μ\"\nrange = \"[0, 2]\"\n\
[[functions]]\nname = \"b0\"\nformula = \"(1 - t)^2*(1 - lambda*t)^2\"\n\
[[functions]]\nname = \"b1\"\nformula = \"1 - (1 - t)^2*(1 - lambda*t)^2 - t^2*(1 - mu*(1 - t))^2\"\n\
[[functions]]\nname = \"b2\"\nformula = \"t^2*(1 - mu*(1 - t))^2\"\n";

#[test]
fn nonnegative_on_the_box_totally_positive_on_a_smaller_one() {
    let v = decide_text(NONNEGATIVE_NOT_TP, "check = \"nonnegative\"");
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    let v = decide_text(NONNEGATIVE_NOT_TP, "check = \"total-positivity\"");
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("is -3/256 < 0 (exact)"),
        "{}",
        evidence_lines(&v)
    );
    let v = decide_text(
        NONNEGATIVE_NOT_TP,
        "check = \"total-positivity\"\nranges = { lambda = \"[0, 1]\", mu = \"[0, 1]\" }",
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
}

/// Han, Ma & Huang's trigonometric cubic (examples/han-ma-huang-cubic.toml)
/// is totally positive on its whole box [−2, 1]² (issue38.md, section 3,
/// item 3: all 192 minors of the degree-6 Bernstein form are ≥ 0).
#[test]
fn a_published_two_parameter_basis_is_totally_positive() {
    let v = decide_text(
        &example_text("han-ma-huang-cubic"),
        "check = \"total-positivity\"",
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("192 nonzero minors"),
        "{}",
        evidence_lines(&v)
    );
}

/// The generalized Bernstein basis of degree 3 with three parameters
/// (Han, Ma & Huang, JCAM 217 (2008) 180–193; issue38.md): totally
/// positive on its whole box (the coefficient matrix is bidiagonal with
/// entries ≥ 0), and not on a box reaching λ2 = 31/10, where
/// b1(31/32) = −31/10485760.
#[test]
fn a_published_three_parameter_basis_both_ways() {
    let gb3 = |l2: &str| {
        tp(
            &[
                ("lambda1", "[-3, 1]"),
                ("lambda2", l2),
                ("lambda3", "[-3, 1]"),
            ],
            &[
                "(1 - t)^3*(1 - lambda1*t)",
                "t*(1 - t)^2*(3 + lambda1 - lambda1*t - lambda2*t)",
                "t^2*(1 - t)*(3 + lambda2 - lambda2*t + lambda3*t)",
                "t^3*(1 - lambda3 + lambda3*t)",
            ],
        )
    };
    let v = gb3("[-3, 3]");
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    let v = gb3("[-3, 31/10]");
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
}

/// A region printed as inequalities — the triangle `a, b ≥ 0`,
/// `a + b ≤ 1` — is stated with an end linear in the other parameter
/// (`ranges = { a = "[0, 1]", b = "[0, 1 - a]" }`) and decided as
/// `b = (1 − a)·b′`, `b′ ∈ [0, 1]`: the triangle basis is totally positive
/// on exactly that triangle, and not on the larger one `b ≤ 1 − a/2`
/// (at `a = 1`, `b = 1/2`: `b1 = −B1 < 0`).
#[test]
fn a_triangle_of_parameters() {
    let text = "id = \"tri\"\ncitation = \"test\"\nvariable = \"polynomial\"\n\
[[parameters]]\nname = \"a\"\nrange = \"[0, 1]\"\n[[parameters]]\nname = \"b\"\nrange = \"[0, 1]\"\n"
        .to_string()
        + &TRIANGLE
            .iter()
            .enumerate()
            .map(|(i, f)| format!("[[functions]]\nname = \"b{i}\"\nformula = \"{f}\"\n"))
            .collect::<String>();
    let v = decide_text(
        &text,
        "check = \"total-positivity\"\nranges = { a = \"[0, 1]\", b = \"[0, 1 - a]\" }",
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("b ∈ [0, 1 - a] (written b = lo + b_u·(hi − lo)"),
        "{}",
        evidence_lines(&v)
    );
    let v = decide_text(
        &text,
        "check = \"total-positivity\"\nranges = { b = \"[0, 1 - a/2]\" }",
    );
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    let v = decide_text(
        &text,
        "check = \"nonnegative\"\nranges = { b = \"[0, 1 - a]\" }",
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    // an upper end below the lower one somewhere is refused with the reason
    let v = decide_text(
        &text,
        "check = \"unity\"\nranges = { b = \"[0, a - 1/2]\" }",
    );
    assert_eq!(v.status, Status::NotCheckable, "{}", evidence_lines(&v));
    // the same triangles as the paper prints them, by inequalities
    let v = decide_text(
        &text,
        "check = \"total-positivity\"\nregion = \"a >= 0, b >= 0, a + b <= 1\"",
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("b ∈ [0, -a + 1]"),
        "{}",
        evidence_lines(&v)
    );
    let v = decide_text(
        &text,
        "check = \"total-positivity\"\nregion = \"a >= 0, a <= 1, b >= 0, a + 2*b <= 2\"",
    );
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
}

/// The constructed basis above with `λ = α²`, `μ = β²`: totally positive
/// exactly for `λ, μ ∈ [0, 1]` (issue38.md, section 3, item 6; `λ > 1`
/// gives `b0` a double zero inside and a negative `2 × 2` minor), so exactly
/// on `[−1, 1]²` in `(α, β)`; nonnegative on a larger box (`Q`'s
/// coefficients `2 + 2α²`, `6 − (α² − 1)² − (β² − 1)²`, `2 + 2β²` stay
/// positive on `[−5/4, 5/4]²`).
const SQUARED_PARAMETERS: &str = "id = \"b7\"\ncitation = \"constructed\"\nvariable = \"polynomial\"\n\
[[parameters]]\nname = \"alpha\"\nsymbol = \"α\"\nrange = \"[-1, 1]\"\n\
[[parameters]]\nname = \"beta\"\nsymbol = \"β\"\nrange = \"[-1, 1]\"\n\
[[functions]]\nname = \"b0\"\nformula = \"(1 - t)^2*(1 - alpha^2*t)^2\"\n\
[[functions]]\nname = \"b1\"\nformula = \"1 - (1 - t)^2*(1 - alpha^2*t)^2 - t^2*(1 - beta^2*(1 - t))^2\"\n\
[[functions]]\nname = \"b2\"\nformula = \"t^2*(1 - beta^2*(1 - t))^2\"\n";

#[test]
fn a_maximal_set_of_two_parameters_smaller_than_nonnegativity_exactly() {
    let maximal = "check = \"total-positivity\"\nmaximal = true";
    let v = decide_text(SQUARED_PARAMETERS, maximal);
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    let lines = evidence_lines(&v);
    assert!(lines.contains("is exactly the maximal set"), "{lines}");
    assert!(
        lines.contains("the face α = 1: the maximal interval"),
        "{lines}"
    );
    // nonnegative beyond it
    let v = decide_text(
        SQUARED_PARAMETERS,
        "check = \"nonnegative\"\nranges = { alpha = \"[-5/4, 5/4]\", beta = \"[-5/4, 5/4]\" }",
    );
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    // a smaller box is not maximal: totally positive beyond its face
    let v = decide_text(
        SQUARED_PARAMETERS,
        &format!("{maximal}\nranges = {{ alpha = \"[-1/2, 1]\" }}"),
    );
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("at α = -3/4, β = 0, outside the printed box"),
        "{}",
        evidence_lines(&v)
    );
}

/// Generalized Bernstein of degree 2 (Han, Ma & Huang, JCAM 217 (2008)):
/// totally positive exactly on `[−2, 1]²` in the plane (issue38.md,
/// section 3, item 1: beyond each face a function is negative).
#[test]
fn published_boxes_are_exactly_the_maximal_sets() {
    let gb2 = [
        "(1 - t)^2*(1 - lambda1*t)",
        "t*(1 - t)*(2 + lambda1 - lambda1*t + lambda2*t)",
        "t^2*(1 - lambda2 + lambda2*t)",
    ];
    let spec = |r1: &str| {
        let mut text = "id = \"gb2\"\ncitation = \"test\"\nvariable = \"polynomial\"\n".to_string();
        for (name, range) in [("lambda1", r1), ("lambda2", "[-2, 1]")] {
            text.push_str(&format!(
                "[[parameters]]\nname = \"{name}\"\nrange = \"{range}\"\n"
            ));
        }
        for (i, f) in gb2.iter().enumerate() {
            text.push_str(&format!(
                "[[functions]]\nname = \"b{i}\"\nformula = \"{f}\"\n"
            ));
        }
        text
    };
    let maximal = "check = \"total-positivity\"\nmaximal = true";
    let v = decide_text(&spec("[-2, 1]"), maximal);
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    let v = decide_text(&spec("[-1, 1]"), maximal);
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    // the face λ1 = −2 left open: totally positive there too (by continuity)
    let v = decide_text(&spec("(-2, 1]"), maximal);
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
    assert!(
        evidence_lines(&v).contains("on the open face lambda1 = -2"),
        "{}",
        evidence_lines(&v)
    );
    let v = decide_text(&example_text("han-ma-huang-cubic"), maximal);
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
}

/// `b0 = 1 − f`, `b1 = f` with `f = t + λ·t(1 − t)(1 − 2t)`: `W(b0, b1) =
/// f′ = 1 + λ(1 − 6t + 6t²)`, positive on `(0, 1)` exactly for
/// `λ ∈ [−1, 2)` (its least value `1 − λ/2` at `t = 1/2` for `λ > 0`,
/// `1 + λ` at the ends for `λ < 0`), and `0 < f < 1` inside there: totally
/// positive on `[−1, 2]` (by hand). The cubic Bernstein coefficients of `f`,
/// `(0, (1 + λ)/3, (2 − λ)/3, 1)`, increase only for `λ ≤ 1/2`: the
/// factorisation's certificate stalls below the true set, degree elevation
/// only narrows the gap, and the Wronskian criterion closes it.
#[test]
fn the_wronskian_criterion_decides_where_the_certificate_stalls() {
    let f = "lambda*t*(1 - t)*(1 - 2*t)";
    let b = [format!("1 - t - {f}"), format!("t + {f}")];
    let functions = [b[0].as_str(), b[1].as_str()];
    let v = tp(&[("lambda", "[-1, 3/2]")], &functions);
    assert_eq!(v.status, Status::Holds, "{}", evidence_lines(&v));
    let lines = evidence_lines(&v);
    assert!(
        lines.contains("the factorisation's certificate does not cover the range")
            && lines.contains("W(b0, b1) > 0 on the open domain"),
        "{lines}"
    );
    // beyond λ = 2, f′(1/2) < 0: refuted
    let v = tp(&[("lambda", "[-1, 5/2]")], &functions);
    assert_eq!(v.status, Status::Fails, "{}", evidence_lines(&v));
}
