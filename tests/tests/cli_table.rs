//! End-to-end tests of `trig-audit table`: every format, exact and numeric,
//! and insta snapshots of the exact table of every family (orders 0–6, both
//! ends, each convention), reviewed by hand against paper derivations.

use trig_e2e::{FAMILIES, assert_errors, stdout_ok};

#[test]
fn exact_tables_of_every_family() {
    for family in FAMILIES {
        let mut all = String::new();
        for wrt in ["angle", "u", "x"] {
            all.push_str(&stdout_ok(&[
                "table", family, "--order", "6", "--wrt", wrt, "--format", "md",
            ]));
        }
        insta::assert_snapshot!(format!("table_{family}"), all);
    }
}

#[test]
fn knot_and_curve_tables() {
    for family in ["seed000-uniform", "bspline3"] {
        let out = stdout_ok(&[
            "table", family, "--at", "knots", "--wrt", "u", "--order", "6",
        ]);
        insta::assert_snapshot!(format!("knots_{family}"), out);
    }
    let cubic = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--curve",
        "--order",
        "2",
        "--wrt",
        "angle",
    ]);
    insta::assert_snapshot!("curve_thesis_cubic", cubic);
    let quartic = stdout_ok(&[
        "table",
        "seed002-quartic",
        "--curve",
        "--rational",
        "--order",
        "2",
    ]);
    insta::assert_snapshot!("curve_seed002_rational", quartic);
}

#[test]
fn thesis_cubic_entries_match_paper_derivations() {
    // Thesis Chapter 4 list (angle convention): Q'(0) = (m+2)(P1 − P0),
    // and b0'' at u = 0 is 4m + 2 (derived by hand: f = (1−s)², f'' = 2;
    // g = 1 − ms, g' = −m; (fg)'' = 2 + 4m).
    let out = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--order",
        "2",
        "--at",
        "start",
        "--format",
        "csv",
    ]);
    assert!(out.contains("start of the domain,1,b0,-m - 2"), "{out}");
    assert!(out.contains("start of the domain,1,b1,m + 2"), "{out}");
    assert!(out.contains("start of the domain,2,b0,4*m + 2"), "{out}");
}

#[test]
fn every_format_renders() {
    let base = ["table", "thesis-cubic", "--order", "3"];
    let md = stdout_ok(&[&base[..], &["--format", "md"]].concat());
    assert!(md.contains("| k | b0 | b1 | b2 | b3 |"));
    let tex = stdout_ok(&[&base[..], &["--format", "tex"]].concat());
    assert!(
        tex.contains("\\begin{longtable}")
            && tex.contains("exact; start of the domain}")
            && tex.contains("$b_{0}$")
            && tex.contains("$-m - 2$"),
        "{tex}"
    );
    let csv = stdout_ok(&[&base[..], &["--format", "csv"]].concat());
    assert!(csv.starts_with("table,row,column,value\n"));
    assert_eq!(csv.lines().count(), 1 + 2 * 4 * 4);
    let json: serde_json::Value =
        serde_json::from_str(&stdout_ok(&[&base[..], &["--format", "json"]].concat()))
            .expect("JSON");
    assert_eq!(json["tables"].as_array().map(Vec::len), Some(2));
    assert_eq!(json["tables"][0]["rows"][1]["values"][0]["latex"], "-m - 2");
}

#[test]
fn numeric_tables_agree_with_exact_ones() {
    // first derivative of b0 at u = 0 in u: −(m+2)·π/2 with m = 0.6
    let out = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--numeric",
        "--param",
        "m=0.6",
        "--wrt",
        "u",
        "--order",
        "1",
        "--at",
        "start",
        "--format",
        "csv",
    ]);
    let line = out.lines().find(|l| l.contains(",1,b0,")).expect("row");
    let value: f64 = line.rsplit(',').next().unwrap().parse().unwrap();
    assert!(
        (value + 2.6 * std::f64::consts::FRAC_PI_2).abs() < 1e-14,
        "{value}"
    );
    let mp = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--numeric",
        "--param",
        "m=0.6",
        "--prec",
        "200",
        "--order",
        "1",
        "--at",
        "start",
        "--format",
        "csv",
    ]);
    // −13/5 enclosed at 200 bits: about 60 proved digits, correctly rounded
    // (uncertified MPFR printed −2.5999…9 here: the rounded input's digits)
    assert!(
        mp.contains(",1,b0,-2.60000000000000000000000000000000000000000000000000000000"),
        "{mp}"
    );
}

