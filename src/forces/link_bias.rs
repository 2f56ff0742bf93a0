//! Link bias: d3-force's uneven share of a link's pull between its two ends, added as
//! forces on top of the (even, physical) spring joints.
//!
//! A spring pulls both ends with the same force `k x`. d3-force's link instead moves
//! its source by `(1 - b)` and its target by `b` of the correction, `b` being the
//! source's share of the two degrees, so the end with fewer neighbours moves more. With
//! [`RapierLayoutConfig::link_bias`](crate::RapierLayoutConfig::link_bias) `g`, end `a`
//! of a spring gets an extra `g (d_b - d_a) / (d_a + d_b) · k x` toward `b`, and end `b`
//! the same force vector: at `g = 1` end `a` feels `2 d_b / (d_a + d_b) · k x`, d3's
//! share of twice the spring force.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use super::{BodyForce, ForceContext};
use crate::config::RapierLayoutConfig;
use crate::sanitize::finite_or;
use crate::world::RapierSceneWorld;

/// One spring, as the bias reads it.
#[derive(Clone, Copy, Debug)]
struct BiasedSpring {
    a: u32,
    b: u32,
    /// `(d_b - d_a) / (d_a + d_b)`: the extra share end `a` takes (end `b` takes its
    /// negative, along the other direction, which is the same force vector).
    share: f32,
    rest_length: f32,
    stiffness: f32,
    /// What the timestep resolves: the joint's own cap, so the extra force is never
    /// stiffer than the spring.
    cap: f32,
}

/// The springs of a world with their degree shares, rebuilt when the world's bodies or
/// joints change.
#[derive(Clone, Debug, Default)]
pub(crate) struct LinkBias {
    version: Option<u64>,
    springs: Vec<BiasedSpring>,
    degrees: Vec<u32>,
}

impl<N: Clone + Eq + Hash> BodyForce<N> for LinkBias {
    fn is_active(&self, config: &RapierLayoutConfig) -> bool {
        finite_or(config.link_bias, 0.0) > 0.0
    }

    fn apply(&mut self, frame: &ForceContext<'_, N>, forces: &mut Vec<Vector2D<f32>>) {
        self.add_forces(frame.world, frame.config.link_bias, frame.points, forces);
    }

    fn reset(&mut self) {
        // A new world counts its versions from 0 again.
        *self = Self::default();
    }
}

impl LinkBias {
    /// Adds `gain` (clamped to `[0, 1]`) times the bias of every spring to `forces`,
    /// indexed by slot like `points`, the bodies' positions. Springs are scaled by the
    /// factor the world's joints have now.
    fn add_forces<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        gain: f32,
        points: &[Point2D<f32>],
        forces: &mut [Vector2D<f32>],
    ) {
        let gain = if gain.is_finite() {
            gain.clamp(0.0, 1.0)
        } else {
            0.0
        };
        if gain == 0.0 {
            return;
        }
        if self.version != Some(world.version()) {
            self.rebuild(world);
        }
        let scale = world.applied_spring_scale();
        for spring in &self.springs {
            let (a, b) = (spring.a as usize, spring.b as usize);
            let (Some(&pa), Some(&pb)) = (points.get(a), points.get(b)) else {
                continue;
            };
            let d = pb - pa;
            let length = d.length();
            if !(length > 1e-3 && length.is_finite()) {
                continue;
            }
            let k = (spring.stiffness * scale).min(spring.cap);
            let f = d * (gain * spring.share * k * (length - spring.rest_length) / length);
            if f.is_finite() {
                forces[a] += f;
                forces[b] += f;
            }
        }
    }

    fn rebuild<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        self.degrees.clear();
        self.degrees.resize(world.slot_count(), 0);
        self.springs.clear();
        for (a, b, rest_length, stiffness, cap) in world.springs() {
            self.degrees[a] += 1;
            self.degrees[b] += 1;
            self.springs.push(BiasedSpring {
                a: a as u32,
                b: b as u32,
                share: 0.0,
                rest_length,
                stiffness,
                cap,
            });
        }
        // Shares once every degree is counted.
        for spring in &mut self.springs {
            let da = self.degrees[spring.a as usize] as f32;
            let db = self.degrees[spring.b as usize] as f32;
            spring.share = (db - da) / (da + db);
        }
        self.version = Some(world.version());
    }
}
