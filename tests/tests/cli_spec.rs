//! `--spec FILE`: audit, table and eval of a basis typed into a spec file,
//! with good files (the shipped examples) and bad ones (one-line errors
//! naming file, line and column, exit status 2).

use std::path::PathBuf;

use trig_e2e::{assert_errors, example, run, stdout_ok};

/// Writes `text` to a fresh file in the target directory and returns its path.
fn bad_file(name: &str, text: &str) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli_spec");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write spec");
    path.display().to_string()
}

const HEADER: &str = "id = \"bad\"\ncitation = \"test\"\nvariable = \"unit-angle\"\n";

#[test]
fn audit_of_the_shipped_examples() {
    for (file, ids) in [
        (
            "thesis-cubic.toml",
            &["T6", "T7", "T9b", "T33", "join-C1"][..],
        ),
        ("seed002-quartic.toml", &["D1b", "D2", "D3"][..]),
        ("bashir-quadratic.toml", &["QTB-unity", "QTB-nonneg"][..]),
    ] {
        let md = stdout_ok(&["audit", "--spec", &example(file)]);
        assert!(md.starts_with("# trig-audit report"), "{file}");
        for id in ids {
            assert!(md.contains(&format!("</a>{id} — ")), "{file}: {id}");
        }
    }
    let json: serde_json::Value = serde_json::from_str(&stdout_ok(&[
        "audit",
        "--spec",
        &example("thesis-cubic.toml"),
        "--format",
        "json",
        "--claim",
        "T33",
    ]))
    .expect("json");
    assert_eq!(json["claims"][0]["verdict"], "fails");
    assert_eq!(json["claims"][0]["seed"], "thesis-cubic");
    let tex = stdout_ok(&[
        "audit",
        "--spec",
        &example("thesis-cubic.toml"),
        "--format",
        "tex",
        "--standalone",
    ]);
    assert!(tex.contains("\\subsection*{Spec thesis-cubic"));
    assert!(tex.trim_end().ends_with("\\end{document}"));
}

#[test]
fn table_and_eval_with_a_spec() {
    let t = stdout_ok(&[
        "table",
        "--spec",
        &example("thesis-cubic.toml"),
        "--order",
        "1",
        "--at",
        "start",
    ]);
    // b0'(0) = −m − 2 with respect to θ
    assert!(t.contains("−m − 2"), "{t}");
    // the same numbers as the catalog family: the spec evaluates the
    // canonical (expanded) form of its formulas, the catalog the printed
    // factored form; both print only proved digits at 128 bits (a value
    // proved to be within b of zero prints as `0 ± b`)
    let values = |text: &str| -> Vec<f64> {
        text.lines()
            .skip(1)
            .map(|l| {
                let v = l.split(" = ").nth(1).expect("value");
                v.strip_prefix("0 ± ")
                    .map_or_else(|| v.parse(), |_| Ok(0.0))
                    .expect("number")
            })
            .collect()
    };
    for at in ["0", "0.25", "1"] {
        let spec = stdout_ok(&[
            "eval",
            "--spec",
            &example("thesis-cubic.toml"),
            "--param",
            "m=0.6",
            "--at",
            at,
            "--prec",
            "128",
        ]);
        let builtin = stdout_ok(&[
            "eval",
            "thesis-cubic",
            "--param",
            "m=0.6",
            "--at",
            at,
            "--prec",
            "128",
        ]);
        for (a, b) in values(&spec).iter().zip(values(&builtin)) {
            assert!((a - b).abs() <= 1e-30, "u = {at}: {a} vs {b}");
        }
    }
}

