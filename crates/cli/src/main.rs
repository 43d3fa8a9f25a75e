//! `trig-audit`: the command-line front end.
//!
//! Every failure is reported as one line `error: …` on standard error with a
//! nonzero exit status; nothing reachable from here panics on bad input.

mod cell;
mod commands;
mod format;

use std::io::{ErrorKind, Write};
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::commands::{fit::FitArgs, plot::PlotArgs};

use crate::commands::{
    audit::AuditArgs, eval::EvalArgs, join::JoinArgs, list::ListArgs, table::TableArgs,
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
    /// Evaluate every function of a family at a point (f64, or MPFR with --prec).
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
    Interp(commands::interp::InterpArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Audit(args) => commands::audit::run(&args),
        Command::List(args) => commands::list::run(&args),
        Command::Eval(args) => commands::eval::run(&args),
        Command::Table(args) => commands::table::run(&args),
        Command::Join(args) => commands::join::run(&args),
        Command::Fit(args) => commands::fit::run(&args),
        Command::Plot(args) => commands::plot::run(&args),
        Command::Interp(args) => commands::interp::run(&args),
    };
    match result {
        Ok(text) => write_stdout(&text),
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Writes the result to standard output. A closed pipe ends the program
/// quietly with success (as Unix tools do: `trig-audit audit | head`);
/// any other write error (a full disk) is a one-line error, exit status 2.
fn write_stdout(text: &str) -> ExitCode {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: cannot write to standard output: {e}");
            ExitCode::from(2)
        }
    }
}
