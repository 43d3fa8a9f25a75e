//! Whole documents and fragments, and their pieces: the preamble every
//! document trig-audit writes shares (reports and tables), the setup a
//! fragment carries so that it can be `\input` into a plain `article`,
//! comments, and displayed equations.

/// The standard packages a fragment needs (loaded by [`PREAMBLE`]).
pub const FRAGMENT_PACKAGES: &str = "amsmath,amssymb,booktabs,longtable,array,graphicx";

/// What a fragment defines for itself (with `\providecommand`, so that a
/// document's own definitions win): [`crate::fitted_math`]'s `\fitmath`,
/// `\fitbox` (a box scaled down only if wider than the line), and links
/// that fall back to plain text when `hyperref` is not loaded.
pub const FRAGMENT_SETUP: &str = r"\providecommand{\hypertarget}[2]{#2}
\providecommand{\hyperlink}[2]{#2}
% a long formula on its own line, scaled down only if wider than the line
\providecommand{\fitmath}[1]{\par\noindent\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{$\displaystyle #1$}\par}
% a box (a figure) scaled down only if wider than the line
\providecommand{\fitbox}[1]{\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{#1}}
";

/// The preamble of every LaTeX document trig-audit writes (reports and
/// tables): page, fonts, math, tables ([`FRAGMENT_PACKAGES`]), links,
/// pgfplots when installed (for figures), and [`FRAGMENT_SETUP`].
pub const PREAMBLE: &str = r"\documentclass[a4paper,10pt]{article}
\usepackage{iftex}
\ifPDFTeX
  \usepackage[T1]{fontenc}
  \usepackage[utf8]{inputenc}
  \IfFileExists{lmodern.sty}{\usepackage{lmodern}}{}
\fi
\usepackage{amsmath,amssymb,booktabs}
\usepackage{array,longtable,graphicx}
\usepackage{booktabs}
\usepackage[margin=2cm]{geometry}
\IfFileExists{pgfplots.sty}{\usepackage{pgfplots}\pgfplotsset{compat=1.16}}{}
\IfFileExists{hyperref.sty}{\usepackage[hidelinks]{hyperref}}{}
\setlength{\parindent}{0pt}
\setlength{\parskip}{3pt}
\setlength{\emergencystretch}{3em}
\sloppy
";

/// A complete document: [`PREAMBLE`] and [`FRAGMENT_SETUP`], then `body`
/// (LaTeX) as the document.
pub fn document(body: &str) -> String {
    format!("{PREAMBLE}{FRAGMENT_SETUP}\\begin{{document}}\n{body}\\end{{document}}\n")
}

/// A fragment to `\input` into a document that loads
/// [`FRAGMENT_PACKAGES`]: `title` and the packages as comments, then
/// [`FRAGMENT_SETUP`], then `body` in a group with ragged-free but
/// stretchable lines (`\emergencystretch`, no indent) that ends with it.
pub fn fragment(title: &str, body: &str) -> String {
    format!(
        "{}{}{FRAGMENT_SETUP}\\begingroup\n\\setlength{{\\parindent}}{{0pt}}\\setlength{{\\parskip}}{{3pt}}\\setlength{{\\emergencystretch}}{{3em}}\\sloppy\n{body}\\endgroup\n",
        comment(title),
        comment(&format!(
            "a fragment: \\input it into a document that loads \\usepackage{{{FRAGMENT_PACKAGES}}} (pgfplots too, to draw the figures given as pgfplots code)"
        )),
    )
}

/// A comment line (line breaks in `line` become spaces).
pub fn comment(line: &str) -> String {
    format!("% {}\n", line.replace('\n', " "))
}

/// Equations `left = right` (LaTeX math) aligned at their `=`, unnumbered.
pub fn align(equations: &[(String, String)]) -> String {
    let lines: Vec<String> = equations
        .iter()
        .map(|(left, right)| format!("{left} &= {right}"))
        .collect();
    format!(
        "\\begin{{align*}}\n{}\n\\end{{align*}}\n",
        lines.join(" \\\\\n")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn documents_comments_and_equations() {
        let doc = document("x\n");
        assert!(doc.starts_with(r"\documentclass"));
        assert!(doc.contains(r"\usepackage{amsmath,amssymb,booktabs}"));
        let part = fragment("T", "x\n");
        assert!(part.starts_with("% T\n% a fragment"));
        assert!(part.contains(FRAGMENT_PACKAGES));
        assert!(
            !part
                .lines()
                .any(|l| l.starts_with(r"\documentclass") || l.starts_with(r"\usepackage"))
        );
        assert!(part.ends_with("x\n\\endgroup\n"));
        assert!(doc.ends_with("\\begin{document}\nx\n\\end{document}\n"));
        assert_eq!(comment("a\nb"), "% a b\n");
        let eqs = [("a", "1"), ("b", "2")].map(|(l, r)| (l.to_string(), r.to_string()));
        assert_eq!(
            align(&eqs),
            "\\begin{align*}\na &= 1 \\\\\nb &= 2\n\\end{align*}\n"
        );
    }
}
