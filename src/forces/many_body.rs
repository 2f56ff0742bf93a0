//! Many-body repulsion as a force on bodies: the force, configured by
//! [`Repulsion`] (with the centre pull's), that builds a Barnes–Hut tree over every body each
//! substep and pushes the awake dynamic ones. The tree is `forces/barnes_hut`; the
//! centre pull is `forces/center.rs`.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use super::barnes_hut::ManyBody;
use super::targets::NodeTargets;
use super::{BodyForce, ForceSums, Lane, SpareFrame};
use crate::config::{RapierLayoutConfig, Repulsion};
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
    pub(crate) fn push(
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

impl<N: Clone + Eq + Hash> BodyForce<N> for ManyBodyForce {
    fn is_active(&self, config: &RapierLayoutConfig, _: &NodeTargets) -> bool {
        config.repulsion.is_some()
    }

    /// From positions alone, so beside the springs.
    fn lane(&self) -> Lane {
        Lane::Spare
    }

    /// Writes every body's entry of `out.forces`: the first force of the registry.
    fn apply_spare(&mut self, frame: &SpareFrame<'_>, out: &mut ForceSums) {
        if let Some(repulsion) = &frame.config.repulsion {
            self.push(
                repulsion,
                frame.heat,
                frame.points,
                frame.pushed,
                &mut out.forces,
            );
        }
    }
}
