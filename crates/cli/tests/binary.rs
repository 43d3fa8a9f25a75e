//! The `trig-audit` binary itself: the exit status and the stream of each
//! outcome (`src/main.rs`). The commands are tested end to end in the
//! workspace's `tests/` crate, which runs this same binary: having an
//! integration test here is what makes `cargo test --workspace` build it.

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_trig-audit"))
        .args(args)
        .output()
        .expect("run trig-audit")
}

#[test]
fn a_command_that_runs_writes_standard_output_and_exits_0() {
    let out = run(&["list"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("thesis-cubic"));
    assert!(out.stderr.is_empty());
}

#[test]
fn version_goes_to_standard_output() {
    let out = run(&["--version"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("trig-audit "));
}

#[test]
fn an_error_is_one_line_on_standard_error_with_status_2() {
    let out = run(&["eval", "no-such-family", "--at", "0"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.starts_with("error: "), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
}

#[test]
fn a_usage_error_keeps_clap_hints_with_status_2() {
    let out = run(&["audti"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("audit"), "{err}");
    assert!(err.lines().count() > 1, "{err}");
}
