//! Fragments and whole documents. What `table --format tex` and the
//! figures' pgfplots code write is by default a fragment to `\input` into
//! the reader's own document, opened by a comment naming the standard
//! packages it needs ([`input_note`]); with `--standalone` the same
//! fragment inside a plain `article` that loads them ([`article`]).

/// The comment lines opening a fragment: what it is, and the packages (and
/// setup lines) the document that `\input`s it needs.
pub fn input_note(what: &str, packages: &[&str], setup: &[&str]) -> String {
    let mut out = crate::comment(what);
    let mut needs = format!(
        r"to \input into a document with \usepackage{{{}}}",
        packages.join(",")
    );
    for line in setup {
        needs.push_str(" and ");
        needs.push_str(line);
    }
    out.push_str(&crate::comment(&needs));
    out
}

/// A whole plain `article` (the class's defaults: 10 pt, its text width)
/// loading `packages`, with the `setup` lines, around `body`.
pub fn article(packages: &[&str], setup: &[&str], body: &str) -> String {
    let mut out = format!(
        "\\documentclass{{article}}\n\\usepackage{{{}}}\n",
        packages.join(",")
    );
    for line in setup {
        out.push_str(line);
        out.push('\n');
    }
    format!("{out}\\begin{{document}}\n{body}\\end{{document}}\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fragments_name_their_packages_and_articles_load_them() {
        let note = input_note(
            "T",
            &["booktabs", "amsmath"],
            &[r"\pgfplotsset{compat=1.16}"],
        );
        assert_eq!(
            note,
            "% T\n% to \\input into a document with \\usepackage{booktabs,amsmath} and \\pgfplotsset{compat=1.16}\n"
        );
        let doc = article(&["booktabs", "amsmath"], &["% setup"], "x\n");
        assert_eq!(
            doc,
            "\\documentclass{article}\n\\usepackage{booktabs,amsmath}\n% setup\n\\begin{document}\nx\n\\end{document}\n"
        );
    }
}
