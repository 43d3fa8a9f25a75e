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

/// Table formats for papers and programs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TableFormat {
    Md,
    Tex,
    Csv,
    Json,
}

/// Renders blocks under a heading in the chosen format.
pub fn render_blocks(heading: &str, blocks: &[Block], format: TableFormat) -> String {
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
        TableFormat::Tex => {
            let _ = writeln!(out, "% {heading}");
            for b in blocks {
                let _ = writeln!(out, "% {}", b.title);
                let _ = writeln!(
                    out,
                    "\\begin{{tabular}}{{l{}}}",
                    "l".repeat(b.columns.len())
                );
                let _ = writeln!(out, "\\hline");
                let _ = writeln!(
                    out,
                    "{} & {} \\\\",
                    tex_text(&b.corner),
                    b.columns
                        .iter()
                        .map(|c| format!("${c}$"))
                        .collect::<Vec<_>>()
                        .join(" & ")
                );
                let _ = writeln!(out, "\\hline");
                for (label, cells) in &b.rows {
                    let cells: Vec<String> =
                        cells.iter().map(|c| format!("${}$", c.latex)).collect();
                    let _ = writeln!(out, "{} & {} \\\\", tex_text(label), cells.join(" & "));
                }
                let _ = writeln!(out, "\\hline\n\\end{{tabular}}\n");
            }
        }
        TableFormat::Csv => {
            let _ = writeln!(out, "table,row,column,value");
            for b in blocks {
                for (label, cells) in &b.rows {
                    for (col, cell) in b.columns.iter().zip(cells) {
                        let _ = writeln!(
                            out,
                            "{},{},{},{}",
                            csv(&b.title),
                            csv(label),
                            csv(col),
                            csv(&cell.text)
                        );
                    }
                }
            }
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
    out
}

fn tex_text(s: &str) -> String {
    s.replace('_', "\\_").replace('^', "\\^{}")
}

/// A CSV field, quoted when it holds a comma, quote or newline.
fn csv(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}
