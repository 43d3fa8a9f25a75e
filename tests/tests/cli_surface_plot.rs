//! `plot surface`: the SVG (snapshot), its pgfplots code (compiled when TeX
//! is there), the meshes (OBJ, PLY, STL) and a drawn join.

use std::path::PathBuf;

use trig_e2e::{assert_errors, example, written};

fn net() -> String {
    example("surfaces/thesis-net.txt")
}

fn scratch(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("trig-e2e-surface-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    dir.join(name).display().to_string()
}

/// `plot surface` of the thesis net at `m` into `name`, with `extra` options.
fn plot(m: &str, name: &str, extra: &[&str]) -> String {
    let out = scratch(name);
    let param = format!("m={m}");
    let net = net();
    let mut args = vec![
        "plot",
        "surface",
        "--family",
        "thesis-cubic",
        "--param",
        &param,
        "--net",
        &net,
        "--output",
        &out,
    ];
    args.extend_from_slice(extra);
    let note = written(&args);
    assert!(note.contains("wrote"), "{note}");
    out
}

/// The vertices of an OBJ file.
fn obj_vertices(text: &str) -> Vec<[f64; 3]> {
    text.lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| {
            let v: Vec<f64> = l.split(' ').map(|x| x.parse().expect("a number")).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

#[test]
fn the_thesis_surface_as_svg_with_its_pgfplots_code() {
    let svg_path = plot("1", "figure-5-1.svg", &["--samples", "4"]);
    let svg = std::fs::read_to_string(&svg_path).expect("svg");
    insta::assert_snapshot!("surface_thesis_m1_samples4", svg);
    // 3 × 3 cells, two triangles each; 16 control points, 8 net lines
    assert_eq!(svg.matches("<polygon").count(), 18);
    assert_eq!(svg.matches("<circle").count(), 16);
    assert_eq!(svg.matches("<polyline").count(), 8);
    let tex = std::fs::read_to_string(PathBuf::from(&svg_path).with_extension("tex")).expect("tex");
    assert!(tex.is_ascii());
    assert!(
        tex.contains("view={-37.5}{30}") && tex.contains("mesh/rows=4]"),
        "{tex}"
    );
    let whole = format!(
        "\\documentclass{{article}}\n\\usepackage{{pgfplots}}\n\\pgfplotsset{{compat=1.16}}\n\\begin{{document}}\n{tex}\\end{{document}}\n"
    );
    if let Some(log) = trig_tex::compile(&whole, "surface-figure") {
        assert!(log.errors.is_empty(), "{:?}", log.errors);
        assert_eq!(log.overfull, 0, "{:?}", log.overfull_lines);
    }
}

#[test]
fn meshes_hold_the_samples_in_every_format() {
    let obj = std::fs::read_to_string(plot("1/2", "s.obj", &["--samples", "5"])).expect("obj");
    let ply = std::fs::read_to_string(plot("1/2", "s.ply", &["--samples", "5"])).expect("ply");
    let stl = std::fs::read_to_string(plot("1/2", "s.stl", &["--samples", "5"])).expect("stl");
    let vertices = obj_vertices(&obj);
    assert_eq!(vertices.len(), 25);
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 32);
    // the corners interpolate P₀₀ = (0, 0, 0) and P₃₃ = (3, 3, 0)
    assert_eq!(vertices[0], [0.0, 0.0, 0.0]);
    let last = vertices[24];
    assert!(
        (last[0] - 3.0).abs() < 1e-15 && (last[1] - 3.0).abs() < 1e-15 && last[2].abs() < 1e-15
    );
    // PLY: the same numbers after its header
    let body = ply.split("end_header\n").nth(1).expect("a PLY body");
    let ply_vertices: Vec<&str> = body.lines().take(25).collect();
    let obj_lines: Vec<&str> = obj.lines().filter_map(|l| l.strip_prefix("v ")).collect();
    assert_eq!(ply_vertices, obj_lines);
    assert!(ply.contains("element face 32\n"));
    assert_eq!(stl.matches("facet normal").count(), 32);
}

#[test]
fn a_drawn_join_shares_its_boundary_with_the_first_patch() {
    let obj = std::fs::read_to_string(plot(
        "1",
        "c2.obj",
        &["--samples", "6", "--join", "c2", "--param2", "m=0"],
    ))
    .expect("obj");
    let v = obj_vertices(&obj);
    assert_eq!(v.len(), 72);
    // the last sample row (u = 1) of patch 1 is the first (u = 0) of patch 2
    for j in 0..6 {
        let (a, b) = (v[5 * 6 + j], v[36 + j]);
        for k in 0..3 {
            assert!((a[k] - b[k]).abs() < 1e-12, "{a:?} {b:?}");
        }
    }
    // and a G² join with its factors draws too
    let svg = plot(
        "1/2",
        "g2.svg",
        &[
            "--samples",
            "4",
            "--join",
            "g2",
            "--alpha",
            "2",
            "--beta",
            "1/2",
            "--across",
            "v",
        ],
    );
    let svg = std::fs::read_to_string(svg).expect("svg");
    assert_eq!(svg.matches("<polygon").count(), 36);
    assert!(svg.contains("G2 join"), "{svg}");
}

#[test]
fn a_rational_join_is_built_in_homogeneous_coordinates() {
    // the thesis net with weights 2 + i + j: the C¹ join's forced weights
    // are positive, and the two rational patches share their boundary
    let text: String = std::fs::read_to_string(net())
        .expect("the example net")
        .split("\n\n")
        .enumerate()
        .map(|(i, row)| {
            row.lines()
                .filter(|l| !l.starts_with('#'))
                .enumerate()
                .map(|(j, l)| format!("{l} {}\n", 2 + i + j))
                .collect::<String>()
        })
        .collect::<Vec<_>>()
        .join("\n");
    let weighted = scratch("weighted-net.txt");
    std::fs::write(&weighted, text).expect("write the net");
    let out = scratch("rational-c1.obj");
    let args = [
        "plot",
        "surface",
        "--family",
        "thesis-cubic",
        "--param",
        "m=1",
        "--net",
        &weighted,
        "--output",
        &out,
        "--samples",
        "6",
        "--join",
        "c1",
    ];
    assert!(written(&args).contains("wrote"));
    let v = obj_vertices(&std::fs::read_to_string(&out).expect("obj"));
    assert_eq!(v.len(), 72);
    for j in 0..6 {
        let (a, b) = (v[5 * 6 + j], v[36 + j]);
        for k in 0..3 {
            assert!((a[k] - b[k]).abs() < 1e-12, "{a:?} {b:?}");
        }
    }
    // weights the join would have to make negative, and a closed pair
    let example_net = example("surfaces/thesis-net-weighted.txt");
    let base = [
        "plot",
        "surface",
        "--family",
        "thesis-cubic",
        "--param",
        "m=1",
        "--net",
        &example_net,
        "--output",
        &out,
    ];
    assert_errors(&[
        (&[&base[..], &["--join", "c2"]].concat(), "weight -6 ≤ 0"),
        (
            &[&base[..], &["--join", "c1", "--close"]].concat(),
            "without weights",
        ),
    ]);
}

#[test]
fn bad_plot_requests_are_one_line_errors() {
    let net = net();
    let base = |out: &'static str, extra: &[&'static str]| {
        let mut a = vec![
            "plot",
            "surface",
            "--family",
            "thesis-cubic",
            "--param",
            "m=1",
            "--output",
            out,
        ];
        a.extend_from_slice(extra);
        a
    };
    let png = base("x.png", &["--net"]);
    let few = base("x.svg", &["--samples", "1", "--net"]);
    let far = base("x.svg", &["--net"]);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            [png, vec![net.as_str()]].concat(),
            "give a name ending in .svg",
        ),
        ([few, vec![net.as_str()]].concat(), "--samples 1"),
        (
            [
                far.clone(),
                vec![net.as_str(), "--net", net.as_str(), "--join", "c1"],
            ]
            .concat(),
            "--join draws one --net",
        ),
        (
            [far, vec![net.as_str(), "--join", "g1", "--alpha", "0"]].concat(),
            "--alpha must be positive",
        ),
    ];
    let cases: Vec<(&[&str], &str)> = cases.iter().map(|(a, e)| (a.as_slice(), *e)).collect();
    assert_errors(&cases);
}

