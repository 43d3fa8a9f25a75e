//! The LaTeX report: a complete document that compiles with pdfLaTeX (and
//! LuaLaTeX, XeLaTeX) using packages of a basic TeX installation (`amsmath`,
//! `amssymb`, `array`, `longtable`, `geometry`; `hyperref` and `lmodern`
//! when present). Formulas are set in math mode (expressions from their
//! LaTeX form, statements through [`prose`]); long expressions are
//! summarised as in the Markdown report ([`LONG`]); tables wrap their text
//! columns so that they fit the page.

use std::fmt::Write;

use super::markdown::{Shown, shown};
use super::{
    Entry, PRINTED_LONG, View, counts, method_short, methods, printed_shown, sections, short,
    size_text,
};
use crate::evidence::{Evidence, Expr, Part, Witness};
use crate::status::Status;

use trig_tex::{Column, LongTable, breakable, document, fitted_math, inline_math, prose, text};

/// Expressions with more characters (Unicode form) are summarised.
pub const LONG: usize = 160;

fn expr_tex(e: &Expr) -> String {
    match shown(e, LONG) {
        // a fraction cannot break across lines: a long one gets its own
        Shown::Full { latex, unicode }
            if latex.contains(r"\frac") && unicode.chars().count() > 60 =>
        {
            fitted_math(latex)
        }
        Shown::Full { latex, .. } => inline_math(latex),
        Shown::Summary {
            degree,
            terms,
            factored,
        } => {
            let f = factored.map_or(String::new(), |(_, l)| {
                format!(", factored {}", inline_math(l))
            });
            format!("[{}{f}; in full in JSON]", size_text(degree, terms))
        }
    }
}

fn witness_tex(w: &Witness) -> String {
    let point: Vec<String> = super::markdown::point_text(
        w,
        |a| a.latex.split(" = ").next().unwrap_or_default().to_string(),
        |a| a.latex.clone(),
    )
    .into_iter()
    .map(|p| inline_math(&p))
    .collect();
    let values: Vec<String> = w
        .values
        .iter()
        .map(|v| format!("{} $=$ {}", prose(&v.label), expr_tex(&v.value)))
        .collect();
    let note = w
        .note
        .as_ref()
        .map_or(String::new(), |n| format!(" ({})", prose(n)));
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
        format!("at {}{note}: {values}", point.join(", "))
    }
}

fn item_tex(group: &[Evidence], part: Option<&Part>, show_witness: bool) -> String {
    let e = &group[0];
    let mut out = String::new();
    if e.subject
        .as_deref()
        .is_some_and(|s| part.is_none_or(|p| p.name != *s))
    {
        let subjects: Vec<String> = group
            .iter()
            .filter_map(|g| g.subject.as_deref())
            .map(prose)
            .collect();
        out.push_str(&subjects.join("; "));
        if let Some(p) = e
            .printed
            .as_deref()
            .filter(|_| e.status != Some(Status::Holds))
        {
            let _ = match printed_shown(p, LONG) {
                Some(p) => write!(out, ", printed \\texttt{{{}}}", breakable(p)),
                None => write!(out, ", {PRINTED_LONG}"),
            };
        }
        if let Some(st) = e.status {
            let _ = write!(out, " --- \\textbf{{{st}}}");
        }
        if !e.text.is_empty() || !e.exprs.is_empty() {
            out.push_str(": ");
        }
    } else if let (Some(st), Some(p)) = (e.status, part)
        && p.status != st
    {
        let _ = write!(out, "\\textbf{{{st}}}: ");
    }
    out.push_str(&prose(&e.text));
    for (i, l) in e.exprs.iter().enumerate() {
        if i > 0 || !e.text.is_empty() {
            out.push_str("; ");
        }
        let _ = write!(out, "{} $=$ {}", prose(&l.label), expr_tex(&l.expr));
    }
    if show_witness && let Some(w) = &e.witness {
        let _ = write!(out, "; witness {}", witness_tex(w));
    }
    out
}

