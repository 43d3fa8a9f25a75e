//! `trig-audit audit`: decide the published claims and print (or write) the
//! report. Exit status 0 whenever the audit ran, whatever the verdicts.

use std::path::{Path, PathBuf};
use std::time::Duration;

use clap::{Args, ValueEnum};
use trig_report::{self as report, View};
use trig_specfile::DocumentFile;
use trig_specfile::Spec;
use trig_verification::Entry;
use trig_verification::budget::CLAIM_BUDGET;
use trig_verification::{Status, documents, spec_audit};

use super::{CliError, CmdResult};
use crate::output::{check_directory, write_atomically, wrote};

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ReportFormat {
    Md,
    Json,
    Tex,
}

/// How a spec audit reports its standard battery (`--battery`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum BatteryArg {
    /// Not run: the file's claims only.
    None,
    /// Run and counted (its own line of the summary), not listed.
    Summary,
    /// Run, counted apart and reported in full after the file's claims.
    Full,
}

/// A verdict to show (`--verdict`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum VerdictArg {
    Holds,
    Fails,
    HoldsAfterCorrection,
    NotCheckable,
}

impl From<VerdictArg> for Status {
    fn from(v: VerdictArg) -> Status {
        match v {
            VerdictArg::Holds => Status::Holds,
            VerdictArg::Fails => Status::Fails,
            VerdictArg::HoldsAfterCorrection => Status::HoldsAfterCorrection,
            VerdictArg::NotCheckable => Status::NotCheckable,
        }
    }
}

