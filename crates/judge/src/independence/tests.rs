//! Independence by exact rank, both ways: Bernstein bases of any degree,
//! one, two and three parameters, closed and open ends, half-lines.

use std::path::PathBuf;
use std::time::Instant;

use trig_core::{Family, ParamRange};
use trig_specfile::Spec;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

use super::{RANK, independent};

/// `C(n, i)`.
fn binomial(n: u64, i: u64) -> u64 {
    (0..i).fold(1, |acc, k| acc * (n - k) / (k + 1))
}

/// A spec file of `functions` (name, formula) with `params` (name,
/// range) on `variable`.
pub(super) fn spec(
    variable: &str,
    params: &[(&str, &str)],
    functions: &[(String, String)],
) -> Spec {
    // `t` on a domain: `t on [0, 1]`
    let variable = match variable.split_once(" on ") {
        Some((v, d)) => format!("{v}\"\ndomain = \"{d}"),
        None => variable.to_string(),
    };
    let mut text = format!("id = \"test\"\ncitation = \"test\"\nvariable = \"{variable}\"\n");
    for (name, range) in params {
        text.push_str(&format!(
            "[[parameters]]\nname = \"{name}\"\nrange = \"{range}\"\nsource = \"test\"\n"
        ));
    }
    for (name, formula) in functions {
        text.push_str(&format!(
            "[[functions]]\nname = \"{name}\"\nformula = \"{formula}\"\n"
        ));
    }
    Spec::from_str_named(&text, "test").unwrap_or_else(|e| panic!("{e}"))
}

pub(super) fn fns(formulas: &[&str]) -> Vec<(String, String)> {
    formulas
        .iter()
        .enumerate()
        .map(|(i, f)| (format!("b{i}"), f.to_string()))
        .collect()
}

fn example(name: &str) -> Spec {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    Spec::from_file(&path).unwrap_or_else(|e| panic!("{e}"))
}

pub(super) fn text(v: &Verdict) -> String {
    v.evidence
        .iter()
        .map(|e| e.line())
        .collect::<Vec<_>>()
        .join("\n")
}

fn bernstein(n: u64) -> Spec {
    let f: Vec<(String, String)> = (0..=n)
        .map(|i| {
            (
                format!("b{i}"),
                format!("{}*t^{i}*(1 - t)^{}", binomial(n, i), n - i),
            )
        })
        .collect();
    spec("polynomial", &[], &f)
}

fn sin2_bernstein(n: u64) -> Spec {
    let f: Vec<(String, String)> = (0..=n)
        .map(|i| {
            (
                format!("b{i}"),
                format!("{}*sin(t)^{}*cos(t)^{}", binomial(n, i), 2 * i, 2 * (n - i)),
            )
        })
        .collect();
    spec("angle", &[], &f)
}

#[test]
fn bernstein_bases_of_every_degree_are_independent() {
    for n in [3, 7, 11, 20] {
        let basis = bernstein(n);
        let start = Instant::now();
        let v = independent(&basis, None);
        let took = start.elapsed();
        assert_eq!(v.status, Status::Holds, "degree {n}: {}", text(&v));
        assert_eq!(v.method, RANK);
        assert!(
            text(&v).contains(&format!("rank {}", n + 1)),
            "{}",
            text(&v)
        );
        println!("Bernstein degree {n}: {took:?}");
        assert!(took.as_secs_f64() < 5.0, "degree {n}: {took:?}");
    }
}

#[test]
fn squared_sine_bernstein_bases_are_independent() {
    for n in [6, 10, 20] {
        let basis = sin2_bernstein(n);
        let start = Instant::now();
        let v = independent(&basis, None);
        let took = start.elapsed();
        assert_eq!(v.status, Status::Holds, "n = {n}: {}", text(&v));
        println!("sin² Bernstein n = {n}: {took:?}");
        assert!(took.as_secs_f64() < 5.0, "n = {n}: {took:?}");
    }
}

#[test]
fn a_short_rank_is_dependent_for_every_value_with_the_relation() {
    let basis = spec(
        "polynomial",
        &[("m", "[0, 1]")],
        &fns(&["t", "2*m*t + t", "1"]),
    );
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    assert!(
        text(&v).contains("for every parameter value"),
        "{}",
        text(&v)
    );
    // (2m + 1)·b0 − b1 ≡ 0
    assert!(text(&v).contains("b1 ≡ 0"), "{}", text(&v));
}

#[test]
fn one_parameter_dependent_at_a_rational_interior_value() {
    // at λ = 1/2: b2 = t = b1
    let basis = spec(
        "polynomial",
        &[("lambda", "[-1, 2]")],
        &fns(&["1 - t", "t", "(2*lambda - 1)*t^2 + t"]),
    );
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(t.contains("lambda = 1/2, inside the range"), "{t}");
    assert!(t.contains("b1 − b2 ≡ 0"), "{t}");
    // away from 1/2 it holds, exactly (gcd of the minors 2λ − 1)
    let r = ParamRange::parse("[1, 2]").unwrap();
    let w = independent(&basis, Some(&r));
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
    assert!(text(&w).contains("no root in the range"), "{}", text(&w));
}

#[test]
fn a_rank_drop_at_a_closed_end_refutes_at_an_open_end_it_does_not() {
    let basis = spec(
        "polynomial",
        &[("lambda", "[0, 1]")],
        &fns(&["1 - t", "t", "lambda*t^2"]),
    );
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(t.contains("lambda = 0, a closed end"), "{t}");
    assert!(t.contains("b2 ≡ 0"), "{t}");
    let open = ParamRange::parse("(0, 1]").unwrap();
    assert_eq!(independent(&basis, Some(&open)).status, Status::Holds);
    // half-lines: [0, ∞) fails at 0, (0, ∞) holds
    let half = ParamRange::parse("[0, inf)").unwrap();
    assert_eq!(independent(&basis, Some(&half)).status, Status::Fails);
    let open_half = ParamRange::parse("(0, inf)").unwrap();
    let w = independent(&basis, Some(&open_half));
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
}

