//! The one error of rendering: what plotters reports, as text.

use std::fmt;

/// A rendering failure (from plotters), as text.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("plot rendering failed: {0}")]
pub struct PlotError(
    /// plotters' error message.
    pub String,
);

/// plotters' error as a [`PlotError`].
pub(crate) fn err<E: fmt::Display>(e: E) -> PlotError {
    PlotError(e.to_string())
}
