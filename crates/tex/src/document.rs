//! Whole documents and their pieces: the preamble every document
//! trig-audit writes shares (reports and tables), comments, and displayed
//! equations.

/// The preamble of every LaTeX document trig-audit writes (reports and
/// tables): page, fonts, math, tables, links; the command of
/// [`crate::fitted_math`].
pub const PREAMBLE: &str = r"\documentclass[a4paper,10pt]{article}
\usepackage{iftex}
\ifPDFTeX
  \usepackage[T1]{fontenc}
  \usepackage[utf8]{inputenc}
  \IfFileExists{lmodern.sty}{\usepackage{lmodern}}{}
\fi
\usepackage{amsmath,amssymb}
\usepackage{array,longtable,graphicx}
\usepackage{booktabs}
\usepackage[margin=2cm]{geometry}
\IfFileExists{hyperref.sty}{\usepackage[hidelinks]{hyperref}}{%
  \providecommand{\hypertarget}[2]{#2}\providecommand{\hyperlink}[2]{#2}}
\setlength{\parindent}{0pt}
\setlength{\parskip}{3pt}
\setlength{\emergencystretch}{3em}
\sloppy
% a long formula on its own line, scaled down only if wider than the line
\newcommand{\fitmath}[1]{\par\noindent\resizebox{\ifdim\width>\linewidth\linewidth\else\width\fi}{!}{$\displaystyle #1$}\par}
";

/// A complete document: [`PREAMBLE`], then `body` (LaTeX) as the document.
pub fn document(body: &str) -> String {
    format!("{PREAMBLE}\\begin{{document}}\n{body}\\end{{document}}\n")
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
        assert!(doc.ends_with("\\begin{document}\nx\n\\end{document}\n"));
        assert_eq!(comment("a\nb"), "% a b\n");
        let eqs = [("a", "1"), ("b", "2")].map(|(l, r)| (l.to_string(), r.to_string()));
        assert_eq!(
            align(&eqs),
            "\\begin{align*}\na &= 1 \\\\\nb &= 2\n\\end{align*}\n"
        );
    }
}
