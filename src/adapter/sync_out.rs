//! Sync out: each free node's displacement during this call, what the host was told
//! (so the next call can tell a host edit from a host that added the deltas), and the
//! motion figures the rest tracker reads.

use std::hash::Hash;

use euclid::default::Point2D;

use super::matching::NO_SLOT;
use super::RapierLayout;
use crate::input::scene::CanvasSceneInput;
use crate::layout::{DeltaMap, IdHasher};

/// What one call reports.
#[derive(Debug)]
pub(super) struct FrameReport<N> {
    /// Per free node, the displacement this call produced.
    pub(super) deltas: DeltaMap<N>,
    /// The fastest awake dynamic body's speed, in world units per second.
    pub(super) max_speed: f32,
    /// How many dynamic bodies are awake.
    pub(super) awake: usize,
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Reads every dynamic body the scene names. `awake_before` is rapier's count of
    /// simulated bodies before the step: when it was 0 and still is, nothing moved and
    /// no body needs reading.
    pub(super) fn sync_out(
        &mut self,
        scene: &CanvasSceneInput<N>,
        awake_before: usize,
    ) -> FrameReport<N> {
        let epsilon = self.config.delta_epsilon.max(0.0);
        let epsilon_sq = epsilon * epsilon;
        // Allocated on the first delta: a resting layout returns an empty map for free.
        let mut report = FrameReport {
            deltas: DeltaMap::with_hasher(IdHasher::default()),
            max_speed: 0.0,
            awake: 0,
        };
        let Some(world) = self.world.as_mut() else {
            return report;
        };
        if awake_before == 0 && world.awake_body_count() == 0 {
            return report;
        }
        let mut max_speed_sq: f32 = 0.0;
        for (node, m) in scene.nodes.iter().zip(self.matching.matches()) {
            if m.slot == NO_SLOT {
                continue;
            }
            let s = m.slot as usize;
            let body = world.body_at(s);
            if !body.is_dynamic() {
                continue;
            }
            if !body.is_sleeping() {
                max_speed_sq = max_speed_sq.max(body.linvel().length_squared());
                report.awake += 1;
            }
            let t = body.translation();
            let anchor = world.anchor_at(s);
            let delta = Point2D::new(t.x, t.y) - anchor;
            if delta.square_length() > epsilon_sq && delta.is_finite() {
                // The host adds the delta with the same f32 addition.
                world.host_at_mut(s).told = anchor + delta;
                if report.deltas.capacity() == 0 {
                    report.deltas.reserve(scene.nodes.len());
                }
                report.deltas.insert(node.id.clone(), delta);
            }
        }
        report.max_speed = max_speed_sq.sqrt();
        report
    }
}
