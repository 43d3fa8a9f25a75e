//! The exceptional set of two and three parameters and the maximal set of
//! independence, against examples/independent/issue38.md section 2
//! (derived with SymPy, independently of this code).

use trig_core::ParamRange;
use trig_verdict::status::Status;

use super::maximal::MAXIMAL;
use super::tests::{fns, spec, text};
use super::{RANK, independent, maximal};

const CONSTRUCTED: [&str; 3] = [
    "(1 - t)*(1 + beta*(alpha + 1)*t)",
    "-2*beta*(alpha + 1)*t*(1 - t)",
    "t*(1 + beta*(alpha + 1) - beta*(alpha + 1)*t)",
];

const GB2: [&str; 3] = [
    "(1 - t)^2*(1 - lambda1*t)",
    "t*(1 - t)*(2 + lambda1 - lambda1*t + lambda2*t)",
    "t^2*(1 - lambda2 + lambda2*t)",
];

#[test]
fn the_constructed_basis_is_dependent_exactly_on_two_lines() {
    let basis = spec(
        "t on [0, 1]",
        &[("alpha", "[-1, 1]"), ("beta", "[-1, 1]")],
        &fns(&CONSTRUCTED),
    );
    let v = independent(&basis, None);
    assert_eq!(
        (v.status, v.method.as_str()),
        (Status::Fails, RANK),
        "{}",
        text(&v)
    );
    let t = text(&v);
    // gcd of the minors ∝ β(α + 1): the lines β = 0 and α = −1, each met
    assert!(
        t.contains("the gcd of the 1 nonzero maximal minor is β·(α + 1)"),
        "{t}"
    );
    assert!(t.contains("curve β = 0: meets the box"), "{t}");
    assert!(t.contains("curve α + 1 = 0: meets the box"), "{t}");
    assert!(
        t.contains("isolated points") && t.contains("exact): none"),
        "{t}"
    );
    // the witness: a rational point of a line, b1 ≡ 0 there
    assert!(t.contains("alpha = -1, beta = 0"), "{t}");
    assert!(t.contains("b1 ≡ 0"), "{t}");
    // away from both lines: independent, exactly (no line meets the box)
    let away = spec(
        "t on [0, 1]",
        &[("alpha", "(-1, 1]"), ("beta", "[1/2, 1]")],
        &fns(&CONSTRUCTED),
    );
    let w = independent(&away, None);
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
    let t = text(&w);
    assert!(t.contains("curve β = 0: does not meet the box"), "{t}");
    assert!(
        t.contains("the exceptional set does not meet the box"),
        "{t}"
    );
}

#[test]
fn gb2_is_dependent_only_at_the_corner() {
    let basis = spec(
        "t on [0, 1]",
        &[("lambda1", "[-2, 1]"), ("lambda2", "[-2, 1]")],
        &fns(&GB2),
    );
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(
        t.contains("the gcd of the 3 nonzero maximal minors is 1"),
        "{t}"
    );
    assert!(t.contains("no curve of dependence"), "{t}");
    // the one isolated point, with its relation
    assert!(
        t.contains("exact): lambda1 = -2, lambda2 = -2 (b1 ≡ 0, exact)"),
        "{t}"
    );
    // with the corner's lower edge open in λ2 only: the other corners and
    // the edges are independent, so it holds, exactly
    let open = spec(
        "t on [0, 1]",
        &[("lambda1", "[-2, 1]"), ("lambda2", "(-2, 1]")],
        &fns(&GB2),
    );
    let w = independent(&open, None);
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
    assert!(text(&w).contains("exact): none"), "{}", text(&w));
    // a half-line: the roots of the resultants are bounded, still exact
    let half = spec(
        "t on [0, 1]",
        &[("lambda1", "[-2, 1]"), ("lambda2", "(-2, inf)")],
        &fns(&GB2),
    );
    let x = independent(&half, None);
    assert_eq!(x.status, Status::Holds, "{}", text(&x));
}

