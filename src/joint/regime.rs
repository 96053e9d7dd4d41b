//! The lubrication regime of an operating point, named from the load shares.

use serde::Serialize;

/// Share of the load below which a carrier counts as absent when naming the regime.
pub const REGIME_SHARE: f64 = 0.01;

/// Lubrication regime, named from the load shares.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    /// The fluid carries less than [`REGIME_SHARE`] of the load.
    Boundary,
    /// Both fluid and asperities carry at least [`REGIME_SHARE`].
    Mixed,
    /// The asperities carry less than [`REGIME_SHARE`].
    FullFilm,
}

impl Regime {
    /// Lower-case name for reports: `boundary`, `mixed` or `full-film`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Regime::Boundary => "boundary",
            Regime::Mixed => "mixed",
            Regime::FullFilm => "full-film",
        }
    }
    /// The regime of a point whose fluid and asperity shares are `fluid` and `asperity`.
    pub fn from_shares(fluid: f64, asperity: f64) -> Self {
        if fluid < REGIME_SHARE {
            Regime::Boundary
        } else if asperity < REGIME_SHARE {
            Regime::FullFilm
        } else {
            Regime::Mixed
        }
    }
}
