//! `trig-audit eval --at-file FILE`: every function at many points, read
//! from a file or standard input, each value certified as for one `--at`
//! (f64 with a proved error bound, or proved digits under `--prec` and
//! `--digits`; the uncertified fast path is the library's
//! [`trig_core::Batch`]). For scripts: the text output is tab-separated
//! columns under `#` header lines (`numpy.loadtxt` reads it as is), written
//! point by point as it is computed — memory stays bounded whatever the
//! number of points — with notes as `#` lines before their row and a last
//! `#` line that sums up (the largest f64 error bound, or whether every
//! requested digit was proved). The JSON output is one array per column,
//! so it holds every value until the end and is bounded by
//! [`cost::MAX_JSON_VALUES`].
//!
//! Cost: a file's points are counted first (a streaming pass), and the
//! work of one point — the first, or one at the domain's midpoint when that
//! costs more — predicts the whole ([`cost::check_points_work`]), so a
//! request beyond the bound is refused before any value is printed; the
//! work spent is also checked as the points are computed (a file whose
//! points cost more than predicted, or standard input, stops with the
//! error after the rows so far).

use std::io::Write;
use std::path::Path;

use rug::Rational;
use serde_json::json;
use trig_core::input::{Lines, Source};
use trig_core::{Affine, Described, SEED000_NONUNIFORM, parse_point, work};

use super::{CliError, EvalArgs, Evaluation, evaluate, subject_of};
use crate::commands::param_pairs;
use crate::cost;
use crate::format::{TextOrJson, json};
use trig_core::evaluation::Arithmetic;
use trig_specfile::AnyBasis;

/// A point of the file: its line number, its text as written, its exact
/// value.
type Point = (usize, String, Affine);

/// The points of `source`, one at a time (blank lines and `#` lines
/// skipped).
fn points(source: &Source) -> Result<impl Iterator<Item = Result<Point, CliError>>, CliError> {
    let name = source.name();
    let lines = Lines::open(source).map_err(|e| CliError::Usage(e.to_string()))?;
    Ok(lines.filter_map(move |line| {
        let (n, text) = match line {
            Ok(l) => l,
            Err(e) => return Some(Err(CliError::Usage(e.to_string()))),
        };
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            return None;
        }
        Some(
            parse_point(text)
                .map(|q| (n, text.to_string(), q))
                .map_err(|e| CliError::Usage(format!("{name} line {n}: {e}"))),
        )
    }))
}

/// A point's error with the file and line it comes from.
fn at_line(e: CliError, name: &str, n: usize) -> CliError {
    match e {
        CliError::Write(e) => CliError::Write(e),
        other => CliError::Usage(format!("{name} line {n}: {other}")),
    }
}

/// The number of points of a file (a first pass; lines are only split,
/// their numbers are read in the second).
fn count(source: &Source) -> Result<u64, CliError> {
    let mut n = 0u64;
    for line in Lines::open(source).map_err(|e| CliError::Usage(e.to_string()))? {
        let (_, text) = line.map_err(|e| CliError::Usage(e.to_string()))?;
        let text = text.trim();
        if !text.is_empty() && !text.starts_with('#') {
            n += 1;
        }
    }
    Ok(n)
}

/// Evaluates `--at-file` into `out` (see the module documentation).
pub(super) fn stream(
    args: &EvalArgs,
    path: &Path,
    mode: Arithmetic,
    out: &mut dyn Write,
) -> Result<(), CliError> {
    if args.piecewise
        || !args.knots.is_empty()
        || (args.family.as_deref() == Some(SEED000_NONUNIFORM.id) && args.spec.is_none())
    {
        return Err(CliError::Usage(
            "--at-file evaluates the functions of a family or spec file (not --piecewise or --knots)"
                .into(),
        ));
    }
    let source = Source::of(path);
    let subject = subject_of(args)?;
    let total = match &source {
        Source::File(_) => Some(count(&source)?),
        Source::Stdin => None,
    };
    let name = source.name();
    if total == Some(0) {
        return Err(CliError::Usage(format!("{name}: no points")));
    }
    if let Some(n) = total.filter(|n| *n > cost::MAX_POINTS) {
        return Err(cost::limit(
            format!("--at-file with {n} points"),
            format!("{} points", cost::MAX_POINTS),
        )
        .into());
    }
    let mut rows = Rows {
        args,
        mode,
        subject: subject.as_ref(),
        total,
        spent: 0,
        done: 0,
        probe: probe(args, mode, subject.as_ref()),
    };
    match args.format {
        TextOrJson::Text => text(&mut rows, points(&source)?, &name, out),
        TextOrJson::Json => {
            let functions = subject.as_ref().map_or(1, |s| s.function_names().len()) as u64;
            if let Some(n) = total.filter(|n| n.saturating_mul(functions) > cost::MAX_JSON_VALUES) {
                return Err(json_limit(n * functions).into());
            }
            let value = json_columns(&mut rows, points(&source)?, &name)?;
            out.write_all(json(&value).as_bytes())
                .map_err(CliError::Write)
        }
    }
}

