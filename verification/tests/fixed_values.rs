//! Parameter values a claim fixes (`at = { lambda = "0" }`, a one-point
//! `range = "[0, 0]"`, `ranges = { w = "[1, 1]" }`) are substituted before
//! deciding, for every kind of check: each kind is tested both ways, at a
//! value where the substituted formulas hold and at one where they fail.
//! The expected values are derived by hand below (and independently in
//! examples/independent/issue38-fixed-values.py).

use std::path::PathBuf;

use crate::common::example_with;
use trig_specfile::Spec;
use trig_verification::{Status, spec_audit};

/// The verdict of the one claim `body` (the fields after `check`) added to
/// the example `name`.
fn decide(name: &str, check: &str, body: &str) -> trig_verification::Verdict {
    let claim = format!(
        "[[claims]]\nid = \"FIXED\"\nsource = \"test\"\nstatement = \"test\"\ncheck = \"{check}\"\n{body}\n"
    );
    let spec = example_with(name, &claim);
    spec_audit::decide(&spec, spec.claims.last().expect("the claim"))
}

fn assert_status(v: &trig_verification::Verdict, status: Status, contains: &str) {
    assert_eq!(v.status, status, "{v:?}");
    assert!(format!("{v:?}").contains(contains), "{contains}: {v:?}");
}

const QUARTER: &str = "values = [\"P0 = (1, 0)\", \"P1 = (1, 1)\", \"P2 = (0, 1)\"]";

/// Han's quadratic with the polygon (1, 0), (1, 1), (0, 1): the curve is
/// X = b0 + b1 = 1 − b2, Y = b1 + b2 = 1 − b0; at λ = 0, b0 = 1 − sin t and
/// b2 = 1 − cos t, so (X, Y) = (cos t, sin t), the unit circle; the residual
/// of X² + Y² − 1 at (sin t, cos t) = (4/5, 3/5) is 4λ(13λ + 85)/625.
#[test]
fn a_conic_at_a_fixed_value_is_decided_at_that_value() {
    let circle = format!("{QUARTER}\nvalue = \"X^2 + Y^2 - 1\"");
    for fix in [
        "range = \"[0, 0]\"",
        "at = { lambda = \"0\" }",
        "at = { \"λ\" = \"0\" }",
    ] {
        let v = decide("han-quadratic", "conic", &format!("{circle}\n{fix}"));
        assert_status(&v, Status::Holds, "decided at λ = 0");
    }
    // λ = 1: at t = π/4 (s = c = √2/2) X = Y = 1 − (1 − √2/2)², so
    // X² + Y² − 1 = 7/2 − 2√2
    let v = decide(
        "han-quadratic",
        "conic",
        &format!("{circle}\nat = {{ lambda = \"1\" }}"),
    );
    assert_status(&v, Status::Fails, "−2·sqrt(2) + 7/2");
    // unfixed, the claim is over the whole range and fails
    let v = decide("han-quadratic", "conic", &circle);
    assert_eq!(v.status, Status::Fails, "{v:?}");
}

