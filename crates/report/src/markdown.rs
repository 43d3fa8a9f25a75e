//! The Markdown report (the `Format` of the report traversal, `render`): summary and
//! index as tables, then one section per document and one entry per
//! claim, evidence as a list nested by the parts of the claim. Expressions
//! longer than [`LONG`] characters are summarised (degree, number of terms,
//! a factored form when short) — the JSON report has them whole — and every
//! failing check shows its witness.

use std::fmt::Write;
use std::path::Path;

use trig_tex::plain;

use super::render::{BATTERY_LABEL, Format, Tally, anchor, point_text, render};
use super::{Document, Entry, View, short};
use trig_verdict::evidence::{Part, Witness};
use trig_verdict::status::Status;
use trig_verification::figures::{Figure, relative};

/// Expressions with more characters are summarised.
pub const LONG: usize = 120;

/// Markdown text: the characters Markdown would read as markup escaped.
pub fn md_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        if matches!(ch, '\\' | '*' | '_' | '`' | '<' | '>' | '[' | ']' | '|') {
            out.push('\\');
        }
        out.push(ch);
    }
    out
}

/// A code span (formulas): backticks inside are replaced by quotes.
fn code(text: &str) -> String {
    format!("`{}`", text.replace('`', "'"))
}

/// The Markdown report: a summary (by verdict and by document), an index
/// (one line per claim), then one section per document and one entry per
/// claim — or, with [`View::summary_only`], the summary and index alone.
pub fn markdown_entries(entries: &[Entry], intro: &str, view: &View) -> String {
    markdown_entries_in(entries, intro, view, None)
}

/// [`markdown_entries`] for a report written in the directory `output_dir`:
/// figures are linked by their path relative to it (`None`: the current
/// directory, where the figures' paths start).
pub fn markdown_entries_in(
    entries: &[Entry],
    intro: &str,
    view: &View,
    output_dir: Option<&Path>,
) -> String {
    render(&Markdown { output_dir }, entries, intro, view)
}

/// The Markdown format of the report.
struct Markdown<'a> {
    output_dir: Option<&'a Path>,
}

/// A table row: `| a | b |`.
fn row<T: std::fmt::Display>(cells: impl IntoIterator<Item = T>) -> String {
    let cells: Vec<String> = cells.into_iter().map(|c| c.to_string()).collect();
    format!("| {} |", cells.join(" | "))
}

