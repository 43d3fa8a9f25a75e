//! The LaTeX report ([`Format`] for [`super::render`]): a complete
//! document that compiles with pdfLaTeX (and LuaLaTeX, XeLaTeX) using
//! packages of a basic TeX installation, written with the one LaTeX writer
//! ([`trig_tex`]). Formulas are set in math mode (expressions from their
//! LaTeX form, statements through [`trig_tex::prose`]); long expressions
//! are summarised as in the Markdown report ([`LONG`]); tables wrap their
//! text columns so that they fit the page.

use std::fmt::Write;

use trig_tex::{Column, LongTable, breakable, document, fitted_math, inline_math, prose, text};

use super::render::{Format, Tally, anchor, point_text, render};
use super::{Document, Entry, View, short};
use crate::evidence::{Part, Witness};
use crate::figures::Figure;
use crate::status::Status;

/// Expressions with more characters (Unicode form) are summarised.
pub const LONG: usize = 160;

/// A complete LaTeX document: summary and index as tables, then one
/// subsection per document and one subsubsection per claim.
pub fn tex_entries(entries: &[Entry], intro: &str, view: &View) -> String {
    render(&Latex, entries, intro, view)
}

/// The LaTeX format of the report.
struct Latex;

impl Format for Latex {
    const LONG: usize = LONG;
    const EQUALS: &'static str = " $=$ ";
    const DASH: &'static str = " --- ";
    const NESTED: &'static str = " $\\rangle$ ";

    fn prose(&self, text: &str) -> String {
        prose(text)
    }

    fn printed(&self, formula: &str) -> String {
        format!("\\texttt{{{}}}", breakable(formula))
    }

    fn strong(&self, text: &str) -> String {
        format!("\\textbf{{{text}}}")
    }

    fn formula(&self, _unicode: &str, latex: &str) -> String {
        inline_math(latex)
    }

    fn full(&self, unicode: &str, latex: &str) -> String {
        // a fraction cannot break across lines: a long one gets its own
        if latex.contains(r"\frac") && unicode.chars().count() > 60 {
            fitted_math(latex)
        } else {
            inline_math(latex)
        }
    }

    fn point(&self, w: &Witness) -> Option<String> {
        let point = point_text(
            w,
            |a| a.latex.split(" = ").next().unwrap_or_default().to_string(),
            |a| a.latex.clone(),
        );
        let point: Vec<String> = point.iter().map(|p| inline_math(p)).collect();
        (!point.is_empty()).then(|| point.join(", "))
    }

    fn witnessed(&self, subject: &str, line: &str) -> String {
        format!("{subject} {line}")
    }

    fn method(&self, short: &str, k: usize) -> String {
        format!("{} (\\hyperlink{{method-{k}}}{{method {k}}})", prose(short))
    }

    fn figure(&self, f: &Figure) -> String {
        format!(
            "{} (\\texttt{{{}}}; data \\texttt{{{}}}; pgfplots \\texttt{{{}}})",
            prose(f.caption),
            breakable(f.path),
            breakable(&f.data_path()),
            breakable(&f.pgf_path())
        )
    }

    fn start(&self, out: &mut String, intro: &str, note: Option<&str>) {
        out.push_str("\\section*{trig-audit report}\n\n");
        let _ = writeln!(
            out,
            "{} Witness values are exact unless marked numeric. Long expressions are summarised here; the JSON report gives every expression in full.\n",
            prose(intro)
        );
        if let Some(n) = note {
            let _ = writeln!(out, "{}\n", text(n));
        }
    }

    fn summary(&self, out: &mut String, documents: &[(&Document, Tally)], all: &Tally) {
        let _ = writeln!(out, "\\subsection*{{Summary}}\n");
        let mut columns = vec![Column::Left; 2];
        columns.extend([Column::Right; Status::ALL.len()]);
        let head = ["document", "claims"]
            .into_iter()
            .chain(Status::ALL.map(|s| s.label()))
            .map(String::from)
            .collect();
        let mut table = LongTable::new(columns, "Verdicts by document".into(), head).unnumbered();
        let cells = |first: String, t: &Tally| -> Vec<String> {
            [first, t.claims.to_string()]
                .into_iter()
                .chain(t.by_status.iter().map(usize::to_string))
                .collect()
        };
        for (doc, t) in documents {
            table.row(cells(text(&doc.id), t));
        }
        table.foot(cells(self.strong("all"), all));
        let _ = writeln!(out, "{table}");
    }

    fn index(&self, out: &mut String, entries: &[&Entry], linked: bool) {
        let _ = writeln!(out, "\\subsection*{{Index}}\n");
        let columns = ["1.1cm", "2.2cm", "0.8cm", "3.2cm", "7.4cm"].map(Column::Wrap);
        let head = ["claim", "verdict", "doc.", "source", "printed"].map(String::from);
        let mut table =
            LongTable::new(columns.to_vec(), "One line per claim".into(), head.to_vec())
                .unnumbered()
                .small();
        for e in entries {
            let id = if linked {
                format!("\\hyperlink{{{}}}{{{}}}", anchor(&e.id), text(&e.id))
            } else {
                text(&e.id)
            };
            table.row(vec![
                id,
                e.verdict.status.to_string(),
                text(&e.document.id),
                prose(&e.source),
                prose(&short(&e.statement, 120)),
            ]);
        }
        let _ = writeln!(out, "{table}");
    }

    fn methods(&self, out: &mut String, methods: &[&str]) {
        let _ = writeln!(out, "\\subsection*{{Methods}}\n\\begin{{enumerate}}");
        for (k, m) in (1..).zip(methods) {
            let _ = writeln!(out, "\\item \\hypertarget{{method-{k}}}{{}}{}", prose(m));
        }
        let _ = writeln!(out, "\\end{{enumerate}}\n");
    }

    fn section(&self, out: &mut String, doc: &Document) {
        let _ = writeln!(
            out,
            "\\subsection*{{{} --- {}}}\n\nSource: \\texttt{{{}}}\n",
            text(&doc.heading),
            prose(&doc.title),
            text(&doc.location)
        );
    }

    fn heading(&self, out: &mut String, e: &Entry) {
        let _ = writeln!(
            out,
            "\\subsubsection*{{\\hypertarget{{{}}}{{{}}} --- {}}}\n",
            anchor(&e.id),
            text(&e.id),
            e.verdict.status
        );
    }

    fn field(&self, out: &mut String, name: &str, value: &str) {
        let _ = writeln!(out, "\\textbf{{{name}:}} {value}\\par");
    }

    fn evidence_start(&self, out: &mut String) {
        let _ = writeln!(out, "\\textbf{{Evidence:}}\n\\begin{{itemize}}");
    }

    /// Items inside parts are grouped under one item naming the parts (its
    /// path, when parts nest).
    fn parts(&self, out: &mut String, from: &[Part], to: &[Part]) {
        if !from.is_empty() {
            let _ = writeln!(out, "  \\end{{itemize}}");
        }
        if let Some(last) = to.last() {
            let path: Vec<String> = to.iter().map(|p| prose(&p.name)).collect();
            let _ = writeln!(
                out,
                "\\item \\textbf{{{}}} --- {}\n  \\begin{{itemize}}",
                path.join(Self::NESTED),
                last.status
            );
        }
    }

    fn item(&self, out: &mut String, _depth: usize, line: &str) {
        let _ = writeln!(out, "  \\item {line}");
    }

    fn evidence_end(&self, out: &mut String) {
        let _ = writeln!(out, "\\end{{itemize}}");
    }

    fn finish(&self, out: String) -> String {
        document(&out)
    }
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
