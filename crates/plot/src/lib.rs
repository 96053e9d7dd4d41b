//! SVG charts for the `pinjoint` front ends (the commands' figures) and the benchmark's report
//! (`pinjoint-bench`): the house look of every plot of the project, with no other part of it.
//!
//! Rendering only: every function returns the SVG document as a `String`; writing it to a
//! file (atomically) is the caller's business, so this crate does no I/O.
//!
//! - [`error`]: [`PlotError`], what plotters reports, as text;
//! - [`axis`]: the axes ([`Axis`], linear or log, fitted or fixed), their ticks and labels,
//!   and the chart frame both kinds of plot are drawn in;
//! - [`line`](mod@line): [`line_plot`], one chart of several series with shaded x-ranges ([`Band`]) and
//!   markers, and [`stacked_plot`], several charts one above the other;
//! - [`heat`]: [`heat_map`], a value over a grid of (x, y) with a colour bar, contour lines and
//!   outlined rectangles ([`Region`]) such as an operating region.
//!
//! Text is emitted as SVG `<text>` (plotters without its font features measures text
//! with a built-in estimate), so any SVG viewer renders it with its own sans-serif font.

// In dependency order: each module uses only those above it (tests/module_graph.py).
pub mod error;
pub mod axis;
pub mod line;
pub mod heat;

pub use error::PlotError;
pub use axis::{log_ticks, tick_label, Axis, Scale};
pub use heat::{contour_segments, heat_map, viridis, HeatMap, Region};
pub use line::{line_plot, stacked_plot, Band, Chart, Corner, Marker, Series, Style, PALETTE};
