//! `trig-audit eval --at-file FILE`: every function at many points, read
//! from a file or standard input, each value certified as for one `--at`
//! (f64 with a proved error bound, or proved digits under `--prec` and
//! `--digits`; the uncertified fast path is the library's
//! [`trig_core::Batch`]). For scripts: the text output is
//! tab-separated columns under `#` header lines (`numpy.loadtxt` reads it
//! as is), the JSON output one array per column.

use std::fmt::Write;
use std::io::Read;
use std::path::Path;

use serde_json::json;
use trig_core::{Affine, SEED000_NONUNIFORM, parse_point};

use super::{
    CliError, CmdResult, EvalArgs, Evaluation, Mode, Shown, evaluate, param_pairs, subject_of,
};
use crate::format::{TextOrJson, json};

/// The points of `path` (`-` for standard input): the text as written and
/// its exact value.
fn read_points(path: &Path) -> Result<Vec<(String, Affine)>, CliError> {
    let stdin = path.as_os_str() == "-";
    let name = if stdin {
        "standard input".to_string()
    } else {
        path.display().to_string()
    };
    let text = if stdin {
        let mut text = String::new();
        std::io::stdin()
            .read_to_string(&mut text)
            .map_err(|e| CliError::Usage(format!("cannot read standard input: {e}")))?;
        text
    } else {
        std::fs::read_to_string(path)
            .map_err(|e| CliError::Usage(format!("cannot read {name}: {e}")))?
    };
    let points: Vec<(String, Affine)> = text
        .lines()
        .enumerate()
        .map(|(i, line)| (i + 1, line.trim()))
        .filter(|(_, line)| !line.is_empty() && !line.starts_with('#'))
        .map(|(n, line)| {
            parse_point(line)
                .map(|q| (line.to_string(), q))
                .map_err(|e| CliError::Usage(format!("{name} line {n}: {e}")))
        })
        .collect::<Result<_, _>>()?;
    if points.is_empty() {
        return Err(CliError::Usage(format!("{name}: no points")));
    }
    Ok(points)
}

/// Evaluates `--at-file` and renders the table: every point through the
/// certified evaluation of a single `--at` (f64 values with certified error
/// bounds, or proved digits under `--prec`/`--digits`).
pub(super) fn run(args: &EvalArgs, path: &Path, mode: Mode) -> CmdResult {
    if args.piecewise
        || !args.knots.is_empty()
        || (args.family.as_deref() == Some(SEED000_NONUNIFORM.id) && args.spec.is_none())
    {
        return Err(CliError::Usage(
            "--at-file evaluates the functions of a family or spec file (not --piecewise or --knots)"
                .into(),
        ));
    }
    let points = read_points(path)?;
    let subject = subject_of(args)?;
    let rows = points
        .iter()
        .map(|(text, q)| evaluate(args, text, q, mode, subject.as_ref()))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(render(args, &points, &rows))
}

fn render(args: &EvalArgs, points: &[(String, Affine)], rows: &[Evaluation]) -> String {
    let first = &rows[0];
    let params = param_pairs(&args.params).unwrap_or_default();
    let column = |k: usize, f: &dyn Fn(&Shown) -> serde_json::Value| {
        json!(rows.iter().map(|r| f(&r.values[k])).collect::<Vec<_>>())
    };
    let precision = rows
        .iter()
        .map(|r| r.precision.as_str())
        .max_by_key(|p| p.len())
        .unwrap_or_default();
    match args.format {
        TextOrJson::Json => {
            let map = |f: &dyn Fn(&Shown) -> serde_json::Value| -> serde_json::Map<_, _> {
                first
                    .names
                    .iter()
                    .enumerate()
                    .map(|(k, n)| (n.clone(), column(k, f)))
                    .collect()
            };
            json(&json!({
                "family": first.id,
                "citation": first.citation,
                "params": params.iter().map(|(n, v)| (n.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
                "precision": precision,
                "at": points.iter().map(|(text, _)| text.as_str()).collect::<Vec<_>>(),
                "values": map(&|v| json!(v.text)),
                "error_bounds": map(&|v| json!(v.bound)),
                "proved_digits": map(&|v| json!(v.digits.filter(|d| *d != usize::MAX))),
                "notes": map(&|v| json!(v.note)),
            }))
        }
        TextOrJson::Text => {
            let shown: Vec<String> = params.iter().map(|(n, v)| format!("{n}={v}")).collect();
            let mut out = String::new();
            let _ = writeln!(
                out,
                "# {} at {} points [{}] ({precision}); {}",
                first.id,
                points.len(),
                shown.join(", "),
                first.citation
            );
            let bounds: Vec<&str> = rows
                .iter()
                .flat_map(|r| r.values.iter().filter_map(|v| v.bound.as_deref()))
                .collect();
            if let Some(largest) = bounds.iter().max_by(|a, b| {
                a.parse::<f64>()
                    .unwrap_or(0.0)
                    .total_cmp(&b.parse().unwrap_or(0.0))
            }) {
                let _ = writeln!(
                    out,
                    "# every f64 value is within {largest} of the exact value"
                );
            }
            for ((text, _), r) in points.iter().zip(rows) {
                for (n, v) in r.names.iter().zip(&r.values) {
                    if let Some(note) = &v.note {
                        let _ = writeln!(out, "# at {text}: {n}: {note}");
                    }
                }
            }
            let _ = writeln!(out, "# at\t{}", first.names.join("\t"));
            for ((text, _), r) in points.iter().zip(rows) {
                let values: Vec<&str> = r.values.iter().map(|v| v.text.as_str()).collect();
                let _ = writeln!(out, "{text}\t{}", values.join("\t"));
            }
            out
        }
    }
}
