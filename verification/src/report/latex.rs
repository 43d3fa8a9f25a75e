//! The LaTeX report: a complete document that compiles with pdfLaTeX (and
//! LuaLaTeX, XeLaTeX) using packages of a basic TeX installation (`amsmath`,
//! `amssymb`, `array`, `longtable`, `geometry`; `hyperref` and `lmodern`
//! when present). Formulas are set in math mode (expressions from their
//! LaTeX form, statements through [`tex_inline`]); long expressions are
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

pub use super::tex_text::{tex_escape, tex_inline, to_math, unmapped};

/// Expressions with more characters (Unicode form) are summarised.
pub const LONG: usize = 160;

/// The preamble of every LaTeX document trig-audit writes (reports and
/// tables): page, fonts, math, tables, links.
pub fn preamble() -> &'static str {
    r"\documentclass[a4paper,10pt]{article}
\usepackage{iftex}
\ifPDFTeX
  \usepackage[T1]{fontenc}
  \usepackage[utf8]{inputenc}
  \IfFileExists{lmodern.sty}{\usepackage{lmodern}}{}
\fi
\usepackage{amsmath,amssymb}
\usepackage{array,longtable,graphicx}
\usepackage[margin=2cm]{geometry}
\IfFileExists{hyperref.sty}{\usepackage[hidelinks]{hyperref}}{%
  \providecommand{\hypertarget}[2]{#2}\providecommand{\hyperlink}[2]{#2}}
\setlength{\parindent}{0pt}
\setlength{\parskip}{3pt}
\setlength{\emergencystretch}{3em}
\sloppy
\newcolumntype{L}[1]{>{\raggedright\arraybackslash}p{#1}}
% a long formula on its own line, scaled down only if wider than the line
\newcommand{\fitmath}[1]{\par\noindent\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{$\displaystyle #1$}\par}
"
}

/// Characters after which a long `\texttt` text (a path, a printed
/// formula) may break.
pub fn tex_breakable(text: &str) -> String {
    let mut out = String::new();
    for ch in text.chars() {
        out.push_str(&tex_escape(&ch.to_string()));
        if matches!(ch, '/' | ')' | ']' | '-' | '+' | ',') {
            out.push_str(r"\allowbreak{}");
        }
    }
    out
}

fn expr_tex(e: &Expr) -> String {
    match shown(e, LONG) {
        // a fraction cannot break across lines: a long one gets its own
        Shown::Full { latex, unicode }
            if latex.contains(r"\frac") && unicode.chars().count() > 60 =>
        {
            format!(r"\fitmath{{{latex}}}")
        }
        Shown::Full { latex, .. } => format!("${latex}$"),
        Shown::Summary {
            degree,
            terms,
            factored,
        } => {
            let f = factored.map_or(String::new(), |(_, l)| format!(", factored ${l}$"));
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
    .map(|p| format!("${p}$"))
    .collect();
    let values: Vec<String> = w
        .values
        .iter()
        .map(|v| format!("{} $=$ {}", tex_inline(&v.label), expr_tex(&v.value)))
        .collect();
    let note = w
        .note
        .as_ref()
        .map_or(String::new(), |n| format!(" ({})", tex_inline(n)));
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
            .map(tex_inline)
            .collect();
        out.push_str(&subjects.join("; "));
        if let Some(p) = e
            .printed
            .as_deref()
            .filter(|_| e.status != Some(Status::Holds))
        {
            let _ = match printed_shown(p, LONG) {
                Some(p) => write!(out, ", printed \\texttt{{{}}}", tex_breakable(p)),
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
    out.push_str(&tex_inline(&e.text));
    for (i, l) in e.exprs.iter().enumerate() {
        if i > 0 || !e.text.is_empty() {
            out.push_str("; ");
        }
        let _ = write!(out, "{} $=$ {}", tex_inline(&l.label), expr_tex(&l.expr));
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
                let path: Vec<String> = parts.iter().map(|p| tex_inline(&p.name)).collect();
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
    let mut out = String::from(preamble());
    out.push_str("\\begin{document}\n\\section*{trig-audit report}\n\n");
    let _ = writeln!(
        out,
        "{} Witness values are exact unless marked numeric. Long expressions are summarised here; the JSON report gives every expression in full.\n",
        tex_inline(intro)
    );
    if let Some(n) = view.note() {
        let _ = writeln!(out, "{}\n", tex_escape(&n));
    }
    let _ = writeln!(out, "\\subsection*{{Summary}}\n");
    let _ = writeln!(
        out,
        "\\begin{{longtable}}{{ll{}}}\n\\caption*{{Verdicts by document}}\\\\\n\\hline\ndocument & claims & {} \\\\\n\\hline\n\\endhead",
        "r".repeat(Status::ALL.len()),
        Status::ALL.map(|s| s.label()).join(" & ")
    );
    let all: Vec<&Entry> = entries.iter().collect();
    for (doc, of_doc) in sections(&all) {
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
    let _ = writeln!(out, "\\subsection*{{Index}}\n");
    let _ = writeln!(
        out,
        "{{\\small\n\\begin{{longtable}}{{L{{1.1cm}}L{{2.2cm}}L{{0.8cm}}L{{3.2cm}}L{{7.4cm}}}}\n\\caption*{{One line per claim}}\\\\\n\\hline\nclaim & verdict & doc. & source & printed \\\\\n\\hline\n\\endhead"
    );
    for e in &shown_entries {
        let id = if view.summary_only {
            tex_escape(&e.id)
        } else {
            format!("\\hyperlink{{{}}}{{{}}}", anchor(&e.id), tex_escape(&e.id))
        };
        let _ = writeln!(
            out,
            "{id} & {} & {} & {} & {} \\\\",
            e.verdict.status,
            tex_escape(&e.document.id),
            tex_inline(&e.source),
            tex_inline(&short(&e.statement, 120))
        );
    }
    let _ = writeln!(out, "\\hline\n\\end{{longtable}}\n}}\n");
    if !view.summary_only {
        let methods = methods(&shown_entries);
        let _ = writeln!(out, "\\subsection*{{Methods}}\n\\begin{{enumerate}}");
        for (k, m) in methods.iter().enumerate() {
            let _ = writeln!(
                out,
                "\\item \\hypertarget{{method-{}}}{{}}{}",
                k + 1,
                tex_inline(m)
            );
        }
        let _ = writeln!(out, "\\end{{enumerate}}\n");
        for (doc, of_doc) in sections(&shown_entries) {
            let _ = writeln!(
                out,
                "\\subsection*{{{} --- {}}}\n\nSource: \\texttt{{{}}}\n",
                tex_escape(&doc.heading),
                tex_inline(&doc.title),
                tex_escape(&doc.location)
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
    out.push_str("\\end{document}\n");
    out
}

fn entry_tex(out: &mut String, e: &Entry, method: usize) {
    let v = &e.verdict;
    let _ = writeln!(
        out,
        "\\subsubsection*{{\\hypertarget{{{}}}{{{}}} --- {}}}\n",
        anchor(&e.id),
        tex_escape(&e.id),
        v.status
    );
    let _ = writeln!(out, "\\textbf{{Source:}} {}\\par", tex_inline(&e.source));
    let _ = writeln!(
        out,
        "\\textbf{{Printed:}} {}\\par",
        tex_inline(&e.statement)
    );
    let _ = writeln!(
        out,
        "\\textbf{{How:}} {} (\\hyperlink{{method-{method}}}{{method {method}}})\\par",
        tex_inline(&method_short(&v.method))
    );
    if let Some(corr) = &v.correction {
        let _ = writeln!(out, "\\textbf{{Correction:}} {}\\par", tex_inline(corr));
    }
    let witness = (v.status != Status::Holds).then(|| e.witness()).flatten();
    if let Some((item, w)) = witness {
        let subject: Vec<String> = item
            .parts
            .iter()
            .map(|p| p.name.as_str())
            .chain(item.subject.as_deref())
            .map(tex_inline)
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
            tex_inline(f.caption),
            tex_breakable(f.path),
            tex_breakable(&f.data_path()),
            tex_breakable(&f.pgf_path())
        );
    }
    let _ = writeln!(out, "\\textbf{{Evidence:}}");
    evidence_tex(out, &v.evidence, witness.map(|(item, _)| item));
    out.push('\n');
}

/// What `pdflatex` said about a document.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct CompileLog {
    /// The error lines (`! …`) of the log.
    pub errors: Vec<String>,
    /// Number of overfull boxes.
    pub overfull: usize,
    /// Their log lines (the first few).
    pub overfull_lines: Vec<String>,
    /// Pages written.
    pub pages: usize,
}

/// Compiles `tex` with `pdflatex` (twice, for the links) in a temporary
/// directory and reads the log; `None` when `pdflatex` is not installed
/// (`./run.sh texlive` installs it). The tests of the reports and tables
/// use this; nothing else runs TeX.
pub fn compile(tex: &str, name: &str) -> Option<CompileLog> {
    let probe = std::process::Command::new("pdflatex")
        .arg("--version")
        .output()
        .ok()?;
    if !probe.status.success() {
        return None;
    }
    let dir = std::env::temp_dir().join(format!("trig-audit-tex-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).ok()?;
    std::fs::write(dir.join(format!("{name}.tex")), tex).ok()?;
    for _ in 0..2 {
        let _ = std::process::Command::new("pdflatex")
            .args(["-interaction=nonstopmode", "-halt-on-error"])
            .arg(format!("{name}.tex"))
            .current_dir(&dir)
            .output()
            .ok()?;
    }
    let log = std::fs::read(dir.join(format!("{name}.log"))).ok()?;
    let log = String::from_utf8_lossy(&log);
    let overfull_lines: Vec<String> = log
        .lines()
        .filter(|l| l.starts_with("Overfull"))
        .map(str::to_string)
        .collect();
    let pages = log
        .lines()
        .find_map(|l| l.split("Output written on ").nth(1))
        .and_then(|rest| rest.split('(').nth(1))
        .and_then(|n| n.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    let out = CompileLog {
        errors: log
            .lines()
            .filter(|l| l.starts_with("! "))
            .map(str::to_string)
            .collect(),
        overfull: overfull_lines.len(),
        overfull_lines: overfull_lines.into_iter().take(10).collect(),
        pages,
    };
    let _ = std::fs::remove_dir_all(&dir);
    Some(out)
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
