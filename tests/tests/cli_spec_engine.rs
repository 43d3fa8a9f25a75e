//! The certification engine on bases outside the polynomial engine —
//! C-curves, H-curves, exponential, half-angle and square bases (issue 24)
//! — end to end through the command line, each decided both ways.
//! Expected values are derived independently of the project in
//! `examples/independent/README.md`, Part C (cited per test).

use rug::Float;
use trig_e2e::{example, stdout_ok};

/// The verdict and evidence of one claim of a spec file.
fn claim(path: &str, id: &str) -> (String, String) {
    let text = stdout_ok(&["audit", "--spec", path, "--claim", id, "--format", "json"]);
    let json: serde_json::Value = serde_json::from_str(&text).expect("json");
    let c = &json["claims"][0];
    (
        c["verdict"].as_str().unwrap_or_default().to_string(),
        c["evidence"].to_string(),
    )
}

/// The first interval `[lo, hi]` printed after `prefix` in `text`, at 256 bits.
fn enclosure_after(text: &str, prefix: &str) -> (Float, Float) {
    let at = text
        .find(prefix)
        .unwrap_or_else(|| panic!("no {prefix:?} in {text}"));
    let rest = &text[at + prefix.len()..];
    let close = rest.find(']').expect("closing bracket");
    let (lo, hi) = rest[..close].split_once(", ").expect("two ends");
    let parse = |s: &str| Float::with_val(256, Float::parse(s.trim()).expect("a decimal"));
    (parse(lo), parse(hi))
}

#[test]
fn c_bspline_maximal_range_ends_at_the_root_of_tan_alpha_equals_alpha() {
    // README C1: nonnegative on (0, π) (holds), maximal (0, α*] with
    // tan α* = α*, α* = 4.49340945790906417530788092728032…, certified in
    // [4.493409457909064175307880927280, …281]; (0, 2π) fails
    let cbs = example("c-bspline.toml");
    assert_eq!(claim(&cbs, "CBS-nonnegative").0, "holds");
    let (v, e) = claim(&cbs, "CBS-maximal");
    assert_eq!(v, "fails", "{e}");
    // the equation it solves: sin α − α cos α = 0, up to a constant factor
    assert!(e.contains("−2·α·cos(α) + 2·sin(α) = 0"), "{e}");
    assert!(
        e.contains("certified enclosure") && e.contains("not called exact"),
        "{e}"
    );
    let (lo, hi) = enclosure_after(&e, "α ∈ [");
    let star = Float::with_val(
        256,
        Float::parse("4.49340945790906417530788092728032").expect("decimal"),
    );
    assert!(lo <= star && star <= hi, "{lo} {hi}");
    assert!(Float::with_val(256, &hi - &lo) < 1e-20, "{lo} {hi}");
    // never an exact upper end
    let upper = &e[e.find("upper end").expect("upper end")..];
    let upper = &upper[..upper.find("the part inside").expect("inside")];
    assert!(
        !upper.contains("(exact") && !upper.contains("exactly"),
        "{upper}"
    );
    // the witnesses of the gaps on both sides
    assert!(
        e.contains("just inside") && e.contains("just outside"),
        "{e}"
    );
    // the wider range fails with a certified negative value
    assert_eq!(claim(&cbs, "CBS-wide").0, "fails");
}

#[test]
fn every_witness_is_a_real_point() {
    // README C1: CBS-C3 fails, the third-derivative jump never vanishes;
    // its witness used to read `α = 1, cos(alpha) = 0` (not a point)
    let cbs = example("c-bspline.toml");
    let (v, e) = claim(&cbs, "CBS-C3");
    assert_eq!(v, "fails", "{e}");
    assert!(e.contains(r#""name":"α","value":"1/2·π""#), "{e}");
    assert!(!e.contains(r#""name":"cos(alpha)""#), "{e}");
    // README B7 / C5: the plain symmetry of the exponential Bernstein
    // functions fails; at α = 1, t = 1/2 b0 = 0.241175365473302455…, b3(α −
    // t) = 0.053813497921914074…, enclosed (exp(1/2) is not exact)
    let eb = example("exp-bernstein-cubic.toml");
    let (v, e) = claim(&eb, "EB-symmetry");
    assert_eq!(v, "fails", "{e}");
    assert!(e.contains("a real point"), "{e}");
    let (lo, hi) = enclosure_after(&e, "\"unicode\":\"[");
    let b0 = Float::with_val(
        256,
        Float::parse("0.241175365473302455443516123523").expect("d"),
    );
    let b3 = Float::with_val(
        256,
        Float::parse("0.0538134979219140746620198001438").expect("d"),
    );
    assert!(
        (lo <= b0 && b0 <= hi) || (lo <= b3 && b3 <= hi),
        "{lo} {hi}"
    );
}
