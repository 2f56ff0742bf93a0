//! Every spring scaled at once, in place: a cooling layout fades its springs with its
//! heat, and a graph far from its rest lengths (by the springs' median stretch) lets them
//! fade faster ([`Cooling::stretch_limit`](crate::config::Cooling::stretch_limit)).

use std::hash::Hash;

use euclid::default::Point2D;
use serde::{Deserialize, Serialize};

use super::RapierSceneWorld;
use crate::sanitize::{finite_or, positive_or};
use crate::world::EdgeJoint;

/// The factor on every spring's stiffness and damping, and the inputs of the last
/// [`RapierSceneWorld::set_spring_scale_by_stretch`] that chose it.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub(crate) struct SpringScale {
    /// The factor near the rest lengths (a cooling layout's `heat^spring_exponent`).
    pub(super) near: f32,
    /// The factor far from them (the heat).
    pub(super) far: f32,
    /// The median stretch from which `far` blends in (infinite: never).
    #[serde(with = "crate::sanitize::infinite_as_null")]
    pub(super) limit: f32,
    /// The factor every spring has now.
    pub(super) applied: f32,
    /// How far the factor went from `near` toward `far` (0 to 1), by the median stretch.
    pub(super) blend: f32,
    /// [`version`](RapierSceneWorld::version) when the median stretch was last read: an
    /// edit re-reads it even at unchanged factors.
    pub(super) version: u64,
}

impl Default for SpringScale {
    fn default() -> Self {
        Self {
            near: 1.0,
            far: 1.0,
            limit: f32::INFINITY,
            applied: 1.0,
            blend: 0.0,
            version: 0,
        }
    }
}

