//! `eval --surface` and `table --surface`: tensor-product surfaces over a
//! control net read from a file (docs/surfaces.md).

use trig_e2e::{assert_errors, example, stdout_ok};

fn net() -> String {
    example("surfaces/thesis-net.txt")
}

/// A scratch file with `text`, named for the test.
fn scratch(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("trig-e2e-surface-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write scratch file");
    path.display().to_string()
}

/// The value printed for `name` (`x = 1.5 ± 2e-16` → 1.5).
fn value(out: &str, name: &str) -> f64 {
    let line = out
        .lines()
        .find(|l| l.starts_with(&format!("{name} = ")))
        .unwrap_or_else(|| panic!("no {name} in {out}"));
    line[name.len() + 3..]
        .split_whitespace()
        .next()
        .expect("a value")
        .parse()
        .expect("a number")
}

#[test]
fn the_surface_interpolates_the_corners_of_the_printed_net_exactly() {
    let net = net();
    // P_{3,3} = (3, 3, 0): z exactly 0, decided in the exact ring
    let out = stdout_ok(&[
        "eval",
        "thesis-cubic",
        "--surface",
        "--net",
        &net,
        "--param",
        "m=1",
        "--at",
        "1,1",
        "--digits",
        "20",
    ]);
    assert!(out.contains("x = 3.0000000000000000000"), "{out}");
    assert!(out.contains("y = 3.0000000000000000000"), "{out}");
    assert!(out.contains("z = 0 (exactly 0"), "{out}");
    assert!(out.contains("all proved"), "{out}");
    // P_{0,3} = (3, 0, 0) at u = 0, v = 1
    let out = stdout_ok(&[
        "eval",
        "thesis-cubic",
        "--surface",
        "--net",
        &net,
        "--param",
        "m=0",
        "--at",
        "0,1",
    ]);
    assert!((value(&out, "x") - 3.0).abs() < 1e-15, "{out}");
    assert!(out.contains("z = 0 ± 0"), "{out}");
}

#[test]
fn f64_and_proved_digits_agree_with_distinct_parameters_per_direction() {
    let net = net();
    let args = |extra: &[&'static str]| {
        let mut a = vec![
            "eval",
            "thesis-cubic",
            "--surface",
            "--net",
            &net,
            "--param",
            "m=1/2",
            "--v-param",
            "m=-1",
            "--at",
            "1/3,2/5",
        ];
        a.extend_from_slice(extra);
        stdout_ok(&a)
    };
    let f64s = args(&[]);
    let digits = args(&["--digits", "30"]);
    assert!(f64s.contains("v parameters [m=-1]"), "{f64s}");
    for c in ["x", "y", "z"] {
        assert!((value(&f64s, c) - value(&digits, c)).abs() < 2e-15, "{c}");
    }
    // a different m in v moves the point: S(u, v; m₁, m₂) of (5.11)
    let same = stdout_ok(&[
        "eval",
        "thesis-cubic",
        "--surface",
        "--net",
        &net,
        "--param",
        "m=1/2",
        "--at",
        "1/3,2/5",
    ]);
    assert!((value(&same, "z") - value(&f64s, "z")).abs() > 1e-3);
    // the partition of unity: a net of equal points is that point everywhere
    let row = "2 -1 7\n".repeat(4);
    let flat = scratch("flat.txt", &[row.as_str(); 4].join("\n"));
    let out = stdout_ok(&[
        "eval",
        "bernstein3",
        "--surface",
        "--v-family",
        "thesis-cubic",
        "--v-param",
        "m=-1",
        "--net",
        &flat,
        "--at",
        "0.3,0.8",
        "--digits",
        "25",
    ]);
    assert!(out.contains("z = 7.000000000000000000000000"), "{out}");
    assert!(
        out.starts_with("bernstein3 × thesis-cubic surface"),
        "{out}"
    );
}

#[test]
fn a_rational_net_with_equal_weights_is_the_polynomial_surface() {
    let text = std::fs::read_to_string(net()).expect("net");
    let weighted: String = text
        .lines()
        .map(|l| {
            if l.is_empty() || l.starts_with('#') {
                format!("{l}\n")
            } else {
                format!("{l} 5/2\n")
            }
        })
        .collect();
    let weighted = scratch("weighted.txt", &weighted);
    let at = ["--param", "m=-1", "--at", "0.3,0.7", "--digits", "20"];
    let a = stdout_ok(
        &[
            &["eval", "thesis-cubic", "--surface", "--net", &net()][..],
            &at,
        ]
        .concat(),
    );
    let b = stdout_ok(
        &[
            &["eval", "thesis-cubic", "--surface", "--net", &weighted][..],
            &at,
        ]
        .concat(),
    );
    assert!(b.contains("rational: weights"), "{b}");
    let values = |s: &str| s.lines().skip(1).map(str::to_string).collect::<Vec<_>>();
    assert_eq!(values(&a), values(&b));
}

