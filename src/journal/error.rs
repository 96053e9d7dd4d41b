//! The errors of the journal-bearing table ([`super::table`]).

/// Errors of the journal-bearing table.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum JournalError {
    /// The length-to-diameter ratio is not a positive finite number.
    #[error("journal bearing: the length-to-diameter ratio L/D = B/(2R) = {value} (dimensionless) must be positive and finite")]
    LengthToDiameter {
        /// L/D given.
        value: f64,
    },
    /// A Reynolds solve failed (not reachable for a valid L/D; a guard).
    #[error(transparent)]
    Solve(#[from] super::reynolds::SolveError),
    /// The solved S(ε) was not strictly decreasing (not reachable; a guard of the table).
    #[error("journal bearing: the solved Sommerfeld numbers are not strictly decreasing in the eccentricity ratio at L/D = {length_to_diameter}")]
    NotMonotone {
        /// L/D of the table.
        length_to_diameter: f64,
    },
}
