//! Every printed witness names a real point: the atoms it shows (`s = sin θ`,
//! `c = cos θ`, `z = tan(θ/2)`) agree with one another and with the
//! variable, and no atom of a parameter or of the variable (`cos(alpha)`,
//! `E = exp(…)`, `sqrt(2)`) is printed as a coordinate of its own — such a
//! point (`α = 1, cos(alpha) = 0`) is no point at all. Scanned: the audit
//! report of the five documents and the reports of the issue-24 spec files
//! (algebraic-trigonometric, hyperbolic, exponential, half-angle bases and a
//! basis of squares), in JSON.

use rug::Rational;
use trig_e2e::{example, stdout_ok};

/// The spec files of issue 24 (bases with parameters inside `sin`, `cos`,
/// `sinh`, `cosh`, `exp` and half angles).
const ISSUE_24: [&str; 11] = [
    "c-bspline.toml",
    "c-bezier-quadratic.toml",
    "c-bezier-cubic.toml",
    "c-bezier-cubic-2pi.toml",
    "h-bezier-quadratic.toml",
    "h-bezier-cubic.toml",
    "trig-bernstein-quartic.toml",
    "exp-bernstein-cubic.toml",
    "exp-bernstein-maximal.toml",
    "half-angle-lambda.toml",
    "squares-han.toml",
];

/// A printed coordinate's value: `p/q`, or `p/q·π` as `(q₀, q_π)`
/// (`None`: another form, not compared).
fn value(text: &str) -> Option<(Rational, Rational)> {
    let text = text.replace('−', "-");
    let rational = |s: &str| -> Option<Rational> {
        match s {
            "" => Some(Rational::from(1)),
            "-" => Some(Rational::from(-1)),
            _ => s.parse().ok(),
        }
    };
    match text.strip_suffix('π') {
        Some(f) => Some((Rational::new(), rational(f.trim_end_matches('·'))?)),
        None => Some((rational(&text)?, Rational::new())),
    }
}

/// Why the witness point `point` (name, printed value) is no real point,
/// if it is not: an atom printed as a coordinate, `s² + c² ≠ 1`, `s`, `c`
/// other than the sine and cosine of `2·atan z`, or `s`, `c` beside the
/// variable `t` or `u` with values that are not its sine and cosine
/// (`θ = t`, `t/2` or `πu/2`; compared in f64 to 10⁻⁹).
fn inconsistency(point: &[(String, String)]) -> Option<String> {
    if let Some((n, v)) = point
        .iter()
        .find(|(n, _)| n.contains('(') || n.as_str() == "E")
    {
        return Some(format!("the atom {n} printed as a coordinate ({n} = {v})"));
    }
    let exact = |name: &str| {
        point
            .iter()
            .find(|(n, _)| n == name)
            .and_then(|(_, v)| value(v))
            .filter(|(_, pi)| *pi == 0)
            .map(|(q, _)| q)
    };
    let (s, c, z) = (exact("s"), exact("c"), exact("z"));
    if let (Some(s), Some(c)) = (&s, &c) {
        if Rational::from(s * s) + Rational::from(c * c) != 1 {
            return Some(format!("s² + c² ≠ 1 at s = {s}, c = {c}"));
        }
    }
    if let Some(z) = &z {
        let w = Rational::from(z * z) + 1u32;
        let (sz, cz) = (
            Rational::from(z * 2u32) / &w,
            (Rational::from(1u32) - Rational::from(z * z)) / &w,
        );
        if s.as_ref().is_some_and(|s| *s != sz) || c.as_ref().is_some_and(|c| *c != cz) {
            return Some(format!("s, c are not sin, cos of 2·atan({z})"));
        }
    }
    let variable = ["t", "u"].iter().find_map(|v| {
        point
            .iter()
            .find(|(n, _)| n == v)
            .and_then(|(n, text)| value(text).map(|x| (n.clone(), x)))
    });
    if let (Some((name, (q, pi))), true) = (variable, s.is_some() || c.is_some()) {
        let x = q.to_f64() + pi.to_f64() * std::f64::consts::PI;
        let angles = if name == "u" {
            vec![x * std::f64::consts::FRAC_PI_2]
        } else {
            vec![x, x / 2.0]
        };
        let near =
            |a: &Option<Rational>, b: f64| a.as_ref().is_none_or(|a| (a.to_f64() - b).abs() < 1e-9);
        if !angles
            .iter()
            .any(|th| near(&s, th.sin()) && near(&c, th.cos()))
        {
            return Some(format!("s, c are not the sine and cosine of θ({name})"));
        }
    }
    None
}