fn json_limit(values: u64) -> trig_core::CoreError {
    cost::limit(
        format!(
            "--at-file --format json with {values} values (the JSON holds them all until the end)"
        ),
        format!(
            "{} values and {} bytes of values (the text format streams any number)",
            cost::MAX_JSON_VALUES,
            cost::MAX_JSON_BYTES
        ),
    )
}

/// The rows as they are evaluated, with the work they spend.
struct Rows<'a> {
    args: &'a EvalArgs,
    mode: Arithmetic,
    subject: Option<&'a AnyBasis>,
    /// The number of points, when known before (a file).
    total: Option<u64>,
    spent: u64,
    done: u64,
    /// The work of one point at a generic place (the domain's midpoint).
    probe: Option<u64>,
}

/// The work of one evaluation at the domain's midpoint: what a point costs
/// when nothing is exactly zero (a point such as `0` can be much cheaper,
/// so it would predict a file badly).
fn probe(args: &EvalArgs, mode: Arithmetic, subject: Option<&AnyBasis>) -> Option<u64> {
    let s = subject?;
    let pairs = param_pairs(&args.params).ok()?;
    let p = s.params_from_pairs(&pairs, args.allow_outside_range).ok()?;
    let d = s.domain();
    let mid = d.start.plus(&d.end).scale(&Rational::from((1, 2))).at(&p);
    let (row, units) = work::measure(|| evaluate(args, "the midpoint", &mid, mode, Some(s)));
    row.ok().map(|_| units)
}

impl Rows<'_> {
    /// The evaluation at one point, within the cost model.
    fn row(&mut self, text: &str, q: &Affine) -> Result<Evaluation, CliError> {
        if self.done >= cost::MAX_POINTS {
            return Err(cost::limit(
                "--at-file with more points",
                format!("{} points", cost::MAX_POINTS),
            )
            .into());
        }
        let (row, units) = work::measure(|| evaluate(self.args, text, q, self.mode, self.subject));
        let row = row?;
        self.done += 1;
        self.spent = self.spent.saturating_add(units);
        match self.total {
            // the first point (or a generic one) predicts the whole file
            Some(n) if self.done == 1 => {
                cost::check_points_work(n, units.max(self.probe.unwrap_or(0)))?;
            }
            _ if self.spent > cost::COMMAND_WORK => {
                return Err(cost::limit(
                    format!(
                        "--at-file after {} points ({} work units)",
                        self.done, self.spent
                    ),
                    format!(
                        "{} work units of certified arithmetic per command",
                        cost::COMMAND_WORK
                    ),
                )
                .into());
            }
            _ => {}
        }
        Ok(row)
    }

    /// The arithmetic as the title states it (before any value).
    fn title_mode(&self) -> String {
        match self.mode {
            Arithmetic::F64 => "f64; ± certified error bounds".into(),
            Arithmetic::Bits(b) => format!("mpfr-{b}, certified: only proved digits are printed"),
            Arithmetic::Digits(n) => format!(
                "{n} significant digits requested, only proved digits printed; the last line says whether all were"
            ),
        }
    }
}

fn write(out: &mut dyn Write, line: &str) -> Result<(), CliError> {
    out.write_all(line.as_bytes())
        .and_then(|()| out.write_all(b"\n"))
        .map_err(CliError::Write)
}

