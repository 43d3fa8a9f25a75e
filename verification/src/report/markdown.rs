//! The Markdown report: summary, index, then one section per document and
//! one entry per claim; evidence nested by the parts of the claim.
//! Expressions longer than [`LONG`] characters are summarised (degree,
//! number of terms, a factored form when short) — the JSON report has them
//! whole — and every failing check shows its witness.

use std::fmt::Write;

use super::{
    Entry, PRINTED_LONG, View, counts, method_short, methods, printed_shown, sections, short,
    size_text,
};
use crate::evidence::{Evidence, Expr, Part, Witness};
use crate::status::Status;

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

/// How an expression is shown where people read.
pub(crate) enum Shown<'a> {
    /// In full (the factored form when it is informative and not longer).
    Full { unicode: &'a str, latex: &'a str },
    /// Too long: its size, and the factored form when that is short.
    Summary {
        degree: u64,
        terms: usize,
        factored: Option<(&'a str, &'a str)>,
    },
}

/// The form of `e` to show, given the longest form allowed.
pub(crate) fn shown(e: &Expr, long: usize) -> Shown<'_> {
    if e.best_unicode().chars().count() <= long {
        return Shown::Full {
            unicode: e.best_unicode(),
            latex: e.best_latex(),
        };
    }
    Shown::Summary {
        degree: e.degree,
        terms: e.terms,
        factored: e
            .factored
            .as_ref()
            .filter(|f| f.unicode.chars().count() <= long)
            .map(|f| (f.unicode.as_str(), f.latex.as_str())),
    }
}

fn expr_md(e: &Expr) -> String {
    match shown(e, LONG) {
        Shown::Full { unicode, .. } => code(unicode),
        Shown::Summary {
            degree,
            terms,
            factored,
        } => {
            let f = factored.map_or(String::new(), |u| format!(", factored {}", code(u.0)));
            format!("[{}{f}; in full in JSON]", size_text(degree, terms))
        }
    }
}

/// The coordinates of a witness: the nonzero ones, then the zero ones as
/// one chain `a = b = … = 0` (shorter, and as easy to check).
pub(crate) fn point_text(
    w: &Witness,
    name: impl Fn(&crate::evidence::Assignment) -> String,
    full: impl Fn(&crate::evidence::Assignment) -> String,
) -> Vec<String> {
    let (zero, other): (Vec<_>, Vec<_>) = w.point.iter().partition(|a| a.value == "0");
    let mut out: Vec<String> = other.into_iter().map(&full).collect();
    match zero.len() {
        0 => {}
        1 => out.push(full(zero[0])),
        _ => out.push(format!(
            "{} = 0",
            zero.into_iter().map(name).collect::<Vec<_>>().join(" = ")
        )),
    }
    out
}

/// A witness on one line.
pub(crate) fn witness_md(w: &Witness) -> String {
    let point = point_text(
        w,
        |a| a.name.clone(),
        |a| format!("{} = {}", a.name, a.value),
    );
    let values: Vec<String> = w
        .values
        .iter()
        .map(|v| format!("{} = {}", md_text(&v.label), expr_md(&v.value)))
        .collect();
    let note = w
        .note
        .as_ref()
        .map_or(String::new(), |n| format!(" ({})", md_text(n)));
    // exact unless marked (the report's opening says so)
    let values = format!(
        "{}{}",
        values.join(", "),
        if w.exact { "" } else { " (numeric)" }
    );
    if point.is_empty() && note.is_empty() {
        values
    } else if point.is_empty() {
        format!("{}: {values}", note.trim_start())
    } else {
        format!("at {}{note}: {values}", code(&point.join(", ")))
    }
}

