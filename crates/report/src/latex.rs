//! The LaTeX report (the `Format` of the report traversal, `render`): by default a
//! fragment to `\input` into a plain `article` that loads the standard
//! packages [`trig_tex::FRAGMENT_PACKAGES`] (with `pgfplots` too, the
//! figures are drawn); with [`TexOptions::standalone`] a complete document.
//! Both compile with pdfLaTeX (and LuaLaTeX, XeLaTeX), written with the one
//! LaTeX writer ([`trig_tex`]). Formulas are set in math mode (expressions
//! from their LaTeX form, printed statements from their markup through
//! [`trig_tex::marked`](mod@trig_tex::marked)); long expressions are summarised as in the
//! Markdown report ([`LONG`]); tables (`booktabs` rules) wrap their text
//! columns at fractions of the line width, so that they fit any page.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use trig_tex::marked::truncate;
use trig_tex::{
    Column, LongTable, breakable, code, document, fitted_math, fragment, inline_math, marked,
    prose, text,
};

use super::render::{BATTERY_LABEL, Format, Tally, anchor, point_text, render};
use super::{Document, Entry, View};
use trig_verdict::evidence::{Part, Witness};
use trig_verdict::status::Status;
use trig_verification::figures::{Figure, relative};

/// Expressions with more characters (Unicode form) are summarised.
pub const LONG: usize = 160;

/// How the LaTeX report is written.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct TexOptions {
    /// A complete document instead of a fragment for `\input`.
    pub standalone: bool,
    /// The directory the report is written to: figures are included by
    /// their path relative to it (`None`: the current directory, where the
    /// figures' paths start).
    pub output_dir: Option<PathBuf>,
}

/// The LaTeX report: summary and index as tables, then one subsection per
/// document and one subsubsection per claim; a fragment or a complete
/// document ([`TexOptions`]).
pub fn tex_entries(entries: &[Entry], intro: &str, view: &View, options: &TexOptions) -> String {
    render(&Latex { options }, entries, intro, view)
}

/// The LaTeX format of the report.
struct Latex<'a> {
    options: &'a TexOptions,
}

