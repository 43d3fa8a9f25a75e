//! One module per subcommand.

pub mod audit;
pub mod eval;
pub mod fit;
pub mod interp;
pub mod join;
pub mod list;
pub mod plot;
pub mod table;

/// Error of a command: a typed library error or a usage problem.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error(transparent)]
    Core(#[from] trig_core::CoreError),
    #[error("{0}")]
    Usage(String),
}

/// Result of a command: the text to print.
pub type CmdResult = Result<String, CliError>;
