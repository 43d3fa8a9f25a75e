//! `trig-audit`: the command-line front end, as a library so that tests can
//! run whole command lines in-process (the fuzz suite in `tests/`).
//!
//! [`run`] parses one command line and runs it. A command that fails says
//! so in one line `error: …` (control characters escaped, long messages
//! cut); a command line that does not parse gets clap's whole message (the
//! error, a "did you mean" tip or the possible values, the usage line),
//! each line bounded. Both exit with status 2; nothing reachable from here
//! panics on bad input.

mod cell;
mod commands;
mod cost;
mod digits;
mod format;
mod names;
mod output;

use std::ffi::OsString;
use std::path::Path;

use clap::error::ErrorKind;
use clap::{CommandFactory, Parser, Subcommand};

use crate::commands::{
    audit::AuditArgs,
    eval::EvalArgs,
    fit::FitArgs,
    fit_surface::FitSurfaceArgs,
    generate::{CompletionsArgs, ManArgs},
    interp::InterpArgs,
    join::JoinArgs,
    list::ListArgs,
    plot::PlotArgs,
    table::TableArgs,
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
    /// Fit a gridded height field by tensor-product patches of a basis (C⁰ or C¹): errors per patch and overall, error map.
    FitSurface(FitSurfaceArgs),
    /// Draw SVG pictures: basis functions, curves, fitted outlines, interpolants.
    Plot(PlotArgs),
    /// A positivity-preserving interpolant of thesis 4.3 on its data: pieces, knot jumps, certified minimum.
    Interp(InterpArgs),
    /// Print the shell completion script (bash, zsh, fish, elvish, powershell).
    Completions(CompletionsArgs),
    /// Print the man page (roff) of trig-audit or of one subcommand.
    Man(ManArgs),
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
    /// A command line that does not parse: clap's message for standard
    /// error, several lines (the error, a tip, the usage), each bounded
    /// (exit status 2).
    Usage(String),
}

/// Longest error message, in characters: the head and the tail are kept.
/// (Echoes of input are bounded where they are made, see
/// [`trig_core::echo()`]; this bounds everything else, e.g. a long formula
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
                    "a subcommand is required: audit, list, eval, table, join, fit, fit-surface, plot or interp (see trig-audit --help)",
                )),
                _ => Outcome::Usage(usage_error(&e.render().to_string())),
            };
        }
    };
    let target = cli.command.output().map(Path::to_path_buf);
    if let Some(path) = &target
        && let Err(e) = output::check_directory(path)
    {
        return Outcome::Error(one_line(&e.to_string()));
    }
    let name = cli.command.name();
    let result = match (cli.command, &target) {
        // `eval --at-file` writes row by row, to the file as to standard output
        (Command::Eval(args), Some(path)) if commands::eval::streams(&args) => {
            output::write_atomically_with(path, &mut |w| commands::eval::stream(&args, w))
                .map(|()| String::new())
        }
        (Command::Eval(args), None) if commands::eval::streams(&args) => {
            commands::eval::stream(&args, out).map(|()| String::new())
        }
        (command, Some(path)) => command.run().and_then(|text| {
            output::write_atomically(path, text.as_bytes()).map(|()| String::new())
        }),
        (command, None) => command.run(),
    };
    if let (Some(path), Ok(_)) = (&target, &result) {
        output::wrote(path, name);
    }
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

impl Command {
    /// The file `--output` names (not `-`), for the commands that print
    /// their result (`audit`, `plot` and `fit` write files themselves).
    fn output(&self) -> Option<&Path> {
        match self {
            Command::List(a) => a.out.path(),
            Command::Eval(a) => a.out.path(),
            Command::Table(a) => a.out.path(),
            Command::Join(a) => a.out.path(),
            Command::FitSurface(a) => a.out.path(),
            Command::Interp(a) => a.out.path(),
            Command::Completions(a) => a.out.path(),
            Command::Man(a) => a.out.path(),
            Command::Audit(_) | Command::Fit(_) | Command::Plot(_) => None,
        }
    }

    /// The subcommand's name, as the `wrote …` note says what was written.
    fn name(&self) -> &'static str {
        match self {
            Command::Audit(_) => "audit",
            Command::List(_) => "list",
            Command::Eval(_) => "eval",
            Command::Table(_) => "table",
            Command::Join(_) => "join",
            Command::Fit(_) => "fit",
            Command::FitSurface(_) => "fit-surface",
            Command::Plot(_) => "plot",
            Command::Interp(_) => "interp",
            Command::Completions(_) => "completions",
            Command::Man(_) => "man page",
        }
    }

    /// Runs the command: the text for standard output (or `--output`).
    fn run(self) -> commands::CmdResult {
        match self {
            Command::Audit(args) => commands::audit::run(&args),
            Command::List(args) => commands::list::run(&args),
            Command::Eval(args) => commands::eval::run(&args),
            Command::Table(args) => commands::table::run(&args),
            Command::Join(args) => commands::join::run(&args),
            Command::Fit(args) => commands::fit::run(&args),
            Command::FitSurface(args) => commands::fit_surface::run(&args),
            Command::Plot(args) => commands::plot::run(&args),
            Command::Interp(args) => commands::interp::run(&args),
            Command::Completions(args) => commands::generate::completions(&args, Cli::command()),
            Command::Man(args) => commands::generate::man(&args, Cli::command()),
        }
    }
}

