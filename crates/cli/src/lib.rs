//! `trig-audit`: the command-line front end, as a library so that tests can
//! run whole command lines in-process (the fuzz suite in `tests/`).
//!
//! [`run`] parses one command line and runs it. Every failure is one line
//! `error: …` (control characters escaped, long messages cut) with exit
//! status 2; nothing reachable from here panics on bad input.

mod cell;
mod commands;
mod cost;
mod digits;
mod format;
mod names;
mod output;

use std::ffi::OsString;

use clap::error::ErrorKind;
use clap::{Parser, Subcommand};

use crate::commands::{
    audit::AuditArgs, eval::EvalArgs, fit::FitArgs, interp::InterpArgs, join::JoinArgs,
    list::ListArgs, plot::PlotArgs, table::TableArgs,
};

/// Machine-checked audits of trigonometric and polynomial spline bases.
#[derive(Debug, Parser)]
#[command(name = "trig-audit", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Decide every published claim and print the report (the main job).
    Audit(AuditArgs),
    /// Print the catalog of bases: id, citation, variable, parameters and ranges.
    List(ListArgs),
    /// Evaluate every function of a family at a point: f64 with certified error bounds, or proved digits (--prec, --digits).
    Eval(EvalArgs),
    /// Exact (or numeric) tables of endpoint derivatives, in Markdown, LaTeX, CSV or JSON.
    Table(TableArgs),
    /// Control points a C0–C3, G1 or G2 join forces, derived exactly.
    Join(JoinArgs),
    /// Fit cubic (trigonometric) curves to an outline: thesis Chapter 6 tables and comparison.
    Fit(FitArgs),
    /// Draw SVG pictures: basis functions, curves, fitted outlines, interpolants.
    Plot(PlotArgs),
    /// A positivity-preserving interpolant of thesis 4.3 on its data: pieces, knot jumps, certified minimum.
    Interp(InterpArgs),
}

/// What a command line produced.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    /// The text for standard output (exit status 0).
    Output(String),
    /// Help or version text (standard output, exit status 0).
    Help(String),
    /// A one-line message for standard error (exit status 2).
    Error(String),
}

/// Longest error message, in characters: the head and the tail are kept.
/// (Echoes of input are bounded where they are made, see
/// [`trig_core::echo`]; this bounds everything else, e.g. a long formula
/// an exact computation derived.)
pub const MAX_ERROR: usize = 10_000;

/// Runs one command line (`args[0]` is the program name) and returns its
/// whole output (for tests and the fuzz suite; the binary streams with
/// [`run_into`]).
pub fn run<I, T>(args: I) -> Outcome
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let mut out = Vec::new();
    match run_into(args, &mut out) {
        Outcome::Output(_) => Outcome::Output(String::from_utf8_lossy(&out).into_owned()),
        other => other,
    }
}

/// Runs one command line, writing its output to `out` as it is produced
/// (`eval --at-file` writes row by row, in bounded memory); the outcome of
/// a command that ran carries no text then. A closed `out` (a broken pipe)
/// ends the command quietly, as Unix tools do; any other write error is
/// the outcome's error.
pub fn run_into<I, T>(args: I, out: &mut dyn std::io::Write) -> Outcome
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            return match e.kind() {
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => Outcome::Help(e.to_string()),
                ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => Outcome::Error(one_line(
                    "a subcommand is required: audit, list, eval, table, join, fit, plot or interp (see trig-audit --help)",
                )),
                _ => {
                    let text = e.to_string();
                    let first = text.lines().next().unwrap_or("bad command line");
                    let first = first.strip_prefix("error: ").unwrap_or(first);
                    // clap quotes the offending argument whole: keep it short
                    Outcome::Error(bounded(&format!("{first} (see --help)"), MAX_USAGE_ERROR))
                }
            };
        }
    };
    let result = match cli.command {
        Command::Eval(args) if commands::eval::streams(&args) => {
            commands::eval::stream(&args, out).map(|()| String::new())
        }
        Command::Audit(args) => commands::audit::run(&args),
        Command::List(args) => commands::list::run(&args),
        Command::Eval(args) => commands::eval::run(&args),
        Command::Table(args) => commands::table::run(&args),
        Command::Join(args) => commands::join::run(&args),
        Command::Fit(args) => commands::fit::run(&args),
        Command::Plot(args) => commands::plot::run(&args),
        Command::Interp(args) => commands::interp::run(&args),
    };
    let written = result.and_then(|text| {
        out.write_all(text.as_bytes())
            .and_then(|()| out.flush())
            .map_err(commands::CliError::Write)
    });
    match written {
        Ok(()) => Outcome::Output(String::new()),
        Err(commands::CliError::Write(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => {
            Outcome::Output(String::new())
        }
        Err(e) => Outcome::Error(one_line(&e.to_string())),
    }
}

/// Longest command-line (usage) error, in characters.
const MAX_USAGE_ERROR: usize = 300;

/// `message` on one line (control characters escaped) and at most
/// [`MAX_ERROR`] characters (the middle cut, its length stated).
pub fn one_line(message: &str) -> String {
    bounded(message, MAX_ERROR)
}

/// `message` on one line and at most `max` characters.
fn bounded(message: &str, max: usize) -> String {
    let flat = trig_core::echo::escape_controls(message);
    let count = flat.chars().count();
    if count <= max {
        return flat;
    }
    let (keep_head, keep_tail) = (max * 2 / 3, max / 4);
    let head: String = flat.chars().take(keep_head).collect();
    let tail: String = flat.chars().skip(count - keep_tail).collect();
    format!(
        "{head} … [{} characters cut] … {tail}",
        count - keep_head - keep_tail
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_are_one_bounded_line() {
        let long = format!("a\nb{}", "x".repeat(50_000));
        let line = one_line(&long);
        assert!(!line.contains('\n'));
        assert!(line.chars().count() < MAX_ERROR + 60, "{}", line.len());
        assert!(line.starts_with("a\\nb"));
    }

    #[test]
    fn clap_errors_are_one_line() {
        for args in [
            &["trig-audit", "eval", "--bogus"][..],
            &["trig-audit", "eval", "thesis-cubic", "--at"],
            &["trig-audit"],
            &[
                "trig-audit",
                "table",
                "x",
                "--order",
                "99999999999999999999999",
            ],
        ] {
            match run(args) {
                Outcome::Error(line) => assert!(!line.contains('\n'), "{line}"),
                other => panic!("{args:?}: {other:?}"),
            }
        }
        assert!(matches!(run(["trig-audit", "--help"]), Outcome::Help(_)));
    }
}
