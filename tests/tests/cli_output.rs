//! `--output FILE` on every command that prints its result (`table`,
//! `join`, `eval` — with `--at-file` too —, `list`, `interp`, `completions`,
//! `man`): the file holds exactly what standard output would, written
//! atomically (issue 40; `audit --output` is tested in `cli_audit.rs`).

use std::path::{Path, PathBuf};

use trig_e2e::{error_line, example, run_with_input, stdout_ok, written};

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("trig-e2e-output-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir
}

/// The files of `dir` (no temporary file may be left behind).
fn files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("list")
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn every_printing_command_writes_its_output_to_a_file() {
    let dir = scratch("all");
    let spec = example("independent/issue40/singular-table.toml");
    let commands: Vec<(&str, Vec<&str>)> = vec![
        ("table.md", vec!["table", "thesis-cubic", "--order", "2"]),
        (
            "table.csv",
            vec![
                "table",
                "--spec",
                &spec,
                "--curve",
                "--rational",
                "--order",
                "1",
                "--format",
                "csv",
            ],
        ),
        ("join.txt", vec!["join", "thesis-cubic", "--kind", "c1"]),
        (
            "join.json",
            vec!["join", "thesis-cubic", "--kind", "g1", "--format", "json"],
        ),
        (
            "eval.txt",
            vec!["eval", "thesis-cubic", "--param", "m=0.6", "--at", "0.25"],
        ),
        (
            "eval.json",
            vec![
                "eval",
                "han",
                "--param",
                "lambda=1/2",
                "--at",
                "1/3",
                "--digits",
                "20",
                "--format",
                "json",
            ],
        ),
        ("list.txt", vec!["list"]),
        (
            "interp.txt",
            vec!["interp", "--data", "thesis-table-4.2", "--scheme", "c2"],
        ),
        ("completions.bash", vec!["completions", "bash"]),
        ("man.roff", vec!["man", "table"]),
    ];
    for (file, args) in &commands {
        let path = dir.join(file);
        let path_text = path.to_str().expect("utf-8 path");
        let mut with = args.clone();
        with.extend(["--output", path_text]);
        let note = written(&with);
        assert!(note.starts_with(&format!("wrote {path_text}")), "{note}");
        let text = std::fs::read_to_string(&path).expect("written");
        assert!(!text.is_empty(), "{file}");
        assert_eq!(
            text,
            stdout_ok(args),
            "{file}: the file is standard output's text"
        );
        // `--output -` is standard output
        let mut dash = args.clone();
        dash.extend(["--output", "-"]);
        assert_eq!(stdout_ok(&dash), text, "{file}");
    }
    let mut expected: Vec<String> = commands.iter().map(|(f, _)| f.to_string()).collect();
    expected.sort();
    assert_eq!(files(&dir), expected, "no temporary file left behind");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `eval --at-file` streams its rows into the file; a point that fails
/// half way leaves the old file as it was (atomic), and a missing
/// directory is refused before any work.
#[test]
fn eval_at_file_output_is_atomic() {
    let dir = scratch("stream");
    let path = dir.join("rows.tsv");
    let path_text = path.to_str().expect("utf-8 path");
    let args = [
        "eval",
        "han",
        "--param",
        "lambda=1/2",
        "--at-file",
        "-",
        "--output",
        path_text,
    ];
    let out = run_with_input(&args, "0\n1/4\n1/2\n");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.is_empty(), "rows go to the file");
    let rows = std::fs::read_to_string(&path).expect("written");
    let printed = run_with_input(&args[..6], "0\n1/4\n1/2\n");
    assert_eq!(rows.as_bytes(), printed.stdout.as_slice());
    assert_eq!(
        rows.lines().filter(|l| !l.starts_with('#')).count(),
        3,
        "{rows}"
    );
    // a bad third point: an error, and the file from before is untouched
    let failed = run_with_input(&args, "0\n1/4\nnot-a-number\n");
    assert!(!failed.status.success());
    assert_eq!(std::fs::read_to_string(&path).expect("kept"), rows);
    assert_eq!(files(&dir), ["rows.tsv"], "no temporary file left behind");
    let missing = dir.join("missing").join("x.txt");
    let line = error_line(&[
        "table",
        "thesis-cubic",
        "--output",
        missing.to_str().expect("utf-8 path"),
    ]);
    assert!(line.contains("cannot write"), "{line}");
    let _ = std::fs::remove_dir_all(&dir);
}