#[test]
fn bad_nets_and_bad_points_are_one_line_errors() {
    let net = net();
    let short = scratch(
        "short.txt",
        "0 0 0\n1 0 0\n2 0 0\n3 0 0\n\n0 1 0\n1 1 0\n2 1 0\n3 1 0\n",
    );
    let nan = scratch("nan.txt", "0 0 0\n0 0 NaN\n");
    let words = scratch("words.txt", "0 0 0\n\n# comment\n1 two 3\n");
    let ragged = scratch("ragged.txt", "0 0 0\n1 0 0\n\n0 1 0\n");
    assert_errors(&[
        (
            &[
                "eval",
                "thesis-cubic",
                "--surface",
                "--net",
                &short,
                "--param",
                "m=0",
                "--at",
                "0,0",
            ],
            "control-net rows for `thesis-cubic` (the net is 2 × 4): expected 4, got 2",
        ),
        (
            &[
                "eval",
                "bernstein3",
                "--surface",
                "--net",
                &nan,
                "--at",
                "0,0",
            ],
            "nan.txt line 2: `NaN` is not a finite number",
        ),
        (
            &[
                "eval",
                "bernstein3",
                "--surface",
                "--net",
                &words,
                "--at",
                "0,0",
            ],
            "words.txt line 4: `1 two 3` is not a control point",
        ),
        (
            &[
                "eval",
                "bernstein3",
                "--surface",
                "--net",
                &ragged,
                "--at",
                "0,0",
            ],
            "net row 1 (from line 4) has 1 points, expected 2",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--surface",
                "--net",
                &net,
                "--param",
                "m=3",
                "--at",
                "0,0",
            ],
            "pass --allow-outside-range",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--surface",
                "--net",
                &net,
                "--param",
                "m=0",
                "--at",
                "2,0",
            ],
            "pass --allow-outside-range",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--surface",
                "--net",
                &net,
                "--param",
                "m=0",
                "--at",
                "0.5",
            ],
            "a surface point is `u,v`",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--surface",
                "--param",
                "m=0",
                "--at",
                "0,0",
            ],
            "needs the control net: --net FILE",
        ),
        (
            &[
                "eval",
                "bernstein3",
                "--surface",
                "--net",
                &net,
                "--v-family",
                "thesis-cubic",
                "--at",
                "0,0",
            ],
            "the v direction (--v-param): family `thesis-cubic` needs parameter `m`",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--param",
                "m=0",
                "--v-param",
                "m=0",
                "--at",
                "0",
            ],
            "they go with --surface",
        ),
        (
            &[
                "eval",
                "bspline3",
                "--surface",
                "--piecewise",
                "--net",
                &net,
                "--at",
                "0,0",
            ],
            "without --piecewise",
        ),
    ]);
    // outside the range when asked for: m = 3 of Figure 5.3
    let out = stdout_ok(&[
        "eval",
        "thesis-cubic",
        "--surface",
        "--net",
        &net,
        "--param",
        "m=3",
        "--at",
        "1/2,1/2",
        "--allow-outside-range",
    ]);
    assert!(value(&out, "z").is_finite(), "{out}");
}

/// One cell of a CSV surface table.
fn cell(csv: &str, corner: &str, a: usize, b: usize) -> String {
    let prefix = format!("\"corner u at its {corner}\",{a},{b},");
    csv.lines()
        .find_map(|l| l.strip_prefix(&prefix))
        .unwrap_or_else(|| panic!("no {corner} {a} {b} in {csv}"))
        .to_string()
}