#[test]
fn bad_spec_files_are_one_line_errors_with_a_position() {
    let unknown = bad_file(
        "unknown.toml",
        &format!("{HEADER}[[functions]]\nname = \"b0\"\nformula = \"1 - q*s\"\n"),
    );
    let wrong_var = bad_file(
        "wrong_var.toml",
        &format!("{HEADER}[[functions]]\nname = \"b0\"\nformula = \"1 - t\"\n"),
    );
    let vanish = bad_file(
        "vanish.toml",
        &format!(
            "{HEADER}[[parameters]]\nname = \"m\"\nrange = \"[-2, 1]\"\n[[functions]]\nname = \"b0\"\nformula = \"s/(m + 2)\"\n"
        ),
    );
    let reversed = bad_file(
        "reversed.toml",
        &format!(
            "{HEADER}[[parameters]]\nname = \"m\"\nrange = \"[1, -2]\"\n[[functions]]\nname = \"b0\"\nformula = \"1\"\n"
        ),
    );
    let unclosed = bad_file(
        "unclosed.toml",
        &format!(
            "{HEADER}[[functions]]\nname = \"b0\"\nformula = \"1\"\n[[claims]]\nid = \"U\"\nsource = \"(1)\"\nstatement = \"⟪b0(t) = 1 for t ∈ [0, 1]\"\ncheck = \"unity\"\n"
        ),
    );
    let malformed = bad_file("malformed.toml", "id = \"x\"\ncitation = \n");
    let missing = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("no-such-spec.toml")
        .display()
        .to_string();
    assert_errors(&[
        (
            &["audit", "--spec", &unknown],
            "unknown.toml:6:16: in formula `1 - q*s` at position 4: unknown symbol `q`",
        ),
        (
            &["eval", "--spec", &wrong_var, "--at", "0"],
            "wrong_var.toml:6:16: in formula `1 - t` at position 4: wrong variable",
        ),
        (
            &["table", "--spec", &vanish],
            "vanish.toml:9:13: in formula `s/(m + 2)` at position 1: division by `m + 2`, which vanishes",
        ),
        (
            &["audit", "--spec", &reversed],
            "reversed.toml:6:9: parameters.range: `[1, -2]`: the ends are reversed",
        ),
        (
            &["audit", "--spec", &unclosed],
            "unclosed.toml:10:13: claims.statement: math marks ⟪…⟫ (character positions counted from the statement's first): ⟪ at 0 is never closed",
        ),
        (
            &["audit", "--spec", &malformed],
            "malformed.toml:2:12: malformed spec file: invalid string; expected",
        ),
        (&["audit", "--spec", &missing], "cannot read"),
        (
            &[
                "audit",
                "--spec",
                &example("thesis-cubic.toml"),
                "--claim",
                "nope",
            ],
            "no claim matches",
        ),
        (
            &[
                "eval",
                "--spec",
                &example("thesis-cubic.toml"),
                "--param",
                "m=5",
                "--at",
                "0",
            ],
            "outside the published range",
        ),
    ]);
    let out = run(&["audit", "--spec", &unknown]);
    assert_eq!(out.status.code(), Some(2));
}

/// A reader corrects a paper without touching Rust (issue 41's test, on the
/// thesis's own spec file): a copy of `examples/thesis-cubic.toml` with the
/// printed C¹ formula `Q1 = 2 P3 − P2` edited is audited anew — a flipped
/// sign is a correctable misprint (the correction and a witness named), a
/// wrong coefficient fails with the witness `P3 = 1, P2 = 0`: printed 3,
/// derived 2.
#[test]
fn an_edited_printed_formula_in_a_copied_spec_file_is_caught() {
    let text = std::fs::read_to_string(example("thesis-cubic.toml")).expect("example");
    let printed = r#"conditions = ["Q0 = P3", "Q1 = 2*P3 - P2"]"#;
    assert!(text.contains(printed), "the printed C¹ formula");
    let verdict = |edited: &str, name: &str| {
        let path = crate::cli_spec_features::spec_file(name, &text.replace(printed, edited));
        stdout_ok(&["audit", "--spec", &path, "--claim", "C1-join"])
    };
    let md = verdict(
        r#"conditions = ["Q0 = P3", "Q1 = 2*P3 + P2"]"#,
        "thesis-sign.toml",
    );
    assert!(
        md.contains("C1-join — holds-after-correction")
            && md.contains("flip the sign of the printed term P₂ in the formula for Q₁"),
        "{md}"
    );
    let md = verdict(
        r#"conditions = ["Q0 = P3", "Q1 = 3*P3 - P2"]"#,
        "thesis-coefficient.toml",
    );
    assert!(
        md.contains("C1-join — fails")
            && md.contains("at `P₃ = 1, P₂ = 0`: printed Q₁ = `3`, derived Q₁ = `2`"),
        "{md}"
    );
}

