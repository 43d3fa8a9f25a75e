//! What the test modules share: the example spec files with claims
//! appended, and a verdict's evidence as lines.

use std::path::PathBuf;

use trig_specfile::Spec;
use trig_verification::Verdict;

/// The text of `examples/{name}.toml`.
pub fn example_text(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../examples")
        .join(format!("{name}.toml"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// `examples/{name}.toml` with `claims` (TOML) appended.
pub fn example_with(name: &str, claims: &str) -> Spec {
    Spec::from_str_named(&format!("{}\n{claims}", example_text(name)), name)
        .unwrap_or_else(|e| panic!("{e}"))
}

/// The evidence of a verdict, one line per item.
pub fn evidence_lines(v: &Verdict) -> String {
    v.evidence
        .clone()
        .into_vec()
        .iter()
        .map(|e| e.line())
        .collect::<Vec<_>>()
        .join("\n")
}