#[test]
fn the_corner_table_reproduces_the_printed_terminal_properties() {
    // thesis (5.12): S'(0) = (m + 2)(P₅ − P₄), S''(0) = 2P₆ − (4m + 4)P₅ +
    // (4m + 2)P₄, S'(1) = (m + 2)(P₃ − P₂), in the angle θ
    let csv = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--surface",
        "--order",
        "2",
        "--format",
        "csv",
    ]);
    assert_eq!(cell(&csv, "start, v at its start", 0, 0), "P00");
    assert_eq!(cell(&csv, "end, v at its end", 0, 0), "P33");
    assert_eq!(
        cell(&csv, "start, v at its start", 1, 0),
        "(-m - 2)*P00 + (m + 2)*P10"
    );
    assert_eq!(
        cell(&csv, "start, v at its start", 2, 0),
        "(4*m + 2)*P00 + (-4*m - 4)*P10 + 2*P20"
    );
    assert_eq!(
        cell(&csv, "end, v at its start", 1, 0),
        "(-m - 2)*P20 + (m + 2)*P30"
    );
    // the mixed derivative is the product of the two directions
    assert_eq!(
        cell(&csv, "start, v at its start", 1, 1),
        "(m^2 + 4*m + 4)*P00 + (-m^2 - 4*m - 4)*P01 + (-m^2 - 4*m - 4)*P10 + (m^2 + 4*m + 4)*P11"
    );
    // another basis in v, at a parameter value, with respect to u
    let csv = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--surface",
        "--v-family",
        "bernstein3",
        "--param",
        "m=0",
        "--order",
        "1",
        "--wrt",
        "u",
        "--format",
        "csv",
    ]);
    assert_eq!(cell(&csv, "start, v at its start", 0, 1), "-3*P00 + 3*P01");
    assert_eq!(
        cell(&csv, "start, v at its start", 1, 0),
        "-pi*P00 + pi*P10"
    );
    assert_errors(&[
        (
            &[
                "table",
                "thesis-cubic",
                "--surface",
                "--numeric",
                "--param",
                "m=0",
            ],
            "table --surface is exact",
        ),
        (
            &["table", "thesis-cubic", "--surface", "--order", "7"],
            "--order 7",
        ),
    ]);
}

#[test]
fn the_rational_corner_table_is_the_quotient_and_equal_weights_change_nothing() {
    let table = |net: &str| {
        stdout_ok(&[
            "table",
            "thesis-cubic",
            "--surface",
            "--order",
            "2",
            "--format",
            "csv",
            "--net",
            net,
        ])
    };
    let weighted = table(&example("surfaces/thesis-net-weighted.txt"));
    // ∂S/∂v at (0, 0) is (w₀₁/w₀₀)(m + 2)(P₀₁ − P₀₀) = 2(m + 2)(P₀₁ − P₀₀)
    assert_eq!(
        cell(&weighted, "start, v at its start", 0, 1),
        "(-2*m - 4)*P00 + (2*m + 4)*P01"
    );
    // the corner point is still interpolated; the mixed derivative is not
    // the polynomial surface's (m + 2)²(P₀₀ − P₀₁ − P₁₀ + P₁₁)
    assert_eq!(cell(&weighted, "end, v at its end", 0, 0), "P33");
    assert!(
        cell(&weighted, "start, v at its start", 1, 1).starts_with("(7*m^2 + 28*m + 28)*P00"),
        "{weighted}"
    );
    // equal weights: the polynomial table, entry by entry
    let plain = stdout_ok(&[
        "table",
        "thesis-cubic",
        "--surface",
        "--order",
        "2",
        "--format",
        "csv",
    ]);
    let equal: String = std::fs::read_to_string(net())
        .expect("the example net")
        .lines()
        .map(|l| match l.starts_with('#') || l.trim().is_empty() {
            true => format!("{l}\n"),
            false => format!("{l} 7/2\n"),
        })
        .collect();
    let equal = table(&scratch("equal-weights.txt", &equal));
    assert_eq!(equal, plain);
    assert_ne!(weighted, plain);
    // a net of the wrong size for the bases
    let small = scratch("small-weighted.txt", "0 0 0 1\n1 0 0 2\n");
    assert_errors(&[(
        &["table", "thesis-cubic", "--surface", "--net", &small],
        "expected 4, got 1",
    )]);
}

/// The line of a forced point in `join` text output.
fn forced<'a>(out: &'a str, point: &str) -> &'a str {
    out.lines()
        .find_map(|l| l.trim().strip_prefix(&format!("{point} = ")))
        .unwrap_or_else(|| panic!("no {point} in {out}"))
}