/// The index's columns — claim, verdict, document, source, printed — with
/// their shares (percent of the line): 10, 17, 9, 20, 44. The document
/// column is left out when the report has one document (its battery aside:
/// the battery's lines say `standard battery` as their source), its share
/// going to the printed statement. The claim, document and source columns
/// are widened to their longest unbreakable piece (a word, or the part of
/// an id between hyphens or of a path between slashes, set at `\small`) at
/// the cost of the printed statement (down to 24), then of the source (down
/// to its own longest piece, at least 14).
fn index_columns(entries: &[&Entry]) -> Vec<(&'static str, u8)> {
    // an upper bound of a `\small` Computer Modern character (about 5 pt)
    // over the text width of an `article` (345 pt), padding 12 pt, percent
    let need = |texts: &mut dyn Iterator<Item = &str>, cap: u8| -> u8 {
        let longest = texts
            .flat_map(|t| t.split([' ', '-', '/']))
            .map(|w| w.chars().count())
            .max()
            .unwrap_or(0);
        u8::try_from((longest * 500 + 1200).div_ceil(345))
            .unwrap_or(u8::MAX)
            .min(cap)
    };
    let mut documents: Vec<&str> = entries
        .iter()
        .filter(|e| !e.document.battery)
        .map(|e| e.document.id.as_str())
        .collect();
    documents.dedup();
    let one = documents.len() <= 1;
    let id = need(&mut entries.iter().map(|e| e.id.as_str()), 30).max(10);
    let doc = need(&mut entries.iter().map(|e| e.document.id.as_str()), 20).max(9);
    let source_least = need(&mut entries.iter().map(|e| e.source.as_str()), 20).max(14);
    let mut shares: Vec<(&'static str, u8)> = vec![("claim", id), ("verdict", 17)];
    if !one {
        shares.push(("doc.", doc));
    }
    shares.extend([("source", 20), ("printed", 0)]);
    let used: u32 = shares.iter().map(|(_, s)| u32::from(*s)).sum();
    let printed = 100u32.saturating_sub(used);
    let last = shares.len() - 1;
    if printed >= 24 {
        shares[last].1 = printed as u8;
    } else {
        // the source gives up to its least, the statement keeps 24
        let source = last - 1;
        let give = (24 - printed).min(u32::from(shares[source].1 - source_least));
        shares[source].1 -= give as u8;
        shares[last].1 = (printed + give) as u8;
    }
    shares
}

/// A claim's source in the index: prose, except that a path too long for
/// the column (`examples/independent/README.md`) may break after its `/`
/// and `.`.
fn source_cell(source: &str) -> String {
    let path = |w: &str| w.contains('/') && w.chars().count() > 16;
    if !source.split(' ').any(path) {
        return prose(source);
    }
    source
        .split(' ')
        .map(|w| {
            if path(w) {
                breakable(w).replace('.', r".\allowbreak{}")
            } else {
                prose(w)
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The file a figure is drawn in, as LaTeX includes it: a PDF or PNG beside
/// the SVG, else its pgfplots code; `None` when none of them exists.
fn figure_file(f: &Figure) -> Option<(String, bool)> {
    let pdf = f
        .path
        .rsplit_once('.')
        .map(|(stem, _)| stem)
        .unwrap_or(&f.path);
    [
        (format!("{pdf}.pdf"), true),
        (format!("{pdf}.png"), true),
        (f.pgf_path(), false),
    ]
    .into_iter()
    .find(|(path, _)| Path::new(path).is_file())
}

impl Format for Latex<'_> {
    const LONG: usize = LONG;
    const EQUALS: &'static str = " $=$ ";
    const DASH: &'static str = " --- ";
    const NESTED: &'static str = " $\\rangle$ ";

    fn prose(&self, text: &str) -> String {
        prose(text)
    }

    fn statement(&self, statement: &str) -> String {
        marked(statement)
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

    /// The figure itself when its file exists (a PDF or PNG with
    /// `\includegraphics`, else the pgfplots code with `\input` when the
    /// document loads pgfplots), by its path relative to where the report
    /// is written; else where it is.
    fn figure(&self, f: &Figure) -> String {
        let base = self.options.output_dir.as_deref();
        let reference = format!(
            "\\texttt{{{}}}; data \\texttt{{{}}}; pgfplots \\texttt{{{}}}",
            breakable(&relative(&f.path, base)),
            breakable(&relative(&f.data_path(), base)),
            breakable(&relative(&f.pgf_path(), base))
        );
        let caption = prose(&f.caption);
        match figure_file(f) {
            None => format!("{caption} ({reference})"),
            Some((file, true)) => {
                let file = relative(&file, base);
                // braces around the name: dots in it are not its extension
                let (stem, ext) = file.rsplit_once('.').unwrap_or((&file, ""));
                format!(
                    "{caption} ({reference})\\par\n\\begin{{center}}\\includegraphics[width=\\linewidth,height=0.4\\textheight,keepaspectratio]{{{{{stem}}}.{ext}}}\\end{{center}}"
                )
            }
            Some((file, false)) => format!(
                "{caption} ({reference})\\par\n\\ifdefined\\pgfplotsset\n\\begin{{center}}\\fitbox{{\\input{{{}}}}}\\end{{center}}\n\\else\n(the figure is drawn when the document loads \\texttt{{pgfplots}})\n\\fi",
                relative(&file, base)
            ),
        }
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
        // the status columns take about 290 pt of the line: a document name
        // longer than a seed's (a spec id, the battery's line) wraps at its
        // hyphens in a small table
        let long = documents
            .iter()
            .any(|(d, _)| d.id.chars().count() > 8 || d.battery);
        let first = if long {
            Column::Share(22)
        } else {
            Column::Left
        };
        let mut columns = vec![first, Column::Left];
        columns.extend([Column::Right; Status::ALL.len()]);
        let head = ["document", "claims"]
            .into_iter()
            .chain(Status::ALL.map(|s| s.label()))
            .map(String::from)
            .collect();
        let mut table = LongTable::new(columns, "Verdicts by document".into(), head).unnumbered();
        if long {
            table = table.small();
        }
        let cells = |first: String, t: &Tally| -> Vec<String> {
            [first, t.claims.to_string()]
                .into_iter()
                .chain(t.by_status.iter().map(usize::to_string))
                .collect()
        };
        for (doc, t) in documents.iter().filter(|(d, _)| !d.battery) {
            table.row(cells(text(&doc.id), t));
        }
        table.foot(cells(self.strong("all"), all));
        for (_, t) in documents.iter().filter(|(d, _)| d.battery) {
            table.foot(cells(text(BATTERY_LABEL), t));
        }
        let _ = writeln!(out, "{table}");
    }

    fn index(&self, out: &mut String, entries: &[&Entry], linked: bool) {
        let _ = writeln!(out, "\\subsection*{{Index}}\n");
        let shares = index_columns(entries);
        let with_document = shares.iter().any(|(name, _)| *name == "doc.");
        let columns = shares.iter().map(|(_, s)| Column::Share(*s)).collect();
        let head = shares.iter().map(|(name, _)| name.to_string()).collect();
        let mut table = LongTable::new(columns, "One line per claim".into(), head)
            .unnumbered()
            .small();
        for e in entries {
            let id = if linked {
                format!("\\hyperlink{{{}}}{{{}}}", anchor(&e.id), text(&e.id))
            } else {
                text(&e.id)
            };
            let mut row = vec![id, e.verdict.status.to_string()];
            if with_document {
                row.push(text(&e.document.id));
            }
            row.extend([source_cell(&e.source), marked(&truncate(&e.statement, 120))]);
            table.row(row);
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
            "\\subsection*{{{} --- {}}}\n\nSource: {}\n",
            text(&doc.heading),
            prose(&doc.title),
            code(&doc.location)
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
        if self.options.standalone {
            document(&out)
        } else {
            fragment("trig-audit report (LaTeX fragment)", &out)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_entries::{doc, entry};
    use super::*;

    #[test]
    fn tex_report_has_summary_index_and_one_subsection_per_document() {
        let entries = [
            entry("A1", doc("b", 5), Status::Fails),
            entry("A2", doc("a", 1), Status::Holds),
        ];
        let standalone = TexOptions {
            standalone: true,
            output_dir: None,
        };
        let tex = tex_entries(&entries, "intro", &View::default(), &standalone);
        assert!(tex.starts_with("\\documentclass"));
        assert!(tex.trim_end().ends_with("\\end{document}"));
        let a = tex.find("\\subsection*{Spec a --- $t_{1}$}").unwrap();
        let b = tex.find("\\subsection*{Spec b --- $t_{1}$}").unwrap();
        assert!(a < b, "sections follow the document order");
        assert!(tex.contains("\\textbf{all} & 2 & 1 & 1 & 0 & 0 \\\\"));
        assert!(tex.contains("\\hyperlink{claim-a1}{A1} & fails"));
        assert!(tex.contains("residual $=$ $m^{2} - 4$"), "{tex}");
        assert!(tex.contains("\\toprule") && !tex.contains("\\hline"));
        assert!(tex.is_ascii(), "every character mapped");
        // the default: a fragment, the same body without a preamble
        let part = tex_entries(&entries, "intro", &View::default(), &TexOptions::default());
        assert!(part.starts_with("% trig-audit report"));
        assert!(!part.contains("\\documentclass") && !part.contains("\\begin{document}"));
        assert!(part.contains("\\hyperlink{claim-a1}{A1} & fails"));
    }

    #[test]
    fn statements_are_set_from_their_markup() {
        let mut e = entry("A1", doc("a", 1), Status::Holds);
        e.statement = "reading of T4 (A45): ⟪R''(π/2) = tan α⟫".into();
        let tex = tex_entries(&[e], "intro", &View::default(), &TexOptions::default());
        assert!(
            tex.contains(r"reading of T4 (A45): $R''(\frac{\pi}{2}) = \tan \alpha$"),
            "{tex}"
        );
    }
}
