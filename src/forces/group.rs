//! Groups held together and kept apart ([`NodeForces::group`](crate::NodeForces::group),
//! [`GroupForce`](crate::config::GroupForce)): every grouped node is pulled toward its group's
//! centre of mass, critically damped against the group's mean velocity (so a group
//! moves as a whole freely) and solved implicitly with the springs like the other pulls (`targets.rs`);
//! with a separation, each node is pushed from the centre of every other group in
//! proportion to that group's size, a many-body force between groups, `groups²` per
//! substep. Every member counts toward its group's centre and mean velocity, pinned and
//! dragged ones too (a group follows a dragged member); only awake dynamic members are
//! pulled.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use super::targets::{add_pull, pull_constants, NodeTargets};
use super::{BodyForce, ForceContext, ForceSums};
use crate::config::RapierLayoutConfig;
use crate::sanitize::finite_or;

/// One group's centre of mass, mean velocity and size this substep.
#[derive(Clone, Copy, Debug)]
struct Centre {
    point: Point2D<f32>,
    velocity: Vector2D<f32>,
    size: f32,
}

/// Pulls every grouped node toward its group's centre; pushes groups apart.
#[derive(Debug, Default)]
pub(crate) struct GroupPull {
    centres: Vec<Centre>,
}

impl<N: Clone + Eq + Hash> BodyForce<N> for GroupPull {
    fn is_active(&self, _: &RapierLayoutConfig, targets: &NodeTargets) -> bool {
        !targets.groups.is_empty()
    }

    fn apply(&mut self, frame: &ForceContext<'_, N>, out: &mut ForceSums) {
        let config = frame.config.groups;
        let pull = finite_or(config.pull, 0.0).max(0.0);
        let separation = finite_or(config.separation, 0.0).max(0.0);
        self.centres.clear();
        for group in &frame.targets.groups {
            let (mut sum, mut momentum, mut mass) = (Vector2D::zero(), Vector2D::zero(), 0.0);
            for &s in &group.members {
                let m = frame.world.mass_at(s as usize);
                sum += frame.points[s as usize].to_vector() * m;
                momentum += frame.velocities[s as usize] * m;
                mass += m;
            }
            let mass = if mass > 0.0 { mass } else { 1.0 };
            self.centres.push(Centre {
                point: (sum / mass).to_point(),
                velocity: momentum / mass,
                size: group.members.len() as f32,
            });
        }
        let scale = frame.world.applied_spring_scale();
        // d3-force's many-body units: a push of `strength / distance` per 1/60 s tick.
        let push = separation * 3600.0 * frame.heat;
        for (g, group) in frame.targets.groups.iter().enumerate() {
            let centre = self.centres[g];
            let mut apart = Vector2D::zero();
            if push > 0.0 {
                for (h, other) in self.centres.iter().enumerate() {
                    let d = centre.point - other.point;
                    let d2 = d.square_length();
                    if h != g && d2 > 1e-6 {
                        apart += d * (push * other.size / d2);
                    }
                }
            }
            for &slot in &group.members {
                let s = slot as usize;
                if !frame.pushed[s] {
                    continue;
                }
                let m = frame.world.mass_at(s);
                let push = apart * m;
                if push.is_finite() {
                    out.forces[s] += push;
                }
                if pull > 0.0 && group.members.len() > 1 {
                    let constants = pull_constants(pull, m, scale);
                    let offset = centre.point - frame.points[s];
                    let v = frame.velocities[s] - centre.velocity;
                    let distance = offset.length();
                    if distance > 1e-3 && distance.is_finite() {
                        let toward = offset / distance;
                        add_pull(out, s, constants, frame.dt, toward, distance, v.dot(toward));
                    }
                }
            }
        }
    }
}
