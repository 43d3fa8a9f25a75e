//! End-to-end tests of `trig-audit list` and `trig-audit eval`.

use trig_e2e::{FAMILIES, assert_errors, error_line, example, run, run_with_input, stdout_ok};

#[test]
fn list_shows_every_catalog_entry_with_citations() {
    let out = stdout_ok(&["list"]);
    for id in FAMILIES.iter().chain(&["seed000-nonuniform", "seed003"]) {
        assert!(out.lines().any(|l| l == *id), "missing {id}");
    }
    assert!(out.contains("seed 001 (thesis), (3.7)"));
    assert!(out.contains("no formulas in our copy"));
    let json: serde_json::Value = serde_json::from_str(&stdout_ok(&["list", "--format", "json"]))
        .expect("list --format json is JSON");
    assert_eq!(json.as_array().map(Vec::len), Some(15));
}

#[test]
fn eval_at_256_bits_prints_mpfr_digits_not_f64_digits() {
    let out = stdout_ok(&[
        "eval",
        "thesis-cubic",
        "--param",
        "m=0.6",
        "--at",
        "0.25",
        "--prec",
        "256",
    ]);
    // b3(1/4; 3/5) = (1−c)²(1−3c/5), c = cos(π/8); digits from an independent
    // evaluation with `bc -l` at scale 60:
    // .002582370291014204890701073050569838390747138200367801381055
    let b3 = out
        .lines()
        .find(|l| l.starts_with("b3 = "))
        .expect("b3 line");
    assert!(
        b3.contains("2.582370291014204890701073050569838390747138200367801381055"),
        "{b3}"
    );
    let f64_out = stdout_ok(&["eval", "thesis-cubic", "--param", "m=0.6", "--at", "0.25"]);
    let b3_f64 = f64_out
        .lines()
        .find(|l| l.starts_with("b3 = "))
        .expect("b3 line");
    assert!(b3_f64.len() < 40, "f64 output is short: {b3_f64}");
}

#[test]
fn eval_every_family_in_f64_and_mpfr() {
    let cases: &[(&str, &[&str])] = &[
        ("thesis-quadratic", &["beta=1"]),
        ("thesis-cubic", &["m=-2"]),
        ("han", &["lambda=1"]),
        ("majeed-qayyum", &["eta=2"]),
        ("usman", &["alpha=1"]),
        ("han-listing", &["lambda=-1"]),
        ("seed000-blending", &["zeta=4"]),
        ("seed000-uniform", &["zeta=0"]),
        ("seed002-quartic", &[]),
        ("eh", &["lambda=0.5", "mu=-1"]),
        ("hermite", &[]),
        ("bernstein3", &[]),
        ("bspline3", &[]),
    ];
    for (family, params) in cases {
        for prec in [None, Some("256")] {
            let mut args = vec!["eval", family, "--at", "0.5", "--format", "json"];
            for p in *params {
                args.extend(["--param", p]);
            }
            if let Some(p) = prec {
                args.extend(["--prec", p]);
            }
            let json: serde_json::Value =
                serde_json::from_str(&stdout_ok(&args)).expect("eval --format json is JSON");
            let values = json["values"].as_object().expect("values");
            assert!(!values.is_empty(), "{family}");
        }
    }
}

