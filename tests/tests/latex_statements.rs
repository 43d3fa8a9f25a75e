//! Printed statements carry their math as markup (`⟪…⟫`): every catalog
//! statement's markup is balanced, its formulas hold no claim label or
//! equation number, the Markdown and JSON reports show the text as printed,
//! and the LaTeX of every statement — and the whole report, as a fragment
//! in a plain `article` and as a complete document — compiles without error
//! or overfull box (when `pdflatex` is installed).

use trig_report::{self as report, TexOptions, View};
use trig_tex::marked::{CLOSE, OPEN, check};
use trig_tex::{FRAGMENT_PACKAGES, compile, marked, plain};
use trig_verification::run;

/// The formulas of marked text.
fn formulas(text: &str) -> Vec<&str> {
    text.split(OPEN)
        .skip(1)
        .filter_map(|rest| rest.split(CLOSE).next())
        .collect()
}

/// Whether `word` is a label: a claim id of the catalog, an equation or
/// appendix number in brackets (`(4.21)`, `(A45)`).
fn is_label(word: &str, ids: &[&str]) -> bool {
    let bare = word.trim_matches(|c: char| ",;:.".contains(c));
    if ids.contains(&bare) {
        return true;
    }
    let Some(inner) = bare.strip_prefix('(').and_then(|w| w.strip_suffix(')')) else {
        return false;
    };
    let number = inner.strip_prefix('A').unwrap_or(inner);
    !number.is_empty()
        && number.contains(|c: char| c.is_ascii_digit())
        && number.chars().all(|c| c.is_ascii_digit() || c == '.')
        && (inner.starts_with('A') || number.contains('.'))
}

#[test]
fn every_statement_marks_its_math_and_no_label_is_math() {
    let claims = crate::audit::entries();
    let ids: Vec<&str> = claims.iter().map(|c| c.id.as_str()).collect();
    let mut marked_statements = 0;
    for c in claims {
        check(&c.statement).unwrap_or_else(|e| panic!("{}: {e}: {}", c.id, c.statement));
        let shown = plain(&c.statement);
        assert!(!shown.contains([OPEN, CLOSE]), "{}", c.id);
        for f in formulas(&c.statement) {
            for word in f.split(' ') {
                assert!(
                    !is_label(word, &ids),
                    "{}: label {word:?} in math: {f}",
                    c.id
                );
            }
        }
        let tex = marked(&c.statement);
        assert!(tex.is_ascii() && !tex.contains("[U+"), "{}: {tex}", c.id);
        assert!(!tex.contains(['⟪', '⟫']), "{}", c.id);
        if c.statement.contains(OPEN) {
            assert!(tex.contains('$'), "{}: {tex}", c.id);
            marked_statements += 1;
        }
    }
    assert!(
        marked_statements > 150,
        "{marked_statements} statements with formulas"
    );
    assert!(is_label("(A45)", &ids) && is_label("(4.21):", &ids) && is_label("T4", &ids));
    assert!(!is_label("(0,0)", &ids) && !is_label("(1)", &ids) && !is_label("P1", &ids));
}

#[test]
fn the_reports_show_statements_as_printed() {
    let entries = run(Some("001"), Some("T4")).expect("the document files");
    let (intro, view) = (report::BUILTIN_INTRO, View::default());
    let md = report::markdown_entries(&entries, intro, &view);
    let json = serde_json::to_string(&report::json_entries(&entries, intro, &view)).expect("JSON");
    let tex = report::tex_entries(&entries, intro, &view, &TexOptions::default());
    let statement = &entries[0].statement;
    assert!(statement.contains(OPEN));
    assert!(
        md.contains("H\\_i(u; β) = H\\_{2−i}(π/2 − u; β) (as printed)"),
        "{md}"
    );
    assert!(json.contains("\"statement\":\"H_i(u; β) = H_{2−i}(π/2 − u; β) (as printed)\""));
    assert!(!md.contains(OPEN) && !json.contains(OPEN));
    assert!(
        tex.contains(r"$H_{i}(u;\allowbreak \beta) = H_{2-i}(\frac{\pi}{2} - u;\allowbreak \beta)$ (as printed)"),
        "{tex}"
    );
}

#[test]
fn every_statement_compiles() {
    let body: String = crate::audit::entries()
        .iter()
        .map(|c| format!("{}: {}\\par\n", c.id, marked(&c.statement)))
        .collect();
    match compile(&trig_tex::document(&body), "statements") {
        Some(log) => {
            assert!(log.errors.is_empty(), "pdflatex errors: {:#?}", log.errors);
            assert_eq!(log.overfull, 0, "{:#?}", log.overfull_lines);
        }
        None => eprintln!("pdflatex not found: the statements were not compiled"),
    }
}

#[test]
fn the_report_compiles_as_a_fragment_in_a_plain_article_and_as_a_document() {
    let entries = crate::audit::entries();
    let tex = |standalone| {
        let options = TexOptions {
            standalone,
            output_dir: None,
        };
        report::tex_entries(entries, report::BUILTIN_INTRO, &View::default(), &options)
    };
    let part = tex(false);
    assert!(!part.contains("\\documentclass") && !part.contains("\\begin{document}"));
    assert!(
        part.contains(FRAGMENT_PACKAGES),
        "the header names the packages it needs"
    );
    let article = format!(
        "\\documentclass{{article}}\n\\usepackage{{{FRAGMENT_PACKAGES}}}\n\\begin{{document}}\n{part}\\end{{document}}\n"
    );
    match compile(&article, "fragment") {
        Some(log) => {
            assert!(log.errors.is_empty(), "pdflatex errors: {:#?}", log.errors);
            assert_eq!(log.overfull, 0, "{:#?}", log.overfull_lines);
            assert!(log.pages > 10, "{} pages", log.pages);
        }
        None => eprintln!("pdflatex not found: the LaTeX fragment was not compiled"),
    }
    let whole = tex(true);
    assert!(whole.starts_with("\\documentclass"));
    if let Some(log) = compile(&whole, "standalone") {
        assert!(log.errors.is_empty(), "pdflatex errors: {:#?}", log.errors);
        assert_eq!(log.overfull, 0, "{:#?}", log.overfull_lines);
    }
}
