//! `trig-audit`: the command-line binary. The commands live in the library
//! (`trig_audit::run`); this writes their output.

use std::io::{ErrorKind, Write};
use std::process::ExitCode;

use trig_audit::{Outcome, run};

fn main() -> ExitCode {
    match run(std::env::args_os()) {
        Outcome::Output(text) | Outcome::Help(text) => write_stdout(&text),
        Outcome::Error(line) => {
            eprintln!("error: {line}");
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
