//! Pulls toward a target x or y per node, d3-force's `forceX` and `forceY`
//! ([`NodeForces::x`](crate::NodeForces::x), [`NodeForces::y`](crate::NodeForces::y)):
//! a timeline puts x at a date, layers put y at a depth, and the rest of the layout
//! works along the free axis. Each pull is a spring to the target line, critically
//! damped along its axis and solved implicitly (see `targets.rs`), scaled by the
//! cooling like the edge springs so the balance between them holds at every heat.

use std::hash::Hash;

use euclid::default::Vector2D;

use super::targets::{add_pull, pull_constants, pulled_bodies, NodeTargets};
use super::{BodyForce, ForceContext, ForceSums};
use crate::config::RapierLayoutConfig;

/// Pulls the nodes that have an x or y target toward it.
#[derive(Debug, Default)]
pub(crate) struct PositionPull;

impl<N: Clone + Eq + Hash> BodyForce<N> for PositionPull {
    fn is_active(&self, _: &RapierLayoutConfig, targets: &NodeTargets) -> bool {
        !targets.pulled.is_empty()
    }

    fn apply(&mut self, frame: &ForceContext<'_, N>, out: &mut ForceSums) {
        let scale = frame.world.applied_spring_scale();
        for (s, forces, m) in pulled_bodies(frame) {
            let (p, v) = (frame.points[s], frame.velocities[s]);
            let axes = [
                (forces.x, Vector2D::new(1.0, 0.0), p.x, v.x),
                (forces.y, Vector2D::new(0.0, 1.0), p.y, v.y),
            ];
            for (target, axis, at, speed) in axes {
                if let Some(t) = target {
                    let pull = pull_constants(t.strength, m, scale);
                    add_pull(out, s, pull, frame.dt, axis, t.value - at, speed);
                }
            }
        }
    }
}
