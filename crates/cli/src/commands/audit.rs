//! `trig-audit audit`: decide the published claims and print (or write) the
//! report. Exit status 0 whenever the audit ran, whatever the verdicts.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::{Args, ValueEnum};
use trig_verification::{Seed, report, run as run_audit};

use super::{CliError, CmdResult};
use crate::format::json;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReportFormat {
    Md,
    Json,
}

#[derive(Debug, Args)]
pub struct AuditArgs {
    /// Only this document: 000, 001, 002, 003 or 004.
    #[arg(long)]
    seed: Option<String>,
    /// Only this claim id (e.g. T4b).
    #[arg(long)]
    claim: Option<String>,
    /// Report format.
    #[arg(long, value_enum, default_value = "md")]
    format: ReportFormat,
    /// Write the report to this file (atomically) instead of standard output.
    #[arg(long)]
    output: Option<PathBuf>,
}

pub fn run(args: &AuditArgs) -> CmdResult {
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
    let outcomes = run_audit(seed, args.claim.as_deref());
    if outcomes.is_empty() {
        return Err(CliError::Usage(format!(
            "no claim matches --claim {}",
            args.claim.as_deref().unwrap_or("")
        )));
    }
    let text = match args.format {
        ReportFormat::Md => report::markdown(&outcomes),
        ReportFormat::Json => json(&report::json(&outcomes)),
    };
    match &args.output {
        None => Ok(text),
        Some(path) => {
            write_atomically(path, &text)
                .map_err(|e| CliError::Usage(format!("cannot write {}: {e}", path.display())))?;
            Ok(format!(
                "wrote {} ({} claims)\n",
                path.display(),
                outcomes.len()
            ))
        }
    }
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
