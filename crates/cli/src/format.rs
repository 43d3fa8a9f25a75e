//! Output formats shared by the commands.

use std::fmt::Write;

use clap::ValueEnum;
use trig_tex::{ValueTable, value_tables};

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

/// Renders blocks under a heading in the chosen format (LaTeX as a
/// fragment to `\input`, or a whole document when `standalone`).
pub fn render_blocks(
    heading: &str,
    blocks: &[Block],
    format: TableFormat,
    standalone: bool,
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
        TableFormat::Tex => out = tex_tables(heading, blocks, standalone),
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

/// The blocks as LaTeX tables of values under `heading` (the one LaTeX
/// writer, [`value_tables`]): a fragment to `\input`, or with
/// `standalone` a whole plain `article`.
fn tex_tables(heading: &str, blocks: &[Block], standalone: bool) -> String {
    let tables: Vec<ValueTable> = blocks
        .iter()
        .map(|b| ValueTable {
            title: b.title.clone(),
            corner: b.corner.clone(),
            columns: b.columns.clone(),
            rows: b
                .rows
                .iter()
                .map(|(label, cells)| {
                    (
                        label.clone(),
                        cells.iter().map(|c| c.latex.clone()).collect(),
                    )
                })
                .collect(),
        })
        .collect();
    value_tables(heading, &tables, standalone)
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