#[test]
fn a_surface_of_revolution_is_an_exact_circle_at_every_height() {
    let profile = scratch("cylinder.txt");
    std::fs::write(&profile, "1 0 0\n1 0 1\n1 0 2\n1 0 3\n").expect("profile");
    let han = example("han-quadratic.toml");
    // the quarter circle in the span of Han's quadratic at λ = 0, and of
    // the thesis cubic at m = 0 (cos θ = b₀ + b₁ + b₂/2 there)
    for circle in [
        vec!["--v-spec", han.as_str(), "--v-param", "lambda=0"],
        vec!["--v-param", "m=0"],
    ] {
        let out = scratch("revolution.obj");
        let mut args = vec![
            "plot",
            "surface",
            "--family",
            "thesis-cubic",
            "--param",
            "m=0",
            "--net",
            &profile,
            "--revolution",
            "--samples",
            "9",
            "--output",
            &out,
        ];
        args.extend_from_slice(&circle);
        written(&args);
        let v = obj_vertices(&std::fs::read_to_string(&out).expect("obj"));
        assert_eq!(v.len(), 4 * 81);
        for p in &v {
            assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15, "{p:?} ({circle:?})");
        }
        // the four quarters meet: patch k's end is patch k + 1's start
        assert!(
            (v[8][0]).abs() < 1e-15 && (v[8][1] - 1.0).abs() < 1e-15,
            "{:?}",
            v[8]
        );
        assert!(
            (v[81][0]).abs() < 1e-15 && (v[81][1] - 1.0).abs() < 1e-15,
            "{:?}",
            v[81]
        );
    }
    let bent = scratch("bent.txt");
    std::fs::write(&bent, "1 0 0\n1 1 1\n1 0 2\n1 0 3\n").expect("profile");
    let cbez = example("c-bezier-cubic.toml");
    let never = scratch("never.svg");
    let run = |net: &str, circle: &[&str]| {
        let mut a = vec![
            "plot",
            "surface",
            "--family",
            "thesis-cubic",
            "--param",
            "m=0",
            "--net",
            net,
            "--revolution",
            "--output",
            &never,
        ];
        a.extend_from_slice(circle);
        trig_e2e::error_line(&a)
    };
    assert!(run(&profile, &["--v-param", "m=1/2"]).contains("does not hold cos"));
    assert!(
        run(&profile, &["--v-spec", &cbez, "--v-param", "alpha=pi/2"])
            .contains("not rational (1, 1, 1/2·π − 1, 0)")
    );
    assert!(run(&bent, &["--v-param", "m=0"]).contains("the profile lies in the xz plane"));
    assert!(run(&net(), &["--v-param", "m=0"]).contains("not a 4 × 4 net"));
}