impl Format for Markdown<'_> {
    const LONG: usize = LONG;
    const EQUALS: &'static str = " = ";
    const DASH: &'static str = " — ";
    const NESTED: &'static str = " › ";

    fn prose(&self, text: &str) -> String {
        md_text(&plain(text))
    }

    fn statement(&self, marked: &str) -> String {
        md_text(&plain(marked))
    }

    fn printed(&self, formula: &str) -> String {
        code(formula)
    }

    fn strong(&self, text: &str) -> String {
        format!("**{text}**")
    }

    fn formula(&self, unicode: &str, _latex: &str) -> String {
        code(unicode)
    }

    fn point(&self, w: &Witness) -> Option<String> {
        let point = point_text(
            w,
            |a| a.name.clone(),
            |a| format!("{} = {}", a.name, a.value),
        );
        (!point.is_empty()).then(|| code(&point.join(", ")))
    }

    fn witnessed(&self, subject: &str, line: &str) -> String {
        if subject.is_empty() {
            line.to_string()
        } else {
            format!("{subject} {line}")
        }
    }

    fn method(&self, short: &str, k: usize) -> String {
        format!("[{}](#method-{k})", md_text(short))
    }

    fn figure(&self, f: &Figure) -> String {
        format!(
            "[{}]({}) (drawn by `trig-audit {}`; data: `{}`; pgfplots: `{}`)",
            md_text(&f.caption),
            relative(&f.path, self.output_dir),
            f.command,
            relative(&f.data_path(), self.output_dir),
            relative(&f.pgf_path(), self.output_dir)
        )
    }

    fn start(&self, out: &mut String, intro: &str, note: Option<&str>) {
        let _ = writeln!(out, "# trig-audit report\n");
        let _ = writeln!(
            out,
            "{intro} Witness values are exact unless marked numeric. Long expressions are summarised here; the JSON report (`--format json`, schema `docs/report.schema.json`) gives every expression in full, in Unicode, LaTeX, SymPy syntax and factored form.\n"
        );
        if let Some(n) = note {
            let _ = writeln!(out, "{n}\n");
        }
    }

    fn summary(&self, out: &mut String, documents: &[(&Document, Tally)], all: &Tally) {
        let _ = writeln!(out, "## Summary\n");
        let labels = Status::ALL.map(|s| s.label());
        let _ = writeln!(out, "{}", row(["document", "claims"].iter().chain(&labels)));
        let _ = writeln!(out, "|---|---|{}", "---|".repeat(Status::ALL.len()));
        let line = |first: String, t: &Tally| {
            row([first, t.claims.to_string()]
                .into_iter()
                .chain(t.by_status.iter().map(usize::to_string)))
        };
        for (doc, t) in documents.iter().filter(|(d, _)| !d.battery) {
            let _ = writeln!(out, "{}", line(doc.id.clone(), t));
        }
        let _ = writeln!(out, "{}", line("**all**".to_string(), all));
        for (_, t) in documents.iter().filter(|(d, _)| d.battery) {
            let _ = writeln!(out, "{}", line(md_text(BATTERY_LABEL), t));
        }
        out.push('\n');
    }

    fn index(&self, out: &mut String, entries: &[&Entry], linked: bool) {
        // the short form shows what each claim says; the full report links to it
        let _ = writeln!(out, "## Index\n");
        if linked {
            let _ = writeln!(out, "| claim | verdict | document | source |");
            let _ = writeln!(out, "|---|---|---|---|");
        } else {
            let _ = writeln!(out, "| claim | verdict | document | source | printed |");
            let _ = writeln!(out, "|---|---|---|---|---|");
        }
        for e in entries {
            let (status, doc, source) = (e.verdict.status, &e.document.id, md_text(&e.source));
            let line = if linked {
                let id = format!("[{}](#{})", e.id, anchor(&e.id));
                row([id, status.to_string(), doc.clone(), source])
            } else {
                let printed = md_text(&short(&plain(&e.statement), 90));
                row([
                    e.id.clone(),
                    status.to_string(),
                    doc.clone(),
                    source,
                    printed,
                ])
            };
            let _ = writeln!(out, "{line}");
        }
        out.push('\n');
    }

    fn methods(&self, out: &mut String, methods: &[&str]) {
        let _ = writeln!(out, "## Methods\n");
        for (k, m) in (1..).zip(methods) {
            let _ = writeln!(out, "{k}. <a id=\"method-{k}\"></a>{}", md_text(m));
        }
        out.push('\n');
    }

    fn section(&self, out: &mut String, doc: &Document) {
        let _ = writeln!(out, "## {} — {}\n", doc.heading, md_text(&doc.title));
        let _ = writeln!(out, "Source: `{}`\n", doc.location);
    }

    fn heading(&self, out: &mut String, e: &Entry) {
        let _ = writeln!(
            out,
            "### <a id=\"{}\"></a>{} — {}\n",
            anchor(&e.id),
            e.id,
            e.verdict.status
        );
    }

    fn field(&self, out: &mut String, name: &str, value: &str) {
        let _ = writeln!(out, "- **{name}:** {value}");
    }

    fn evidence_start(&self, out: &mut String) {
        let _ = writeln!(out, "- **Evidence:**");
    }

    fn parts(&self, out: &mut String, from: &[Part], to: &[Part]) {
        let common = from.iter().zip(to).take_while(|(a, b)| a == b).count();
        for (depth, p) in to.iter().enumerate().skip(common) {
            let indent = "  ".repeat(depth + 1);
            let _ = writeln!(out, "{indent}- **{}** — {}", md_text(&p.name), p.status);
        }
    }

    fn item(&self, out: &mut String, depth: usize, line: &str) {
        let _ = writeln!(out, "{}- {line}", "  ".repeat(depth + 1));
    }

    fn evidence_end(&self, _out: &mut String) {}

    fn finish(&self, out: String) -> String {
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_entries::{doc, entry};
    use super::*;

    #[test]
    fn report_has_summary_index_and_nested_evidence() {
        let entries = [
            entry("A1", doc("b", 5), Status::Fails),
            entry("A2", doc("a", 1), Status::Holds),
        ];
        let md = markdown_entries(&entries, "intro", &View::default());
        assert!(md.contains("| **all** | 2 | 1 | 1 | 0 | 0 |"), "{md}");
        assert!(md.contains("| [A1](#claim-a1) | fails | b | (1) |"), "{md}");
        assert!(
            md.contains("  - **part** — fails\n    - Σ b\\_i − 1 — **fails**: residual = `m² − 4`"),
            "{md}"
        );
        let a = md.find("## Spec a").unwrap();
        let b = md.find("## Spec b").unwrap();
        assert!(a < b);
        let short = markdown_entries(
            &entries,
            "intro",
            &View {
                summary_only: true,
                ..View::default()
            },
        );
        assert!(!short.contains("## Spec"), "{short}");
        assert!(short.contains("| A1 | fails |"));
    }

    #[test]
    fn markup_characters_are_escaped() {
        assert_eq!(md_text("b_i * [x] <y>"), r"b\_i \* \[x\] \<y\>");
    }
}
