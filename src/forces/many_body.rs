//! Many-body repulsion as a force on bodies: [`Repulsion`] (its configuration, with the
//! centre pull's) and the force that builds a Barnes–Hut tree over every body each
//! substep and pushes the awake dynamic ones. The tree is `forces/barnes_hut`; the
//! centre pull is `forces/center.rs`.

use euclid::default::{Point2D, Vector2D};
use serde::{Deserialize, Serialize};

use super::barnes_hut::ManyBody;
use crate::sanitize::finite_or;

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

/// Every body pushes every other: `strength × heat / d`, through the tree.
#[derive(Debug, Default)]
pub(crate) struct ManyBodyForce {
    tree: ManyBody,
}

impl ManyBodyForce {
    /// Writes each body's repulsion at `heat` into `forces` (zero for the bodies not
    /// `pushed`), from a tree built over every point. It writes every entry, so it
    /// comes before the forces that add to them.
    pub(crate) fn apply(
        &mut self,
        repulsion: &Repulsion,
        heat: f32,
        points: &[Point2D<f32>],
        pushed: &[bool],
        forces: &mut Vec<Vector2D<f32>>,
    ) {
        self.tree.build(points);
        let strength = finite_or(repulsion.strength, 0.0) * heat;
        let theta = finite_or(repulsion.theta, 0.0).max(0.0);
        let min_distance = finite_or(repulsion.min_distance, 1.0).max(1e-3);
        self.tree
            .forces(strength, theta, min_distance, |s| pushed[s], forces);
    }
}