#[test]
fn bad_input_gives_one_line_errors() {
    let cases: &[(&[&str], &str)] = &[
        (&["eval", "no-such-family", "--at", "0"], "unknown family"),
        (
            &["eval", "thesis-cubic", "--param", "m", "--at", "0"],
            "NAME=VALUE",
        ),
        (
            &["eval", "thesis-cubic", "--param", "m=abc", "--at", "0"],
            "cannot read",
        ),
        (
            &["eval", "thesis-cubic", "--param", "m=2", "--at", "0"],
            "outside the published range",
        ),
        (
            &["eval", "thesis-cubic", "--param", "k=2", "--at", "0"],
            "no parameter",
        ),
        (&["eval", "thesis-cubic", "--at", "0"], "needs parameter"),
        (
            &["eval", "thesis-cubic", "--param", "m=0", "--at", "1.5"],
            "outside the domain",
        ),
        (
            &["eval", "thesis-cubic", "--param", "m=0", "--at", "nan"],
            "not a finite",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--param",
                "m=0",
                "--at",
                "0",
                "--prec",
                "1",
            ],
            "--prec",
        ),
        (&["eval", "seed003", "--at", "0"], "no formulas"),
        (
            &[
                "eval",
                "thesis-quadratic",
                "--param",
                "beta=-1",
                "--at",
                "0.5",
                "--allow-outside-range",
            ],
            "division by zero",
        ),
        (
            &[
                "eval",
                "seed000-nonuniform",
                "--param",
                "zeta=1",
                "--knots",
                "0,1,1,2",
                "--at",
                "0.5",
            ],
            "zero-length",
        ),
        (
            &[
                "eval",
                "seed000-nonuniform",
                "--param",
                "zeta=1",
                "--knots",
                "0,1,2,3,4",
                "--at",
                "0.5",
            ],
            "undefined",
        ),
    ];
    assert_errors(cases);
}

#[test]
fn outside_range_is_allowed_on_request() {
    let out = stdout_ok(&[
        "eval",
        "thesis-cubic",
        "--param",
        "m=3",
        "--at",
        "0.5",
        "--allow-outside-range",
    ]);
    assert!(out.contains("b0 = "));
}

#[test]
fn uniform_knots_make_the_printed_c_j2_divide_by_zero() {
    let knots = (0..=16)
        .map(|k| k.to_string())
        .collect::<Vec<_>>()
        .join(",");
    let err = error_line(&[
        "eval",
        "seed000-nonuniform",
        "--param",
        "zeta=1",
        "--knots",
        &knots,
        "--at",
        "8.5",
    ]);
    assert!(err.contains("division by zero in c_{8,2}"), "{err}");
}

