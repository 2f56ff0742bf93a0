//! Pulls toward a ring per node, d3-force's `forceRadial`
//! ([`NodeForces::ring`](crate::NodeForces::ring)): rings by category, distance from a
//! focus node. The pull acts along the line from the ring's centre through the node,
//! critically damped along it and solved implicitly with the springs (`targets.rs`), scaled by the
//! cooling like the edge springs; the node moves freely around the ring.

use std::hash::Hash;

use super::targets::{add_pull, pull_constants, pulled_bodies, NodeTargets};
use super::{BodyForce, ForceContext, ForceSums};
use crate::config::RapierLayoutConfig;

/// Pulls the nodes that have a ring toward it.
#[derive(Debug, Default)]
pub(crate) struct RadialPull;

impl<N: Clone + Eq + Hash> BodyForce<N> for RadialPull {
    fn is_active(&self, _: &RapierLayoutConfig, targets: &NodeTargets) -> bool {
        !targets.pulled.is_empty()
    }

    fn apply(&mut self, frame: &ForceContext<'_, N>, out: &mut ForceSums) {
        let scale = frame.world.applied_spring_scale();
        for (s, forces, m) in pulled_bodies(frame) {
            let Some(ring) = forces.ring else {
                continue;
            };
            let offset = frame.points[s] - ring.center;
            let distance = offset.length();
            if !(distance > 1e-3 && distance.is_finite()) {
                // At the centre every direction is as good: wait for a push.
                continue;
            }
            let outward = offset / distance;
            let pull = pull_constants(ring.strength, m, scale);
            let speed = frame.velocities[s].dot(outward);
            add_pull(
                out,
                s,
                pull,
                frame.dt,
                outward,
                ring.radius - distance,
                speed,
            );
        }
    }
}
