//! `cargo test` as the audit: every checker runs, one test per document, and
//! the whole report is snapshotted (a changed verdict is a snapshot diff that
//! must be explained in the commit message). The report's promises are
//! tested here too: a witness for every claim that fails, a Markdown report
//! short enough to read, JSON that validates against the published schema,
//! LaTeX that maps every character (and compiles, when `pdflatex` is on the
//! machine).

use std::path::PathBuf;
use std::sync::OnceLock;

use trig_report::{self as report, View};
use trig_verification::Entry;
use trig_verification::{Status, run};

/// The whole audit, run once for the tests of this file.
pub(crate) fn entries() -> &'static [Entry] {
    static ALL: OnceLock<Vec<Entry>> = OnceLock::new();
    ALL.get_or_init(|| run(None, None).expect("the document files"))
}

/// The Markdown report of the whole audit.
pub(crate) fn markdown() -> String {
    report::markdown_entries(entries(), report::BUILTIN_INTRO, &View::default())
}

/// The JSON report of the whole audit.
pub(crate) fn json() -> report::Report {
    report::json_entries(entries(), report::BUILTIN_INTRO, &View::default())
}

/// The LaTeX report of the whole audit, a complete document.
pub(crate) fn tex() -> String {
    let standalone = report::TexOptions {
        standalone: true,
        output_dir: None,
    };
    report::tex_entries(
        entries(),
        report::BUILTIN_INTRO,
        &View::default(),
        &standalone,
    )
}

fn check_document(id: &str) {
    let of_document: Vec<&Entry> = entries().iter().filter(|e| e.document.id == id).collect();
    assert!(!of_document.is_empty(), "{id} has claims");
    // the document filter of `run` selects the same claims
    let ids = |o: &[&Entry]| o.iter().map(|e| e.id.clone()).collect::<Vec<_>>();
    if id == "003" {
        let filtered = run(Some(id), None).expect("the document files");
        assert_eq!(ids(&filtered.iter().collect::<Vec<_>>()), ids(&of_document));
    }
    for e in of_document {
        assert!(!e.verdict.evidence.is_empty(), "{} has evidence", e.id);
        assert!(!e.verdict.method.is_empty(), "{} says how", e.id);
        if e.verdict.status == Status::HoldsAfterCorrection {
            assert!(
                e.verdict.correction.is_some(),
                "{} names its correction",
                e.id
            );
        }
    }
}

#[test]
fn seed_001_thesis() {
    check_document("001");
}

#[test]
fn seed_000_majeed_et_al() {
    check_document("000");
}

#[test]
fn seed_002_quartic_bezier() {
    check_document("002");
}

#[test]
fn seed_003_missing_formulas() {
    check_document("003");
}

#[test]
fn seed_004_eh_spline() {
    check_document("004");
}

#[test]
fn claim_ids_are_unique() {
    let mut ids: Vec<&str> = entries().iter().map(|e| e.id.as_str()).collect();
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n);
}

#[test]
fn every_claim_that_does_not_hold_shows_a_witness() {
    let md = markdown();
    for e in entries() {
        if matches!(
            e.verdict.status,
            Status::Fails | Status::HoldsAfterCorrection
        ) {
            let (_, w) = e
                .witness()
                .unwrap_or_else(|| panic!("{} has no witness", e.id));
            assert!(!w.values.is_empty(), "{}: a witness shows values", e.id);
            let section = md
                .split("### ")
                .find(|s| s.contains(&format!("</a>{} — ", e.id)))
                .unwrap_or_else(|| panic!("{} has a section", e.id));
            assert!(section.contains("- **Witness:**"), "{}", e.id);
        }
    }
}

#[test]
fn the_markdown_report_is_short_and_its_lines_readable() {
    let md = markdown();
    // about 1.85 KB a claim: 119 claims of the first list and the 64 of the
    // second, whose evidence lists more parts (quoted figures against
    // tables, a witness per property and basis); the claims stated as data
    // also show what the Rust left implicit (the printed conditions of each
    // join, the functions as encoded, every part of an umbrella over bases:
    // T70's 24 parts over the Bernstein bases of degrees 1–6 with their
    // certificates, E12's convex hull at three parameter values, T57's four
    // tables × schemes, T31's parts at λ = −1, −2 on two bases; seed 000's
    // M4, M23, M11, M3 as umbrellas of their parts with each part's
    // evidence, T68's premise decided, T59's proof steps as identities)
    assert!(
        md.len() < 1_860 * 183,
        "the Markdown report has {} bytes",
        md.len()
    );
    let longest = md.lines().map(|l| l.chars().count()).max().unwrap_or(0);
    assert!(longest < 2_000, "a line of {longest} characters");
}

