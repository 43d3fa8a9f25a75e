//! The document files (`documents/`): every Rust checker decides a claim
//! marked `built-in` in exactly one of them, and one document's folder
//! audits as its part of the whole audit.

use trig_specfile::DocumentClaim;
use trig_verification::documents::{audit, default_dir, load};
use trig_verification::{checkers, run};

#[test]
fn every_rust_checker_is_a_built_in_claim_of_one_document() {
    let documents = load(&default_dir()).expect("the document files");
    let mut built_in: Vec<&str> = documents
        .iter()
        .flat_map(|d| &d.claims)
        .filter(|c| matches!(c, DocumentClaim::BuiltIn { .. }))
        .map(DocumentClaim::id)
        .collect();
    built_in.sort_unstable();
    let mut rust: Vec<&str> = checkers().iter().map(|c| c.id).collect();
    rust.sort_unstable();
    assert_eq!(
        built_in, rust,
        "a checker no document file names is dead code"
    );
    let all: usize = documents.iter().map(|d| d.claims.len()).sum();
    assert_eq!(all, 183, "the claims of shared/claims.md");
}

#[test]
fn one_document_folder_audits_as_its_part_of_the_whole() {
    let dir = default_dir().join("c3-bspline");
    let document = trig_specfile::DocumentFile::from_path(&dir).expect("the seed 003 file");
    let alone = audit(&[document], None, None).expect("audited");
    let part = run(Some("003"), None).expect("the document files");
    let strip =
        |e: &trig_verification::Entry| (e.id.clone(), e.statement.clone(), e.verdict.clone());
    assert_eq!(
        alone.iter().map(strip).collect::<Vec<_>>(),
        part.iter().map(strip).collect::<Vec<_>>()
    );
}
