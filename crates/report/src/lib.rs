//! # trig-report
//!
//! The audit report: Markdown for people ([`markdown`](mod@markdown)), LaTeX for papers
//! ([`latex`]), JSON for machines ([`json`](mod@json), with a versioned schema) — all
//! rendered from the same entries and the same structured evidence
//! ([`trig_verdict::evidence`]). The text formats are one traversal of the
//! report (`render`) with a writer per format; the JSON is the entries
//! through serde. Entries ([`Entry`]) are owned: the claims of the
//! document files and of a spec file report exactly alike.
//!
//! Every format has the same parts: a summary (counts by verdict and by
//! document), an index (one line per claim), then one section per document
//! and one entry per claim. [`View`] selects the short form (summary and
//! index only) and filters by verdict.
//!
//! ```
//! use trig_report::{View, markdown_entries};
//! use trig_verification::run;
//!
//! // the thesis's partition of unity (3.1), decided and rendered
//! let entries = run(None, Some("T1")).unwrap();
//! let md = markdown_entries(&entries, "One claim.", &View::default());
//! assert!(md.starts_with("# trig-audit report"));
//! assert!(md.contains("T1"));
//! ```

pub mod json;
pub mod latex;
pub mod markdown;
mod render;

use trig_verdict::Status;
use trig_verification::{Document, Entry};

pub use json::{Report, SCHEMA_VERSION, json_entries, schema};
pub use latex::{TexOptions, tex_entries};
pub use markdown::{markdown_entries, markdown_entries_in};

/// The opening sentence of the built-in report.
pub const BUILTIN_INTRO: &str = "Every verdict below is computed by `trig-audit audit` from the formulas as printed in `shared/seeds/`; identities are decided exactly in the symbolic ring, counterexamples in 256-bit MPFR.";

/// The opening sentence of the report of one document file (`audit --spec
/// documents/thesis/`): the same as the audit's, naming the file.
pub fn document_intro(path: &str) -> String {
    format!(
        "Every verdict below is computed by `trig-audit audit --spec {path}` from the claims of the document file as printed; identities are decided exactly in the symbolic ring, counterexamples in 256-bit MPFR."
    )
}

/// What a report shows: everything, or the short form (summary and index,
/// no claim sections), optionally only some verdicts.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct View {
    /// Summary and index only.
    pub summary_only: bool,
    /// Only claims with one of these verdicts (all when empty).
    pub verdicts: Vec<Status>,
    /// A standard battery by its counts only: its checks are left out of
    /// the index and the sections (`--battery summary`).
    pub battery_counts_only: bool,
}

impl View {
    /// The entries this view shows.
    pub fn select<'a>(&self, entries: &'a [Entry]) -> Vec<&'a Entry> {
        entries
            .iter()
            .filter(|e| self.verdicts.is_empty() || self.verdicts.contains(&e.verdict.status))
            .filter(|e| !(self.battery_counts_only && e.document.battery))
            .collect()
    }

    /// A sentence saying what the view leaves out, if anything.
    pub fn note(&self) -> Option<String> {
        if self.verdicts.is_empty() {
            return None;
        }
        let labels: Vec<&str> = self.verdicts.iter().map(Status::label).collect();
        Some(format!(
            "Only the claims whose verdict is {} are shown.",
            labels.join(" or ")
        ))
    }
}

/// Counts of each status among `entries`, in [`Status::ALL`] order.
pub(crate) fn counts<'a>(entries: impl Iterator<Item = &'a Entry> + Clone) -> Vec<(Status, usize)> {
    Status::ALL
        .iter()
        .map(|s| {
            (
                *s,
                entries.clone().filter(|e| e.verdict.status == *s).count(),
            )
        })
        .collect()
}

