//! End-to-end tests of `trig-audit audit`.

use trig_e2e::{error_line, run, stdout_ok};

#[test]
fn audit_runs_and_exits_zero_whatever_the_verdicts() {
    // the one full audit of this file; the others select a few claims
    let out = stdout_ok(&["audit"]);
    assert!(out.starts_with("# trig-audit report"));
    assert!(out.contains("## Summary"));
    assert!(out.contains("fails"), "some printed claims fail");
}

#[test]
fn filters_and_json() {
    let out = stdout_ok(&["audit", "--seed", "004", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let claims = json["claims"].as_array().expect("claims");
    assert!(!claims.is_empty());
    assert!(claims.iter().all(|c| c["seed"] == "004"));
    let one = stdout_ok(&["audit", "--claim", "t4b", "--format", "json"]);
    let json: serde_json::Value = serde_json::from_str(&one).expect("JSON");
    assert_eq!(json["claims"].as_array().map(Vec::len), Some(1));
}

#[test]
fn output_file_is_written_whole() {
    let dir = std::env::temp_dir().join(format!("trig-audit-e2e-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("report.md");
    let msg = trig_e2e::written(&[
        "audit",
        "--seed",
        "004",
        "--output",
        path.to_str().expect("utf-8 path"),
    ]);
    assert!(msg.starts_with("wrote "), "{msg}");
    let written = std::fs::read_to_string(&path).expect("report written");
    assert_eq!(written, stdout_ok(&["audit", "--seed", "004"]));
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .expect("list")
        .filter_map(Result::ok)
        .filter(|e| e.file_name() != "report.md")
        .collect();
    assert!(leftovers.is_empty(), "no temporary file left behind");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&path)
            .expect("written")
            .permissions()
            .mode();
        assert_eq!(
            mode & 0o777,
            0o644,
            "an ordinary file, not the private temporary one"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_audit_requests_fail_cleanly() {
    assert!(error_line(&["audit", "--seed", "7"]).contains("--seed"));
    assert!(error_line(&["audit", "--claim", "Z99"]).contains("no claim"));
    let out = run(&["audit", "--output", "/nonexistent-dir/x.md"]);
    assert!(!out.status.success());
    // refused before the claims are decided, with the write's own error
    assert!(
        error_line(&["audit", "--output", "/nonexistent-dir/x.md"])
            .contains("cannot write /nonexistent-dir/x.md: its directory does not exist")
    );
    assert!(
        error_line(&["audit", "--output", "/etc/passwd/x.md"])
            .contains("cannot write /etc/passwd/x.md: a part of its path is not a directory")
    );
}

#[test]
fn closed_and_full_standard_output_end_without_a_panic() {
    use std::process::{Command, Stdio};
    // a reader that goes away before the output is written: exit 0, as
    // Unix tools do
    let mut child = Command::new(trig_e2e::binary())
        .args(["list"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("wait");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // a full disk: one line on standard error, exit 2
    if let Ok(full) = std::fs::File::create("/dev/full") {
        let out = Command::new(trig_e2e::binary())
            .args(["list"])
            .stdout(full)
            .output()
            .expect("run");
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.starts_with("error: cannot write to standard output") && err.lines().count() == 1,
            "{err}"
        );
    }
    // a full device as the output file: the device's error, and the device
    // is still a device (an atomic rename would have replaced it)
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let is_device =
            || std::fs::metadata("/dev/full").is_ok_and(|m| m.file_type().is_char_device());
        if is_device() {
            let err = trig_e2e::error_line(&["audit", "--seed", "003", "--output", "/dev/full"]);
            assert!(err.contains("cannot write /dev/full"), "{err}");
            assert!(is_device(), "/dev/full was replaced");
        }
    }
}
