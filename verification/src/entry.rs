//! One claim of the audit with its computed verdict, owned ([`Entry`]), in
//! its document ([`Document`]): what the report renders. The claims of a
//! document file ([`crate::documents`]) and of a spec file
//! ([`crate::spec_audit`]) give the same entries, so both report exactly
//! alike.

use trig_verdict::{Evidence, Verdict, Witness};

use crate::figures::Figure;

/// A document of the report: a seed of `shared/seeds/` or a spec file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Document {
    /// Section heading before the title (`Seed 001`, `Spec thesis-cubic`).
    pub heading: String,
    /// Short id (summary table, JSON `seed`).
    pub id: String,
    pub title: String,
    /// File name (JSON `seed_file`).
    pub file: String,
    /// Where the document is, as the Markdown section states it.
    pub location: String,
    /// Sort key of the sections (the document files' order first).
    pub order: usize,
    /// The tool's own checks of a basis (a spec's standard battery), not
    /// claims the document makes: reported apart, with their own counts.
    pub battery: bool,
}

/// One claim of the report with its computed verdict.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry {
    pub id: String,
    pub document: Document,
    /// Equation or section.
    pub source: String,
    /// The statement as printed, its formulas marked
    /// (`trig_tex::marked`; `trig_tex::plain` is the text as printed).
    pub statement: String,
    pub verdict: Verdict,
    /// A figure supporting the verdict ([`crate::figures`]).
    pub figure: Option<Figure>,
}

impl Entry {
    /// The first witness of the evidence (the one the report shows beside
    /// the verdict of a failing claim).
    pub fn witness(&self) -> Option<(&Evidence, &Witness)> {
        self.verdict
            .evidence
            .iter()
            .find_map(|e| e.witness.as_ref().map(|w| (e, w)))
    }
}
