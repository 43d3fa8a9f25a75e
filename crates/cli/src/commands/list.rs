//! `trig-audit list`: the catalog.

use std::fmt::Write;

use clap::Args;
use serde_json::json;
use trig_core::catalog;

use super::CmdResult;
use crate::format::{TextOrJson, json};

#[derive(Debug, Args)]
pub struct ListArgs {
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    format: TextOrJson,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

pub fn run(args: &ListArgs) -> CmdResult {
    let entries = catalog();
    match args.format {
        TextOrJson::Json => {
            let items: Vec<_> = entries
                .iter()
                .map(|f| {
                    json!({
                        "id": f.id,
                        "title": f.title,
                        "citation": f.citation,
                        "variable": f.variable.domain(),
                        "functions": f.functions,
                        "has_formulas": !f.functions.is_empty(),
                        "piecewise": f.piecewise,
                        "params": f.params.iter().map(|p| json!({
                            "name": p.name,
                            "symbol": p.symbol,
                            "range": p.range.to_string(),
                            "range_source": p.range_source,
                        })).collect::<Vec<_>>(),
                    })
                })
                .collect();
            Ok(json(&json!(items)))
        }
        TextOrJson::Text => {
            let mut out = String::new();
            for f in &entries {
                let params = if f.params.is_empty() {
                    "none".to_string()
                } else {
                    f.params
                        .iter()
                        .map(|p| format!("{} ({}) in {}", p.name, p.symbol, p.range))
                        .collect::<Vec<_>>()
                        .join("; ")
                };
                let functions = if f.functions.is_empty() {
                    "no formulas in our copy".to_string()
                } else {
                    f.functions.join(", ")
                };
                let _ = writeln!(out, "{}", f.id);
                let _ = writeln!(out, "  {}", f.title);
                let _ = writeln!(out, "  source:    {}", f.citation);
                let _ = writeln!(out, "  variable:  {}", f.variable.domain());
                let _ = writeln!(out, "  params:    {params}");
                let _ = writeln!(out, "  functions: {functions}");
                if f.piecewise {
                    let _ = writeln!(
                        out,
                        "  piecewise: the uniform B-spline basis function over 4 intervals (eval --piecewise)"
                    );
                }
            }
            Ok(out)
        }
    }
}