/// One group of items ([`super::groups`]): subjects and status, prose,
/// expressions, witness.
fn item_md(group: &[Evidence], part: Option<&Part>, show_witness: bool) -> String {
    let e = &group[0];
    let mut out = String::new();
    if e.subject
        .as_deref()
        .is_some_and(|s| part.is_none_or(|p| p.name != *s))
    {
        let subjects: Vec<String> = group
            .iter()
            .filter_map(|g| g.subject.as_deref())
            .map(md_text)
            .collect();
        out.push_str(&subjects.join("; "));
        if let Some(p) = e
            .printed
            .as_deref()
            .filter(|_| e.status != Some(Status::Holds))
        {
            let _ = match printed_shown(p, LONG) {
                Some(p) => write!(out, ", printed {}", code(p)),
                None => write!(out, ", {PRINTED_LONG}"),
            };
        }
        if let Some(st) = e.status {
            let _ = write!(out, " — **{st}**");
        }
        if !e.text.is_empty() || !e.exprs.is_empty() {
            out.push_str(": ");
        }
    } else if let (Some(st), Some(p)) = (e.status, part)
        && p.status != st
    {
        let _ = write!(out, "**{st}**: ");
    }
    out.push_str(&md_text(&e.text));
    for (i, l) in e.exprs.iter().enumerate() {
        if i > 0 || !e.text.is_empty() {
            out.push_str("; ");
        }
        let _ = write!(out, "{} = {}", md_text(&l.label), expr_md(&l.expr));
    }
    if show_witness && let Some(w) = &e.witness {
        let _ = write!(out, "; witness {}", witness_md(w));
    }
    out
}

/// The evidence as a nested list under `- **Evidence:**`; `skip` is the
/// item whose witness the entry already shows.
fn evidence_md(out: &mut String, items: &[Evidence], skip: Option<&Evidence>) {
    let mut path: Vec<&Part> = Vec::new();
    for group in super::groups(items) {
        let e = &group[0];
        let common = path
            .iter()
            .zip(&e.parts)
            .take_while(|(a, b)| **a == *b)
            .count();
        path.truncate(common);
        for p in &e.parts[common..] {
            let indent = "  ".repeat(path.len() + 1);
            let _ = writeln!(out, "{indent}- **{}** — {}", md_text(&p.name), p.status);
            path.push(p);
        }
        let indent = "  ".repeat(path.len() + 1);
        let own = skip.is_none_or(|s| !std::ptr::eq(s, e));
        let _ = writeln!(
            out,
            "{indent}- {}",
            item_md(group, path.last().copied(), own)
        );
    }
}

