//! Output formats shared by the commands.

use clap::ValueEnum;

/// Plain text for people, JSON for machines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TextOrJson {
    Text,
    Json,
}

/// Renders a JSON value with a trailing newline.
pub fn json(value: &serde_json::Value) -> String {
    let mut s = serde_json::to_string_pretty(value).unwrap_or_else(|e| format!("\"{e}\""));
    s.push('\n');
    s
}

use std::fmt::Write;

use crate::cell::Block;
use crate::commands::CliError;

/// Table formats for papers and programs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TableFormat {
    Md,
    Tex,
    Csv,
    Json,
}

/// Renders blocks under a heading in the chosen format.
pub fn render_blocks(
    heading: &str,
    blocks: &[Block],
    format: TableFormat,
) -> Result<String, CliError> {
    let mut out = String::new();
    match format {
        TableFormat::Md => {
            let _ = writeln!(out, "## {heading}\n");
            for b in blocks {
                let _ = writeln!(out, "### {}\n", b.title);
                let _ = writeln!(out, "| {} | {} |", b.corner, b.columns.join(" | "));
                let _ = writeln!(out, "|---|{}", "---|".repeat(b.columns.len()));
                for (label, cells) in &b.rows {
                    let cells: Vec<&str> = cells.iter().map(|c| c.unicode.as_str()).collect();
                    let _ = writeln!(out, "| {label} | {} |", cells.join(" | "));
                }
                out.push('\n');
            }
        }
        TableFormat::Tex => out = tex_document(heading, blocks),
        TableFormat::Csv => {
            let rows = blocks.iter().flat_map(|b| {
                b.rows.iter().flat_map(move |(label, cells)| {
                    b.columns.iter().zip(cells).map(move |(col, cell)| {
                        [&b.title, label, col, &cell.text].map(String::as_str)
                    })
                })
            });
            out = csv_text(&["table", "row", "column", "value"], rows)?;
        }
        TableFormat::Json => {
            let tables: Vec<serde_json::Value> = blocks
                .iter()
                .map(|b| {
                    serde_json::json!({
                        "title": b.title,
                        "corner": b.corner,
                        "columns": b.columns,
                        "rows": b.rows.iter().map(|(label, cells)| serde_json::json!({
                            "label": label,
                            "values": cells.iter().map(|c| serde_json::json!({
                                "text": c.text, "latex": c.latex,
                            })).collect::<Vec<_>>(),
                        })).collect::<Vec<_>>(),
                    })
                })
                .collect();
            out = json(&serde_json::json!({ "heading": heading, "tables": tables }));
        }
    }
    Ok(out)
}

/// CSV text (RFC 4180 through the `csv` crate: fields with commas, quotes
/// or line breaks quoted): a header, then the rows.
pub fn csv_text<'a, R>(
    header: &[&str],
    rows: impl IntoIterator<Item = R>,
) -> Result<String, CliError>
where
    R: IntoIterator<Item = &'a str>,
{
    let fail = |e: csv::Error| CliError::Usage(format!("cannot write CSV: {e}"));
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).map_err(fail)?;
    for row in rows {
        w.write_record(row).map_err(fail)?;
    }
    let bytes = w
        .into_inner()
        .map_err(|e| CliError::Usage(format!("cannot write CSV: {}", e.error())))?;
    String::from_utf8(bytes).map_err(|e| CliError::Usage(format!("cannot write CSV: {e}")))
}

/// Characters of the widest table set with `l` columns (wider ones are set
/// one entry per line, the value in a wrapping column).
const TEX_WIDE: usize = 90;

