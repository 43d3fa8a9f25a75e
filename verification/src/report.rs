//! The audit report: Markdown for people, JSON for machines, LaTeX for
//! papers — same content. Entries ([`Entry`]) are owned, so claims built at
//! run time (from a spec file, see [`crate::spec_audit`]) report exactly
//! like the built-in ones ([`Outcome`]).

use std::fmt::Write;

use serde_json::json;

use crate::Outcome;
use crate::claim::Seed;
use crate::figures::{self, Figure};
use crate::verdict::{Status, Verdict};

/// The opening sentence of the built-in report.
pub const BUILTIN_INTRO: &str = "Every verdict below is computed by `trig-audit audit` from the formulas as printed in `shared/seeds/`; identities are decided exactly in the symbolic ring, counterexamples in 256-bit MPFR.";

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
    /// Sort key of the sections (seeds in [`Seed::ALL`] order first).
    pub order: usize,
}

impl Document {
    /// The document of a seed.
    pub fn seed(seed: Seed) -> Document {
        Document {
            heading: format!("Seed {}", seed.id()),
            id: seed.id().to_string(),
            title: seed.title().to_string(),
            file: seed.file().to_string(),
            location: format!("shared/seeds/{}", seed.file()),
            order: Seed::ALL.iter().position(|s| *s == seed).unwrap_or(0),
        }
    }
}

/// One claim of the report with its computed verdict.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry {
    pub id: String,
    pub document: Document,
    /// Equation or section.
    pub source: String,
    /// The statement as printed.
    pub statement: String,
    pub verdict: Verdict,
    /// A figure supporting the verdict ([`crate::figures`]).
    pub figure: Option<&'static Figure>,
}

impl From<&Outcome> for Entry {
    fn from(o: &Outcome) -> Entry {
        Entry {
            id: o.claim.id.to_string(),
            document: Document::seed(o.claim.seed),
            source: o.claim.source.to_string(),
            statement: o.claim.statement.to_string(),
            verdict: o.verdict.clone(),
            figure: figures::for_claim(o.claim.id),
        }
    }
}

/// The entries of built-in outcomes.
pub fn entries(outcomes: &[Outcome]) -> Vec<Entry> {
    outcomes.iter().map(Entry::from).collect()
}