#[test]
fn a_closed_pair_is_a_cylinder_joined_at_both_seams() {
    let half = example("surfaces/half-cylinder-net.txt");
    for join in [
        vec!["--join", "c1", "--param2", "m=1/2"],
        vec!["--join", "g1", "--alpha", "2"],
    ] {
        let out = scratch("closed.obj");
        let mut args = vec![
            "plot",
            "surface",
            "--family",
            "thesis-cubic",
            "--param",
            "m=1",
            "--net",
            &half,
            "--close",
            "--samples",
            "5",
            "--output",
            &out,
        ];
        args.extend_from_slice(&join);
        written(&args);
        let v = obj_vertices(&std::fs::read_to_string(&out).expect("obj"));
        assert_eq!(v.len(), 50);
        // u = 1 of each patch is u = 0 of the other
        for j in 0..5 {
            for (a, b) in [(v[20 + j], v[25 + j]), (v[45 + j], v[j])] {
                for k in 0..3 {
                    assert!((a[k] - b[k]).abs() < 1e-14, "{join:?}: {a:?} {b:?}");
                }
            }
        }
    }
    let never = scratch("never.svg");
    let run = |family: &str, kind: &str| {
        trig_e2e::error_line(&[
            "plot", "surface", "--family", family, "--net", &half, "--join", kind, "--close",
            "--output", &never,
        ])
    };
    // the second seam read backwards is not the same join for a B-spline basis
    assert!(run("bspline3", "c1").contains("the closing seam of `bspline3` is not C1"));
    // C² and G² overlap: both patches are solved together (both seams exact)
    // and every column lies on the line through its kept ends — here the
    // plane y = 0 of the half cylinder's rows 0 and 3
    for (kind, extra) in [
        ("c2", &["--param2", "m=1/2"][..]),
        ("g2", &["--alpha", "1/2", "--beta", "2"][..]),
    ] {
        let out = scratch(&format!("closed-{kind}.obj"));
        let mut args = vec![
            "plot",
            "surface",
            "--family",
            "thesis-cubic",
            "--param",
            "m=1",
            "--net",
            &half,
            "--join",
            kind,
            "--close",
            "--samples",
            "5",
            "--output",
            &out,
        ];
        args.extend_from_slice(extra);
        assert!(written(&args).contains("wrote"));
        let v = obj_vertices(&std::fs::read_to_string(&out).expect("obj"));
        assert_eq!(v.len(), 50);
        assert!(v.iter().all(|p| p[1].abs() < 1e-12), "{kind}: {v:?}");
    }
}

