//! Helpers for the end-to-end tests: locate (building if needed) the
//! `trig-audit` binary of this workspace and run it.

pub mod fuzz;

use std::path::PathBuf;
use std::process::{Command, Output};
use std::sync::OnceLock;

/// Ids of every catalog family that has formulas and no knot vector.
pub const FAMILIES: &[&str] = &[
    "thesis-quadratic",
    "thesis-cubic",
    "han",
    "majeed-qayyum",
    "usman",
    "han-listing",
    "seed000-blending",
    "seed000-uniform",
    "seed002-quartic",
    "eh",
    "hermite",
    "bernstein3",
    "bspline3",
];

/// Path of the `trig-audit` binary of this workspace's test build: the
/// binary `cargo test --workspace` links (the command-line crate has an
/// integration test, so its binary is built with the test build's features).
/// Found by running `cargo test --workspace --no-run` once: after
/// `cargo test --workspace` (or `./run.sh test`) a no-op of a fraction of a
/// second; after `cargo test -p trig-e2e` it builds the rest of the
/// workspace's tests. A `cargo build -p trig-audit` would select other
/// features and compile every crate again (70 s in a clean clone's CI run).
/// The environment variable `TRIG_AUDIT_BIN` names another binary instead
/// (to run a new test against an older build and see it fail).
pub fn binary() -> PathBuf {
    static BIN: OnceLock<PathBuf> = OnceLock::new();
    BIN.get_or_init(|| {
        if let Some(other) = std::env::var_os("TRIG_AUDIT_BIN") {
            return PathBuf::from(other);
        }
        let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .parent()
            .expect("workspace root")
            .to_path_buf();
        // a relative CARGO_TARGET_DIR is read from the workspace root, where
        // the build below runs (`join` keeps an absolute one as it is)
        let target = root.join(
            std::env::var_os("CARGO_TARGET_DIR")
                .map(PathBuf::from)
                .unwrap_or_else(|| PathBuf::from("target")),
        );
        let mut cargo = Command::new(env!("CARGO"));
        cargo.args(["test", "--workspace", "--no-run", "--quiet"]);
        if trig_core::mpfr::SYSTEM_LIBS {
            cargo.args(["--features", "trig-core/system-gmp"]);
        }
        let status = cargo
            .current_dir(&root)
            .status()
            .expect("run cargo test --no-run");
        assert!(status.success(), "building the workspace's tests failed");
        target.join("debug").join("trig-audit")
    })
    .clone()
}

/// The path of a shipped spec file under `examples/`.
pub fn example(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../examples")
        .join(name)
        .display()
        .to_string()
}

/// Runs `trig-audit` with `args`.
pub fn run(args: &[&str]) -> Output {
    Command::new(binary())
        .args(args)
        .output()
        .expect("run trig-audit")
}

/// Runs `trig-audit` with `input` on its standard input.
pub fn run_with_input(args: &[&str], input: &str) -> Output {
    use std::io::Write;
    let mut child = Command::new(binary())
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run trig-audit");
    child
        .stdin
        .take()
        .expect("piped standard input")
        .write_all(input.as_bytes())
        .expect("write standard input");
    child.wait_with_output().expect("wait for trig-audit")
}

/// Runs `trig-audit`, asserts success, returns standard output.
pub fn stdout_ok(args: &[&str]) -> String {
    let out = run(args);
    assert!(
        out.status.success(),
        "trig-audit {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8 output")
}

/// Runs a `trig-audit` command that writes a file (`--output`): asserts
/// success and an empty standard output, returns standard error (the
/// `wrote …` note).
pub fn written(args: &[&str]) -> String {
    let out = run(args);
    let err = String::from_utf8(out.stderr).expect("utf-8 errors");
    assert!(out.status.success(), "trig-audit {args:?} failed: {err}");
    assert!(out.stdout.is_empty(), "trig-audit {args:?} printed results");
    err
}

/// Runs `trig-audit`, asserts failure with a one-line `error: …` message,
/// returns that line.
pub fn error_line(args: &[&str]) -> String {
    let out = run(args);
    assert!(!out.status.success(), "trig-audit {args:?} should fail");
    let err = String::from_utf8(out.stderr).expect("utf-8 error");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 1, "one-line error expected, got {err:?}");
    assert!(lines[0].starts_with("error: "), "{err}");
    assert!(out.stdout.is_empty(), "nothing on stdout when failing");
    lines[0].to_string()
}

/// The message of a command line that does not parse (clap's: the error,
/// a tip or the possible values, the usage), asserting exit status 2 and
/// nothing on standard output.
pub fn usage_error(args: &[&str]) -> String {
    let out = run(args);
    assert_eq!(
        out.status.code(),
        Some(2),
        "trig-audit {args:?} should fail"
    );
    let err = String::from_utf8(out.stderr).expect("utf-8 error");
    assert!(err.starts_with("error: "), "{err}");
    assert!(out.stdout.is_empty(), "nothing on stdout when failing");
    err
}

/// Asserts that each argument list fails with a one-line error containing
/// the expected text.
pub fn assert_errors(cases: &[(&[&str], &str)]) {
    for (args, expected) in cases {
        let line = error_line(args);
        assert!(line.contains(expected), "{args:?}: {line}");
    }
}
