//! Many-body repulsion as a force on bodies: the force, configured by
//! [`Repulsion`] (with the centre pull's), that builds a Barnes–Hut tree over every body each
//! substep and pushes the awake dynamic ones. The tree is `forces/barnes_hut`; the
//! centre pull is `forces/center.rs`.

use euclid::default::{Point2D, Vector2D};

use super::barnes_hut::ManyBody;
use crate::config::Repulsion;
use crate::sanitize::finite_or;

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
