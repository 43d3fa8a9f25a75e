//! Typed errors of the plots.

use thiserror::Error;

/// What can go wrong when a picture is drawn.
#[derive(Debug, Error)]
pub enum PlotError {
    /// An error of the catalog (parameters, ranges, evaluation).
    #[error(transparent)]
    Core(#[from] trig_core::CoreError),
    /// An error of the fitting pipeline.
    #[error(transparent)]
    Fit(#[from] trig_fit::FitError),
    /// Bad input to a plot (no parameter values, non-finite data, …).
    #[error("cannot plot: {0}")]
    Input(String),
    /// Several parameters are free and none is chosen to vary.
    #[error(
        "`{id}` has {} free parameters ({}); {what} plots vary one: fix the others with --param NAME=VALUE (e.g. --param {}=…), or choose the varied one with --vary NAME and fix the rest",
        free.len(),
        free.join(", "),
        free.last().map_or("", String::as_str)
    )]
    Vary {
        id: String,
        what: String,
        free: Vec<String>,
    },
    /// The drawing backend failed.
    #[error("drawing failed: {0}")]
    Draw(String),
}

/// Result alias for this crate.
pub type Result<T, E = PlotError> = std::result::Result<T, E>;

/// Maps any drawing error to [`PlotError::Draw`].
pub fn draw<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Draw(e.to_string())
}