#[test]
fn gb3_reports_what_is_exact_and_brackets_the_rest() {
    let basis = spec(
        "t on [0, 1]",
        &[
            ("lambda1", "[-3, 1]"),
            ("lambda2", "[-3, 3]"),
            ("lambda3", "[-3, 1]"),
        ],
        &fns(&[
            "(1 - t)^3*(1 - lambda1*t)",
            "t*(1 - t)^2*(3 + lambda1 - lambda1*t - lambda2*t)",
            "t^2*(1 - t)*(3 + lambda2 - lambda2*t + lambda3*t)",
            "t^3*(1 - lambda3 + lambda3*t)",
        ]),
    );
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    // the edges are of codimension 2: no surface, the gcd is 1
    assert!(
        t.contains("exact part: the gcd of the 4 nonzero maximal minors is 1"),
        "{t}"
    );
    // on the faces, exact: E1 {λ1 = −3, λ2 = 3}, E2 {λ1 = −3, λ3 = −3},
    // E3 {λ2 = −3, λ3 = −3}, each seen from both of its faces
    for line in [
        "face lambda1 = -3: the gcd of the 1 nonzero maximal minor is (λ₂ − 3)·(λ₃ + 3)",
        "face lambda2 = 3: the gcd of the 4 nonzero maximal minors is λ₁ + 3",
        "face lambda3 = -3: the gcd of the 4 nonzero maximal minors is (λ₁ + 3)·(λ₂ + 3)",
        "face lambda2 = -3: the gcd of the 2 nonzero maximal minors is λ₃ + 3",
        // the faces the edges only end on: one point each, with the
        // relations of issue38.md ((1, −3, −3): b2 ≡ 0; on E1: b1 ≡ 0)
        "lambda1 = 1, lambda2 = -3, lambda3 = -3 (b2 ≡ 0, exact)",
        "lambda1 = -3, lambda2 = 3, lambda3 = 1 (b1 ≡ 0, exact)",
    ] {
        assert!(t.contains(line), "{line}\n{t}");
    }
    assert!(
        t.contains("not computed (a bracket): inside the box"),
        "{t}"
    );
    // a corner on E2 ∩ E3 (λ2 = λ3 = −3): b2 ≡ 0 there (issue38.md)
    assert!(
        t.contains("lambda1 = -3, lambda2 = -3, lambda3 = -3"),
        "{t}"
    );
    assert!(t.contains("b2 ≡ 0"), "{t}");
}

fn sines() -> trig_specfile::Spec {
    spec(
        "t on [0, alpha]",
        &[("alpha", "(0, pi]")],
        &fns(&["sin(alpha - t)^2", "sin(alpha - t)*sin(t)", "sin(t)^2"]),
    )
}

#[test]
fn one_parameter_maximal_holds_on_the_open_range_and_fails_with_the_end() {
    let basis = sines();
    // (0, π) within (0, π]: independent there, dependent at π
    let open = ParamRange::parse("(0, pi)").unwrap();
    let v = maximal(&basis, &basis, Some(&open));
    assert_eq!(
        (v.status, v.method.as_str()),
        (Status::Holds, MAXIMAL),
        "{}",
        text(&v)
    );
    let t = text(&v);
    assert!(t.contains("alpha = pi (a declared closed end"), "{t}");
    assert!(t.contains("the rank there is 1 < 3"), "{t}");
    assert!(t.contains("b0 − b2 ≡ 0"), "{t}");
    // (0, π] itself: dependent at π, inside the claim's range
    let w = maximal(&basis, &basis, None);
    assert_eq!(w.status, Status::Fails, "{}", text(&w));
    assert!(text(&w).contains("at alpha = π"), "{}", text(&w));
    // (0, π/2): independent somewhere in [π/2, π], a nonzero minor there
    let half = ParamRange::parse("(0, pi/2)").unwrap();
    let x = maximal(&basis, &basis, Some(&half));
    assert_eq!(x.status, Status::Fails, "{}", text(&x));
    assert!(text(&x).contains("≠ 0 (exact)"), "{}", text(&x));
}