#[test]
fn the_rational_quadratic_is_dependent_at_weight_zero_only() {
    let basis = example("rational-quadratic.toml");
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    assert!(text(&v).contains("w = 0"), "{}", text(&v));
    let r = ParamRange::parse("(0, inf)").unwrap();
    assert_eq!(independent(&basis, Some(&r)).status, Status::Holds);
}

#[test]
fn the_trigonometric_bernstein_quartic_is_dependent_exactly_at_pi() {
    // (0, π]: cos(α/2) = 0 at α = π, where b1 ≡ b3 ≡ 0
    let basis = example("trig-bernstein-quartic.toml");
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(t.contains("α = π, a closed end"), "{t}");
    assert!(t.contains("b1 ≡ 0") || t.contains("b3 ≡ 0"), "{t}");
    let open = ParamRange::parse("(0, pi)").unwrap();
    let w = independent(&basis, Some(&open));
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
}

#[test]
fn the_c_bspline_is_independent_on_its_open_range() {
    let v = independent(&example("c-bspline.toml"), None);
    assert_eq!(v.status, Status::Holds, "{}", text(&v));
    assert!(text(&v).contains("sin(alpha)"), "{}", text(&v));
}

#[test]
fn two_parameters_fail_at_the_corner_where_a_function_vanishes() {
    // Bashir et al.: b1 = (α + 1)·… + (β + 1)·… vanishes at α = β = −1 only
    let basis = example("bashir-quadratic.toml");
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(t.contains("α = -1, β = -1"), "{t}");
    assert!(t.contains("b1 ≡ 0"), "{t}");
}

#[test]
fn two_parameters_hold_away_from_the_corner() {
    let basis = spec(
        "angle",
        &[("alpha", "[-1/2, 1]"), ("beta", "[-1, 1]")],
        &fns(&[
            "(1 - sin(t))*(1 - alpha*sin(t))",
            "alpha*sin(t)*(1 - sin(t)) + beta*cos(t)*(1 - cos(t)) + sin(t) + cos(t) - 1",
            "(1 - cos(t))*(1 - beta*cos(t))",
        ]),
    );
    let v = independent(&basis, None);
    assert_eq!(v.status, Status::Holds, "{}", text(&v));
}

#[test]
fn three_parameters_are_decided_both_ways() {
    let ranges = [("a", "[0, 1]"), ("b", "[0, 1]"), ("g", "[0, 1]")];
    let holds = spec(
        "polynomial",
        &ranges,
        &fns(&[
            "(1 - t)^2",
            "2*t*(1 - t)*(1 + a^2 + b*g)",
            "t^2 + a*b*g*t*(1 - t)",
        ]),
    );
    let v = independent(&holds, None);
    assert_eq!(v.status, Status::Holds, "{}", text(&v));
    let fails = spec(
        "polynomial",
        &ranges,
        &fns(&["(1 - t)^2", "2*t*(1 - t)", "(a + b + g)*t^2"]),
    );
    let w = independent(&fails, None);
    assert_eq!(w.status, Status::Fails, "{}", text(&w));
    let t = text(&w);
    assert!(t.contains("a = 0, b = 0, g = 0"), "{t}");
    assert!(t.contains("b2 ≡ 0"), "{t}");
}

#[test]
fn the_catalog_bases_agree_with_their_wronskians() {
    for f in [Family::ThesisCubic, Family::Seed002Quartic] {
        assert_eq!(independent(&f, None).status, Status::Holds, "{f:?}");
        assert_eq!(super::by_wronskian(&f, None).status, Status::Holds, "{f:?}");
    }
}

#[test]
fn other_atoms_fall_back_to_the_wronskian_and_say_why_beyond_it() {
    // exp: the Wronskian, which does not know E either
    let v = independent(&example("exp-bernstein-cubic.toml"), None);
    assert_eq!(v.status, Status::NotCheckable);
    assert!(text(&v).contains("written in E"), "{}", text(&v));
    let f: Vec<(String, String)> = (0..8)
        .map(|i| (format!("b{i}"), format!("exp({i}*t)")))
        .collect();
    let w = independent(&spec("t on [0, alpha]", &[("alpha", "(0, 1]")], &f), None);
    assert_eq!(w.status, Status::NotCheckable);
    assert!(
        text(&w).contains("not known to be independent"),
        "{}",
        text(&w)
    );
}

#[test]
fn one_parameter_at_an_irrational_value_is_decided_exactly() {
    // at λ = √2: b2 = t = b1
    let fails = spec(
        "polynomial",
        &[("lambda", "[0, 2]")],
        &fns(&["1 - t", "t", "(lambda^2 - 2)*t^2 + t"]),
    );
    let v = independent(&fails, None);
    assert_eq!(v.status, Status::Fails, "{}", text(&v));
    let t = text(&v);
    assert!(t.contains("lambda^2 - 2"), "{t}");
    assert!(t.contains("b1 − b2 ≡ 0"), "{t}");
    // the pivot minor vanishes at √2, the rank there is full all the same
    let holds = spec(
        "polynomial",
        &[("lambda", "[0, 2]")],
        &fns(&["1", "(lambda^2 - 2)*t + t^2", "t^2 + t^3"]),
    );
    let w = independent(&holds, None);
    assert_eq!(w.status, Status::Holds, "{}", text(&w));
    println!("{}\n{}", text(&v), text(&w));
}