#[test]
fn the_closed_c2_pair_of_the_thesis_net_as_svg() {
    let svg = plot(
        "1",
        "closed-c2.svg",
        &[
            "--samples",
            "3",
            "--join",
            "c2",
            "--param2",
            "m=1/2",
            "--close",
        ],
    );
    let svg = std::fs::read_to_string(svg).expect("svg");
    assert!(svg.contains("closed C2 join"), "{svg}");
    insta::assert_snapshot!("surface_closed_c2_samples3", svg);
}

#[test]
fn a_uniform_bspline_surface_is_one_patch_per_span_and_they_meet() {
    let grid = scratch("grid6.txt");
    let rows: Vec<String> = (0..6)
        .map(|i| {
            (0..6)
                .map(|j| format!("{i} {j} {}\n", (i * j) % 5))
                .collect()
        })
        .collect();
    std::fs::write(&grid, rows.join("\n")).expect("net");
    let out = scratch("bspline.obj");
    written(&[
        "plot",
        "surface",
        "--family",
        "bspline3",
        "--net",
        &grid,
        "--bspline",
        "--samples",
        "3",
        "--output",
        &out,
    ]);
    let v = obj_vertices(&std::fs::read_to_string(&out).expect("obj"));
    // (6 − 3)² spans of 3 × 3 samples
    assert_eq!(v.len(), 81);
    let at = |patch: usize, i: usize, j: usize| v[patch * 9 + i * 3 + j];
    for j in 0..3 {
        // span (0, 0) at u = 1 is span (1, 0) at u = 0; (0, 0) at v = 1 is (0, 1) at v = 0
        for (a, b) in [(at(0, 2, j), at(3, 0, j)), (at(0, j, 2), at(1, j, 0))] {
            for k in 0..3 {
                assert!((a[k] - b[k]).abs() < 1e-14, "{a:?} {b:?}");
            }
        }
    }
    let never = scratch("never.svg");
    let line = trig_e2e::error_line(&[
        "plot",
        "surface",
        "--family",
        "thesis-cubic",
        "--param",
        "m=0",
        "--net",
        &grid,
        "--bspline",
        "--output",
        &never,
    ]);
    assert!(line.contains("`thesis-cubic` is not one"), "{line}");
}