#[test]
fn one_parameter_maximal_at_a_closed_end_of_a_polynomial_basis() {
    // the example: declared [−2, 1], dependent at −2 only (GB2's
    // diagonal λ1 = λ2 = λ)
    let diagonal: Vec<String> = GB2
        .iter()
        .map(|f| f.replace("lambda1", "lambda").replace("lambda2", "lambda"))
        .collect();
    let diagonal: Vec<&str> = diagonal.iter().map(String::as_str).collect();
    let basis = spec("t on [0, 1]", &[("lambda", "[-2, 1]")], &fns(&diagonal));
    let claim = ParamRange::parse("(-2, 1]").unwrap();
    let v = maximal(&basis, &basis, Some(&claim));
    assert_eq!(v.status, Status::Holds, "{}", text(&v));
    // claiming [−1, 1]: [−2, −1) is declared and independent at −3/2
    let short = ParamRange::parse("[-1, 1]").unwrap();
    let w = maximal(&basis, &basis, Some(&short));
    assert_eq!(w.status, Status::Fails, "{}", text(&w));
    assert!(text(&w).contains("lambda = -3/2"), "{}", text(&w));
    // a claim beyond the declared range is not decided
    let beyond = ParamRange::parse("(-2, 2]").unwrap();
    let x = maximal(&basis, &basis, Some(&beyond));
    assert_eq!(x.status, Status::NotCheckable, "{}", text(&x));
}

#[test]
fn two_parameter_maximal_against_the_lines_of_dependence() {
    let declared = spec(
        "t on [0, 1]",
        &[("alpha", "[-1, 1]"), ("beta", "[0, 1]")],
        &fns(&CONSTRUCTED),
    );
    // dependent on the edges α = −1 and β = 0, independent off them
    let claimed = spec(
        "t on [0, 1]",
        &[("alpha", "(-1, 1]"), ("beta", "(0, 1]")],
        &fns(&CONSTRUCTED),
    );
    let v = maximal(&declared, &claimed, None);
    assert_eq!(v.status, Status::Holds, "{}", text(&v));
    assert!(
        text(&v).contains("with alpha = -1 the rank is 2 < 3"),
        "{}",
        text(&v)
    );
    // GB2: its lower edges are not dependent (only the corner is)
    let gb2 = spec(
        "t on [0, 1]",
        &[("lambda1", "[-2, 1]"), ("lambda2", "[-2, 1]")],
        &fns(&GB2),
    );
    let edges = spec(
        "t on [0, 1]",
        &[("lambda1", "(-2, 1]"), ("lambda2", "(-2, 1]")],
        &fns(&GB2),
    );
    let w = maximal(&gb2, &edges, None);
    assert_eq!(w.status, Status::Fails, "{}", text(&w));
    assert!(
        text(&w).contains("at lambda1 = -2, lambda2 = 1, outside the claim's range"),
        "{}",
        text(&w)
    );
}

#[test]
fn an_isolated_point_with_both_coordinates_irrational_is_exact() {
    // the minors p² − 2 and q − p − 1: dependent at (√2, 1 + √2) only
    let fs = fns(&["1", "t", "(p^2 - 2)*t^2 + (q - p - 1)*t^3"]);
    let basis = spec("t on [0, 1]", &[("p", "[0, 2]"), ("q", "[0, 3]")], &fs);
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(t.contains("p = the root of p^2 - 2 = 0"), "{t}");
    assert!(t.contains("q = the root of q^2 - 2*q - 1 = 0"), "{t}");
    // with q ≤ 2 the point is outside: independent, exactly
    let below = spec("t on [0, 1]", &[("p", "[0, 2]"), ("q", "[0, 2]")], &fs);
    let w = independent(&below, None);
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
    assert!(text(&w).contains("exact): none"), "{}", text(&w));
}