/// The evidence as an itemised list; items inside parts are grouped under
/// one item naming the part (its path, when parts nest).
fn evidence_tex(out: &mut String, items: &[Evidence], skip: Option<&Evidence>) {
    let _ = writeln!(out, "\\begin{{itemize}}");
    let mut open: Option<&[Part]> = None;
    for group in super::groups(items) {
        let e = &group[0];
        let parts = e.parts.as_slice();
        if open != Some(parts) {
            if open.is_some_and(|p| !p.is_empty()) {
                let _ = writeln!(out, "  \\end{{itemize}}");
            }
            if let Some(last) = parts.last() {
                let path: Vec<String> = parts.iter().map(|p| prose(&p.name)).collect();
                let _ = writeln!(
                    out,
                    "\\item \\textbf{{{}}} --- {}\n  \\begin{{itemize}}",
                    path.join(" $\\rangle$ "),
                    last.status
                );
            }
            open = Some(parts);
        }
        let own = skip.is_none_or(|s| !std::ptr::eq(s, e));
        let _ = writeln!(out, "  \\item {}", item_tex(group, parts.last(), own));
    }
    if open.is_some_and(|p| !p.is_empty()) {
        let _ = writeln!(out, "  \\end{{itemize}}");
    }
    let _ = writeln!(out, "\\end{{itemize}}");
}

fn anchor(id: &str) -> String {
    format!("claim-{}", id.to_ascii_lowercase())
}

/// A complete LaTeX document: summary and index as tables, then one
/// subsection per document and one subsubsection per claim.
pub fn tex_entries(entries: &[Entry], intro: &str, view: &View) -> String {
    let shown_entries = view.select(entries);
    let mut out = String::from("\\section*{trig-audit report}\n\n");
    let _ = writeln!(
        out,
        "{} Witness values are exact unless marked numeric. Long expressions are summarised here; the JSON report gives every expression in full.\n",
        prose(intro)
    );
    if let Some(n) = view.note() {
        let _ = writeln!(out, "{}\n", text(&n));
    }
    let _ = writeln!(out, "\\subsection*{{Summary}}\n");
    let mut columns = vec![Column::Left; 2];
    columns.extend([Column::Right; Status::ALL.len()]);
    let mut head = vec!["document".to_string(), "claims".to_string()];
    head.extend(Status::ALL.map(|s| s.label().to_string()));
    let mut summary = LongTable::new(columns, "Verdicts by document".into(), head).unnumbered();
    let all: Vec<&Entry> = entries.iter().collect();
    let count_cells = |of: &[&Entry]| -> Vec<String> {
        counts(of.iter().copied())
            .iter()
            .map(|(_, k)| k.to_string())
            .collect()
    };
    for (doc, of_doc) in sections(&all) {
        let mut row = vec![text(&doc.id), of_doc.len().to_string()];
        row.extend(count_cells(&of_doc));
        summary.row(row);
    }
    let mut total = vec!["\\textbf{all}".to_string(), entries.len().to_string()];
    total.extend(count_cells(&all));
    summary.foot(total);
    let _ = writeln!(out, "{summary}");
    let _ = writeln!(out, "\\subsection*{{Index}}\n");
    let mut index = LongTable::new(
        ["1.1cm", "2.2cm", "0.8cm", "3.2cm", "7.4cm"]
            .map(Column::Wrap)
            .to_vec(),
        "One line per claim".into(),
        ["claim", "verdict", "doc.", "source", "printed"]
            .map(String::from)
            .to_vec(),
    )
    .unnumbered()
    .small();
    for e in &shown_entries {
        let id = if view.summary_only {
            text(&e.id)
        } else {
            format!("\\hyperlink{{{}}}{{{}}}", anchor(&e.id), text(&e.id))
        };
        index.row(vec![
            id,
            e.verdict.status.to_string(),
            text(&e.document.id),
            prose(&e.source),
            prose(&short(&e.statement, 120)),
        ]);
    }
    let _ = writeln!(out, "{index}");
    if !view.summary_only {
        let methods = methods(&shown_entries);
        let _ = writeln!(out, "\\subsection*{{Methods}}\n\\begin{{enumerate}}");
        for (k, m) in methods.iter().enumerate() {
            let _ = writeln!(
                out,
                "\\item \\hypertarget{{method-{}}}{{}}{}",
                k + 1,
                prose(m)
            );
        }
        let _ = writeln!(out, "\\end{{enumerate}}\n");
        for (doc, of_doc) in sections(&shown_entries) {
            let _ = writeln!(
                out,
                "\\subsection*{{{} --- {}}}\n\nSource: \\texttt{{{}}}\n",
                text(&doc.heading),
                prose(&doc.title),
                text(&doc.location)
            );
            for e in of_doc {
                let k = methods
                    .iter()
                    .position(|m| *m == e.verdict.method)
                    .unwrap_or(0)
                    + 1;
                entry_tex(&mut out, e, k);
            }
        }
    }
    document(&out)
}

