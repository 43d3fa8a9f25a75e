//! `trig-audit fit` and `trig-audit plot` end to end, on the committed glyph
//! data (`data/glyphs/`).

use std::path::{Path, PathBuf};

use trig_e2e::{assert_errors, stdout_ok};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

fn glyph(name: &str) -> String {
    root()
        .join("data/glyphs")
        .join(format!("{name}.csv"))
        .display()
        .to_string()
}

/// The comparison section (after `## Comparison`) of a Markdown fit report.
fn comparison(md: &str) -> String {
    md[md.find("## Comparison").expect("comparison section")..].to_string()
}

#[test]
fn epsilon_comparison_across_all_families() {
    let eps = glyph("epsilon");
    let md = stdout_ok(&["fit", "--glyph", &eps, "--family", "all", "--refine", "c1"]);
    // one per-method table per family, six families in the comparison, two stages each
    for id in [
        "thesis-cubic",
        "majeed-qayyum",
        "han",
        "usman",
        "han-listing",
        "bernstein3",
    ] {
        assert!(md.contains(&format!("## {id} (")), "{id}");
    }
    let table = comparison(&md);
    assert_eq!(table.lines().filter(|l| l.contains("| C⁰ |")).count(), 6);
    assert_eq!(table.lines().filter(|l| l.contains("| C¹ |")).count(), 6);
    insta::assert_snapshot!("fit_epsilon_all_c1", table);
}

#[test]
fn optimised_fits_in_json_and_csv() {
    let delta = glyph("delta");
    let json = stdout_ok(&[
        "fit",
        "--glyph",
        &delta,
        "--family",
        "all",
        "--optimise",
        "--range",
        "published",
        "--refine",
        "c1-arc",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&json).expect("JSON");
    let methods = v["methods"].as_array().expect("methods");
    // five one-parameter families twice (0.6 and optimised), Bézier once
    assert_eq!(methods.len(), 11);
    for m in methods {
        let fit = &m["fit"];
        let before = fit["before"]["total"].as_f64().unwrap();
        let after = fit["after"]["total"].as_f64().unwrap();
        assert!(
            after >= before * (1.0 - 1e-9),
            "{}: refinement cannot lower the total",
            m["setting"]
        );
    }
    let csv = stdout_ok(&[
        "fit",
        "--glyph",
        &delta,
        "--family",
        "bernstein3",
        "--format",
        "csv",
    ]);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("method,setting,stage,segment,points,parameter,total,max,min,average,bad")
    );
    assert!(lines.all(|l| l.split(',').count() == 11));
}

#[test]
fn explicit_corners_define_the_segments() {
    let eps = glyph("epsilon");
    let md = stdout_ok(&[
        "fit",
        "--glyph",
        &eps,
        "--family",
        "bernstein3",
        "--corners",
        "0,100,200,300",
        "--max-points",
        "0",
    ]);
    assert!(md.contains("; 4 segments;"), "{md}");
    assert!(
        md.contains("| 1 | 101 |"),
        "segment 1 covers points 0..=100"
    );
}

