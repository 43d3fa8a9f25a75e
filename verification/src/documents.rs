//! The audit of document files (`documents/`, `docs/spec.md` "Document
//! files"): every claim a document prints, as data, decided by the judges
//! through the spec language, and reported as one [`Entry`] each, in the
//! files' order.

use std::path::{Path, PathBuf};

use trig_specfile::document::{Header, read_set};
use trig_specfile::{Check, DocumentClaim, DocumentFile, Part, Spec, SpecClaim, SpecError};
use trig_verdict::Verdict;

use crate::entry::{Document, Entry};
use crate::figures::Figure;

/// Why the document files cannot be audited.
#[derive(Debug, thiserror::Error)]
pub enum DocumentsError {
    #[error(transparent)]
    Spec(#[from] SpecError),
}

/// The folder of the five documents: `documents/` of the working directory
/// when it has the list, else the one of the checkout this was built from.
pub fn default_dir() -> PathBuf {
    let here = PathBuf::from("documents");
    if here.join(trig_specfile::document::LIST).is_file() {
        here
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../documents")
    }
}

/// Reads the documents `dir` lists (`dir/audit.toml`).
pub fn load(dir: &Path) -> Result<Vec<DocumentFile>, DocumentsError> {
    Ok(read_set(dir)?)
}

/// The report document of a document file at position `order`.
pub fn document(header: &Header, order: usize) -> Document {
    Document {
        heading: header.heading.clone(),
        id: header.id.clone(),
        title: header.title.clone(),
        file: header.file_name().to_string(),
        location: header.location.clone(),
        order,
        battery: false,
    }
}

/// What decides one claim.
enum Decider<'a> {
    Stated(&'a Spec, &'a SpecClaim),
    /// An umbrella over parts about the document's bases, with its notes.
    Parts(Vec<(&'a Spec, &'a Part)>, &'a [String]),
    /// An umbrella over claims of the document (`check = "all"`): decided
    /// from the verdicts of the claims it lists, after them.
    Umbrella(&'a DocumentFile, &'a SpecClaim),
}

/// What decides `c`, a claim of `doc`.
fn decider<'a>(doc: &'a DocumentFile, c: &'a DocumentClaim) -> Decider<'a> {
    match c {
        DocumentClaim::Stated { claim, .. } if matches!(claim.check, Check::All { .. }) => {
            Decider::Umbrella(doc, claim)
        }
        DocumentClaim::Stated { basis, claim } => Decider::Stated(&doc.bases[*basis].1, claim),
        DocumentClaim::Parts { parts, notes, .. } => Decider::Parts(
            parts.iter().map(|p| (&doc.bases[p.basis].1, p)).collect(),
            notes,
        ),
    }
}

/// The verdict of a claim that is not an umbrella over claims.
fn decide(decider: &Decider<'_>) -> Option<Verdict> {
    match decider {
        Decider::Stated(spec, claim) => Some(crate::spec_audit::decide_in(spec, claim)),
        Decider::Parts(parts, notes) => Some(crate::spec_audit::decide_parts(parts, notes)),
        Decider::Umbrella(..) => None,
    }
}

/// The verdict of an umbrella over claims of `doc`: each listed claim's
/// verdict from `known` (the claims this audit decided), or decided here
/// when the audit did not select it.
fn umbrella(
    doc: &DocumentFile,
    claim: &SpecClaim,
    known: &dyn Fn(&str) -> Option<Verdict>,
) -> Verdict {
    let Check::All { claims, brief } = &claim.check else {
        unreachable!("an umbrella is a `check = \"all\"` claim")
    };
    let mut parts = Vec::new();
    for id in claims {
        let verdict = match known(id) {
            Some(v) => v,
            None => {
                let part = doc
                    .claims
                    .iter()
                    .find(|c| c.id() == id)
                    .expect("the reader checks that an umbrella lists claims of the file");
                match decider(doc, part) {
                    Decider::Umbrella(d, c) => umbrella(d, c, known),
                    other => decide(&other).expect("not an umbrella"),
                }
            }
        };
        parts.push((id.clone(), verdict));
    }
    let mut v = crate::spec_audit::umbrella_verdict(parts, *brief);
    v.evidence.extend(claim.notes.iter().map(String::as_str));
    v
}

/// The claims of `documents` (those of the document with id `only_document`
/// and the claim with id `only_claim`, case-insensitive, when given),
/// decided on every available core, in the files' order. Figures are
/// linked by their path from `root` (the folder above `documents/`).
pub fn audit(
    documents: &[DocumentFile],
    root: &Path,
    only_document: Option<&str>,
    only_claim: Option<&str>,
) -> Vec<Entry> {
    let mut chosen: Vec<(Entry, Decider<'_>)> = Vec::new();
    for (order, doc) in documents.iter().enumerate() {
        if only_document.is_some_and(|d| d != doc.header.id) {
            continue;
        }
        let report = document(&doc.header, order);
        for c in &doc.claims {
            if only_claim.is_some_and(|id| !c.id().eq_ignore_ascii_case(id)) {
                continue;
            }
            let decider = decider(doc, c);
            let entry = Entry {
                id: c.id().to_string(),
                document: report.clone(),
                source: c.source().to_string(),
                statement: c.statement().to_string(),
                verdict: Verdict::not_checkable("not decided yet"),
                figure: c.figure().map(|f| Figure::of(f, root)),
            };
            chosen.push((entry, decider));
        }
    }
    let mut verdicts = trig_core::parallel::map(&chosen, |(_, d)| decide(d));
    // the umbrellas over claims last, from their parts' verdicts
    for i in 0..chosen.len() {
        if let Decider::Umbrella(doc, claim) = &chosen[i].1 {
            let known = |id: &str| {
                chosen
                    .iter()
                    .zip(&verdicts)
                    .find(|((e, _), _)| e.id == id && e.document.id == doc.header.id)
                    .and_then(|(_, v)| v.clone())
            };
            verdicts[i] = Some(umbrella(doc, claim, &known));
        }
    }
    chosen
        .into_iter()
        .zip(verdicts)
        .map(|((entry, _), verdict)| Entry {
            verdict: verdict.expect("every claim decided"),
            ..entry
        })
        .collect()
}