#[test]
fn summary_and_verdict_filter() {
    let entries = entries();
    let view = View {
        summary_only: true,
        verdicts: vec![Status::Fails],
        ..View::default()
    };
    let md = report::markdown_entries(entries, report::BUILTIN_INTRO, &view);
    let fails = entries
        .iter()
        .filter(|e| e.verdict.status == Status::Fails)
        .count();
    // the index rows (the summary table above it has a `fails` column)
    let index = md.split("## Index").nth(1).expect("an index");
    let rows = index
        .lines()
        .filter(|l| l.starts_with("| ") && l.contains(" | fails | "))
        .count();
    assert_eq!(rows, fails, "one index line per failing claim");
    assert!(!md.contains("**Evidence:**"));
}

/// Long strings replaced by their length and a hash: the snapshot stays
/// small and still changes when any of them does.
fn redacted(v: serde_json::Value) -> serde_json::Value {
    use serde_json::Value;
    match v {
        Value::String(s) if s.len() > 1_000 => {
            let hash = s.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
                (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
            });
            Value::String(format!("<{} bytes, fnv {hash:016x}>", s.len()))
        }
        Value::Array(a) => Value::Array(a.into_iter().map(redacted).collect()),
        Value::Object(o) => Value::Object(o.into_iter().map(|(k, v)| (k, redacted(v))).collect()),
        other => other,
    }
}

#[test]
fn report_markdown_snapshot() {
    insta::assert_snapshot!("report_md", markdown());
}

#[test]
fn report_json_snapshot() {
    let value = serde_json::to_value(json()).expect("JSON");
    insta::assert_json_snapshot!("report_json", redacted(value));
}

fn published_schema() -> serde_json::Value {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/report.schema.json");
    let text = std::fs::read_to_string(&path).expect("docs/report.schema.json");
    serde_json::from_str(&text).expect("the schema is JSON")
}

#[test]
fn the_published_schema_is_the_generated_one() {
    let generated = report::schema();
    if std::env::var_os("TRIG_AUDIT_WRITE_SCHEMA").is_some() {
        let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/report.schema.json");
        let mut text = serde_json::to_string_pretty(&generated).expect("JSON");
        text.push('\n');
        std::fs::write(path, text).expect("write the schema");
    }
    assert_eq!(
        published_schema(),
        generated,
        "docs/report.schema.json is stale: regenerate it with TRIG_AUDIT_WRITE_SCHEMA=1 cargo test -p trig-e2e --test e2e the_published_schema"
    );
}

#[test]
fn the_json_report_validates_against_the_published_schema() {
    let validator = jsonschema::validator_for(&published_schema()).expect("a valid schema");
    let report = serde_json::to_value(json()).expect("JSON");
    let errors: Vec<String> = validator
        .iter_errors(&report)
        .take(5)
        .map(|e| format!("{e} at {}", e.instance_path()))
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
    // a report of another version does not validate
    let mut other = report.clone();
    other["schema_version"] = "0.9.0".into();
    assert!(!validator.is_valid(&other), "the schema pins its version");
    // and a filtered summary, which leaves the evidence out
    let view = View {
        summary_only: true,
        verdicts: vec![Status::HoldsAfterCorrection],
        ..View::default()
    };
    let short = serde_json::to_value(report::json_entries(
        entries(),
        report::BUILTIN_INTRO,
        &view,
    ))
    .expect("JSON");
    assert!(validator.is_valid(&short));
}

#[test]
fn the_latex_report_maps_every_character_and_compiles() {
    let tex = tex();
    assert!(trig_tex::unmapped(&tex).is_empty());
    assert!(tex.is_ascii(), "every character mapped to ASCII LaTeX");
    assert!(!tex.contains("[U+"), "no unmapped character");
    match trig_tex::compile(&tex, "report") {
        Some(log) => {
            assert!(log.errors.is_empty(), "pdflatex errors: {:#?}", log.errors);
            assert!(
                log.overfull < 10,
                "{} overfull boxes: {:#?}",
                log.overfull,
                log.overfull_lines
            );
            assert!(log.pages > 10, "{} pages", log.pages);
        }
        None => eprintln!("pdflatex not found: the LaTeX report was not compiled"),
    }
}