/// Longest line of a command-line (usage) error, in characters: clap
/// quotes the offending argument whole.
const MAX_USAGE_LINE: usize = 300;

/// Most lines of a command-line (usage) error: an argument with line
/// breaks in it spreads over lines.
pub const MAX_USAGE_LINES: usize = 24;

/// Clap's message for a command line that does not parse, every line on
/// its own (control characters escaped) and at most [`MAX_USAGE_LINE`]
/// characters, at most [`MAX_USAGE_LINES`] lines, without trailing blanks.
fn usage_error(text: &str) -> String {
    let lines: Vec<&str> = text.trim_end().lines().collect();
    let keep =
        |ls: &[&str]| -> Vec<String> { ls.iter().map(|l| bounded(l, MAX_USAGE_LINE)).collect() };
    let shown = if lines.len() <= MAX_USAGE_LINES {
        keep(&lines)
    } else {
        let (head, tail) = (MAX_USAGE_LINES / 2, MAX_USAGE_LINES / 2 - 1);
        let mut shown = keep(&lines[..head]);
        shown.push(format!("… [{} lines cut] …", lines.len() - head - tail));
        shown.extend(keep(&lines[lines.len() - tail..]));
        shown
    };
    shown.join("\n")
}

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

    /// A command line that does not parse keeps clap's hints: the
    /// similar subcommand or option, the possible values.
    #[test]
    fn usage_errors_keep_clap_hints() {
        for (args, hint) in [
            (
                &["trig-audit", "audti"][..],
                "similar subcommand exists: 'audit'",
            ),
            (
                &["trig-audit", "audit", "--formt", "md"],
                "similar argument exists: '--format'",
            ),
            (
                &["trig-audit", "audit", "--verdict", "fail"],
                "[possible values: holds, fails",
            ),
            (
                &["trig-audit", "eval", "--bogus"],
                "unexpected argument '--bogus'",
            ),
        ] {
            match run(args) {
                Outcome::Usage(text) => {
                    assert!(text.starts_with("error: "), "{text}");
                    assert!(text.contains(hint), "{args:?}: {text}");
                    assert!(text.contains("--help"), "{text}");
                }
                other => panic!("{args:?}: {other:?}"),
            }
        }
    }

    #[test]
    fn usage_errors_are_bounded() {
        let long = "9".repeat(100_000);
        let many = "1\n".repeat(10_000);
        for args in [
            &["trig-audit", "table", "x", "--order", &long][..],
            &["trig-audit", "eval", "thesis-cubic", "--at"],
            &["trig-audit", "audit", "--format", &many],
        ] {
            match run(args) {
                Outcome::Usage(text) => {
                    let lines: Vec<&str> = text.lines().collect();
                    assert!(lines.len() <= MAX_USAGE_LINES + 1, "{} lines", lines.len());
                    assert!(
                        lines
                            .iter()
                            .all(|l| l.chars().count() <= MAX_USAGE_LINE + 60)
                    );
                }
                other => panic!("{:?}: {other:?}", &args[..2]),
            }
        }
        assert!(matches!(run(["trig-audit"]), Outcome::Error(_)));
        assert!(matches!(run(["trig-audit", "--help"]), Outcome::Help(_)));
    }

    #[test]
    fn completions_and_man_pages() {
        let Outcome::Output(bash) = run(["trig-audit", "completions", "bash"]) else {
            panic!("no bash completions")
        };
        assert!(
            bash.contains("audit") && bash.contains("--format"),
            "{bash}"
        );
        let Outcome::Output(page) = run(["trig-audit", "man"]) else {
            panic!("no man page")
        };
        assert!(
            page.starts_with(".ie") || page.contains(".TH trig-audit"),
            "{page}"
        );
        let Outcome::Output(page) = run(["trig-audit", "man", "audit"]) else {
            panic!("no man page of audit")
        };
        assert!(
            page.contains("trig-audit-audit") && page.contains("verdict"),
            "{page}"
        );
        assert!(
            matches!(run(["trig-audit", "man", "nope"]), Outcome::Error(e) if e.contains("one of: audit"))
        );
    }
}
