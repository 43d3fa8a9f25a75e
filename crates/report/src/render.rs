//! One traversal of the report for every text format: [`render`] walks the
//! structure once — opening, summary, index, methods, then per document its
//! section and per claim its entry (fields, witness, figure, evidence
//! nested by parts) — and composes the lines every format shares (an
//! evidence item, a witness, an expression or its summary); a [`Format`]
//! says how each piece is written (Markdown in [`super::markdown`], LaTeX in
//! [`super::latex`]). The JSON report is the same entries through serde.

use trig_verdict::plural;

use super::{Document, Entry, View, counts, sections};
use trig_verdict::evidence::{Assignment, Evidence, Expr, Part, Witness};
use trig_verdict::status::Status;
use trig_verification::figures::Figure;

/// The claims of a document (or of all) and how many have each status, in
/// [`Status::ALL`] order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Tally {
    pub claims: usize,
    pub by_status: Vec<usize>,
}

impl Tally {
    fn of(entries: &[&Entry]) -> Tally {
        Tally {
            claims: entries.len(),
            by_status: counts(entries.iter().copied())
                .into_iter()
                .map(|(_, k)| k)
                .collect(),
        }
    }
}

/// How a format writes the pieces of the report. Inline pieces return
/// text; block pieces append to the document.
pub(crate) trait Format {
    /// Expressions with more characters (Unicode form) are summarised.
    const LONG: usize;
    /// Between a label and its value.
    const EQUALS: &'static str;
    /// Between a subject and its status.
    const DASH: &'static str;
    /// Between the names of nested parts.
    const NESTED: &'static str;

    /// Prose, with its formulas (a label, a note).
    fn prose(&self, text: &str) -> String;
    /// A printed statement, its formulas marked ([`trig_tex::marked`]).
    fn statement(&self, marked: &str) -> String;
    /// A formula as printed in the source (transcribed text).
    fn printed(&self, formula: &str) -> String;
    /// Emphasised text (a status).
    fn strong(&self, text: &str) -> String;
    /// A formula given in Unicode and in LaTeX, inline.
    fn formula(&self, unicode: &str, latex: &str) -> String;
    /// An expression shown in full.
    fn full(&self, unicode: &str, latex: &str) -> String {
        self.formula(unicode, latex)
    }
    /// The coordinates of a witness point, if it has any.
    fn point(&self, w: &Witness) -> Option<String>;
    /// The witness of an entry: what fails (`subject`, in this format)
    /// and the witness line.
    fn witnessed(&self, subject: &str, line: &str) -> String;
    /// A reference to method `k` (numbered from 1) by its short form.
    fn method(&self, short: &str, k: usize) -> String;
    /// A figure: caption, where it is and how it is drawn.
    fn figure(&self, f: &Figure) -> String;

    /// The title and opening paragraph (and what the view leaves out).
    fn start(&self, out: &mut String, intro: &str, note: Option<&str>);
    /// The summary: a line per document, then all (the documents' claims,
    /// without the battery), then a line per battery ([`Document::battery`]).
    fn summary(&self, out: &mut String, documents: &[(&Document, Tally)], all: &Tally);
    /// The index: a line per claim, linked to its entry when `linked`.
    fn index(&self, out: &mut String, entries: &[&Entry], linked: bool);
    /// The methods, numbered from 1.
    fn methods(&self, out: &mut String, methods: &[&str]);
    /// The heading of a document's section.
    fn section(&self, out: &mut String, doc: &Document);
    /// The heading of a claim's entry.
    fn heading(&self, out: &mut String, e: &Entry);
    /// A named field of an entry.
    fn field(&self, out: &mut String, name: &str, value: &str);
    /// Before the evidence of an entry.
    fn evidence_start(&self, out: &mut String);
    /// The parts around the next items change from `from` to `to`.
    fn parts(&self, out: &mut String, from: &[Part], to: &[Part]);
    /// An evidence item inside `depth` parts.
    fn item(&self, out: &mut String, depth: usize, line: &str);
    /// After the evidence of an entry.
    fn evidence_end(&self, out: &mut String);
    /// The finished document.
    fn finish(&self, out: String) -> String;
}

/// The report in format `f`: a summary (by verdict and by document), an
/// index (one line per claim), then one section per document and one entry
/// per claim — or, with [`View::summary_only`], the summary and index alone.
pub(crate) fn render<F: Format>(f: &F, entries: &[Entry], intro: &str, view: &View) -> String {
    let shown = view.select(entries);
    let mut out = String::new();
    f.start(&mut out, intro, view.note().as_deref());
    let all: Vec<&Entry> = entries.iter().collect();
    let documents: Vec<(&Document, Tally)> = sections(&all)
        .into_iter()
        .map(|(d, of_doc)| (d, Tally::of(&of_doc)))
        .collect();
    f.summary(&mut out, &documents, &Tally::of(&claims_only(&all)));
    f.index(&mut out, &shown, !view.summary_only);
    if !view.summary_only {
        let methods = methods(&shown);
        f.methods(&mut out, &methods);
        for (doc, of_doc) in sections(&shown) {
            f.section(&mut out, doc);
            for e in of_doc {
                let k = methods
                    .iter()
                    .position(|m| *m == e.verdict.method)
                    .unwrap_or(0)
                    + 1;
                entry(f, &mut out, e, k);
            }
        }
    }
    f.finish(out)
}

