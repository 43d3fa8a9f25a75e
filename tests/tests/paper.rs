//! A researcher's own paper, end to end (issue 40): a plain `article` that
//! `\input`s the audits of every spec file of `examples/` (Greek symbols,
//! weights, two and three parameters), an exact table, a G² join fragment
//! and a figure of a two-parameter basis must compile with no error and no
//! overfull box. Under
//! `./run.sh test` (TeX installed, `TRIG_AUDIT_REQUIRE_TEX`) it cannot be
//! skipped.

use std::path::Path;

use crate::cli_paste::{compiles_cleanly, draw, scratch};
use trig_e2e::{example, stdout_ok, written};

/// The spec files whose audits the paper includes: every one of
/// `examples/` and `examples/catalog/` — Greek symbols, weights (a rational
/// one fixed in a claim), two and three parameters, exchange symmetry,
/// joins with poles in the printed ranges, irrational range ends.
fn audited() -> Vec<String> {
    let mut files: Vec<String> = ["", "catalog"]
        .iter()
        .flat_map(|dir| {
            let root = Path::new(&example("")).join(dir);
            std::fs::read_dir(&root)
                .expect("examples/")
                .filter_map(Result::ok)
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
        })
        .collect();
    files.sort();
    assert!(files.len() >= 30, "{files:?}");
    files
}

/// Writes `text` to `dir/name` and returns its path as LaTeX reads it.
fn fragment(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("fragment written");
    path.display().to_string()
}

#[test]
fn a_paper_inputting_spec_audits_a_table_a_join_and_a_figure_compiles() {
    let dir = scratch("paper");
    let mut body = String::from("\\section{Audits of the bases}\n");
    for (k, spec) in audited().iter().enumerate() {
        let path = dir.join(format!("audit-{k}.tex"));
        let out = written(&[
            "audit",
            "--spec",
            spec,
            "--format",
            "tex",
            "--output",
            &path.display().to_string(),
        ]);
        assert!(out.contains("wrote"), "{spec}: {out}");
        let tex = std::fs::read_to_string(&path).expect("audit written");
        // symbols as LaTeX, never raw Greek in math; roots as radicals
        assert!(
            !tex.contains("$α") && !tex.contains("$β") && !tex.contains("$λ"),
            "{spec}"
        );
        assert!(!tex.contains("operatorname{sqrt}"), "{spec}");
        body.push_str(&format!("\\input{{{}}}\n\\clearpage\n", path.display()));
    }
    let rqtb = example("rational-trig-two-shape.toml");
    let table = stdout_ok(&["table", "--spec", &rqtb, "--order", "2", "--format", "tex"]);
    body.push_str(&format!(
        "\\section{{An exact table}}\n\\input{{{}}}\n",
        fragment(&dir, "table.tex", &table)
    ));
    let hmh = example("han-ma-huang-cubic.toml");
    let join = stdout_ok(&[
        "join",
        "--spec",
        &hmh,
        "--kind",
        "g2",
        "--params",
        "different",
        "--format",
        "tex",
    ]);
    // the long G² formula one control point per line
    assert!(join.contains("&\\quad - ("), "{join}");
    body.push_str(&format!(
        "\\section{{A \\texorpdfstring{{$G^2$}}{{G2}} join}}\n\\input{{{}}}\n",
        fragment(&dir, "join.tex", &join)
    ));
    let (_, _) = draw(
        &dir,
        "figure",
        &["basis", "--spec", &hmh, "--param", "mu=1/2"],
    );
    body.push_str(&format!(
        "\\section{{A figure}}\n\\begin{{figure}}[h]\n\\centering\n\\input{{{}}}\n\\caption{{Han, Ma and Huang's basis at $\\mu = 1/2$.}}\n\\end{{figure}}\n",
        dir.join("figure.tex").display()
    ));
    let paper = format!(
        "\\documentclass{{article}}\n\\usepackage{{amsmath,amssymb,booktabs,longtable,array,graphicx}}\n\\usepackage{{hyperref}}\n\\usepackage{{pgfplots}}\n\\pgfplotsset{{compat=1.16}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    compiles_cleanly(&paper, "paper", true);
    let _ = std::fs::remove_dir_all(&dir);
}