/// The springs' slots and rest lengths, kept while the world's bodies and joints stay as
/// they are, and the buffers the median stretch is read with: a graph of 250,000 edges
/// would otherwise look up 500,000 node ids each time.
#[derive(Clone, Debug, Default)]
pub(crate) struct StretchCache {
    version: Option<u64>,
    springs: Vec<(u32, u32, f32)>,
    positions: Vec<Point2D<f32>>,
    stretches: Vec<f32>,
}

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Multiplies every spring's stiffness and damping by `scale` (relative to the kind
    /// it was inserted as), in place and without waking anything; new springs take the
    /// factor too. A cooling layout passes its spring factor through
    /// [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch). Non-finite or negative values
    /// count as 0. Returns how many joints changed.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, EdgeJoint, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// world.build_bodies(
    ///     &[NodeAvatarBinding::circle(0_u32, 16.0), NodeAvatarBinding::circle(1, 16.0)],
    ///     &[snap(0, 0.0), snap(1, 300.0)],
    /// );
    /// world.insert_edge_joint(&0, &1, &EdgeJoint::default());
    /// assert_eq!(world.set_spring_scale(0.5), 1);
    /// assert_eq!(world.spring_scale(), 0.5);
    /// assert_eq!(world.edge_joint(&0, &1), Some(EdgeJoint::default()), "the kind is unscaled");
    /// ```
    pub fn set_spring_scale(&mut self, scale: f32) -> usize {
        self.set_spring_scale_by_stretch(scale, scale, f32::INFINITY)
    }

    /// Like [`set_spring_scale`](Self::set_spring_scale), choosing the factor by how far
    /// the graph is from its rest lengths: every spring is scaled by `near` while the
    /// springs' median stretch (length over rest length, read now) is at most
    /// `stretch_limit`, by `far` once it is twice that or more, and by a geometric blend
    /// of the two in between. A non-finite or non-positive limit always gives `near`.
    /// A cooling layout passes `heat^spring_exponent`, the heat and
    /// [`Cooling::stretch_limit`](crate::config::Cooling::stretch_limit). Calls with the same three
    /// values as the last are skipped unless bodies or joints changed since (the median
    /// is read again then). Returns how many joints changed.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, EdgeJoint, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// let bind = |id| NodeAvatarBinding::circle(id, 16.0);
    /// world.build_bodies(&[bind(0_u32), bind(1)], &[snap(0, 0.0), snap(1, 450.0)]);
    /// world.insert_edge_joint(&0, &1, &EdgeJoint::default()); // rest length 100
    /// // Stretched 4.5 times: half way from a limit of 3 to twice it.
    /// assert_eq!(world.set_spring_scale_by_stretch(0.04, 0.01, 3.0), 1);
    /// assert!((world.applied_spring_scale() - 0.02).abs() < 1e-6, "{}", world.applied_spring_scale());
    /// // Within 10 times its rest length: `near`.
    /// world.set_spring_scale_by_stretch(0.04, 0.01, 10.0);
    /// assert_eq!(world.applied_spring_scale(), 0.04);
    /// ```
    pub fn set_spring_scale_by_stretch(
        &mut self,
        near: f32,
        far: f32,
        stretch_limit: f32,
    ) -> usize {
        let near = finite_or(near, 0.0).max(0.0);
        let far = finite_or(far, 0.0).max(0.0);
        let limit = positive_or(stretch_limit, f32::INFINITY);
        // The median matters only between two different factors.
        let by_stretch = limit.is_finite() && near.to_bits() != far.to_bits();
        let last = self.spring_scale;
        if (near, far, limit) == (last.near, last.far, last.limit)
            && (!by_stretch || last.version == self.version)
        {
            return 0;
        }
        self.spring_scale = SpringScale {
            near,
            far,
            limit,
            version: self.version,
            ..last
        };
        let blend = if by_stretch {
            (self.median_spring_stretch() / limit - 1.0).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let scale = if blend > 0.0 {
            finite_or(blended(near, far, blend), near)
        } else {
            near
        };
        self.spring_scale.blend = blend;
        if scale.to_bits() == last.applied.to_bits() {
            return 0;
        }
        self.spring_scale.applied = scale;
        let mut changed = 0;
        for joint in &self.joints {
            if !matches!(joint.kind, EdgeJoint::Spring { .. }) {
                continue;
            }
            let Some(handle) = joint.handle else {
                // A spring applied as forces reads the factor when it pulls.
                changed += 1;
                continue;
            };
            let (Some(&ia), Some(&ib)) = (self.index.get(&joint.a), self.index.get(&joint.b))
            else {
                continue;
            };
            if let (Some(data), Some(rapier)) = (
                self.joint_data(ia, ib, &joint.kind, scale),
                self.impulse_joints.get_mut(handle, false),
            ) {
                rapier.data = data;
                changed += 1;
            }
        }
        changed
    }

    /// The median of length over rest length across the springs (0 without any).
    fn median_spring_stretch(&mut self) -> f32 {
        let mut cache = std::mem::take(&mut self.stretch);
        if cache.version != Some(self.version) {
            cache.springs.clear();
            cache.springs.extend(
                self.springs()
                    // A rest length that is not finite and positive builds a joint of rest
                    // 0 (infinitely stretched): left out, as it says nothing about the
                    // layout.
                    .filter(|spring| spring.rest_length.is_finite() && spring.rest_length > 0.0)
                    .map(|spring| (spring.a as u32, spring.b as u32, spring.rest_length)),
            );
            cache.version = Some(self.version);
        }
        cache.positions.clear();
        cache
            .positions
            .extend((0..self.slot_count()).map(|s| self.position_at(s)));
        let positions = &cache.positions;
        cache.stretches.clear();
        cache
            .stretches
            .extend(cache.springs.iter().filter_map(|&(a, b, rest_length)| {
                let length = (positions[a as usize] - positions[b as usize]).length();
                let stretch = length / rest_length;
                stretch.is_finite().then_some(stretch)
            }));
        let median = if cache.stretches.is_empty() {
            0.0
        } else {
            let mid = cache.stretches.len() / 2;
            *cache
                .stretches
                .select_nth_unstable_by(mid, f32::total_cmp)
                .1
        };
        self.stretch = cache;
        median
    }

    /// How far the last [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch)
    /// blended from its `near` factor toward its `far` one, from 0 to 1.
    pub(crate) fn spring_blend(&self) -> f32 {
        self.spring_scale.blend
    }

    /// The factor [`set_spring_scale`](Self::set_spring_scale) last set, or the `near`
    /// factor of [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch)
    /// (1 by default).
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn spring_scale(&self) -> f32 {
        self.spring_scale.near
    }

    /// The factor every spring's stiffness and damping has now: what the last
    /// [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch) chose (1 by
    /// default).
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn applied_spring_scale(&self) -> f32 {
        self.spring_scale.applied
    }
}

/// The spring scale `blend` of the way from `near` to `far`, geometrically:
/// `near^(1 - blend) × far^blend`. The one blend law of the springs' scale: the world's
/// re-tune by stretch (above) and a heated node's springs
/// ([`HeatLaw`](crate::config::cooling::HeatLaw)) both take it.
pub(crate) fn blended(near: f32, far: f32, blend: f32) -> f32 {
    near.powf(1.0 - blend) * far.powf(blend)
}
