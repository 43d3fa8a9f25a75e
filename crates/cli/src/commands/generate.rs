//! `trig-audit completions SHELL` and `trig-audit man`: the shell
//! completion script and the man page, generated from the command-line
//! definition itself (so they cannot fall out of date).
//!
//! ```text
//! trig-audit completions bash > /etc/bash_completion.d/trig-audit
//! trig-audit man > trig-audit.1 && man ./trig-audit.1
//! trig-audit man audit > trig-audit-audit.1
//! ```

use clap::{Args, Command};
use clap_complete::Shell;

use super::{CliError, CmdResult};

/// Arguments of `completions`.
#[derive(Debug, Args)]
pub struct CompletionsArgs {
    /// The shell the script is for.
    #[arg(value_enum)]
    pub shell: Shell,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

/// The completion script of `shell` for the command line `cli`.
pub fn completions(args: &CompletionsArgs, mut cli: Command) -> CmdResult {
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut cli, "trig-audit", &mut script);
    text(script)
}

/// Arguments of `man`.
#[derive(Debug, Args)]
pub struct ManArgs {
    /// The page of this subcommand (`trig-audit-audit(1)`, …) instead of
    /// the page of `trig-audit` itself.
    pub command: Option<String>,
    #[command(flatten)]
    pub out: crate::output::OutputArg,
}

/// The man page (roff) of the command line `cli`, or of one of its
/// subcommands.
pub fn man(args: &ManArgs, mut cli: Command) -> CmdResult {
    // building names each subcommand `trig-audit-NAME` (its page title)
    cli.build();
    let page = match &args.command {
        None => cli,
        Some(name) => {
            let names = || cli.get_subcommands().map(|s| s.get_name().to_string());
            cli.find_subcommand(name).cloned().ok_or_else(|| {
                let known: Vec<String> = names().filter(|n| n != "help").collect();
                CliError::Usage(format!(
                    "no subcommand '{}'; one of: {}",
                    trig_core::echo::echo(name),
                    known.join(", ")
                ))
            })?
        }
    };
    let mut roff = Vec::new();
    clap_mangen::Man::new(page)
        .render(&mut roff)
        .map_err(CliError::Write)?;
    text(roff)
}

fn text(bytes: Vec<u8>) -> CmdResult {
    String::from_utf8(bytes)
        .map_err(|e| CliError::Usage(format!("generated text is not UTF-8: {e}")))
}