#[test]
fn the_surface_join_is_the_printed_theorems_column_by_column() {
    // Theorem 5.1 (5.13): P₅ = 2P₃ − P₂ with one m; the cylinder's C²
    // points (Section 5.4.3): Q₂ = P₁ − (4m + 4)P₂ + (4m + 4)P₃
    let out = stdout_ok(&["join", "thesis-cubic", "--surface", "--kind", "c2"]);
    for j in 0..4 {
        assert_eq!(
            forced(&out, &format!("Q₀{}", sub(j))),
            format!("P₃{}", sub(j))
        );
        assert_eq!(
            forced(&out, &format!("Q₁{}", sub(j))),
            format!("−P₂{0} + 2·P₃{0}", sub(j))
        );
        assert_eq!(
            forced(&out, &format!("Q₂{}", sub(j))),
            format!("P₁{0} + (−4·m − 4)·P₂{0} + (4·m + 4)·P₃{0}", sub(j))
        );
    }
    assert!(out.contains("across u: u = 1 of the first patch is u = 0 of the second"));
    // Theorem 5.2 (5.25): P₅ = α(P₃ − P₂) + P₃, here across v (rows)
    let out = stdout_ok(&[
        "join",
        "thesis-cubic",
        "--surface",
        "--kind",
        "g1",
        "--across",
        "v",
    ]);
    assert_eq!(forced(&out, "Q₂₁"), "−α·P₂₂ + (α + 1)·P₂₃");
    assert_eq!(forced(&out, "Q₂₀"), "P₂₃");
    // another basis in v changes nothing of a join across u: only the count
    let out = stdout_ok(&[
        "join",
        "bernstein3",
        "--surface",
        "--kind",
        "c1",
        "--v-family",
        "thesis-cubic",
        "--format",
        "json",
    ]);
    assert!(out.contains("\"v\": \"thesis-cubic\""), "{out}");
    assert!(out.contains("\"point\": \"Q13\""), "{out}");
    assert_errors(&[(
        &[
            "join",
            "thesis-cubic",
            "--surface",
            "--kind",
            "c1",
            "--v-param",
            "m=0",
        ],
        "drop --v-param",
    )]);
}

/// The subscript digit of `j`.
fn sub(j: usize) -> char {
    char::from_u32(0x2080 + j as u32).expect("a subscript digit")
}

#[test]
fn a_spline_surface_over_knot_vectors_is_the_window_of_its_span() {
    // seed 004 (5): 5 × 4 points, u knots 0,0,0,0,1,3,3,3 (spans [0, 1],
    // [1, 3]), v knots 0,0,0,0,1,1,1 (one span): the point u = 2 lies in
    // the second span at local 1/2, the patch over rows 1 … 4
    let row = |i: i64| {
        (0..4)
            .map(|j| format!("{i} {j} {}", (i * j) % 3 + i))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let net = |rows: std::ops::Range<i64>| rows.map(row).collect::<Vec<_>>().join("\n\n") + "\n";
    let whole = scratch("knots-whole.txt", &net(0..5));
    let window = scratch("knots-window.txt", &net(1..5));
    let eval = |net: &str, extra: &[&str]| {
        let mut args = vec![
            "eval",
            "thesis-cubic",
            "--surface",
            "--net",
            net,
            "--param",
            "m=1/2",
            "--digits",
            "25",
        ];
        args.extend_from_slice(extra);
        stdout_ok(&args)
    };
    let spline = eval(
        &whole,
        &[
            "--knots",
            "0,0,0,0,1,3,3,3",
            "--v-knots",
            "0,0,0,0,1,1,1",
            "--at",
            "2,1/3",
        ],
    );
    let patch = eval(&window, &["--at", "1/2,1/3"]);
    for name in ["x", "y", "z"] {
        let line = |out: &str| {
            out.lines()
                .find(|l| l.starts_with(&format!("{name} =")))
                .map(str::to_string)
        };
        assert_eq!(line(&spline), line(&patch), "{spline}\n{patch}");
    }
    assert!(
        spline.contains("the piece of the net's 5 × 4 points at local (1/2, 1/3)"),
        "{spline}"
    );
    // one-line errors: a knot vector of the wrong length, a zero-length
    // span, a point outside the spans, one knot vector only
    fn knots<'a>(whole: &'a str, u: &'a str, v: &'a str, at: &'a str) -> Vec<&'a str> {
        vec![
            "eval",
            "thesis-cubic",
            "--surface",
            "--net",
            whole,
            "--param",
            "m=1/2",
            "--knots",
            u,
            "--v-knots",
            v,
            "--at",
            at,
        ]
    }
    assert_errors(&[
        (
            &knots(&whole, "0,0,0,0,1,3,3", "0,0,0,0,1,1,1", "2,0")[..],
            "take 8 knots",
        ),
        (
            &knots(&whole, "0,0,0,0,1,1,3,3", "0,0,0,0,1,1,1", "2,0")[..],
            "zero-length interval",
        ),
        (
            &knots(&whole, "0,0,0,0,1,3,3,3", "0,0,0,0,1,1,1", "4,0")[..],
            "outside the domain",
        ),
        (
            &[
                "eval",
                "thesis-cubic",
                "--surface",
                "--net",
                whole.as_str(),
                "--param",
                "m=1/2",
                "--knots",
                "0,0,0,0,1,3,3,3",
                "--at",
                "2,0",
            ][..],
            "takes both: --knots (u) and --v-knots (v)",
        ),
    ]);
}