fn text(
    rows: &mut Rows<'_>,
    points: impl Iterator<Item = Result<Point, CliError>>,
    name: &str,
    out: &mut dyn Write,
) -> Result<(), CliError> {
    let params = param_pairs(&rows.args.params).unwrap_or_default();
    let shown: Vec<String> = params.iter().map(|(n, v)| format!("{n}={v}")).collect();
    let (mut largest, mut bits, mut short) = (None::<(f64, String)>, 0, 0usize);
    let mut first = true;
    for point in points {
        let (n, text, q) = point?;
        let r = rows.row(&text, &q).map_err(|e| at_line(e, name, n))?;
        if first {
            let count = rows.total.map_or_else(
                || format!("the points of {name}"),
                |n| format!("{n} points"),
            );
            write(
                out,
                &format!(
                    "# {} at {count} [{}] ({}); {}",
                    r.id,
                    shown.join(", "),
                    rows.title_mode(),
                    r.citation
                ),
            )?;
            write(out, &format!("# at\t{}", r.names.join("\t")))?;
            first = false;
        }
        for (n, v) in r.names.iter().zip(&r.values) {
            if let Some(note) = &v.note {
                write(out, &format!("# at {text}: {n}: {note}"))?;
            }
            if let Some(b) = &v.bound {
                let x = b.parse::<f64>().unwrap_or(f64::INFINITY);
                if largest.as_ref().is_none_or(|(l, _)| x > *l) {
                    largest = Some((x, b.clone()));
                }
            }
            if let (Arithmetic::Digits(n), Some(d)) = (rows.mode, v.digits) {
                short += usize::from(d < n);
            }
        }
        bits = bits.max(r.bits);
        let values: Vec<&str> = r.values.iter().map(|v| v.text.as_str()).collect();
        write(out, &format!("{text}\t{}", values.join("\t")))?;
        // each row is out as soon as it is computed (a pipe reads it now)
        out.flush().map_err(CliError::Write)?;
    }
    if first {
        return Err(CliError::Usage(format!("{name}: no points")));
    }
    let last = match rows.mode {
        Arithmetic::F64 => largest.map(|(_, b)| {
            format!(
                "# every f64 value is within {b} of the exact value (enclosures up to {bits} bits)"
            )
        }),
        Arithmetic::Bits(_) => None,
        Arithmetic::Digits(n) if short == 0 => Some(format!(
            "# {n} significant digits of every value, all proved (MPFR up to {bits} bits)"
        )),
        Arithmetic::Digits(n) => Some(format!(
            "# {n} significant digits requested: {short} values have fewer (marked above)"
        )),
    };
    if let Some(line) = last {
        write(out, &line)?;
    }
    out.flush().map_err(CliError::Write)
}

fn json_columns(
    rows: &mut Rows<'_>,
    points: impl Iterator<Item = Result<Point, CliError>>,
    name: &str,
) -> Result<serde_json::Value, CliError> {
    let mut at = Vec::new();
    let mut all: Vec<Evaluation> = Vec::new();
    let (mut values, mut bytes) = (0u64, 0u64);
    for point in points {
        let (n, text, q) = point?;
        let r = rows.row(&text, &q).map_err(|e| at_line(e, name, n))?;
        values += r.values.len() as u64;
        bytes += r.values.iter().map(|v| v.text.len() as u64).sum::<u64>();
        if values > cost::MAX_JSON_VALUES || bytes > cost::MAX_JSON_BYTES {
            return Err(json_limit(values).into());
        }
        at.push(text);
        all.push(r);
    }
    let Some(first) = all.first() else {
        return Err(CliError::Usage(format!("{name}: no points")));
    };
    let params = param_pairs(&rows.args.params).unwrap_or_default();
    let column = |k: usize, f: &dyn Fn(&super::Shown) -> serde_json::Value| {
        json!(all.iter().map(|r| f(&r.values[k])).collect::<Vec<_>>())
    };
    let map = |f: &dyn Fn(&super::Shown) -> serde_json::Value| -> serde_json::Map<_, _> {
        first
            .names
            .iter()
            .enumerate()
            .map(|(k, n)| (n.clone(), column(k, f)))
            .collect()
    };
    let precision = all
        .iter()
        .map(|r| r.precision.as_str())
        .max_by_key(|p| p.len())
        .unwrap_or_default();
    Ok(json!({
        "family": first.id,
        "citation": first.citation,
        "params": params.iter().map(|(n, v)| (n.clone(), json!(v))).collect::<serde_json::Map<_, _>>(),
        "precision": precision,
        "at": at,
        "values": map(&|v| json!(v.text)),
        "error_bounds": map(&|v| json!(v.bound)),
        "proved_digits": map(&|v| json!(v.digits.filter(|d| *d != usize::MAX))),
        "notes": map(&|v| json!(v.note)),
    }))
}