/// Counts of each status among `entries`.
fn counts<'a>(entries: impl Iterator<Item = &'a Entry> + Clone) -> Vec<(Status, usize)> {
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
fn sections(entries: &[Entry]) -> Vec<(&Document, Vec<&Entry>)> {
    let mut docs: Vec<&Document> = Vec::new();
    for e in entries {
        if !docs.contains(&&e.document) {
            docs.push(&e.document);
        }
    }
    docs.sort_by_key(|d| d.order);
    docs.into_iter()
        .map(|d| (d, entries.iter().filter(|e| &e.document == d).collect()))
        .collect()
}

/// The built-in Markdown report.
pub fn markdown(outcomes: &[Outcome]) -> String {
    markdown_entries(&entries(outcomes), BUILTIN_INTRO)
}

/// The Markdown report: a summary (by verdict and by document), then one
/// section per document and one entry per claim.
pub fn markdown_entries(entries: &[Entry], intro: &str) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# trig-audit report\n");
    let _ = writeln!(out, "{intro}\n");
    let _ = writeln!(out, "## Summary\n");
    let _ = writeln!(
        out,
        "| document | claims | {} |",
        Status::ALL.map(|s| s.label()).join(" | ")
    );
    let _ = writeln!(out, "|---|---|{}", "---|".repeat(Status::ALL.len()));
    let sections = sections(entries);
    for (doc, of_doc) in &sections {
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
    for (doc, of_doc) in sections {
        let _ = writeln!(out, "## {} — {}\n", doc.heading, doc.title);
        let _ = writeln!(out, "Source: `{}`\n", doc.location);
        for e in of_doc {
            let v = &e.verdict;
            let _ = writeln!(out, "### {} — {}\n", e.id, v.status);
            let _ = writeln!(out, "- **Source:** {}", e.source);
            let _ = writeln!(out, "- **Printed:** {}", e.statement);
            let _ = writeln!(out, "- **Verdict:** {}", v.status);
            let _ = writeln!(out, "- **How:** {}", v.method);
            if let Some(corr) = &v.correction {
                let _ = writeln!(out, "- **Correction:** {corr}");
            }
            if let Some(f) = e.figure {
                let _ = writeln!(
                    out,
                    "- **Figure:** [{}]({}) (drawn by `trig-audit {}`)",
                    f.caption, f.path, f.command
                );
            }
            let _ = writeln!(out, "- **Evidence:**");
            for line in &v.evidence {
                let _ = writeln!(out, "  - `{}`", line.replace('`', "'"));
            }
            out.push('\n');
        }
    }
    out
}

/// The built-in report as JSON.
pub fn json(outcomes: &[Outcome]) -> serde_json::Value {
    json_entries(&entries(outcomes))
}

/// The same content as JSON.
pub fn json_entries(entries: &[Entry]) -> serde_json::Value {
    let summary: serde_json::Map<String, serde_json::Value> = counts(entries.iter())
        .into_iter()
        .map(|(s, n)| (s.label().to_string(), json!(n)))
        .collect();
    json!({
        "summary": summary,
        "claims": entries.iter().map(|e| json!({
            "id": e.id,
            "seed": e.document.id,
            "seed_file": e.document.file,
            "source": e.source,
            "statement": e.statement,
            "verdict": e.verdict.status.label(),
            "method": e.verdict.method,
            "evidence": e.verdict.evidence,
            "correction": e.verdict.correction,
            "figure": e.figure.map(|f| f.path),
        })).collect::<Vec<_>>(),
    })
}

/// The built-in report as a LaTeX document.
pub fn tex(outcomes: &[Outcome]) -> String {
    tex_entries(&entries(outcomes), BUILTIN_INTRO)
}

/// A complete LaTeX document: the summary as a table, then one subsection
/// per document with its claims as a description list. Every text is
/// escaped ([`tex_escape`]); compiles with pdfLaTeX, LuaLaTeX or XeLaTeX.
pub fn tex_entries(entries: &[Entry], intro: &str) -> String {
    let mut out = String::new();
    out.push_str("\\documentclass[a4paper,10pt]{article}\n\\usepackage{iftex}\n\\ifPDFTeX\n  \\usepackage[T1]{fontenc}\n  \\usepackage[utf8]{inputenc}\n\\fi\n\\usepackage{amsmath,amssymb}\n\\usepackage{longtable}\n\\usepackage[margin=2cm]{geometry}\n\\begin{document}\n\\section*{trig-audit report}\n\n");
    let _ = writeln!(out, "{}\n", tex_escape(intro));
    let _ = writeln!(out, "\\subsection*{{Summary}}\n");
    let _ = writeln!(
        out,
        "\\begin{{longtable}}{{ll{}}}\n\\hline\ndocument & claims & {} \\\\\n\\hline\n\\endhead",
        "r".repeat(Status::ALL.len()),
        Status::ALL.map(|s| tex_escape(s.label())).join(" & ")
    );
    let sections = sections(entries);
    for (doc, of_doc) in &sections {
        let c: Vec<String> = counts(of_doc.iter().copied())
            .iter()
            .map(|(_, k)| k.to_string())
            .collect();
        let _ = writeln!(
            out,
            "{} & {} & {} \\\\",
            tex_escape(&doc.id),
            of_doc.len(),
            c.join(" & ")
        );
    }
    let c: Vec<String> = counts(entries.iter())
        .iter()
        .map(|(_, k)| k.to_string())
        .collect();
    let _ = writeln!(
        out,
        "\\hline\n\\textbf{{all}} & {} & {} \\\\\n\\hline\n\\end{{longtable}}\n",
        entries.len(),
        c.join(" & ")
    );
    for (doc, of_doc) in sections {
        let _ = writeln!(
            out,
            "\\subsection*{{{} --- {}}}\n\nSource: \\texttt{{{}}}\n\n\\begin{{description}}",
            tex_escape(&doc.heading),
            tex_escape(&doc.title),
            tex_escape(&doc.location)
        );
        for e in of_doc {
            let v = &e.verdict;
            let _ = writeln!(
                out,
                "\\item[{} --- {}] \\mbox{{}}\\\\\n\\textbf{{Source:}} {}\\\\\n\\textbf{{Printed:}} {}\\\\\n\\textbf{{How:}} {}",
                tex_escape(&e.id),
                tex_escape(v.status.label()),
                tex_escape(&e.source),
                tex_escape(&e.statement),
                tex_escape(&v.method)
            );
            if let Some(corr) = &v.correction {
                let _ = writeln!(out, "\\\\\n\\textbf{{Correction:}} {}", tex_escape(corr));
            }
            if let Some(f) = e.figure {
                let _ = writeln!(
                    out,
                    "\\\\\n\\textbf{{Figure:}} {} (\\texttt{{{}}})",
                    tex_escape(f.caption),
                    tex_escape(f.path)
                );
            }
            let _ = writeln!(out, "\\\\\n\\textbf{{Evidence:}}\n\\begin{{itemize}}");
            for line in &v.evidence {
                let _ = writeln!(out, "  \\item {{\\small {}}}", tex_escape(line));
            }
            let _ = writeln!(out, "\\end{{itemize}}");
        }
        let _ = writeln!(out, "\\end{{description}}\n");
    }
    out.push_str("\\end{document}\n");
    out
}

/// Unicode math characters of the reports as LaTeX.
const TEX_SYMBOLS: &[(char, &str)] = &[
    ('α', "$\\alpha$"),
    ('β', "$\\beta$"),
    ('γ', "$\\gamma$"),
    ('δ', "$\\delta$"),
    ('ε', "$\\varepsilon$"),
    ('ζ', "$\\zeta$"),
    ('η', "$\\eta$"),
    ('θ', "$\\theta$"),
    ('λ', "$\\lambda$"),
    ('μ', "$\\mu$"),
    ('ξ', "$\\xi$"),
    ('π', "$\\pi$"),
    ('σ', "$\\sigma$"),
    ('ω', "$\\omega$"),
    ('Σ', "$\\Sigma$"),
    ('Δ', "$\\Delta$"),
    ('−', "$-$"),
    ('≥', "$\\geq$"),
    ('≤', "$\\leq$"),
    ('≠', "$\\neq$"),
    ('≈', "$\\approx$"),
    ('∈', "$\\in$"),
    ('↦', "$\\mapsto$"),
    ('→', "$\\to$"),
    ('∞', "$\\infty$"),
    ('·', "$\\cdot$"),
    ('×', "$\\times$"),
    ('′', "$'$"),
    ('√', "$\\surd$"),
    ('∂', "$\\partial$"),
    ('…', "\\ldots{}"),
    ('—', "---"),
    ('–', "--"),
    ('“', "``"),
    ('”', "''"),
    ('‘', "`"),
    ('’', "'"),
    ('⁰', "$^{0}$"),
    ('¹', "$^{1}$"),
    ('²', "$^{2}$"),
    ('³', "$^{3}$"),
    ('⁴', "$^{4}$"),
    ('⁵', "$^{5}$"),
    ('⁶', "$^{6}$"),
    ('⁷', "$^{7}$"),
    ('⁸', "$^{8}$"),
    ('⁹', "$^{9}$"),
    ('⁻', "$^{-}$"),
    ('₀', "$_{0}$"),
    ('₁', "$_{1}$"),
    ('₂', "$_{2}$"),
    ('₃', "$_{3}$"),
    ('₄', "$_{4}$"),
    ('₅', "$_{5}$"),
    ('₆', "$_{6}$"),
    ('₇', "$_{7}$"),
    ('₈', "$_{8}$"),
    ('₉', "$_{9}$"),
];

/// Escapes text for LaTeX: the ten special characters, and the Unicode
/// math symbols of [`TEX_SYMBOLS`] as math. Other characters pass through.
pub fn tex_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        match ch {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '$' | '&' | '#' | '_' | '%' => {
                out.push('\\');
                out.push(ch);
            }
            '^' => out.push_str("\\textasciicircum{}"),
            '~' => out.push_str("\\textasciitilde{}"),
            '<' => out.push_str("\\textless{}"),
            '>' => out.push_str("\\textgreater{}"),
            '|' => out.push_str("\\textbar{}"),
            _ => match TEX_SYMBOLS.iter().find(|(c, _)| *c == ch) {
                Some((_, tex)) => out.push_str(tex),
                None => out.push(ch),
            },
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_special_characters_are_escaped() {
        assert_eq!(
            tex_escape(r"50% of {a_b} & $x^2 # ~\"),
            r"50\% of \{a\_b\} \& \$x\textasciicircum{}2 \# \textasciitilde{}\textbackslash{}"
        );
        assert_eq!(
            tex_escape("θ ↦ π/2 − θ, b₀ ≥ 0"),
            r"$\theta$ $\mapsto$ $\pi$/2 $-$ $\theta$, b$_{0}$ $\geq$ 0"
        );
    }

    #[test]
    fn tex_report_has_a_summary_and_one_subsection_per_document() {
        let doc = |id: &str, order| Document {
            heading: format!("Spec {id}"),
            id: id.into(),
            title: "t_1".into(),
            file: "f".into(),
            location: "f".into(),
            order,
        };
        let entry = |id: &str, d: Document, status| Entry {
            id: id.into(),
            document: d,
            source: "(1)".into(),
            statement: "Σ b_i = 1".into(),
            verdict: Verdict::new(status, "exact", vec!["residual 0".into()]),
            figure: None,
        };
        let tex = tex_entries(
            &[
                entry("A1", doc("b", 5), Status::Fails),
                entry("A2", doc("a", 1), Status::Holds),
            ],
            "intro",
        );
        assert!(tex.starts_with("\\documentclass"));
        assert!(tex.trim_end().ends_with("\\end{document}"));
        let a = tex.find("\\subsection*{Spec a --- t\\_1}").unwrap();
        let b = tex.find("\\subsection*{Spec b --- t\\_1}").unwrap();
        assert!(a < b, "sections follow the document order");
        assert!(tex.contains("\\textbf{all} & 2 & 1 & 1 & 0 & 0 \\\\"));
        assert!(tex.contains("\\item[A1 --- fails]"));
        assert!(tex.contains("$\\Sigma$ b\\_i = 1"));
    }
}