/// The rational quadratic with weight w and the same polygon is the unit
/// quarter circle exactly for w = √2/2 (cos of half the arc's angle), and
/// for w = 1 the parabola (X − Y)² + 2(X + Y) − 3 = 0 (X = 1 − t²,
/// Y = 2t − t²).
#[test]
fn an_algebraic_fixed_value_is_substituted_exactly() {
    let circle = format!("{QUARTER}\nvalue = \"X^2 + Y^2 - 1\"");
    let parabola = format!("{QUARTER}\nvalue = \"(X - Y)^2 + 2*(X + Y) - 3\"");
    let at = |w: &str| format!("at = {{ w = \"{w}\" }}");
    let v = decide(
        "rational-quadratic",
        "conic",
        &format!("{circle}\n{}", at("sqrt(2)/2")),
    );
    assert_status(&v, Status::Holds, "w = sqrt(2)/2");
    let v = decide(
        "rational-quadratic",
        "conic",
        &format!("{circle}\n{}", at("1")),
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let v = decide(
        "rational-quadratic",
        "conic",
        &format!("{parabola}\nranges = {{ w = \"[1, 1]\" }}"),
    );
    assert_status(&v, Status::Holds, "w = 1");
    let v = decide(
        "rational-quadratic",
        "conic",
        &format!("{parabola}\n{}", at("sqrt(2)/2")),
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
}

/// Han's quadratic: b1 = (1 + λ)(sin t + cos t − 1) ≡ 0 at λ = −1, so the
/// functions are dependent there and independent at λ = 0.
#[test]
fn independence_at_a_fixed_value() {
    let v = decide("han-quadratic", "independent", "at = { lambda = \"-1\" }");
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let v = decide("han-quadratic", "independent", "at = { lambda = \"0\" }");
    assert_eq!(v.status, Status::Holds, "{v:?}");
}

/// The squared Han basis (examples/squares-han.toml) is nonnegative on
/// [0, π/2] exactly for λ ∈ [−1, 2 + 2√2]: it holds at λ = 4 and fails at
/// λ = 5 (b1 = −70704/707281 at (sin t, cos t) = (20/29, 21/29)); its
/// first derivative at 0 is r'(0) = 2(1 + λ)(P1 − P0), its second
/// b0''(0) = 2(λ² + 4λ + 1): 12 at λ = 1, 2 at λ = 0.
#[test]
fn inequalities_and_printed_values_at_a_fixed_value() {
    let v = decide("squares-han", "nonnegative", "range = \"[4, 4]\"");
    assert_status(&v, Status::Holds, "decided at λ = 4");
    let v = decide("squares-han", "nonnegative", "at = { lambda = \"5\" }");
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let v = decide("squares-han", "convex-hull", "at = { lambda = \"4\" }");
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = decide("squares-han", "convex-hull", "at = { lambda = \"5\" }");
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let tangent = "end = \"start\"\norder = 1\nvalue = \"4*(P1 - P0)\"";
    let v = decide(
        "squares-han",
        "curve-derivative",
        &format!("{tangent}\nat = {{ lambda = \"1\" }}"),
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = decide(
        "squares-han",
        "curve-derivative",
        &format!("{tangent}\nat = {{ lambda = \"0\" }}"),
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let second =
        "end = \"start\"\norder = 2\nvalues = [\"b0 = 2*(lambda^2 + 4*lambda + 1)\", \"b1 = -12\"]";
    let v = decide(
        "squares-han",
        "endpoint-derivatives",
        &format!("{second}\nat = {{ lambda = \"1\" }}"),
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = decide(
        "squares-han",
        "endpoint-derivatives",
        &format!("{second}\nat = {{ lambda = \"0\" }}"),
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
    let values = "end = \"end\"\nvalues = [\"b2 = lambda\"]";
    let v = decide(
        "squares-han",
        "endpoint-values",
        &format!("{values}\nat = {{ lambda = \"1\" }}"),
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = decide(
        "squares-han",
        "endpoint-values",
        &format!("{values}\nat = {{ lambda = \"1/2\" }}"),
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
}

/// Partition of unity of `1 − t, λt` holds only at λ = 1.
#[test]
fn identities_at_a_fixed_value() {
    let spec = |fix: &str| {
        Spec::from_str_named(
            &format!(
                "id = \"lin\"\ncitation = \"test\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"lambda\"\nrange = \"[0, 2]\"\n[[functions]]\nname = \"b0\"\nformula = \"1 - t\"\n[[functions]]\nname = \"b1\"\nformula = \"lambda*t\"\n[[claims]]\nid = \"U\"\nsource = \"test\"\nstatement = \"unity\"\ncheck = \"unity\"\n{fix}\n"
            ),
            "lin",
        )
        .unwrap_or_else(|e| panic!("{e}"))
    };
    let status = |fix: &str| {
        let s = spec(fix);
        spec_audit::decide(&s, &s.claims[0]).status
    };
    assert_eq!(status("at = { lambda = \"1\" }"), Status::Holds);
    assert_eq!(status("at = { lambda = \"2\" }"), Status::Fails);
    assert_eq!(status(""), Status::Fails);
}

/// Total positivity of the squared Han basis: the certificate covers
/// [−1, 1], so λ = 1/2 holds; at λ = 4 (nonnegative) it is refuted by a
/// negative collocation minor (examples/independent/, Part D).
#[test]
fn total_positivity_at_a_fixed_value() {
    let v = decide(
        "squares-han",
        "total-positivity",
        "at = { lambda = \"1/2\" }",
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = decide("squares-han", "total-positivity", "at = { lambda = \"4\" }");
    assert_eq!(v.status, Status::Fails, "{v:?}");
}

/// A parameter-dependent domain `[0, α]` takes the fixed value: the
/// quadratic C-Bézier basis at α = π/2 traces the quarter circle with the
/// points (1, 0), (1, 1), (0, 1) — and with α = π/3 the same points are
/// not on the circle.
#[test]
fn a_fixed_value_enters_the_domain_and_the_parameter_atoms() {
    let circle = format!("{QUARTER}\nvalue = \"X^2 + Y^2 - 1\"");
    let v = decide(
        "c-bezier-quadratic",
        "conic",
        &format!("{circle}\nat = {{ alpha = \"pi/2\" }}"),
    );
    assert_status(&v, Status::Holds, "α = pi/2");
    let v = decide(
        "c-bezier-quadratic",
        "conic",
        &format!("{circle}\nat = {{ alpha = \"pi/3\" }}"),
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
}

/// What cannot be fixed is a typed error or a reasoned `not-checkable`,
/// never a panic: a value that is no number, a parameter fixed twice, a
/// range on a basis with two parameters, varying a fixed parameter, and a
/// value where the formulas divide by zero.
#[test]
fn fixed_values_that_cannot_be_taken() {
    let text = |name: &str| {
        std::fs::read_to_string(
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("../examples/{name}.toml")),
        )
        .expect("example")
    };
    let read = |name: &str, body: &str| {
        Spec::from_str_named(
            &format!(
                "{}\n[[claims]]\nid = \"F\"\nsource = \"t\"\nstatement = \"t\"\n{body}\n",
                text(name)
            ),
            name,
        )
    };
    let err = |name: &str, body: &str| read(name, body).expect_err(body).to_string();
    assert!(
        err(
            "han-quadratic",
            "check = \"unity\"\nat = { lambda = \"t\" }"
        )
        .contains("a fixed value is a number")
    );
    assert!(
        err("han-quadratic", "check = \"unity\"\nat = { kappa = \"1\" }")
            .contains("not a parameter")
    );
    assert!(
        err(
            "han-quadratic",
            "check = \"unity\"\nat = { lambda = \"0\" }\nrange = \"[1, 1]\""
        )
        .contains("fixed twice")
    );
    assert!(
        err(
            "han-ma-huang-cubic",
            "check = \"unity\"\nrange = \"[0, 1]\""
        )
        .contains("ranges = {")
    );
    assert!(
        err(
            "han-quadratic",
            "check = \"shape-effect\"\nparameter = \"lambda\"\ndirection = \"towards-polygon\"\nat = { lambda = \"0\" }"
        )
        .contains("also fixes")
    );
    // `maximal` is decided for nonnegativity, the convex hull,
    // independence and total positivity: elsewhere it is refused, never
    // silently ignored
    assert!(
        err("han-quadratic", "check = \"unity\"\nmaximal = true")
            .contains("not decided for `unity`")
    );
    assert!(read("han-quadratic", "check = \"independent\"\nmaximal = true").is_ok());
    assert!(
        err(
            "han-quadratic",
            "check = \"nonnegative\"\nmaximal = true\nrange = \"[1, 1]\""
        )
        .contains("no range is left to be maximal")
    );
    let spec = Spec::from_str_named(
        "id = \"pole\"\ncitation = \"test\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"m\"\nrange = \"[0, 1]\"\n[[functions]]\nname = \"b0\"\nformula = \"(1 - t)/(m + 2)\"\n[[functions]]\nname = \"b1\"\nformula = \"1 - b0\"\n[[claims]]\nid = \"U\"\nsource = \"t\"\nstatement = \"t\"\ncheck = \"unity\"\nat = { m = \"-2\" }\n",
        "pole",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let v = spec_audit::decide(&spec, &spec.claims[0]);
    assert_status(&v, Status::NotCheckable, "vanishes there");
}

/// With several parameters a claim narrows the box by `ranges`: Han, Ma
/// & Huang's cubic decided on a narrower box than declared, and with one
/// parameter fixed.
#[test]
fn ranges_of_several_parameters() {
    let v = decide(
        "han-ma-huang-cubic",
        "nonnegative",
        "ranges = { lambda = \"[0, 1]\", mu = \"[0, 1/2]\" }",
    );
    assert_status(&v, Status::Holds, "μ ∈ [0, 1/2]");
    let v = decide(
        "han-ma-huang-cubic",
        "unity",
        "ranges = { mu = \"[1, 1]\" }",
    );
    assert_status(&v, Status::Holds, "μ = 1");
}

/// A line of the parameter plane, as papers print it (`μ = λ`,
/// `β = 3 − 3α`): the value is an expression in the other parameters,
/// substituted before deciding. Han, Ma & Huang's cubic with the polygon
/// (0, 0), (1/2, 0), (1, 1), (1, 1) traces the parabola Y = X² exactly
/// for λ = 0 and every μ (Y = sin²t, X = sin t); on the diagonal μ = λ only
/// at λ = 0 (examples/independent/issue38.md: at (1, any μ) and
/// (sin t, cos t) = (3/5, 4/5) the residual is −936/15625). On the
/// diagonal of [−2, 1]² the basis is nonnegative; on the line μ = λ − 2 it
/// is not (μ < −2 there for λ < 0).
#[test]
fn lines_of_the_parameter_plane() {
    let parabola = "values = [\"P0 = (0, 0)\", \"P1 = (1/2, 0)\", \"P2 = (1, 1)\", \"P3 = (1, 1)\"]\nvalue = \"Y - X^2\"";
    let v = decide(
        "han-ma-huang-cubic",
        "conic",
        &format!("{parabola}\nat = {{ lambda = \"0\" }}"),
    );
    assert_status(&v, Status::Holds, "decided at λ = 0");
    let v = decide(
        "han-ma-huang-cubic",
        "conic",
        &format!("{parabola}\nat = {{ mu = \"lambda\" }}"),
    );
    assert_status(&v, Status::Fails, "decided at μ = lambda");
    let v = decide(
        "han-ma-huang-cubic",
        "nonnegative",
        "at = { mu = \"lambda\" }",
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = decide(
        "han-ma-huang-cubic",
        "nonnegative",
        "at = { mu = \"lambda - 2\" }",
    );
    assert_eq!(v.status, Status::Fails, "{v:?}");
    // fixed one after the other: λ = 0, then μ = 1 − λ = 1
    let v = decide(
        "han-ma-huang-cubic",
        "conic",
        &format!("{parabola}\nat = {{ lambda = \"0\", mu = \"1 - lambda\" }}"),
    );
    assert_status(&v, Status::Holds, "μ = 1 - lambda");
    // values that refer to each other in a circle fix nothing
    let v = decide(
        "han-ma-huang-cubic",
        "unity",
        "at = { lambda = \"mu\", mu = \"lambda\" }",
    );
    assert_status(&v, Status::NotCheckable, "in a circle");
}

/// A join of two segments with their own parameters (`different = true`):
/// fixing `λ` fixes both segments' copies `λ1`, `λ2`. Han, Ma & Huang's C¹
/// condition `Q1 = P3 + (μ1 + 2)/(λ2 + 2)·(P3 − P2)` (singular at
/// λ2 = −2 on the closed box) at λ = 0 is `Q1 = P3 + (μ1 + 2)/2·(P3 − P2)`;
/// at λ = μ = 0 it is `Q1 = 2P3 − P2`, and `Q1 = 3P3 − 2P2` is wrong.
#[test]
fn a_join_of_segments_with_their_own_parameters_at_a_fixed_value() {
    let join = |q1: &str, at: &str| {
        decide(
            "han-ma-huang-cubic",
            "join",
            &format!(
                "join = \"C1\"\nwrt = \"t\"\ndifferent = true\nconditions = [\"Q0 = P3\", \"Q1 = {q1}\"]\nat = {{ {at} }}"
            ),
        )
    };
    let v = join("P3 + (mu1 + 2)/(lambda2 + 2)*(P3 - P2)", "lambda = \"0\"");
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = join("2*P3 - P2", "lambda = \"0\", mu = \"0\"");
    assert_eq!(v.status, Status::Holds, "{v:?}");
    let v = join("3*P3 - 2*P2", "lambda = \"0\", mu = \"0\"");
    assert_eq!(v.status, Status::Fails, "{v:?}");
}

/// Fixing `m` leaves a parameter `m1` alone (only a join of segments with
/// their own parameters has copies `m1`, `m2`): `b1 = m1·t` sums to 1 with
/// `b0 = 1 − t` at m1 = 1, whatever m is fixed to.
#[test]
fn fixing_a_parameter_leaves_one_with_a_longer_name_alone() {
    let spec = Spec::from_str_named(
        "id = \"names\"\ncitation = \"test\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"m\"\nrange = \"[0, 2]\"\n[[parameters]]\nname = \"m1\"\nrange = \"[0, 2]\"\n[[functions]]\nname = \"b0\"\nformula = \"1 - t + (m - 1)*0\"\n[[functions]]\nname = \"b1\"\nformula = \"m1*t\"\n[[claims]]\nid = \"U\"\nsource = \"t\"\nstatement = \"t\"\ncheck = \"unity\"\nat = { m = \"1\" }\n[[claims]]\nid = \"U1\"\nsource = \"t\"\nstatement = \"t\"\ncheck = \"unity\"\nat = { m = \"1\", m1 = \"1\" }\n",
        "names",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        spec_audit::decide(&spec, &spec.claims[0]).status,
        Status::Fails
    );
    assert_eq!(
        spec_audit::decide(&spec, &spec.claims[1]).status,
        Status::Holds
    );
}

/// A claim's own box that leaves out the pole of a printed join formula
/// decides the formula where it is defined: Han, Ma & Huang's C¹ condition
/// divides by λ2 + 2, which vanishes only at λ = −2, outside [0, 1]. On the
/// printed range [−2, 1] it holds too, λ2 = −2 named as an exceptional value
/// (the derived formula is singular there as well).
#[test]
fn a_box_without_the_pole_of_a_printed_formula() {
    let claim = "join = \"C1\"\nwrt = \"t\"\ndifferent = true\nconditions = [\"Q0 = P3\", \"Q1 = P3 + (mu1 + 2)/(lambda2 + 2)*(P3 - P2)\"]";
    let exceptional = |v: &trig_verdict::Verdict| {
        v.evidence
            .iter()
            .any(|e| e.line().contains("exceptional values"))
    };
    let v = decide("han-ma-huang-cubic", "join", claim);
    assert_eq!(v.status, Status::Holds, "{v:?}");
    assert!(exceptional(&v), "{v:?}");
    let v = decide(
        "han-ma-huang-cubic",
        "join",
        &format!("{claim}\nranges = {{ lambda = \"[0, 1]\" }}"),
    );
    assert_eq!(v.status, Status::Holds, "{v:?}");
    assert!(!exceptional(&v), "{v:?}");
}

/// A conic claim for some, or for no, value of the parameter
/// (`for = "some value"`, `"no value"`), decided exactly from the common
/// zeros of the residual's coefficients (examples/independent/issue38.md):
/// Han's quadratic with the polygon (1, 0), (1, 1), (0, 1) is on the unit
/// circle exactly at λ = 0 and on the line X + Y = 1 exactly at λ = −1; the
/// rational quadratic is the unit circle exactly at w = √2/2, irrational;
/// a residual in the sine of a parameter (the C-Bézier quadratic) is
/// `not-checkable` with the reason.
#[test]
fn conics_for_some_value_and_for_no_value() {
    let circle = format!("{QUARTER}\nvalue = \"X^2 + Y^2 - 1\"");
    let line = format!("{QUARTER}\nvalue = \"X + Y - 1\"");
    let decide_for = |name: &str, conic: &str, quantifier: &str| {
        decide(name, "conic", &format!("{conic}\nfor = \"{quantifier}\""))
    };
    let v = decide_for("han-quadratic", &circle, "some value");
    assert_status(&v, Status::Holds, "exactly for λ = 0 in the range");
    let v = decide_for("han-quadratic", &circle, "no value");
    assert_status(&v, Status::Fails, "exactly for λ = 0 in the range");
    let v = decide_for("han-quadratic", &line, "some value");
    assert_status(&v, Status::Holds, "exactly for λ = -1 in the range");
    // away from −1 the line is never reached
    let v = decide(
        "han-quadratic",
        "conic",
        &format!("{line}\nfor = \"no value\"\nrange = \"[0, 1]\""),
    );
    assert_status(&v, Status::Holds, "for no parameter value in the range");
    let v = decide_for("rational-quadratic", &circle, "some value");
    assert_status(
        &v,
        Status::Holds,
        "the root of 2*w^2 - 1 = 0 in [0.707106781186, 0.707106781187] (minimal polynomial)",
    );
    let v = decide_for("c-bezier-quadratic", &circle, "no value");
    assert_status(&v, Status::NotCheckable, "`cos(alpha)`");
}

/// A value with π where the parameter is a coefficient (Han's quadratic at
/// λ = π/3 and π/4) leaves π in the formulas: the interval engine decides
/// (b0 = (1 − sin t)(1 − λ sin t) < 0 near t = π/2 exactly when λ > 1).
#[test]
fn pi_as_a_coefficient_goes_to_the_interval_engine() {
    let v = decide("han-quadratic", "nonnegative", "at = { lambda = \"pi/3\" }");
    assert_status(&v, Status::Fails, "the interval engine decides");
    let v = decide("han-quadratic", "nonnegative", "at = { lambda = \"pi/4\" }");
    assert_status(&v, Status::Holds, "the interval engine decides");
}