/// The thesis's document file copied to a scratch directory with its
/// `[bases]` pointing at the shipped spec files, and the printed C¹ join
/// formula (4.6) of claim T12 edited: the copy is audited anew, no Rust
/// touched — a flipped sign is a correctable misprint (the sign to flip and
/// a witness named), a wrong coefficient fails with the witness `P3 = 1,
/// P2 = 0`: printed 3, derived 2.
#[test]
fn an_edited_printed_formula_in_a_copied_document_file_is_caught() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../documents/thesis");
    let text =
        std::fs::read_to_string(dir.join("document.toml")).expect("the thesis's document file");
    // every basis by its absolute path, so the copy reads the shipped spec files
    let mut in_bases = false;
    let absolute: String = text
        .lines()
        .map(|line| {
            if line.starts_with('[') {
                in_bases = line == "[bases]";
            }
            match line.split_once(" = \"") {
                Some((name, path)) if in_bases => {
                    let path = path.trim_end_matches('"');
                    format!("{name} = \"{}\"\n", dir.join(path).display())
                }
                _ => format!("{line}\n"),
            }
        })
        .collect();
    assert_ne!(absolute, text, "the [bases] paths rewritten");
    let start = absolute.find("id = \"T12\"").expect("claim T12");
    let end = start
        + absolute[start..]
            .find("[[claims]]")
            .expect("the next claim");
    let printed = r#""P5 = 2*P3 - P2""#;
    assert!(absolute[start..end].contains(printed), "the printed (4.6)");
    let audit = |edited: &str, name: &str| {
        let copy = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
            .join("cli_spec_document")
            .join(name);
        std::fs::create_dir_all(&copy).expect("scratch dir");
        // the data files beside the document file (the printed tables) come along
        for entry in std::fs::read_dir(&dir).expect("the thesis's folder") {
            let path = entry.expect("a file of the folder").path();
            if let Some(name) = path.file_name().filter(|n| *n != "document.toml") {
                std::fs::copy(&path, copy.join(name)).expect("copy a data file");
            }
        }
        let file = copy.join("document.toml");
        let block = absolute[start..end].replace(printed, edited);
        std::fs::write(
            &file,
            format!("{}{block}{}", &absolute[..start], &absolute[end..]),
        )
        .expect("write the copy");
        stdout_ok(&[
            "audit",
            "--spec",
            &file.display().to_string(),
            "--claim",
            "T12",
        ])
    };
    let md = audit(r#""P5 = 2*P3 + P2""#, "sign");
    assert!(
        md.contains("T12 — holds-after-correction")
            && md.contains("flip the sign of the printed term P₂ in the formula for P₅")
            && md.contains("**Witness:** derived (angle θ) at `P₂ = 1, P₃ = 0`: printed P₅ = `1`, derived P₅ = `−1`"),
        "{md}"
    );
    let md = audit(r#""P5 = 3*P3 - P2""#, "coefficient");
    assert!(
        md.contains("T12 — fails")
            && md.contains("use the derived formula: P₄ = P₃; P₅ = −P₂ + 2·P₃")
            && md.contains("at `P₃ = 1, P₂ = 0`: printed P₅ = `3`, derived P₅ = `2`"),
        "{md}"
    );
    // the copy as shipped holds, as the document file does
    assert!(audit(printed, "as-printed").contains("T12 — holds\n"));
}