#[derive(Debug, Args)]
pub struct AuditArgs {
    /// Only this document: 000, 001, 002, 003 or 004.
    #[arg(long)]
    seed: Option<String>,
    /// Only this claim id (e.g. T4b).
    #[arg(long)]
    claim: Option<String>,
    /// Audit the basis and claims of a spec file (TOML, docs/spec.md), or one document file (a folder of `documents/`, or its `document.toml`), instead of the five documents.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["seed", "documents"])]
    spec: Option<PathBuf>,
    /// The folder of the document files the audit decides (its `audit.toml` lists them in report order): by default `documents/` of this checkout.
    #[arg(long, value_name = "DIR")]
    documents: Option<PathBuf>,
    /// The short form: the summary and the index (one line per claim), no evidence.
    #[arg(long)]
    summary: bool,
    /// Only claims with these verdicts (comma separated), e.g. --verdict fails,holds-after-correction.
    #[arg(long, value_enum, value_delimiter = ',')]
    verdict: Vec<VerdictArg>,
    /// Report format.
    #[arg(long, value_enum, default_value = "md")]
    format: ReportFormat,
    /// Write the report to this file (atomically) instead of standard output (`-`: standard output).
    #[arg(long)]
    output: Option<PathBuf>,
    /// With --format tex: a complete document (preamble and all) instead of a fragment to \input into an article loading amsmath, amssymb, booktabs, longtable, array, graphicx.
    #[arg(long)]
    standalone: bool,
    /// With --spec: seconds each claim's decision may take (0.1 to 3600,
    /// default 10);
    /// a decision that runs over is cut off: an entry `not-checkable` naming
    /// the limit (every other verdict comes from counted budgets, the same
    /// anywhere).
    #[arg(long, value_parser = time_limit)]
    time_limit: Option<f64>,
    /// With --spec: the standard battery (the tool's own checks of every
    /// basis, not claims of the file), always counted apart from the file's
    /// claims: not run, its counts only, or in full (default).
    #[arg(long, value_enum)]
    battery: Option<BatteryArg>,
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
    if let Some(path) = args.output.as_deref().filter(|p| p.as_os_str() != "-") {
        check_directory(path)?;
    }
    let (entries, intro) = match &args.spec {
        Some(path) if trig_specfile::document::is_document(path) => {
            let document = DocumentFile::from_path(path)
                .map_err(|e| CliError::Usage(e.to_string().replace('\n', " ")))?;
            let entries = documents::audit(&[document], Path::new(""), None, args.claim.as_deref());
            (entries, report::document_intro(&path.display().to_string()))
        }
        Some(path) => {
            let spec = Spec::from_file(path)
                .map_err(|e| CliError::Usage(e.to_string().replace('\n', " ")))?;
            let limit = args.time_limit.unwrap_or(CLAIM_BUDGET.as_secs_f64());
            let budget = Duration::from_secs_f64(limit);
            let chosen = |id: &str| {
                args.claim
                    .as_deref()
                    .is_none_or(|c| id.eq_ignore_ascii_case(c))
            };
            let battery = args.battery.unwrap_or(BatteryArg::Full);
            let audit = spec_audit::audit_within(
                &spec,
                Some(budget),
                args.claim.as_deref(),
                battery != BatteryArg::None,
            );
            let entries: Vec<Entry> = audit
                .entries
                .into_iter()
                .filter(|e| chosen(&e.id))
                .collect();
            let cut_off: Vec<String> = audit.cut_off.into_iter().filter(|id| chosen(id)).collect();
            let mut intro = spec_audit::intro(&spec, battery != BatteryArg::None);
            if !cut_off.is_empty() {
                intro.push_str(&format!(
                    " Cut off by the time limit of {} s per claim, and so not-checkable (a longer --time-limit may decide them): {}. Every other verdict below is the one any machine computes.",
                    limit,
                    cut_off.join(", ")
                ));
            }
            (entries, intro)
        }
        None if args.time_limit.is_some() => {
            return Err(CliError::Usage(
                "--time-limit applies to --spec: the audit of the five documents is bounded by counted budgets, not by time".into(),
            ));
        }
        None if args.battery.is_some() => {
            return Err(CliError::Usage(
                "--battery applies to --spec: the five documents have no standard battery, only their claims".into(),
            ));
        }
        None => (builtin(args)?, report::BUILTIN_INTRO.to_string()),
    };
    if entries.is_empty() {
        return Err(CliError::Usage(format!(
            "no claim matches --claim {}",
            args.claim.as_deref().unwrap_or("")
        )));
    }
    if args.standalone && args.format != ReportFormat::Tex {
        return Err(CliError::Usage(
            "--standalone applies to --format tex (a complete LaTeX document)".into(),
        ));
    }
    let view = View {
        summary_only: args.summary,
        verdicts: args.verdict.iter().map(|v| Status::from(*v)).collect(),
        battery_counts_only: args.battery == Some(BatteryArg::Summary),
    };
    // figures are linked by their path from where the report is written
    let output_dir = args
        .output
        .as_deref()
        .filter(|p| p.as_os_str() != "-")
        .map(|p| match p.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
            _ => PathBuf::from("."),
        });
    let text = match args.format {
        ReportFormat::Md => {
            report::markdown_entries_in(&entries, &intro, &view, output_dir.as_deref())
        }
        ReportFormat::Json => {
            let mut s =
                serde_json::to_string_pretty(&report::json_entries(&entries, &intro, &view))
                    .map_err(|e| CliError::Usage(format!("cannot encode the report: {e}")))?;
            s.push('\n');
            s
        }
        ReportFormat::Tex => {
            let options = report::TexOptions {
                standalone: args.standalone,
                output_dir,
            };
            report::tex_entries(&entries, &intro, &view, &options)
        }
    };
    match &args.output {
        // `--output -` is standard output
        None => Ok(text),
        Some(path) if path.as_os_str() == "-" => Ok(text),
        Some(path) => {
            write_atomically(path, text.as_bytes())?;
            // the file's claims and the battery's checks counted apart
            let (checks, claims): (Vec<&Entry>, Vec<&Entry>) = view
                .select(&entries)
                .into_iter()
                .partition(|e| e.document.battery);
            let mut what = trig_verdict::plural(claims.len(), "claim", "claims");
            if !checks.is_empty() {
                what.push_str(&format!(
                    " and {} of the standard battery",
                    trig_verdict::plural(checks.len(), "check", "checks")
                ));
            }
            wrote(path, &what);
            Ok(String::new())
        }
    }
}

/// The claims of the document files selected by `--seed` and `--claim`,
/// decided.
fn builtin(args: &AuditArgs) -> Result<Vec<Entry>, CliError> {
    let dir = args
        .documents
        .clone()
        .unwrap_or_else(documents::default_dir);
    let files = documents::load(&dir).map_err(|e| CliError::Usage(e.to_string()))?;
    let seed = match &args.seed {
        None => None,
        Some(id) => {
            let id = id.trim_start_matches("seed").trim_start_matches(' ');
            if !files.iter().any(|d| d.header.id == id) {
                let ids: Vec<&str> = files.iter().map(|d| d.header.id.as_str()).collect();
                return Err(CliError::Usage(format!(
                    "--seed {id}: expected one of {}",
                    ids.join(", ")
                )));
            }
            Some(id)
        }
    };
    let root = dir.parent().unwrap_or(Path::new(""));
    Ok(documents::audit(&files, root, seed, args.claim.as_deref()))
}
