//! `trig-audit fit-surface` end to end, on the committed volcano grid
//! (`data/volcano/`): a small table against its snapshot, the tables of
//! docs/fitting.md regenerated and found there, a spec-file basis against
//! the same catalog family, the error map, and the typed errors.

use std::path::{Path, PathBuf};

use trig_e2e::{assert_errors, example, stdout_ok, written};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

fn volcano() -> String {
    root()
        .join("data/volcano/volcano.csv")
        .display()
        .to_string()
}

/// The table rows (lines starting with `|`) of a Markdown output.
fn table_rows(md: &str) -> Vec<&str> {
    md.lines().filter(|l| l.starts_with('|')).collect()
}

#[test]
fn thesis_cubic_and_bernstein_small_table() {
    let md = stdout_ok(&[
        "fit-surface",
        "--grid",
        &volcano(),
        "--family",
        "thesis-cubic",
        "--patches",
        "1x1,2x2",
        "--continuity",
        "c0",
    ]);
    // the comparison and one per-patch table per fit, each with a TOTAL row
    assert_eq!(md.matches("| TOTAL |").count(), 2);
    assert!(
        md.contains("| thesis-cubic | m = 0.6 | 2×2 | 49 | 5307 |"),
        "{md}"
    );
    insta::assert_snapshot!("fit_surface_volcano_thesis_cubic_c0", md);
}

/// Every table row of the surfaces section of docs/fitting.md is the
/// tool's output of the command printed above it: regenerated here.
#[test]
fn the_documented_surface_tables_are_the_tools_output() {
    let docs = std::fs::read_to_string(root().join("docs/fitting.md")).expect("docs/fitting.md");
    let grid = volcano();
    let spec = example("c-bezier-cubic.toml");
    let commands: [&[&str]; 5] = [
        &["--summary"],
        &["--summary", "--continuity", "c0"],
        &["--summary", "--optimise", "--patches", "4x4,8x6"],
        &[
            "--summary",
            "--optimise",
            "--optimise-per",
            "segment",
            "--patches",
            "4x4,8x6",
        ],
        &["--summary", "--spec", &spec, "--param", "alpha=1"],
    ];
    for extra in commands {
        let mut args = vec!["fit-surface", "--grid", &grid];
        args.extend_from_slice(extra);
        let md = stdout_ok(&args);
        let rows = table_rows(&md);
        assert!(rows.len() > 3, "{md}");
        for row in rows {
            assert!(
                docs.contains(row),
                "{extra:?}: docs/fitting.md lacks the row\n{row}"
            );
        }
    }
}

#[test]
fn a_spec_file_basis_fits_as_its_catalog_family() {
    let fit = |basis: &[&str]| {
        let grid = volcano();
        let mut args = vec![
            "fit-surface",
            "--grid",
            &grid,
            "--patches",
            "2x3",
            "--summary",
        ];
        args.extend_from_slice(basis);
        let md = stdout_ok(&args);
        // the numbers of the one row, after the basis's name
        let row = table_rows(&md)[2].to_string();
        row.split('|').skip(2).collect::<Vec<_>>().join("|")
    };
    let spec = example("thesis-cubic.toml");
    assert_eq!(
        fit(&["--family", "thesis-cubic"]),
        fit(&["--spec", &spec, "--param", "m=0.6"])
    );
}