fn entry_tex(out: &mut String, e: &Entry, method: usize) {
    let v = &e.verdict;
    let _ = writeln!(
        out,
        "\\subsubsection*{{\\hypertarget{{{}}}{{{}}} --- {}}}\n",
        anchor(&e.id),
        text(&e.id),
        v.status
    );
    let _ = writeln!(out, "\\textbf{{Source:}} {}\\par", prose(&e.source));
    let _ = writeln!(out, "\\textbf{{Printed:}} {}\\par", prose(&e.statement));
    let _ = writeln!(
        out,
        "\\textbf{{How:}} {} (\\hyperlink{{method-{method}}}{{method {method}}})\\par",
        prose(&method_short(&v.method))
    );
    if let Some(corr) = &v.correction {
        let _ = writeln!(out, "\\textbf{{Correction:}} {}\\par", prose(corr));
    }
    let witness = (v.status != Status::Holds).then(|| e.witness()).flatten();
    if let Some((item, w)) = witness {
        let subject: Vec<String> = item
            .parts
            .iter()
            .map(|p| p.name.as_str())
            .chain(item.subject.as_deref())
            .map(prose)
            .collect();
        let _ = writeln!(
            out,
            "\\textbf{{Witness:}} {} {}\\par",
            subject.join(" $\\rangle$ "),
            witness_tex(w)
        );
    }
    if let Some(f) = e.figure {
        let _ = writeln!(
            out,
            "\\textbf{{Figure:}} {} (\\texttt{{{}}}; data \\texttt{{{}}}; pgfplots \\texttt{{{}}})\\par",
            prose(f.caption),
            breakable(f.path),
            breakable(&f.data_path()),
            breakable(&f.pgf_path())
        );
    }
    let _ = writeln!(out, "\\textbf{{Evidence:}}");
    evidence_tex(out, &v.evidence, witness.map(|(item, _)| item));
    out.push('\n');
}

#[cfg(test)]
mod tests {
    use super::super::test_entries::{doc, entry};
    use super::*;

    #[test]
    fn tex_report_has_summary_index_and_one_subsection_per_document() {
        let tex = tex_entries(
            &[
                entry("A1", doc("b", 5), Status::Fails),
                entry("A2", doc("a", 1), Status::Holds),
            ],
            "intro",
            &View::default(),
        );
        assert!(tex.starts_with("\\documentclass"));
        assert!(tex.trim_end().ends_with("\\end{document}"));
        let a = tex.find("\\subsection*{Spec a --- $t_{1}$}").unwrap();
        let b = tex.find("\\subsection*{Spec b --- $t_{1}$}").unwrap();
        assert!(a < b, "sections follow the document order");
        assert!(tex.contains("\\textbf{all} & 2 & 1 & 1 & 0 & 0 \\\\"));
        assert!(tex.contains("\\hyperlink{claim-a1}{A1} & fails"));
        assert!(tex.contains("residual $=$ $m^{2} - 4$"), "{tex}");
        assert!(tex.is_ascii(), "every character mapped");
    }
}