/// The claims of the documents, without the checks of a battery (counted
/// apart).
pub(crate) fn claims_only<'a>(entries: &[&'a Entry]) -> Vec<&'a Entry> {
    entries
        .iter()
        .copied()
        .filter(|e| !e.document.battery)
        .collect()
}

/// What a summary row of a battery is called: that it is a battery, not
/// in the total (short: the row shares a table with the status columns).
pub(crate) const BATTERY_LABEL: &str = "battery (not in all)";

/// One claim: source, printed statement, method, correction, the witness
/// of a claim that does not hold, figure, evidence.
fn entry<F: Format>(f: &F, out: &mut String, e: &Entry, method: usize) {
    let v = &e.verdict;
    f.heading(out, e);
    f.field(out, "Source", &f.prose(&e.source));
    f.field(out, "Printed", &f.statement(&e.statement));
    f.field(out, "How", &f.method(&method_short(&v.method), method));
    if let Some(corr) = &v.correction {
        f.field(out, "Correction", &f.prose(corr));
    }
    let witness = (v.status != Status::Holds).then(|| e.witness()).flatten();
    if let Some((item, w)) = witness {
        let subject: Vec<String> = item
            .parts
            .iter()
            .map(|p| p.name.as_str())
            .chain(item.subject.as_deref())
            .map(|s| f.prose(s))
            .collect();
        let line = f.witnessed(&subject.join(F::NESTED), &witness_line(f, w));
        f.field(out, "Witness", &line);
    }
    if let Some(fig) = &e.figure {
        f.field(out, "Figure", &f.figure(fig));
    }
    evidence(f, out, &v.evidence, witness.map(|(item, _)| item));
    out.push('\n');
}

/// The evidence, items grouped ([`groups`]) and nested by their
/// parts; `skip` is the item whose witness the entry already shows.
fn evidence<F: Format>(f: &F, out: &mut String, items: &[Evidence], skip: Option<&Evidence>) {
    f.evidence_start(out);
    let mut open: &[Part] = &[];
    for group in groups(items) {
        let e = &group[0];
        if e.parts != open {
            f.parts(out, open, &e.parts);
            open = &e.parts;
        }
        let own = skip.is_none_or(|s| !std::ptr::eq(s, e));
        f.item(out, open.len(), &item(f, group, open.last(), own));
    }
    f.parts(out, open, &[]);
    f.evidence_end(out);
}

/// One group of items: subjects and status, prose, expressions, witness.
fn item<F: Format>(f: &F, group: &[Evidence], part: Option<&Part>, show_witness: bool) -> String {
    let e = &group[0];
    let mut out = String::new();
    if e.subject
        .as_deref()
        .is_some_and(|s| part.is_none_or(|p| p.name != *s))
    {
        let subjects: Vec<String> = group
            .iter()
            .filter_map(|g| g.subject.as_deref())
            .map(|s| f.prose(s))
            .collect();
        out.push_str(&subjects.join("; "));
        if let Some(p) = e
            .printed
            .as_deref()
            .filter(|_| e.status != Some(Status::Holds))
        {
            match printed_shown(p, F::LONG) {
                Some(p) => out.push_str(&format!(", printed {}", f.printed(p))),
                None => out.push_str(&format!(", {PRINTED_LONG}")),
            }
        }
        if let Some(st) = e.status {
            out.push_str(F::DASH);
            out.push_str(&f.strong(st.label()));
        }
        if !e.text.is_empty() || !e.exprs.is_empty() {
            out.push_str(": ");
        }
    } else if let (Some(st), Some(p)) = (e.status, part)
        && p.status != st
    {
        out.push_str(&format!("{}: ", f.strong(st.label())));
    }
    out.push_str(&f.prose(&e.text));
    for (i, l) in e.exprs.iter().enumerate() {
        if i > 0 || !e.text.is_empty() {
            out.push_str("; ");
        }
        out.push_str(&labelled(f, &l.label, &l.expr));
    }
    if show_witness && let Some(w) = &e.witness {
        out.push_str(&format!("; witness {}", witness_line(f, w)));
    }
    out
}

/// `label = expression`.
fn labelled<F: Format>(f: &F, label: &str, e: &Expr) -> String {
    format!("{}{}{}", f.prose(label), F::EQUALS, expr(f, e))
}