#[test]
fn json_and_csv_carry_the_same_numbers() {
    let args = |format: &'static str| {
        vec![
            "fit-surface".to_string(),
            "--grid".into(),
            volcano(),
            "--family".into(),
            "bernstein3".into(),
            "--patches".into(),
            "4x4".into(),
            "--format".into(),
            format.into(),
        ]
    };
    let run = |format| {
        let a = args(format);
        stdout_ok(&a.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let json: serde_json::Value = serde_json::from_str(&run("json")).expect("JSON");
    let tables = json["tables"].as_array().expect("tables");
    // the comparison and the per-patch table: 16 patches and TOTAL
    assert_eq!(tables.len(), 2);
    assert_eq!(tables[1]["rows"].as_array().expect("rows").len(), 17);
    let rms = tables[0]["rows"][0]["values"][6]["text"]
        .as_str()
        .expect("RMS");
    let csv = run("csv");
    assert!(csv.contains(&format!(",RMS,{rms}")), "{rms}\n{csv}");
}

#[test]
fn the_error_map_is_written_with_its_pgfplots_code_and_data() {
    let dir = std::env::temp_dir().join(format!("trig-audit-surface-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let svg = dir.join("map.svg");
    let err = written(&[
        "fit-surface",
        "--grid",
        &volcano(),
        "--family",
        "usman",
        "--patches",
        "4x4",
        "--error-map",
        &svg.display().to_string(),
        "--spacing",
        "10",
        "--output",
        &dir.join("table.md").display().to_string(),
    ]);
    assert!(err.contains("map.svg") && err.contains("map.tex"), "{err}");
    let text = std::fs::read_to_string(&svg).expect("SVG");
    assert!(text.starts_with("<svg") || text.contains("<svg"), "an SVG");
    // a legend entry per error class, and the patch boundaries
    assert!(text.contains("patch boundaries"), "legend");
    assert!(text.matches("|error| in").count() >= 2, "error classes");
    let data = std::fs::read_to_string(dir.join("map.csv")).expect("CSV");
    // two corners of each of the 87 × 61 cells
    assert_eq!(
        data.lines()
            .filter(|l| l.starts_with("error at row"))
            .count(),
        2 * 87 * 61
    );
    let table = std::fs::read_to_string(dir.join("table.md")).expect("table");
    assert!(
        table.contains("| usman | α = 0.6 | 4×4 | 100 | 5307 |"),
        "{table}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_fitted_surface_is_written_by_the_surface_writer() {
    let dir = std::env::temp_dir().join(format!("trig-audit-fitted-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let fit = |output: &Path| {
        written(&[
            "fit-surface",
            "--grid",
            &volcano(),
            "--family",
            "thesis-cubic",
            "--patches",
            "4x4",
            "--spacing",
            "10",
            "--surface-output",
            &output.display().to_string(),
            "--output",
            &dir.join("table.md").display().to_string(),
        ])
    };
    let obj = dir.join("fitted.obj");
    assert!(fit(&obj).contains("vertices"));
    let text = std::fs::read_to_string(&obj).expect("OBJ");
    assert!(
        text.starts_with("# trig-audit fit-surface: volcano: fitted surface of thesis-cubic"),
        "{text:.200}"
    );
    let vertices: Vec<[f64; 3]> = text
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split(' ').map(|x| x.parse().expect("a number")).collect();
            [v[0], v[1], v[2]]
        })
        .collect();
    // 87 rows in 4 patches of 23 grid lines each (around 21.5 rows), 61
    // columns in 4 of 16: one vertex per grid point of every patch
    assert_eq!(vertices.len(), (4 * 23) * (4 * 16));
    assert_eq!(
        text.lines().filter(|l| l.starts_with("f ")).count(),
        16 * 22 * 15 * 2
    );
    // x, y on the 10 m grid, the heights those of the volcano (94 to 195 m)
    assert!(
        vertices
            .iter()
            .all(|v| v[0] % 10.0 == 0.0 && v[1] % 10.0 == 0.0 && v[0] <= 860.0 && v[1] <= 600.0)
    );
    assert!(
        vertices.iter().all(|v| (85.0..205.0).contains(&v[2])),
        "{vertices:?}"
    );
    let svg = dir.join("fitted.svg");
    let note = fit(&svg);
    assert!(
        note.contains("fitted.svg") && note.contains("fitted.tex"),
        "{note}"
    );
    assert_eq!(
        std::fs::read_to_string(&svg)
            .expect("SVG")
            .matches("<polygon")
            .count(),
        16 * 22 * 15 * 2
    );
    std::fs::remove_dir_all(&dir).ok();
    assert_errors(&[
        (
            &[
                "fit-surface",
                "--grid",
                &volcano(),
                "--surface-output",
                "/tmp/x.obj",
            ],
            "--surface-output draws one fit",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &volcano(),
                "--family",
                "thesis-cubic",
                "--patches",
                "2x2",
                "--surface-output",
                "/tmp/x.png",
            ],
            "give a name ending in .svg",
        ),
    ]);
}

fn scratch(name: &str, text: &str) -> String {
    let path = std::env::temp_dir().join(format!("trig-surface-{}-{name}", std::process::id()));
    std::fs::write(&path, text).expect("scratch grid");
    path.display().to_string()
}

#[test]
fn bad_grids_and_options_get_one_line_errors() {
    let ragged = scratch("ragged.csv", "1,2,3\n4,5,6\n7,8\n");
    let nan = scratch("nan.csv", "1,2\n3,inf\n");
    let word = scratch("word.csv", "1,2\n3,x\n");
    let small = scratch("small.csv", &"1,2,3,4,5,6,7\n".repeat(7));
    let v = volcano();
    assert_errors(&[
        (
            &["fit-surface", "--grid", "/nonexistent/volcano.csv"],
            "cannot read grid `/nonexistent/volcano.csv`",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &v,
                "--family",
                "usman",
                "--param",
                "alpha=0",
                "--allow-outside-range",
            ],
            "collocation matrix has deficient rank",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &v,
                "--error-map",
                "/tmp/x.svg",
                "--spacing",
                "-1",
            ],
            "--spacing -1: a positive number",
        ),
        (
            &["fit-surface", "--grid", &ragged],
            "line 3: 2 heights in this row, the first row has 3",
        ),
        (
            &["fit-surface", "--grid", &nan],
            "line 2: height 2 is not finite",
        ),
        (
            &["fit-surface", "--grid", &word],
            "line 2: height 2 `x` is not a number",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &small,
                "--family",
                "bernstein3",
                "--patches",
                "3x1",
                "--continuity",
                "c0",
            ],
            "the linear system is singular",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &v,
                "--family",
                "bernstein3",
                "--patches",
                "50x1",
            ],
            "(87 data lines for 102 coefficients)",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &v,
                "--family",
                "thesis-cubic",
                "--param",
                "m=3/2",
            ],
            "pass --allow-outside-range",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &v,
                "--family",
                "thesis-cubic",
                "--param",
                "q=1",
            ],
            "no selected basis has a parameter `q`",
        ),
        (
            &["fit-surface", "--grid", &v, "--error-map", "/tmp/x.svg"],
            "--error-map draws one fit",
        ),
        (
            &[
                "fit-surface",
                "--grid",
                &v,
                "--family",
                "bernstein3",
                "--optimise",
            ],
            "`bernstein3` has no shape parameter",
        ),
    ]);
    for f in [ragged, nan, word, small] {
        std::fs::remove_file(Path::new(&f)).ok();
    }
    // outside the range on request: fitted
    let md = stdout_ok(&[
        "fit-surface",
        "--grid",
        &v,
        "--family",
        "thesis-cubic",
        "--param",
        "m=3/2",
        "--allow-outside-range",
        "--patches",
        "2x2",
        "--summary",
    ]);
    assert!(md.contains("| thesis-cubic | m = 1.5 | 2×2 |"), "{md}");
}
