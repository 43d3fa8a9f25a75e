//! One module per subcommand.

pub mod audit;
pub mod eval;
pub mod fit;
pub mod fit_surface;
pub mod generate;
pub mod interp;
pub mod join;
pub mod list;
pub mod plot;
pub mod surface;
pub mod table;

/// Error of a command: a typed library error or a usage problem.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    #[error(transparent)]
    Core(#[from] trig_core::CoreError),
    #[error("{0}")]
    Usage(String),
    /// Output that could not be written (a closed pipe ends quietly).
    #[error("cannot write to standard output: {0}")]
    Write(std::io::Error),
}

impl From<trig_specfile::OpenError> for CliError {
    fn from(e: trig_specfile::OpenError) -> Self {
        use trig_specfile::OpenError;
        match e {
            OpenError::Core(e) => CliError::Core(e),
            e => CliError::Usage(e.to_string().replace('\n', " ")),
        }
    }
}

/// Result of a command: the text to print.
pub type CmdResult = Result<String, CliError>;

/// The error of a command that takes `--allow-outside-range`: a parameter
/// outside its published range or a point outside the domain gets the hint.
pub fn range_hint(e: trig_core::CoreError) -> CliError {
    use trig_core::CoreError::{OutOfRange, PointOutsideDomain};
    match e {
        OutOfRange { .. } | PointOutsideDomain { .. } => CliError::Usage(format!(
            "{e} (pass --allow-outside-range to evaluate anyway)"
        )),
        e => e.into(),
    }
}

/// Splits `name=value` arguments.
pub fn param_pairs(raw: &[String]) -> Result<Vec<(String, String)>, CliError> {
    raw.iter()
        .map(|p| {
            p.split_once('=')
                .map(|(n, v)| (n.trim().to_string(), v.trim().to_string()))
                .filter(|(n, v)| !n.is_empty() && !v.is_empty())
                .ok_or_else(|| CliError::Usage(format!("--param `{p}`: expected NAME=VALUE")))
        })
        .collect()
}
