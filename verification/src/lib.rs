//! # trig-verification
//!
//! The audit: every claim of `shared/claims.md` is a claim of a document
//! file under `documents/` ([`documents`]: id, source, statement as
//! printed, and what decides it), decided by the judges of `trig-judge`
//! through the spec language ([`spec_audit`]) — identities exactly in the
//! symbolic ring, with the exact residual or a 256-bit MPFR counterexample
//! as evidence when a claim fails. No claim is Rust: a new claim is a line
//! of data, a new kind of claim one judge. A claim never carries its
//! verdict: [`run`] computes every verdict, and `trig-report` renders them.

pub mod budget;
pub mod documents;
pub mod entry;
pub mod figures;
pub mod spec_audit;

pub use documents::DocumentsError;
pub use entry::{Document, Entry};
pub use trig_verdict::{Status, Verdict, Witness};

/// The audit of the five documents: the claims of the document files of
/// [`documents::default_dir`] (those of the document with id `document`
/// and the claim with id `claim`, case-insensitive, when given), decided,
/// in report order.
pub fn run(document: Option<&str>, claim: Option<&str>) -> Result<Vec<Entry>, DocumentsError> {
    let dir = documents::default_dir();
    Ok(documents::audit(
        &documents::load(&dir)?,
        dir.parent().unwrap_or(std::path::Path::new("")),
        document,
        claim,
    ))
}