#[test]
fn bad_table_requests_are_one_line_errors() {
    let cases: &[(&[&str], &str)] = &[
        (&["table", "nope"], "unknown family"),
        (&["table", "thesis-cubic", "--order", "13"], "at most 12"),
        (&["table", "thesis-cubic", "--at", "knots"], "--at knots"),
        (&["table", "seed003"], "no formulas"),
        (&["table", "thesis-cubic", "--numeric"], "needs parameter"),
        (
            &[
                "table",
                "thesis-cubic",
                "--numeric",
                "--param",
                "m=1",
                "--h",
                "0",
            ],
            "positive",
        ),
        (
            &[
                "table",
                "thesis-cubic",
                "--numeric",
                "--param",
                "m=1",
                "--curve",
            ],
            "drop --numeric",
        ),
    ];
    assert_errors(cases);
}

/// With `--standalone` the LaTeX tables are complete plain articles that
/// compile with pdflatex and fit the page — the rational curve table too
/// (set one entry per line, its long fractions inline so that they break)
/// — when `pdflatex` is on the machine.
#[test]
fn latex_tables_compile() {
    for (name, args) in [
        ("basis", &["table", "thesis-cubic", "--order", "6"][..]),
        (
            "rational",
            &[
                "table",
                "thesis-cubic",
                "--order",
                "6",
                "--curve",
                "--rational",
            ][..],
        ),
    ] {
        let tex = stdout_ok(&[args, &["--format", "tex", "--standalone"]].concat());
        assert!(
            tex.starts_with("\\documentclass{article}\n") && tex.ends_with("\\end{document}\n"),
            "{tex}"
        );
        match trig_tex::compile(&tex, &format!("table-{name}")) {
            Some(log) => {
                assert!(log.errors.is_empty(), "{name}: {:#?}", log.errors);
                assert_eq!(log.overfull, 0, "{name}: {:#?}", log.overfull_lines);
                assert!(log.pages >= 1);
            }
            None => eprintln!("pdflatex not found: the {name} table was not compiled"),
        }
    }
}

/// An exact rational-curve table that divides by a parameter names where it
/// is singular when that value is inside the parameter's range (`k = 0` in
/// `[0, 1]`: the weighted sum at the start is `k·w₀`), in every format, as
/// the joins do; with the range `(0, 1]` the division is proved safe and
/// nothing is noted (issue 40).
#[test]
fn exact_tables_name_where_a_division_by_a_parameter_is_singular() {
    let spec = trig_e2e::example("independent/issue40/singular-table.toml");
    let table = |spec: &str, format: &str| {
        stdout_ok(&[
            "table",
            "--spec",
            spec,
            "--curve",
            "--rational",
            "--order",
            "1",
            "--format",
            format,
        ])
    };
    let md = table(&spec, "md");
    // the start's first derivative divides by k, the end's does not
    let start = md.split("### end").next().expect("start block");
    assert!(start.contains("k·w₀"), "the table divides by k: {md}");
    assert!(
        start.contains("### start of the domain: rational curve R (singular where k = 0)"),
        "{md}"
    );
    let end = md.split("### end").nth(1).expect("end block");
    assert!(
        !end.contains("singular where"),
        "the end divides by w₁ only: {md}"
    );
    for format in ["csv", "json", "tex"] {
        assert!(
            table(&spec, format).contains("singular where"),
            "{format}: the note in every format"
        );
    }
    let text = std::fs::read_to_string(&spec).expect("spec");
    let open = text.replace("range = \"[0, 1]\"", "range = \"(0, 1]\"");
    assert_ne!(open, text);
    let path = std::env::temp_dir().join(format!("trig-e2e-singular-{}.toml", std::process::id()));
    std::fs::write(&path, open).expect("write spec");
    let md = table(path.to_str().expect("utf-8"), "md");
    let _ = std::fs::remove_file(&path);
    assert!(md.contains("k·w₀"), "{md}");
    assert!(
        !md.contains("singular where"),
        "k = 0 is outside (0, 1]: {md}"
    );
}