/// A witness on one line: the point, what it means, the values there.
fn witness_line<F: Format>(f: &F, w: &Witness) -> String {
    let values: Vec<String> = w
        .values
        .iter()
        .map(|v| labelled(f, &v.label, &v.value))
        .collect();
    let note = w
        .note
        .as_ref()
        .map_or(String::new(), |n| format!(" ({})", f.prose(n)));
    // exact unless marked (the report's opening says so)
    let values = format!(
        "{}{}",
        values.join(", "),
        if w.exact { "" } else { " (numeric)" }
    );
    match f.point(w) {
        // no variable: the values are numbers
        None if note.is_empty() => format!("(no variable): {values}"),
        None => format!("{}: {values}", note.trim_start()),
        Some(point) => format!("at {point}{note}: {values}"),
    }
}

/// An expression in full, or summarised when longer than [`Format::LONG`].
fn expr<F: Format>(f: &F, e: &Expr) -> String {
    match shown(e, F::LONG) {
        Shown::Full { unicode, latex } => f.full(unicode, latex),
        Shown::Summary {
            degree,
            terms,
            factored,
        } => {
            let factored = factored.map_or(String::new(), |(u, l)| {
                format!(", factored {}", f.formula(u, l))
            });
            format!("[{}{factored}; in full in JSON]", size_text(degree, terms))
        }
    }
}

/// How an expression is shown where people read.
enum Shown<'a> {
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
fn shown(e: &Expr, long: usize) -> Shown<'_> {
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

/// The size of a summarised expression: `degree 15, 315 terms`.
fn size_text(degree: u64, terms: usize) -> String {
    format!(
        "numerator of degree {degree}, {}",
        plural(terms, "term", "terms")
    )
}

/// What stands for a printed formula too long to repeat (the seed has it,
/// the JSON report too).
const PRINTED_LONG: &str = "printed formula as in the seed";

/// A printed formula, if it is short enough to repeat beside its check.
fn printed_shown(printed: &str, long: usize) -> Option<&str> {
    (printed.chars().count() <= long).then_some(printed)
}

/// Items grouped for display: consecutive confirmations (same parts, same
/// kind, status and prose, about different subjects, no expressions or
/// witness — "residual is exactly 0" for each of ten identities) become one
/// group, shown as one line listing their subjects; every other item is a
/// group of its own.
fn groups(items: &[Evidence]) -> Vec<&[Evidence]> {
    let plain = |e: &Evidence| {
        e.subject.is_some() && e.exprs.is_empty() && e.witness.is_none() && e.status.is_some()
    };
    let mut out: Vec<&[Evidence]> = Vec::new();
    let mut start = 0;
    for i in 1..=items.len() {
        let joins = i < items.len() && {
            let (a, b) = (&items[start], &items[i]);
            plain(a)
                && plain(b)
                && a.parts == b.parts
                && a.kind == b.kind
                && a.status == b.status
                && a.text == b.text
        };
        if !joins {
            out.push(&items[start..i]);
            start = i;
        }
    }
    out
}

/// The distinct methods of `entries`, in order of first use (the report
/// states each once and refers to it by number).
fn methods<'a>(entries: &[&'a Entry]) -> Vec<&'a str> {
    let mut out: Vec<&str> = Vec::new();
    for e in entries {
        if !out.contains(&e.verdict.method.as_str()) {
            out.push(&e.verdict.method);
        }
    }
    out
}

/// A method's short form: up to its first `;` or `,` outside brackets (or
/// the whole text when it has none), cut after a word to at most 40
/// characters (the full method is stated once, in the methods list).
fn method_short(method: &str) -> String {
    let mut depth = 0i32;
    let end = method
        .char_indices()
        .find(|&(_, ch)| {
            match ch {
                '(' | '[' | '{' => depth += 1,
                ')' | ']' | '}' => depth -= 1,
                _ => {}
            }
            depth == 0 && (ch == ';' || ch == ',')
        })
        .map_or(method.len(), |(i, _)| i);
    let text = method[..end].trim();
    if text.chars().count() <= 40 {
        return text.to_string();
    }
    let cut: String = text.chars().take(40).collect();
    let words = cut.rfind(' ').map_or(cut.as_str(), |i| &cut[..i]);
    format!("{}…", words.trim_end_matches([',', ':', ';']))
}

/// The anchor of a claim's entry.
pub(crate) fn anchor(id: &str) -> String {
    format!("claim-{}", id.to_ascii_lowercase())
}

/// The coordinates of a witness: the nonzero ones, then the zero ones as
/// one chain `a = b = … = 0` (shorter, and as easy to check); `name` and
/// `full` write a coordinate's name and `name = value`.
pub(crate) fn point_text(
    w: &Witness,
    name: impl Fn(&Assignment) -> String,
    full: impl Fn(&Assignment) -> String,
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