/// A complete LaTeX document (the report's preamble): the heading as a
/// section, each block as a captioned `longtable`. A block whose entries
/// fit the line keeps its rows and columns; a wider one is set one entry
/// per line (row, column, value), the value wrapping at its operators.
fn tex_document(heading: &str, blocks: &[Block]) -> String {
    use trig_verification::report::latex::{preamble, tex_inline};
    let mut out = String::from(preamble());
    out.push_str("\\begin{document}\n");
    let _ = writeln!(out, "\\section*{{{}}}\n", tex_inline(heading));
    for b in blocks {
        let width = |s: &str| s.chars().count();
        let widest = |k: usize| {
            b.rows
                .iter()
                .filter_map(|(_, cells)| cells.get(k))
                .map(|c| width(&c.unicode))
                .chain([width(&b.columns[k])])
                .max()
                .unwrap_or(0)
        };
        let labels = b
            .rows
            .iter()
            .map(|(l, _)| width(l))
            .chain([width(&b.corner)])
            .max()
            .unwrap_or(0);
        let total = labels + (0..b.columns.len()).map(widest).sum::<usize>() + 3 * b.columns.len();
        let caption = format!("\\caption{{{}}}\\\\", tex_inline(&b.title));
        if total <= TEX_WIDE {
            let _ = writeln!(
                out,
                "\\begin{{longtable}}{{l{}}}\n{caption}\n\\hline",
                "l".repeat(b.columns.len())
            );
            let headers: Vec<String> = b.columns.iter().map(|c| header_tex(c)).collect();
            let _ = writeln!(
                out,
                "{} & {} \\\\\n\\hline\n\\endhead",
                tex_inline(&b.corner),
                headers.join(" & ")
            );
            for (label, cells) in &b.rows {
                let cells: Vec<String> = cells.iter().map(|c| format!("${}$", c.latex)).collect();
                let _ = writeln!(out, "{} & {} \\\\", tex_inline(label), cells.join(" & "));
            }
        } else {
            let _ = writeln!(
                out,
                "\\begin{{longtable}}{{L{{1.2cm}}L{{2cm}}L{{12.4cm}}}}\n{caption}\n\\hline"
            );
            let _ = writeln!(
                out,
                "{} & entry & value \\\\\n\\hline\n\\endhead",
                tex_inline(&b.corner)
            );
            for (label, cells) in &b.rows {
                for (col, cell) in b.columns.iter().zip(cells) {
                    let _ = writeln!(
                        out,
                        "{} & {} & ${}$ \\\\",
                        tex_inline(label),
                        header_tex(col),
                        inline_fractions(&cell.latex)
                    );
                }
            }
        }
        let _ = writeln!(out, "\\hline\n\\end{{longtable}}\n");
    }
    out.push_str("\\end{document}\n");
    out
}

/// A column header: a function name (`b0`, `H2`) as math with its index,
/// a word (`derivative`) as text.
fn header_tex(name: &str) -> String {
    let digits = name.trim_start_matches(|c: char| c.is_ascii_alphabetic());
    let letters = &name[..name.len() - digits.len()];
    if !letters.is_empty() && !digits.is_empty() && digits.chars().all(|c| c.is_ascii_digit()) {
        format!("${letters}_{{{digits}}}$")
    } else {
        trig_verification::report::latex::tex_inline(name)
    }
}

/// `\frac{a}{b}` as `(a)/(b)` (brackets left out around one symbol): a
/// fraction cannot break across lines, its inline form breaks at the
/// operators of its numerator.
fn inline_fractions(latex: &str) -> String {
    const FRAC: &str = r"\frac{";
    let Some(at) = latex.find(FRAC) else {
        return latex.to_string();
    };
    // the group opened at byte `open` (a `{`) and the rest after its `}`
    let group = |open: usize| -> Option<(&str, &str)> {
        let mut depth = 0usize;
        for (k, c) in latex[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        return Some((&latex[open + 1..open + k], &latex[open + k + 1..]));
                    }
                }
                _ => {}
            }
        }
        None
    };
    let Some((num, rest)) = group(at + FRAC.len() - 1) else {
        return latex.to_string();
    };
    let Some((den, rest)) = rest
        .starts_with('{')
        .then(|| group(latex.len() - rest.len()))
        .flatten()
    else {
        return latex.to_string();
    };
    let wrap = |s: &str| {
        let s = inline_fractions(s);
        if s.contains([' ', '+', '-']) {
            format!("({s})")
        } else {
            s
        }
    };
    format!(
        "{}{}/{}{}",
        &latex[..at],
        wrap(num),
        wrap(den),
        inline_fractions(rest)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fractions_inline_and_headers_as_math() {
        assert_eq!(
            inline_fractions(r"(\frac{-m w_{1} - 2}{w_{0}^{2}}) P_{0} + \frac{1}{2}"),
            r"((-m w_{1} - 2)/w_{0}^{2}) P_{0} + 1/2"
        );
        assert_eq!(header_tex("b0"), "$b_{0}$");
        assert_eq!(header_tex("derivative"), "derivative");
    }

    #[test]
    fn csv_fields_are_quoted_when_needed() {
        let text = csv_text(&["a", "b"], [["x, y", "say \"hi\""]]).unwrap();
        assert_eq!(text, "a,b\n\"x, y\",\"say \"\"hi\"\"\"\n");
    }
}