/// The distinct documents, in section order, with their entries.
pub(crate) fn sections<'a>(entries: &[&'a Entry]) -> Vec<(&'a Document, Vec<&'a Entry>)> {
    let mut docs: Vec<&Document> = Vec::new();
    for e in entries {
        if !docs.contains(&&e.document) {
            docs.push(&e.document);
        }
    }
    docs.sort_by_key(|d| d.order);
    docs.into_iter()
        .map(|d| {
            (
                d,
                entries
                    .iter()
                    .copied()
                    .filter(|e| &e.document == d)
                    .collect(),
            )
        })
        .collect()
}

/// A statement shortened to at most `max` characters for the index.
pub(crate) fn short(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        return text.to_string();
    }
    let cut: String = text.chars().take(max - 1).collect();
    format!("{}…", cut.trim_end())
}

#[cfg(test)]
pub(crate) mod test_entries {
    //! Small entries for the renderers' unit tests.

    use super::*;
    use trig_symbolic::Sym;
    use trig_verdict::Verdict;
    use trig_verdict::evidence::{Evidence, Expr, Kind};

    pub fn doc(id: &str, order: usize) -> Document {
        Document {
            heading: format!("Spec {id}"),
            id: id.into(),
            title: "t_1".into(),
            file: "f".into(),
            location: "f".into(),
            order,
            battery: false,
        }
    }

    pub fn entry(id: &str, d: Document, status: Status) -> Entry {
        let residual = Sym::var("m") * &Sym::var("m") - &Sym::int(4);
        let item = Evidence::new(Kind::Identity, "")
            .about("Σ b_i − 1", status)
            .with("residual", Expr::new(&residual))
            .in_part("part", status);
        Entry {
            id: id.into(),
            document: d,
            source: "(1)".into(),
            statement: "Σ b_i = 1".into(),
            verdict: Verdict::new(status, "exact", [item]),
            figure: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::test_entries::{doc, entry};
    use super::*;

    #[test]
    fn views_filter_by_verdict() {
        let entries = [
            entry("A1", doc("b", 5), Status::Fails),
            entry("A2", doc("a", 1), Status::Holds),
        ];
        let view = View {
            summary_only: false,
            verdicts: vec![Status::Fails],
            ..View::default()
        };
        let ids: Vec<&str> = view
            .select(&entries)
            .iter()
            .map(|e| e.id.as_str())
            .collect();
        assert_eq!(ids, ["A1"]);
        assert!(view.note().unwrap().contains("fails"));
        assert_eq!(short("abcdef", 4), "abc…");
        let all: Vec<&Entry> = entries.iter().collect();
        let s = sections(&all);
        assert_eq!(s[0].0.id, "a", "sections follow the document order");
    }

    #[test]
    fn a_battery_is_counted_apart_and_can_be_left_to_its_counts() {
        let battery = Document {
            battery: true,
            ..doc("s battery", 2)
        };
        let entries = [
            entry("C1", doc("s", 1), Status::Holds),
            entry("symmetry", battery.clone(), Status::Fails),
            entry("unity", battery, Status::Holds),
        ];
        let md = markdown_entries(&entries, "intro", &View::default());
        assert!(md.contains("| **all** | 1 | 1 | 0 | 0 | 0 |"), "{md}");
        assert!(
            md.contains("| battery (not in all) | 2 | 1 | 1 | 0 | 0 |"),
            "{md}"
        );
        assert!(md.contains("symmetry — fails"), "the battery in full: {md}");
        let json = json_entries(&entries, "intro", &View::default());
        assert_eq!((json.summary.holds, json.summary.fails), (1, 0));
        assert!(json.documents.iter().any(|d| d.battery && d.claims == 2));
        let counts_only = View {
            battery_counts_only: true,
            ..View::default()
        };
        let ids: Vec<&str> = counts_only
            .select(&entries)
            .iter()
            .map(|e| e.id.as_str())
            .collect();
        assert_eq!(ids, ["C1"]);
        let md = markdown_entries(&entries, "intro", &counts_only);
        assert!(!md.contains("symmetry"), "{md}");
        assert!(md.contains("(not in all) | 2 |"), "{md}");
    }
}
