//! `trig-audit audit`: decide the published claims and print (or write) the
//! report. Exit status 0 whenever the audit ran, whatever the verdicts.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Duration;

use clap::{Args, ValueEnum};
use trig_spec::Spec;
use trig_verification::budget::CLAIM_BUDGET;
use trig_verification::report::Entry;
use trig_verification::{Seed, report, run as run_audit, spec_audit};

use super::{CliError, CmdResult};
use crate::format::json;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReportFormat {
    Md,
    Json,
    Tex,
}

#[derive(Debug, Args)]
pub struct AuditArgs {
    /// Only this document: 000, 001, 002, 003 or 004.
    #[arg(long)]
    seed: Option<String>,
    /// Only this claim id (e.g. T4b).
    #[arg(long)]
    claim: Option<String>,
    /// Audit the basis and claims of a spec file (TOML, docs/spec.md) instead of the built-in claims.
    #[arg(long, value_name = "FILE", conflicts_with = "seed")]
    spec: Option<PathBuf>,
    /// Report format.
    #[arg(long, value_enum, default_value = "md")]
    format: ReportFormat,
    /// Write the report to this file (atomically) instead of standard output.
    #[arg(long)]
    output: Option<PathBuf>,
    /// With --spec: seconds each claim's decision may take (0.1 to 3600);
    /// a decision that runs over is reported `not-checkable`.
    #[arg(long, default_value_t = CLAIM_BUDGET.as_secs_f64(), value_parser = time_limit)]
    time_limit: f64,
}

/// A time limit in seconds, from 0.1 to 3600.
fn time_limit(text: &str) -> Result<f64, String> {
    let t: f64 = text.parse().map_err(|_| "expected seconds".to_string())?;
    if (0.1..=3600.0).contains(&t) {
        Ok(t)
    } else {
        Err("expected 0.1 to 3600 seconds".into())
    }
}

pub fn run(args: &AuditArgs) -> CmdResult {
    let (entries, intro) = match &args.spec {
        Some(path) => {
            let spec = Spec::from_file(path)
                .map_err(|e| CliError::Usage(e.to_string().replace('\n', " ")))?;
            let budget = Duration::from_secs_f64(args.time_limit);
            let entries: Vec<Entry> = spec_audit::audit_within(&spec, Some(budget))
                .into_iter()
                .filter(|e| {
                    args.claim
                        .as_deref()
                        .is_none_or(|id| e.id.eq_ignore_ascii_case(id))
                })
                .collect();
            (entries, spec_audit::intro(&spec))
        }
        None => (builtin(args)?, report::BUILTIN_INTRO.to_string()),
    };
    if entries.is_empty() {
        return Err(CliError::Usage(format!(
            "no claim matches --claim {}",
            args.claim.as_deref().unwrap_or("")
        )));
    }
    let text = match args.format {
        ReportFormat::Md => report::markdown_entries(&entries, &intro),
        ReportFormat::Json => json(&report::json_entries(&entries)),
        ReportFormat::Tex => report::tex_entries(&entries, &intro),
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            write_atomically(path, &text)
                .map_err(|e| CliError::Usage(format!("cannot write {}: {e}", path.display())))?;
            Ok(format!(
                "wrote {} ({} claims)\n",
                path.display(),
                entries.len()
            ))
        }
    }
}

/// The built-in claims selected by `--seed` and `--claim`, decided.
fn builtin(args: &AuditArgs) -> Result<Vec<Entry>, CliError> {
    let seed = match &args.seed {
        None => None,
        Some(id) => Some(
            Seed::ALL
                .into_iter()
                .find(|s| s.id() == id.trim_start_matches("seed").trim_start_matches(' '))
                .ok_or_else(|| {
                    CliError::Usage(format!("--seed {id}: expected 000, 001, 002, 003 or 004"))
                })?,
        ),
    };
    Ok(report::entries(&run_audit(seed, args.claim.as_deref())))
}

/// Writes to a temporary file beside `path`, then renames it over `path`:
/// an interrupted run never leaves a half-written report.
fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .ok_or_else(|| std::io::Error::other("not a file name"))?;
    let tmp = dir.join(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let mut file = std::fs::File::create(&tmp)?;
    file.write_all(text.as_bytes())?;
    file.sync_all()?;
    std::fs::rename(&tmp, path).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}