/// `--at-file` (and `-` for standard input) gives, for every point, the
/// same digits as `--at` at that point (each value certified the same way),
/// the rows streamed between a header and a last line stating the largest
/// f64 error bound.
#[test]
fn eval_at_file_matches_eval_at_each_point() {
    let points = ["0", "0.25", "1/3", "0.9", "1"];
    let path = std::env::temp_dir().join(format!("trig-e2e-points-{}.txt", std::process::id()));
    std::fs::write(&path, format!("# u\n{}\n\n", points.join("\n"))).expect("write points");
    let file = path.display().to_string();
    for prec in [None, Some("200")] {
        let mut args = vec!["eval", "han", "--param", "lambda=-1/2", "--at-file", &file];
        args.extend(prec.iter().flat_map(|p| ["--prec", *p]));
        let out = stdout_ok(&args);
        let mut lines = out.lines();
        assert!(
            lines
                .next()
                .expect("title")
                .starts_with("# han at 5 points [lambda=-1/2]")
        );
        assert_eq!(lines.next(), Some("# at\tb0\tb1\tb2\tb3"));
        if prec.is_none() {
            // the rows stream; the largest bound comes last
            let bound = out.lines().last().expect("bound line");
            assert!(bound.starts_with("# every f64 value is within "), "{bound}");
        }
        for (line, at) in lines.filter(|l| !l.starts_with('#')).zip(points) {
            let mut one = vec!["eval", "han", "--param", "lambda=-1/2", "--at", at];
            one.extend(prec.iter().flat_map(|p| ["--prec", *p]));
            let single = stdout_ok(&one);
            let values: Vec<&str> = single
                .lines()
                .skip(1)
                .map(|l| match prec {
                    // f64: the value before its error bound
                    None => l[5..].split(" ± ").next().unwrap_or_default(),
                    Some(_) => &l[5..],
                })
                .collect();
            let row: Vec<&str> = line.split('\t').collect();
            assert_eq!(row[0], at);
            assert_eq!(row[1..], values[..], "at {at}");
        }
    }
    let piped = run_with_input(
        &[
            "eval",
            "han",
            "--param",
            "lambda=-1/2",
            "--at-file",
            "-",
            "--format",
            "json",
        ],
        "0.25\n1\n",
    );
    assert!(piped.status.success());
    let json: serde_json::Value = serde_json::from_slice(&piped.stdout).expect("JSON");
    assert_eq!(json["at"], serde_json::json!(["0.25", "1"]));
    assert_eq!(json["values"]["b3"].as_array().map(Vec::len), Some(2));
    let spec = stdout_ok(&[
        "eval",
        "--spec",
        &example("thesis-cubic.toml"),
        "--param",
        "m=0.6",
        "--at-file",
        &file,
    ]);
    assert_eq!(spec.lines().count(), 3 + points.len());
    std::fs::write(&path, "0.5\n2\n").expect("write points");
    // the rows stream: an error at a later point ends the output there,
    // after the rows before it, with the one-line error and exit status 2
    let late = run(&["eval", "han", "--param", "lambda=0", "--at-file", &file]);
    assert!(!late.status.success());
    let err = String::from_utf8_lossy(&late.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("point 2 is outside the domain"), "{err}");
    // the error names the line of the file it comes from
    assert!(err.contains("line 2: "), "{err}");
    let rows = String::from_utf8_lossy(&late.stdout);
    assert!(rows.lines().any(|l| l.starts_with("0.5\t")), "{rows}");
    assert_errors(&[
        (
            &[
                "eval",
                "han",
                "--param",
                "lambda=0",
                "--at-file",
                "/nonexistent/points",
            ],
            "cannot read /nonexistent/points",
        ),
        (
            &["eval", "bspline3", "--piecewise", "--at-file", &file],
            "--at-file evaluates the functions",
        ),
    ]);
    let bad = run_with_input(
        &["eval", "han", "--param", "lambda=0", "--at-file", "-"],
        "x\n",
    );
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(err.contains("standard input line 1"), "{err}");
    let _ = std::fs::remove_file(&path);
}

/// Points in multiples of π are exact: the end `π/2` of `[0, π/2]` is in
/// the domain (decided exactly, not by rounding), a decimal just above it
/// is not, and at `π/4` Majeed–Qayyum's `g0` (η = 1) is `3/2 − √2`
/// (hand computation: the thesis (6.1) at θ = π/4, sin = cos = √2/2).
#[test]
fn points_may_be_rational_multiples_of_pi() {
    let at = |point: &str| {
        stdout_ok(&[
            "eval",
            "majeed-qayyum",
            "--param",
            "eta=1",
            "--at",
            point,
            "--digits",
            "15",
        ])
    };
    let end = at("pi/2");
    assert!(end.contains("g3 = 1.00000000000000"), "{end}");
    let quarter = at("pi/4");
    // 3/2 − √2 = 0.0857864376269049512…
    assert!(quarter.contains("g0 = 8.57864376269050e-2"), "{quarter}");
    assert_eq!(at("2*pi/8"), quarter.replace("pi/4", "2*pi/8"));
    assert_errors(&[
        (
            &[
                "eval",
                "majeed-qayyum",
                "--param",
                "eta=1",
                "--at",
                "1.5708",
            ],
            "outside the domain",
        ),
        (
            &["eval", "majeed-qayyum", "--param", "eta=1", "--at", "pi/0"],
            "division by zero",
        ),
        (
            &["eval", "bspline3", "--piecewise", "--at", "pi/2"],
            "take a rational point",
        ),
    ]);
}

/// `R1 = 2(1 + α)w·t(1 − t)/d` of `examples/independent/issue40/vanishing.toml`
/// at exact values, computed here from the formula.
fn vanishing_r1(alpha: rug::Rational, w: rug::Rational, t: rug::Rational) -> rug::Rational {
    let one = rug::Rational::from(1);
    let u = one.clone() - &t;
    let middle = rug::Rational::from(2) * (one + &alpha) * &w * &t * &u;
    let d = u.clone() * &u + &middle + t.clone() * &t;
    middle / d
}

