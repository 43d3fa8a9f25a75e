//! Text for LaTeX: the ten special characters escaped, every mapped
//! Unicode character written (math symbols as inline math). The output is
//! ASCII and compiles with pdfLaTeX. Text with formulas is [`prose`](fn@crate::prose).

use crate::math::{inline_math, math};
use crate::symbols::{TEXT, is_mathy, lookup};

/// Escapes text for LaTeX: the ten special characters, and every mapped
/// Unicode character (math symbols as inline math).
pub fn text(line: &str) -> String {
    let chars: Vec<char> = line.chars().collect();
    let mut out = String::with_capacity(line.len());
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if is_mathy(ch) {
            // a run of math characters, with the ASCII between them, as one formula
            let start = i;
            while i < chars.len() && (is_mathy(chars[i]) || chars[i] == '\u{304}') {
                i += 1;
            }
            let run: String = chars[start..i].iter().collect();
            out.push_str(&inline_math(&math(&run)));
            continue;
        }
        match ch {
            '\\' => out.push_str(r"\textbackslash{}"),
            '{' | '}' | '$' | '&' | '#' | '_' | '%' => {
                out.push('\\');
                out.push(ch);
            }
            '^' => out.push_str(r"\textasciicircum{}"),
            '~' => out.push_str(r"\textasciitilde{}"),
            '<' => out.push_str(r"\textless{}"),
            '>' => out.push_str(r"\textgreater{}"),
            '|' => out.push_str(r"\textbar{}"),
            '"' => out.push_str("''"),
            _ if ch.is_ascii() => out.push(ch),
            _ => match lookup(TEXT, ch) {
                Some(t) => out.push_str(t),
                None => out.push_str(&format!("[U+{:04X}]", u32::from(ch))),
            },
        }
        i += 1;
    }
    out
}

/// Escaped text that may break after `/`, `)`, `]`, `-`, `+` and `,` (a
/// long path or printed formula in `\texttt`).
pub fn breakable(line: &str) -> String {
    let mut out = String::new();
    for ch in line.chars() {
        out.push_str(&text(&ch.to_string()));
        if matches!(ch, '/' | ')' | ']' | '-' | '+' | ',') {
            out.push_str(r"\allowbreak{}");
        }
    }
    out
}

/// A code span (a command, a file name) in typewriter: breakable after
/// `/`, `-` and the like when longer than 48 characters (`CODE_UNBROKEN`; a
/// path of any length fits the line), else kept on one line.
pub fn code(span: &str) -> String {
    if span.chars().count() > CODE_UNBROKEN {
        format!(r"\texttt{{{}}}", breakable(span))
    } else {
        format!(r"\texttt{{{}}}", text(span))
    }
}

/// The longest code span [`code`] keeps unbroken: 48 typewriter characters
/// (about 250 pt at 10 pt) always fit the text width of an `article`.
const CODE_UNBROKEN: usize = 48;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latex_special_characters_are_escaped() {
        assert_eq!(
            text(r"50% of {a_b} & $x^2 # ~\"),
            r"50\% of \{a\_b\} \& \$x\textasciicircum{}2 \# \textasciitilde{}\textbackslash{}"
        );
        assert_eq!(
            text("θ ↦ π/2 − θ, b₀ ≥ 0 — “ok”"),
            r"$\theta$ $\mapsto$ $\pi$/2 $-$ $\theta$, b$_{0}$ $\geq$ 0 --- ``ok''"
        );
    }

    #[test]
    fn unknown_characters_are_marked() {
        assert_eq!(text("☃"), "[U+2603]");
        assert_eq!(breakable("a/b"), r"a/\allowbreak{}b");
        assert_eq!(code("a/b"), r"\texttt{a/b}");
        let long = "/a/very/long/checkout/of/the/project/examples/basis.toml";
        assert!(
            code(long).contains(r"/\allowbreak{}examples"),
            "{}",
            code(long)
        );
    }
}
