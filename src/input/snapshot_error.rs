//! What can be wrong with a snapshot handed back to
//! [`RapierLayout::restore`](crate::RapierLayout::restore).

use std::fmt;

/// Why [`RapierLayout::restore`](crate::RapierLayout::restore) refused a snapshot. The
/// layout is left as it was.
#[derive(Clone, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum SnapshotError {
    /// The snapshot was written in another format than this build reads
    /// ([`LayoutSnapshot::FORMAT`](crate::LayoutSnapshot::FORMAT)).
    Format {
        /// The snapshot's format.
        found: u32,
        /// The format this build reads.
        expected: u32,
    },
    /// The snapshot's parts do not agree with each other (edited by hand, or damaged):
    /// which part, in words.
    Inconsistent(String),
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SnapshotError::Format { found, expected } => write!(
                f,
                "snapshot format {found}, this build reads format {expected}"
            ),
            SnapshotError::Inconsistent(what) => write!(f, "inconsistent snapshot: {what}"),
        }
    }
}

impl std::error::Error for SnapshotError {}

/// The largest count a snapshot may hold (calls, rebuilds, world versions, serials):
/// 2⁵³, which a session counting once a microsecond reaches in 285 years. A larger one
/// was damaged, and counting on from it would overflow.
pub(crate) const COUNTER_LIMIT: u64 = 1 << 53;

/// `Err` naming the first of `counters` above [`COUNTER_LIMIT`].
pub(crate) fn check_counters(counters: &[(u64, &str)]) -> Result<(), SnapshotError> {
    match counters.iter().find(|(value, _)| *value > COUNTER_LIMIT) {
        Some((value, name)) => Err(SnapshotError::Inconsistent(format!(
            "{name} is {value}, beyond any session's count"
        ))),
        None => Ok(()),
    }
}