/// The Markdown report: a summary (by verdict and by document), an index
/// (one line per claim), then one section per document and one entry per
/// claim — or, with [`View::summary_only`], the summary and index alone.
pub fn markdown_entries(entries: &[Entry], intro: &str, view: &View) -> String {
    let shown_entries = view.select(entries);
    let mut out = String::new();
    let _ = writeln!(out, "# trig-audit report\n");
    let _ = writeln!(
        out,
        "{intro} Witness values are exact unless marked numeric. Long expressions are summarised here; the JSON report (`--format json`, schema `docs/report.schema.json`) gives every expression in full, in Unicode, LaTeX, SymPy syntax and factored form.\n"
    );
    if let Some(n) = view.note() {
        let _ = writeln!(out, "{n}\n");
    }
    let _ = writeln!(out, "## Summary\n");
    let _ = writeln!(
        out,
        "| document | claims | {} |",
        Status::ALL.map(|s| s.label()).join(" | ")
    );
    let _ = writeln!(out, "|---|---|{}", "---|".repeat(Status::ALL.len()));
    let all: Vec<&Entry> = entries.iter().collect();
    for (doc, of_doc) in sections(&all) {
        let c: Vec<String> = counts(of_doc.iter().copied())
            .iter()
            .map(|(_, k)| k.to_string())
            .collect();
        let _ = writeln!(out, "| {} | {} | {} |", doc.id, of_doc.len(), c.join(" | "));
    }
    let c: Vec<String> = counts(entries.iter())
        .iter()
        .map(|(_, k)| k.to_string())
        .collect();
    let _ = writeln!(out, "| **all** | {} | {} |\n", entries.len(), c.join(" | "));
    // the short form shows what each claim says; the full report links to it
    let _ = writeln!(out, "## Index\n");
    if view.summary_only {
        let _ = writeln!(out, "| claim | verdict | document | source | printed |");
        let _ = writeln!(out, "|---|---|---|---|---|");
    } else {
        let _ = writeln!(out, "| claim | verdict | document | source |");
        let _ = writeln!(out, "|---|---|---|---|");
    }
    for e in &shown_entries {
        if view.summary_only {
            let _ = writeln!(
                out,
                "| {} | {} | {} | {} | {} |",
                e.id,
                e.verdict.status,
                e.document.id,
                md_text(&e.source),
                md_text(&short(&e.statement, 90))
            );
        } else {
            let _ = writeln!(
                out,
                "| [{}](#{}) | {} | {} | {} |",
                e.id,
                anchor(&e.id),
                e.verdict.status,
                e.document.id,
                md_text(&e.source)
            );
        }
    }
    out.push('\n');
    if view.summary_only {
        return out;
    }
    let methods = methods(&shown_entries);
    let _ = writeln!(out, "## Methods\n");
    for (k, m) in methods.iter().enumerate() {
        let _ = writeln!(
            out,
            "{}. <a id=\"method-{}\"></a>{}",
            k + 1,
            k + 1,
            md_text(m)
        );
    }
    out.push('\n');
    for (doc, of_doc) in sections(&shown_entries) {
        let _ = writeln!(out, "## {} — {}\n", doc.heading, md_text(&doc.title));
        let _ = writeln!(out, "Source: `{}`\n", doc.location);
        for e in of_doc {
            let k = methods
                .iter()
                .position(|m| *m == e.verdict.method)
                .unwrap_or(0)
                + 1;
            entry_md(&mut out, e, k);
        }
    }
    out
}

/// The anchor of a claim's heading.
fn anchor(id: &str) -> String {
    format!("claim-{}", id.to_ascii_lowercase())
}

fn entry_md(out: &mut String, e: &Entry, method: usize) {
    let v = &e.verdict;
    let _ = writeln!(
        out,
        "### <a id=\"{}\"></a>{} — {}\n",
        anchor(&e.id),
        e.id,
        v.status
    );
    let _ = writeln!(out, "- **Source:** {}", md_text(&e.source));
    let _ = writeln!(out, "- **Printed:** {}", md_text(&e.statement));
    let _ = writeln!(
        out,
        "- **How:** [{}](#method-{method})",
        md_text(&method_short(&v.method))
    );
    if let Some(corr) = &v.correction {
        let _ = writeln!(out, "- **Correction:** {}", md_text(corr));
    }
    let witness = (v.status != Status::Holds).then(|| e.witness()).flatten();
    if let Some((item, w)) = witness {
        let subject = item
            .parts
            .iter()
            .map(|p| p.name.as_str())
            .chain(item.subject.as_deref())
            .collect::<Vec<_>>()
            .join(" › ");
        let subject = if subject.is_empty() {
            String::new()
        } else {
            format!("{} ", md_text(&subject))
        };
        let _ = writeln!(out, "- **Witness:** {subject}{}", witness_md(w));
    }
    if let Some(f) = e.figure {
        let _ = writeln!(
            out,
            "- **Figure:** [{}]({}) (drawn by `trig-audit {}`; data: `{}`; pgfplots: `{}`)",
            md_text(f.caption),
            f.path,
            f.command,
            f.data_path(),
            f.pgf_path()
        );
    }
    let _ = writeln!(out, "- **Evidence:**");
    evidence_md(out, &v.evidence, witness.map(|(item, _)| item));
    out.push('\n');
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
                verdicts: vec![],
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
