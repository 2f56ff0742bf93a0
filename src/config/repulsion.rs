//! Many-body repulsion's settings ([`Repulsion`], with the centre pull's), read by the
//! repulsion force (`forces/many_body.rs`) and the centre pull (`forces/center.rs`).

use euclid::default::Point2D;
use serde::{Deserialize, Serialize};

/// Many-body repulsion and centre pull, applied as forces on every substep.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Repulsion {
    /// Force between two nodes `d` apart is `strength / d` (force × length). Larger
    /// values spread the graph out; springs balance it at the edge length where
    /// `stiffness × stretch = strength × neighbours / length`. Default: `430_000.0`
    /// (d3-force's many-body strength −30 for a default node of mass 4 at 60 ticks per
    /// second: `30 × 4 × 60²`).
    pub strength: f32,
    /// Barnes–Hut opening ratio: a cell of width `w` at distance `d` counts as one body
    /// when `w / d < theta`. 0 is the exact sum; larger is cheaper and coarser (see the
    /// error/time table of `docs/performance.md`). Default: `0.9` (d3-force's default).
    pub theta: f32,
    /// Distances below this count as this, so coincident nodes get a finite push.
    /// Default: `8.0`.
    pub min_distance: f32,
    /// Pull toward `center`, in force per unit of distance, so disconnected parts do not
    /// drift away for ever. Default: `0.5`.
    pub center_pull: f32,
    /// The point the centre pull aims at. Default: the origin.
    pub center: Point2D<f32>,
}

impl Default for Repulsion {
    fn default() -> Self {
        Self {
            strength: 430_000.0,
            theta: 0.9,
            min_distance: 8.0,
            center_pull: 0.5,
            center: Point2D::origin(),
        }
    }
}
