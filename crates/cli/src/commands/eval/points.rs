//! `trig-audit eval --at-file FILE`: every function at many points, read
//! from a file or standard input, evaluated in one batch
//! ([`trig_core::Batch`]: parameters converted once, vectorised `sin`/`cos`
//! in f64, reused buffers in MPFR). For scripts: the text output is
//! tab-separated columns under `#` header lines (`numpy.loadtxt` reads it
//! as is), the JSON output one array per column.

use std::fmt::{Display, Write};
use std::io::Read;
use std::path::Path;

use rug::Rational;
use serde_json::json;
use trig_core::batch::BatchReal;
use trig_core::{Basis, Batch, Mpfr, SEED000_NONUNIFORM, parse_exact};

use super::{CliError, CmdResult, EvalArgs, MAX_PREC, Subject, param_pairs};
use crate::format::{TextOrJson, json};

/// The points of `path` (`-` for standard input): the text as written and
/// its exact value.
fn read_points(path: &Path) -> Result<Vec<(String, Rational)>, CliError> {
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
    let points: Vec<(String, Rational)> = text
        .lines()
        .enumerate()
        .map(|(i, line)| (i + 1, line.trim()))
        .filter(|(_, line)| !line.is_empty() && !line.starts_with('#'))
        .map(|(n, line)| {
            parse_exact(line)
                .map(|q| (line.to_string(), q))
                .map_err(|e| CliError::Usage(format!("{name} line {n}: {e}")))
        })
        .collect::<Result<_, _>>()?;
    if points.is_empty() {
        return Err(CliError::Usage(format!("{name}: no points")));
    }
    Ok(points)
}

/// Evaluates `--at-file` and renders the table.
pub(super) fn run(args: &EvalArgs, path: &Path) -> CmdResult {
    if args.piecewise
        || !args.knots.is_empty()
        || (args.family.as_deref() == Some(SEED000_NONUNIFORM.id) && args.spec.is_none())
    {
        return Err(CliError::Usage(
            "--at-file evaluates the functions of a family or spec file (not --piecewise or --knots)"
                .into(),
        ));
    }
    let subject = Subject::from_args(args.family.as_deref(), args.spec.as_deref())?;
    let params =
        subject.params_from_pairs(&param_pairs(&args.params)?, args.allow_outside_range)?;
    let points = read_points(path)?;
    let rows = match args.prec {
        None => evaluate(args, &subject, &params, &points, 0.0_f64, |q| q.to_f64())?,
        Some(bits) if (2..=MAX_PREC).contains(&bits) => evaluate(
            args,
            &subject,
            &params,
            &points,
            Mpfr::from_f64(bits, 0.0),
            |q| Mpfr::from_rational(bits, q),
        )?,
        Some(bits) => {
            return Err(CliError::Usage(format!(
                "--prec {bits}: expected a precision from 2 to {MAX_PREC} bits"
            )));
        }
    };
    Ok(render(args, &subject, &params, &points, &rows))
}

/// The values, one row per point (`rows[i][k] = b_k(xᵢ)` as text).
fn evaluate<T: BatchReal + Display>(
    args: &EvalArgs,
    subject: &Subject,
    params: &[Rational],
    points: &[(String, Rational)],
    like: T,
    make: impl Fn(&Rational) -> T,
) -> Result<Vec<Vec<String>>, CliError> {
    let xs: Vec<T> = points.iter().map(|(_, q)| make(q)).collect();
    let allow = args.allow_outside_range;
    match subject {
        Subject::Family(family) => {
            let mut batch = Batch::new(*family, params, &like, allow)?;
            let values = batch.eval(&xs)?;
            let n = xs.len();
            Ok((0..n)
                .map(|i| {
                    (0..batch.functions())
                        .map(|k| values[k * n + i].to_string())
                        .collect()
                })
                .collect())
        }
        // A spec's formulas are syntax trees: one point at a time.
        Subject::Spec(spec) => xs
            .iter()
            .map(|x| {
                let values = spec.eval_at(x, params, allow)?;
                Ok(values.iter().map(ToString::to_string).collect())
            })
            .collect(),
    }
}

fn render(
    args: &EvalArgs,
    subject: &Subject,
    params: &[Rational],
    points: &[(String, Rational)],
    rows: &[Vec<String>],
) -> String {
    let precision = args.prec.map_or("f64".to_string(), |b| format!("mpfr-{b}"));
    let names = subject.function_names();
    let shown: Vec<(String, String)> = subject
        .param_names()
        .into_iter()
        .zip(params.iter().map(ToString::to_string))
        .collect();
    match args.format {
        TextOrJson::Json => {
            let values: serde_json::Map<_, _> = names
                .iter()
                .enumerate()
                .map(|(k, name)| {
                    let column: Vec<&str> = rows.iter().map(|r| r[k].as_str()).collect();
                    (name.clone(), json!(column))
                })
                .collect();
            json(&json!({
                "family": subject.id(),
                "citation": subject.citation(),
                "params": shown.iter().map(|(n, v)| (n.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
                "precision": precision,
                "at": points.iter().map(|(text, _)| text.as_str()).collect::<Vec<_>>(),
                "values": values,
            }))
        }
        TextOrJson::Text => {
            let shown: Vec<String> = shown.iter().map(|(n, v)| format!("{n}={v}")).collect();
            let mut out = String::new();
            let _ = writeln!(
                out,
                "# {} at {} points [{}] ({precision}); {}",
                subject.id(),
                points.len(),
                shown.join(", "),
                subject.citation()
            );
            let _ = writeln!(out, "# at\t{}", names.join("\t"));
            for ((text, _), row) in points.iter().zip(rows) {
                let _ = writeln!(out, "{text}\t{}", row.join("\t"));
            }
            out
        }
    }
}
