//! `cargo test` as the audit: every checker runs, one test per document, and
//! the whole report is snapshotted (a changed verdict is a snapshot diff that
//! must be explained in the commit message).

use std::sync::OnceLock;

use trig_verification::{Outcome, Seed, Status, report, run};

/// The whole audit, run once for every test of this file (the claims are
/// decided in parallel, in report order).
fn outcomes() -> &'static [Outcome] {
    static OUTCOMES: OnceLock<Vec<Outcome>> = OnceLock::new();
    OUTCOMES.get_or_init(|| run(None, None))
}

fn check_seed(seed: Seed) {
    let outcomes: Vec<&Outcome> = outcomes().iter().filter(|o| o.claim.seed == seed).collect();
    assert!(!outcomes.is_empty(), "{seed:?} has claims");
    // the seed filter of `run` selects the same claims
    let ids = |o: &[&Outcome]| o.iter().map(|o| o.claim.id).collect::<Vec<_>>();
    if seed == Seed::S003 {
        let filtered = run(Some(seed), None);
        assert_eq!(ids(&filtered.iter().collect::<Vec<_>>()), ids(&outcomes));
    }
    for o in &outcomes {
        assert_eq!(o.claim.seed, seed);
        assert!(
            !o.verdict.evidence.is_empty(),
            "{} has evidence",
            o.claim.id
        );
        assert!(!o.verdict.method.is_empty(), "{} says how", o.claim.id);
        if o.verdict.status == Status::HoldsAfterCorrection {
            assert!(
                o.verdict.correction.is_some(),
                "{} names its correction",
                o.claim.id
            );
        }
    }
}

#[test]
fn seed_001_thesis() {
    check_seed(Seed::S001);
}

#[test]
fn seed_000_majeed_et_al() {
    check_seed(Seed::S000);
}

#[test]
fn seed_002_quartic_bezier() {
    check_seed(Seed::S002);
}

#[test]
fn seed_003_missing_formulas() {
    check_seed(Seed::S003);
}

#[test]
fn seed_004_eh_spline() {
    check_seed(Seed::S004);
}

#[test]
fn claim_ids_are_unique() {
    let mut ids: Vec<&str> = trig_verification::all_claims()
        .iter()
        .map(|c| c.id)
        .collect();
    let n = ids.len();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids.len(), n);
}

#[test]
fn report_markdown_snapshot() {
    insta::assert_snapshot!("report_md", report::markdown(outcomes()));
}

#[test]
fn report_json_snapshot() {
    insta::assert_json_snapshot!("report_json", report::json(outcomes()));
}
