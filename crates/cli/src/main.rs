//! `trig-audit`: the command-line binary. The commands live in the library
//! (`trig_audit::run_into`), which writes their output to standard output
//! as it is produced.

use std::io::Write;
use std::process::ExitCode;

use trig_audit::{Outcome, run_into};

fn main() -> ExitCode {
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    match run_into(std::env::args_os(), &mut out) {
        Outcome::Output(_) => ExitCode::SUCCESS,
        Outcome::Help(text) => write_help(&mut out, &text),
        Outcome::Error(line) => {
            // what was written before the error stays written
            let _ = out.flush();
            eprintln!("error: {line}");
            ExitCode::from(2)
        }
        Outcome::Usage(text) => {
            eprintln!("{text}");
            ExitCode::from(2)
        }
    }
}

/// Writes help or version text. A closed pipe ends the program quietly
/// with success (as Unix tools do: `trig-audit --help | head`); any other
/// write error is a one-line error, exit status 2.
fn write_help(out: &mut impl Write, text: &str) -> ExitCode {
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: cannot write to standard output: {e}");
            ExitCode::from(2)
        }
    }
}
