//! The figures the audit report links (`[claims.figure]` of the document
//! files): each is drawn by the `trig-audit` command the report states, into a scratch directory here
//! (or over the committed file with `TRIG_AUDIT_REDRAW_FIGURES=1`, which is
//! what `./run.sh figures` does), and the committed file exists, with its
//! data (`.csv`) and its pgfplots code (`.tex`) beside it; the pgfplots code
//! is ASCII and, when `pdflatex` is on the machine, compiles.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

#[test]
fn every_linked_figure_is_drawn_by_its_command_and_committed() {
    let redraw = std::env::var_os("TRIG_AUDIT_REDRAW_FIGURES").is_some();
    let scratch = std::env::temp_dir().join(format!("trig-audit-figures-{}", std::process::id()));
    std::fs::create_dir_all(&scratch).expect("scratch directory");
    let entries = trig_verification::run(None, None).expect("the document files");
    let figures: Vec<_> = entries
        .iter()
        .filter_map(|e| e.figure.as_ref().map(|f| (e.id.as_str(), f)))
        .collect();
    assert!(!figures.is_empty(), "the report links no figure");
    for (claim, f) in figures {
        let target = if redraw {
            root().join(&f.path)
        } else {
            scratch.join(Path::new(&f.path).file_name().expect("file name"))
        };
        let target = target.to_string_lossy().into_owned();
        let args: Vec<&str> = f
            .command
            .split_whitespace()
            .map(|a| if a == f.path { target.as_str() } else { a })
            .collect();
        let out = trig_e2e::written(&args);
        assert!(out.contains("wrote"), "{claim}: {out}");
        let svg = std::fs::read_to_string(&target).expect("figure written");
        assert!(
            svg.starts_with("<svg") || svg.starts_with("<?xml"),
            "{claim}"
        );
        let data = std::fs::read_to_string(Path::new(&target).with_extension("csv"))
            .expect("the data written beside the figure");
        assert!(data.starts_with("series,point,x,y\n"), "{claim}");
        let pgf = Path::new(&target).with_extension("tex");
        let tex = std::fs::read_to_string(&pgf).expect("the pgfplots code beside the figure");
        assert!(tex.is_ascii(), "{claim}: non-ASCII pgfplots code");
        assert!(
            tex.contains("\\begin{axis}") && tex.contains("\\addlegendentry{"),
            "{claim}"
        );
        compiles(&pgf, &scratch, claim);
        for path in [f.path.clone(), f.data_path(), f.pgf_path()] {
            assert!(root().join(&path).exists(), "{path} is not committed");
        }
    }
    let _ = std::fs::remove_dir_all(&scratch);
}

/// Compiles the pgfplots code `pgf` in a figure of a plain article with
/// pdflatex in the directory `dir` (no error, no overfull box), when
/// pdflatex (with pgfplots) is on the machine; says so when not.
fn compiles(pgf: &Path, dir: &Path, claim: &str) {
    let available = Command::new("kpsewhich")
        .arg("pgfplots.sty")
        .output()
        .is_ok_and(|o| o.status.success());
    if !available {
        eprintln!("skipped: pdflatex with pgfplots is not on this machine ({claim})");
        return;
    }
    let name = pgf.file_name().and_then(|n| n.to_str()).expect("file name");
    if pgf.parent() != Some(dir) {
        std::fs::copy(pgf, dir.join(name)).expect("pgfplots code copied");
    }
    let doc = dir.join(format!("doc-{name}"));
    std::fs::write(
        &doc,
        format!(
            "\\documentclass{{article}}\n\\usepackage{{pgfplots}}\n\\pgfplotsset{{compat=1.16}}\n\\begin{{document}}\n\\begin{{figure}}\n\\centering\n\\input{{{name}}}\n\\caption{{C}}\n\\end{{figure}}\n\\end{{document}}\n"
        ),
    )
    .expect("document written");
    let out = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error"])
        .arg(doc.file_name().expect("name"))
        .current_dir(dir)
        .output()
        .expect("pdflatex runs");
    let log = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{claim}: pdflatex failed:\n{log}");
    assert!(
        !log.contains("Missing character"),
        "{claim}: a character is missing:\n{log}"
    );
    // a default article's text width, no margin added
    assert!(
        !log.contains("Overfull"),
        "{claim}: wider than the text:\n{log}"
    );
    assert!(
        doc.with_extension("pdf").exists(),
        "{claim}: no PDF written"
    );
}