/// The (name, value) points of every witness in a JSON report, with where
/// each was found.
fn witness_points(report: &serde_json::Value) -> Vec<(String, Vec<(String, String)>)> {
    fn walk(v: &serde_json::Value, path: String, out: &mut Vec<(String, Vec<(String, String)>)>) {
        match v {
            serde_json::Value::Object(map) => {
                for (k, x) in map {
                    if k == "witness" {
                        if let Some(points) = x["point"].as_array() {
                            let point = points
                                .iter()
                                .map(|p| {
                                    let text = |f: &str| p[f].as_str().unwrap_or("").to_string();
                                    (text("name"), text("value"))
                                })
                                .collect();
                            out.push((path.clone(), point));
                        }
                    }
                    walk(x, format!("{path}/{k}"), out);
                }
            }
            serde_json::Value::Array(items) => {
                for (i, x) in items.iter().enumerate() {
                    walk(x, format!("{path}[{i}]"), out);
                }
            }
            _ => {}
        }
    }
    let mut out = Vec::new();
    walk(report, String::new(), &mut out);
    out
}

#[test]
fn the_checker_sees_points_that_are_no_points() {
    let point = |pairs: &[(&str, &str)]| -> Vec<(String, String)> {
        pairs
            .iter()
            .map(|(n, v)| (n.to_string(), v.to_string()))
            .collect()
    };
    for bad in [
        point(&[("α", "1"), ("cos(α)", "0")]),
        point(&[("sin(α/2)", "1"), ("cos(α/2)", "2")]),
        point(&[("s", "1"), ("c", "1")]),
        point(&[("z", "1/2"), ("s", "1"), ("c", "0")]),
        point(&[("t", "1/3"), ("s", "3/5"), ("c", "4/5")]),
        point(&[("E", "2"), ("t", "0")]),
    ] {
        assert!(inconsistency(&bad).is_some(), "{bad:?}");
    }
    for good in [
        point(&[("α", "1/2·π"), ("t", "1/3")]),
        point(&[("m", "1"), ("z", "1"), ("s", "1"), ("c", "0")]),
        point(&[("s", "3/5"), ("c", "4/5"), ("P₀", "0")]),
        point(&[("t", "0"), ("s", "0"), ("c", "1")]),
        point(&[("u", "1"), ("s", "1"), ("c", "0")]),
    ] {
        assert_eq!(inconsistency(&good), None, "{good:?}");
    }
}

#[test]
fn every_witness_of_the_audit_and_the_issue_24_files_is_a_real_point() {
    let mut reports = vec![("the five documents".to_string(), vec!["audit".to_string()])];
    for file in ISSUE_24 {
        reports.push((
            file.to_string(),
            vec!["audit".into(), "--spec".into(), example(file)],
        ));
    }
    let mut seen = 0;
    let mut bad = Vec::new();
    for (what, mut args) in reports {
        args.extend(["--format".into(), "json".into()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let report: serde_json::Value =
            serde_json::from_str(&stdout_ok(&args)).expect("a JSON report");
        for (path, point) in witness_points(&report) {
            seen += 1;
            if let Some(why) = inconsistency(&point) {
                bad.push(format!("{what} {path}: {why}"));
            }
        }
    }
    assert!(seen > 100, "only {seen} witnesses scanned");
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