/// A function that vanishes identically at the given parameter values is
/// decided in the exact ring first: `0`, exact, in every arithmetic —
/// never "not decided whether zero" after the climb to the precision
/// limit (issue 40); at other values it is still evaluated.
#[test]
fn eval_prints_an_identically_zero_function_as_exact_zero() {
    let spec = example("independent/issue40/vanishing.toml");
    let q = |n: i64, d: i64| rug::Rational::from((n, d));
    let at = |alpha: &str, extra: &[&str]| {
        let mut args = vec![
            "eval", "--spec", &spec, "--param", alpha, "--param", "w=2", "--at", "0.3",
        ];
        args.extend_from_slice(extra);
        stdout_ok(&args)
    };
    // the value really is 0 there, and the formula is not 0 elsewhere
    assert_eq!(vanishing_r1(q(-1, 1), q(2, 1), q(3, 10)), 0);
    for extra in [&["--digits", "30"][..], &[], &["--prec", "100"]] {
        let out = at("alpha=-1", extra);
        let r1 = out.lines().find(|l| l.starts_with("R1 = ")).expect("R1");
        assert!(r1.starts_with("R1 = 0 (exact"), "{extra:?}: {out}");
        assert!(!out.contains("not decided"), "{out}");
        assert!(!out.contains("65536"), "no climb to the limit: {out}");
    }
    let json: serde_json::Value =
        serde_json::from_str(&at("alpha=-1", &["--format", "json"])).expect("JSON");
    assert_eq!(json["values"]["R1"], "0");
    assert!(
        json["error_bounds"]["R1"].is_null(),
        "exact: no error bound"
    );
    // nonzero at α = −1/2: evaluated, to the digits asked
    let exact = vanishing_r1(q(-1, 2), q(2, 1), q(3, 10));
    assert_ne!(exact, 0);
    let out = at("alpha=-1/2", &["--digits", "30"]);
    let r1 = out.lines().find(|l| l.starts_with("R1 = ")).expect("R1");
    assert!(!r1.contains("exact"), "{r1}");
    let printed: f64 = r1["R1 = ".len()..].parse().expect("a decimal");
    assert!((printed - exact.to_f64()).abs() < 1e-15, "{r1} vs {exact}");
    assert!(out.contains("all proved"), "{out}");
}

/// A function that is 0 at an exact point (a multiple of π/12, where sine
/// and cosine are exact) prints as an exact 0, decided in the exact ring,
/// never as an enclosure of zero that no precision decides (found by a new
/// user): Han, Ma & Huang's b₀ = (1 − sin t)²(1 − λ sin t) at t = π/2.
#[test]
fn eval_prints_a_zero_at_an_exact_point_as_exact_zero() {
    let hmh = trig_e2e::example("han-ma-huang-cubic.toml");
    let args = |at: &'static str| {
        [
            "eval", "--spec", &hmh, "--param", "lambda=1", "--param", "mu=1/2", "--at", at,
            "--digits", "30",
        ]
        .map(String::from)
    };
    let out = stdout_ok(&args("pi/2").each_ref().map(String::as_str));
    assert!(
        out.contains("b0 = 0 (exactly 0") && out.contains("b1 = 0 (exactly 0"),
        "{out}"
    );
    assert!(!out.contains("not decided"), "{out}");
    // b3(π/2) = (1 − 0)²(1 − 0) = 1 is evaluated, not marked
    assert!(
        out.contains("b3 = 1.00000000000000000000000000000\n"),
        "{out}"
    );
    // at π/3 nothing vanishes: every value is evaluated
    let out = stdout_ok(&args("pi/3").each_ref().map(String::as_str));
    assert!(!out.contains("exactly 0"), "{out}");
}
