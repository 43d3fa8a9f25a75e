//! Compiling a document with `pdflatex` and reading its log: what the
//! tests of the reports, tables and figures check.

/// What `pdflatex` said about a document.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CompileLog {
    /// The error lines (`! …`) of the log.
    pub errors: Vec<String>,
    /// Number of overfull boxes.
    pub overfull: usize,
    /// Their log lines (the first few).
    pub overfull_lines: Vec<String>,
    /// Pages written.
    pub pages: usize,
}

/// Set (to anything) when TeX must be there: `./run.sh test` sets it after
/// installing a minimal TeX, so that a compile test cannot be skipped.
pub const REQUIRE_TEX: &str = "TRIG_AUDIT_REQUIRE_TEX";

/// Compiles `tex` with `pdflatex` (twice, for the links) in a temporary
/// directory and reads the log; `None` when `pdflatex` is not installed
/// (`./run.sh test` installs it) — unless [`REQUIRE_TEX`] is set: then a
/// log whose one error says so, which every compile test reports as a
/// failure. The tests of the reports, tables and figures use this; nothing
/// else runs TeX.
pub fn compile(tex: &str, name: &str) -> Option<CompileLog> {
    let installed = std::process::Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|probe| probe.status.success());
    if !installed {
        return std::env::var_os(REQUIRE_TEX).map(|_| CompileLog {
            errors: vec![format!(
                "! pdflatex is not installed, and {REQUIRE_TEX} requires it"
            )],
            ..CompileLog::default()
        });
    }
    let dir = std::env::temp_dir().join(format!("trig-audit-tex-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).ok()?;
    std::fs::write(dir.join(format!("{name}.tex")), tex).ok()?;
    for _ in 0..2 {
        let _ = std::process::Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error"])
            .arg(format!("{name}.tex"))
            .current_dir(&dir)
            .output()
            .ok()?;
    }
    let log = std::fs::read(dir.join(format!("{name}.log"))).ok()?;
    let log = String::from_utf8_lossy(&log);
    let overfull_lines: Vec<String> = log
        .lines()
        .filter(|l| l.starts_with("Overfull"))
        .map(str::to_string)
        .collect();
    let pages = log
        .lines()
        .find_map(|l| l.split("Output written on ").nth(1))
        .and_then(|rest| rest.split('(').nth(1))
        .and_then(|n| n.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    let out = CompileLog {
        errors: log
            .lines()
            .filter(|l| l.starts_with("! "))
            .map(str::to_string)
            .collect(),
        overfull: overfull_lines.len(),
        overfull_lines: overfull_lines.into_iter().take(10).collect(),
        pages,
    };
    let _ = std::fs::remove_dir_all(&dir);
    Some(out)
}