#[test]
fn bad_fit_input_is_a_one_line_error() {
    let eps = glyph("epsilon");
    let dir = std::env::temp_dir().join(format!("trig-audit-fit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let malformed = dir.join("bad.csv");
    std::fs::write(&malformed, "contour,x,y\n0,1,2\n0,3,oops\n").unwrap();
    let malformed = malformed.display().to_string();
    assert_errors(&[
        (
            &["fit", "--glyph", "/nonexistent/glyph.csv"],
            "cannot read outline data `/nonexistent/glyph.csv`",
        ),
        (
            &["fit", "--glyph", &malformed],
            "line 3: `oops` is not a finite number",
        ),
        (
            &[
                "fit",
                "--glyph",
                &eps,
                "--corners",
                "0,2",
                "--max-points",
                "0",
            ],
            "segment 1 has 3 data points; a segment needs at least 4",
        ),
        (
            &["fit", "--glyph", &eps, "--corners", "0,99999"],
            "corner index 99999 is out of range: the outline has 475 points",
        ),
        (
            &["fit", "--glyph", &eps, "--family", "seed002-quartic"],
            "has 6 functions; the fit needs four",
        ),
        (
            &[
                "fit",
                "--glyph",
                &eps,
                "--family",
                "thesis-cubic",
                "--param",
                "m=2",
            ],
            "outside the published range",
        ),
        (
            &["fit", "--glyph", &eps, "--param", "zeta=1"],
            "no selected basis has a parameter `zeta`",
        ),
        (
            &["fit", "--glyph", &eps, "--threshold", "-1"],
            "threshold -1 must be a finite number",
        ),
        (
            &["fit", "--glyph", &eps, "--max-points", "3"],
            "must be 0 (no splitting) or at least 4",
        ),
    ]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn plots_are_written_as_svg() {
    let dir = std::env::temp_dir().join(format!("trig-audit-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = |name: &str| dir.join(name).display().to_string();
    let eps = glyph("ain");
    let cases: Vec<(Vec<String>, String, usize)> = vec![
        // (args, file, polylines of ≥ 20 points = solid curve series; a
        // dashed curve is drawn as short pieces)
        (
            // a colour per function, the first value solid, the others dashed
            vec!["basis".into(), "--family".into(), "majeed-qayyum".into()],
            out("basis.svg"),
            4,
        ),
        (
            vec![
                "curve".into(),
                "--family".into(),
                "han".into(),
                "--values".into(),
                "-2,-1,0,1".into(),
            ],
            // the four curves (the control polygon has four points)
            out("curve.svg"),
            4,
        ),
        (
            vec![
                "fit".into(),
                "--glyph".into(),
                eps.clone(),
                "--family".into(),
                "usman".into(),
                "--refine".into(),
                "c1".into(),
            ],
            out("fit.svg"),
            2 * 16,
        ),
        (
            vec!["interp".into(), "--data".into(), "thesis-table-4.1".into()],
            out("interp.svg"),
            4,
        ),
    ];
    for (args, file, curves) in cases {
        let mut all: Vec<&str> = vec!["plot"];
        all.extend(args.iter().map(String::as_str));
        all.extend(["--output", file.as_str()]);
        let msg = trig_e2e::written(&all);
        assert!(msg.starts_with("wrote "), "{msg}");
        let svg = std::fs::read_to_string(&file).unwrap();
        assert!(
            svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"),
            "{file}"
        );
        let long = svg
            .split("<polyline")
            .skip(1)
            .filter(|p| {
                let pts = p
                    .split("points=\"")
                    .nth(1)
                    .and_then(|q| q.split('"').next())
                    .unwrap_or("");
                pts.split_whitespace().count() >= 20
            })
            .count();
        assert_eq!(long, curves, "{args:?}");
        let tex = std::fs::read_to_string(Path::new(&file).with_extension("tex")).unwrap();
        assert!(tex.contains("\\begin{axis}"), "{file}");
        let csv = std::fs::read_to_string(Path::new(&file).with_extension("csv")).unwrap();
        assert!(csv.starts_with("series,point,x,y\n"), "{file}");
    }
    assert_errors(&[
        (
            &[
                "plot",
                "basis",
                "--family",
                "thesis-cubic",
                "--values",
                "5",
                "--output",
                &out("x.svg"),
            ],
            "outside the published range",
        ),
        (
            &[
                "plot",
                "fit",
                "--glyph",
                "/nonexistent.csv",
                "--family",
                "han",
                "--output",
                &out("x.svg"),
            ],
            "cannot read outline data",
        ),
        (
            &[
                "plot",
                "curve",
                "--family",
                "han",
                "--control",
                "0,0,1",
                "--output",
                &out("x.svg"),
            ],
            "expected x,y pairs",
        ),
        (
            &[
                "plot",
                "basis",
                "--family",
                "han",
                "--output",
                "/nonexistent-dir/x.svg",
            ],
            "cannot write /nonexistent-dir/x.svg",
        ),
        (
            &[
                "plot",
                "basis",
                "--family",
                "han",
                "--output",
                &out("x.png"),
            ],
            "written as SVG",
        ),
    ]);
    std::fs::remove_dir_all(&dir).unwrap();
}
