//! Output formats shared by the commands.

use std::fmt::Write;

use clap::ValueEnum;
use trig_tex::expr::inline_fractions;
use trig_tex::{Column, LongTable, column_name, document, inline_math, prose};

use crate::cell::Block;
use crate::commands::CliError;

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
    let mut out = String::new();
    let _ = writeln!(out, "\\section*{{{}}}\n", prose(heading));
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
        let caption = prose(&b.title);
        let table = if total <= TEX_WIDE {
            let mut head = vec![prose(&b.corner)];
            head.extend(b.columns.iter().map(|c| column_name(c)));
            let mut t = LongTable::new(vec![Column::Left; b.columns.len() + 1], caption, head);
            for (label, cells) in &b.rows {
                let mut row = vec![prose(label)];
                row.extend(cells.iter().map(|c| inline_math(&c.latex)));
                t.row(row);
            }
            t
        } else {
            let columns = ["1.2cm", "2cm", "12.4cm"].map(Column::Wrap).to_vec();
            let head = vec![prose(&b.corner), "entry".into(), "value".into()];
            let mut t = LongTable::new(columns, caption, head);
            for (label, cells) in &b.rows {
                for (col, cell) in b.columns.iter().zip(cells) {
                    t.row(vec![
                        prose(label),
                        column_name(col),
                        inline_math(&inline_fractions(&cell.latex)),
                    ]);
                }
            }
            t
        };
        let _ = writeln!(out, "{table}");
    }
    document(&out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_fields_are_quoted_when_needed() {
        let text = csv_text(&["a", "b"], [["x, y", "say \"hi\""]]).unwrap();
        assert_eq!(text, "a,b\n\"x, y\",\"say \"\"hi\"\"\"\n");
    }
}
