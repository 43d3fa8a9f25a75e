//! The document files (`documents/`): every claim of `shared/claims.md` is
//! a claim of one of them, and one document's folder audits as its part of
//! the whole audit.

use std::collections::BTreeSet;

use trig_specfile::DocumentClaim;
use trig_verification::documents::{audit, default_dir, load};
use trig_verification::run;

#[test]
fn the_claims_of_the_five_documents_are_data() {
    let documents = load(&default_dir()).expect("the document files");
    let ids: Vec<&str> = documents
        .iter()
        .flat_map(|d| &d.claims)
        .map(DocumentClaim::id)
        .collect();
    assert_eq!(ids.len(), 183, "the claims of shared/claims.md");
    let unique: BTreeSet<&str> = ids.iter().copied().collect();
    assert_eq!(unique.len(), ids.len(), "every id once");
}

#[test]
fn one_document_folder_audits_as_its_part_of_the_whole() {
    let dir = default_dir().join("c3-bspline");
    let document = trig_specfile::DocumentFile::from_path(&dir).expect("the seed 003 file");
    let alone = audit(&[document], std::path::Path::new(""), None, None);
    let part = run(Some("003"), None).expect("the document files");
    let strip =
        |e: &trig_verification::Entry| (e.id.clone(), e.statement.clone(), e.verdict.clone());
    assert_eq!(
        alone.iter().map(strip).collect::<Vec<_>>(),
        part.iter().map(strip).collect::<Vec<_>>()
    );
}

/// An umbrella of parts about several bases: each part decided on its own
/// basis; a part shown for information keeps its verdict and never decides.
#[test]
fn an_umbrella_of_parts_is_decided_part_by_part() {
    let catalog = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/catalog");
    let umbrella = |shown: bool| {
        let text = format!(
            "[document]\nid = \"x\"\nheading = \"x\"\ntitle = \"t\"\nlocation = \"x.pdf\"\n\
             [bases]\nhan = \"han.toml\"\nmq = \"majeed-qayyum.toml\"\n\
             [[claims]]\nid = \"U\"\nsource = \"(1)\"\nstatement = \"s\"\ncheck = \"all\"\nnotes = [\"a remark\"]\n\
             [[claims.parts]]\nid = \"a\"\nsource = \"(6.2)\"\nstatement = \"han: sum 1\"\nbasis = \"han\"\ncheck = \"unity\"\n\
             [[claims.parts]]\nid = \"b\"\nsource = \"(6.1)\"\nstatement = \"mq: maximal\"\nbasis = \"mq\"\ncheck = \"nonnegative\"\nmaximal = true\nshown = {shown}\n"
        );
        let doc = trig_specfile::DocumentFile::from_str_in(&text, "x.toml", &catalog)
            .expect("a document of parts");
        audit(&[doc], std::path::Path::new(""), None, None)
            .remove(0)
            .verdict
    };
    // (6.1) is nonnegative exactly on [−1, 2], wider than its printed (1/2, 2]
    let counted = umbrella(false);
    assert_eq!(counted.status, trig_verdict::status::Status::Fails);
    let shown = umbrella(true);
    assert_eq!(shown.status, trig_verdict::status::Status::Holds);
    let lines: Vec<String> = shown.evidence.iter().map(|e| e.line()).collect();
    assert!(lines[0].starts_with("han: sum 1: holds"), "{lines:?}");
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("mq: maximal (shown, not a condition of the claim): fails")),
        "{lines:?}"
    );
    assert_eq!(lines.last().map(String::as_str), Some("a remark"));
}

/// An umbrella of a document file lists claims of the file (T26 over
/// T26a–k), decided from their verdicts — the same whether the audit decides the parts or only the
/// umbrella.
#[test]
fn an_umbrella_lists_any_claim_of_its_document() {
    let thesis = run(Some("001"), None).expect("the document files");
    let whole = thesis.iter().find(|e| e.id == "T26").expect("T26");
    let alone = run(None, Some("T26")).expect("the document files");
    assert_eq!(alone[0].verdict, whole.verdict);
    for part in ["T26a", "T26i", "T26j", "T26k"] {
        let status = thesis
            .iter()
            .find(|e| e.id == part)
            .expect("a part")
            .verdict
            .status;
        assert!(
            whole
                .verdict
                .evidence
                .iter()
                .any(|e| e.subject.as_deref() == Some(part) && e.status == Some(status)),
            "{part} is shown with its verdict"
        );
    }
}
