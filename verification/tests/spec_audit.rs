//! The audit of spec files: the thesis-cubic spec reproduces the built-in
//! thesis claims verdict for verdict and evidence line for line, and every
//! shipped example audits.

use std::path::PathBuf;

use trig_specfile::Spec;
use trig_verification::report::Entry;
use trig_verification::{Status, run, spec_audit};

fn example(name: &str) -> Spec {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../examples")
        .join(name);
    Spec::from_file(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn entry<'a>(entries: &'a [Entry], id: &str) -> &'a Entry {
    entries
        .iter()
        .find(|e| e.id == id)
        .unwrap_or_else(|| panic!("no entry {id}"))
}

#[test]
fn spec_thesis_cubic_matches_builtin() {
    let entries = spec_audit::audit(&example("thesis-cubic.toml"));
    for id in ["T6", "T7", "T8", "T8a", "T8b", "T9", "T9b", "T33"] {
        let builtin = run(None, Some(id));
        assert_eq!(builtin.len(), 1, "{id}");
        let (b, s) = (&builtin[0].verdict, &entry(&entries, id).verdict);
        assert_eq!(s.status, b.status, "{id}");
        assert_eq!(s.method, b.method, "{id}");
        assert_eq!(s.evidence, b.evidence, "{id}");
        assert_eq!(s.correction, b.correction, "{id}");
        assert_eq!(
            entry(&entries, id).statement,
            builtin[0].claim.statement,
            "{id}"
        );
    }
}

#[test]
fn thesis_cubic_battery_and_extra_claims() {
    let entries = spec_audit::audit(&example("thesis-cubic.toml"));
    let status = |id: &str| entry(&entries, id).verdict.status;
    for id in [
        "unity",
        "nonnegativity",
        "symmetry",
        "interpolation",
        "derivatives",
        "join-C1",
        "join-C2",
        "first-derivatives",
        "C1-join",
    ] {
        assert_eq!(
            status(id),
            Status::Holds,
            "{id}: {:?}",
            entry(&entries, id).verdict
        );
    }
}

#[test]
fn seed002_quartic_spec_audits() {
    let entries = spec_audit::audit(&example("seed002-quartic.toml"));
    let status = |id: &str| entry(&entries, id).verdict.status;
    // the built-in D1b, D2, D3 decide the same statements
    for id in ["D1b", "D2", "D3"] {
        assert_eq!(status(id), run(None, Some(id))[0].verdict.status, "{id}");
    }
    assert_eq!(status("unity"), Status::Holds);
    assert_eq!(status("interpolation"), Status::Holds);
}

#[test]
fn literature_example_audits() {
    let entries = spec_audit::audit(&example("bashir-quadratic.toml"));
    assert_eq!(entry(&entries, "unity").verdict.status, Status::Holds);
    assert!(
        entries.iter().all(|e| !e.verdict.evidence.is_empty()),
        "every entry has evidence"
    );
}
