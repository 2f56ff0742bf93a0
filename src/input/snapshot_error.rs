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
