//! `audit --format tex`: a fragment for `\input` by default, a complete
//! document with `--standalone`; figures included by their path relative to
//! where the report is written, or named when their file is not there.

use std::path::{Path, PathBuf};
use std::process::Command;

use trig_e2e::{binary, error_line, stdout_ok};

/// The workspace root (where the figures' paths start).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

/// Runs `trig-audit` in `dir`, asserting success.
/// Runs `trig-audit` in `dir`; its standard output.
fn run_in(dir: &Path, args: &[&str]) -> String {
    let out = Command::new(binary())
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run trig-audit");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8 output")
}

#[test]
fn a_fragment_by_default_a_document_with_standalone() {
    let part = stdout_ok(&["audit", "--seed", "004", "--format", "tex"]);
    assert!(part.starts_with("% trig-audit report"), "{part}");
    assert!(part.contains("amsmath,amssymb,booktabs,longtable,array,graphicx"));
    assert!(!part.contains("\\documentclass") && !part.contains("\\begin{document}"));
    assert!(part.contains("\\toprule") && !part.contains("\\hline"));
    let whole = stdout_ok(&["audit", "--seed", "004", "--format", "tex", "--standalone"]);
    assert!(whole.starts_with("\\documentclass"));
    assert!(whole.trim_end().ends_with("\\end{document}"));
    let bad = error_line(&["audit", "--seed", "004", "--standalone"]);
    assert!(
        bad.contains("--standalone applies to --format tex"),
        "{bad}"
    );
    let body = |t: &str| t[t.find("\\section*").expect("a title")..].to_string();
    assert!(
        body(&whole).starts_with(&body(&part)[..200]),
        "the same report"
    );
}

/// T7's report (with the figure) written by `audit --output` to
/// `report.EXT` in the subdirectory `paper` of a fresh temporary
/// directory, run from the repository root: the temporary directory, the
/// subdirectory and the report.
fn written_in_subdirectory(ext: &str, format: &[&str]) -> (PathBuf, PathBuf, String) {
    let out = std::env::temp_dir().join(format!("trig-audit-{ext}-{}", std::process::id()));
    let sub = out.join("paper");
    std::fs::create_dir_all(&sub).unwrap();
    let file = sub.join(format!("report.{ext}"));
    let file_arg = file.display().to_string();
    let args = [
        &["audit", "--claim", "T7"],
        format,
        &["--output", &file_arg],
    ]
    .concat();
    run_in(&root(), &args);
    let text = std::fs::read_to_string(&file).unwrap();
    (out, sub, text)
}

#[test]
fn figures_are_included_relative_to_the_output_directory() {
    let (out, sub, tex) = written_in_subdirectory("tex", &["--format", "tex"]);
    let included = tex
        .split("\\input{")
        .nth(1)
        .and_then(|rest| rest.split('}').next())
        .unwrap_or_else(|| panic!("the figure is included: {tex}"));
    assert!(!Path::new(included).is_absolute(), "{included}");
    assert!(included.ends_with("audit-T7-thesis-cubic-outside-range.tex"));
    assert!(
        sub.join(included).is_file(),
        "{included} from {}",
        sub.display()
    );
    // run elsewhere, the figure file is not there: named, not included
    let file = sub.join("report.tex");
    let file_arg = file.display().to_string();
    run_in(
        &out,
        &[
            "audit", "--claim", "T7", "--format", "tex", "--output", &file_arg,
        ],
    );
    let tex = std::fs::read_to_string(&file).unwrap();
    assert!(!tex.contains("\\input{"), "{tex}");
    let named = tex.replace("\\allowbreak{}", "");
    assert!(named.contains("docs/figures/audit-T7-thesis-cubic-outside-range.tex"));
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn markdown_links_figures_relative_to_the_output_directory() {
    let (out, sub, md) = written_in_subdirectory("md", &[]);
    let link = md
        .split("**Figure:** [")
        .nth(1)
        .and_then(|rest| rest.split("](").nth(1))
        .and_then(|rest| rest.split(')').next())
        .unwrap_or_else(|| panic!("a figure link: {md}"));
    assert!(
        !Path::new(link).is_absolute() && link.starts_with("../"),
        "{link}"
    );
    assert!(sub.join(link).is_file(), "{link} from {}", sub.display());
    // the figure's data and pgfplots code too
    for (label, ext) in [("data: `", ".csv"), ("pgfplots: `", ".tex")] {
        let path = md
            .split(label)
            .nth(1)
            .and_then(|rest| rest.split('`').next())
            .unwrap_or_else(|| panic!("{label}…`: {md}"));
        assert!(path.starts_with("../") && path.ends_with(ext), "{path}");
        assert!(sub.join(path).is_file(), "{path} from {}", sub.display());
    }
    // on standard output the link is from the current directory, as before
    let stdout = run_in(&root(), &["audit", "--claim", "T7"]);
    assert!(
        stdout.contains("](docs/figures/audit-T7-thesis-cubic-outside-range.svg)"),
        "{stdout}"
    );
    let _ = std::fs::remove_dir_all(&out);
}
