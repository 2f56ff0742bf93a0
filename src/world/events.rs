//! Contact events: what the world reports ([`SceneEvent`]), how it collects them from
//! rapier without channels, and how a host drains them. Worlds built without events
//! have no collector and no handler runs.

use std::hash::Hash;
use std::sync::Mutex;

use rapier2d::prelude::{
    ColliderHandle, ColliderSet, CollisionEvent, ContactPair, EventHandler, Real, RigidBodySet,
    SoftBodySet, SoftBodyTearEvent,
};
use serde::{Deserialize, Serialize};

use super::{RapierSceneWorld, MAX_PENDING_EVENTS};

/// Something that happened in the world, named by node ids.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
pub enum SceneEvent<N> {
    /// Two nodes' colliders started touching.
    ContactBegin {
        /// One node.
        a: N,
        /// The other node.
        b: N,
    },
    /// Two nodes' colliders stopped touching.
    ContactEnd {
        /// One node.
        a: N,
        /// The other node.
        b: N,
    },
}

/// Collects rapier's collision events during a step. Rapier calls the handler through a
/// shared reference (and from worker threads with `parallel`), hence the mutex; it is
/// uncontended, and only exists in worlds that report events.
#[derive(Default)]
pub(crate) struct CollisionCollector {
    events: Mutex<Vec<CollisionEvent>>,
}

impl CollisionCollector {
    /// Takes the events collected so far, leaving the buffer's capacity in place.
    pub(crate) fn drain_into(&mut self, out: &mut Vec<CollisionEvent>) {
        let events = self
            .events
            .get_mut()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        out.append(events);
    }
}

impl EventHandler for CollisionCollector {
    fn handle_collision_event(
        &self,
        _bodies: &RigidBodySet,
        _colliders: &ColliderSet,
        event: CollisionEvent,
        _contact_pair: Option<&ContactPair>,
    ) {
        self.events
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .push(event);
    }

    fn handle_contact_force_event(
        &self,
        _dt: Real,
        _bodies: &RigidBodySet,
        _colliders: &ColliderSet,
        _contact_pair: &ContactPair,
        _total_force_magnitude: Real,
    ) {
    }

    fn handle_soft_body_tear_event(&self, _soft_bodies: &SoftBodySet, _event: &SoftBodyTearEvent) {}
}

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    pub(super) fn collect_events(&mut self) {
        let Some(collector) = self.collector.as_mut() else {
            return;
        };
        collector.drain_into(&mut self.raw_events);
        for event in self.raw_events.drain(..) {
            let node_of = |handle: ColliderHandle| {
                let body = self.colliders.get(handle)?.parent()?;
                let slot = self.bodies.get(body)?.user_data as usize;
                self.ids.get(slot).cloned()
            };
            let (Some(a), Some(b)) = (node_of(event.collider1()), node_of(event.collider2()))
            else {
                continue;
            };
            if self.events.len() >= MAX_PENDING_EVENTS {
                self.events.pop_front();
                self.dropped_events += 1;
            }
            self.events.push_back(if event.started() {
                SceneEvent::ContactBegin { a, b }
            } else {
                SceneEvent::ContactEnd { a, b }
            });
        }
    }

    /// Drains the contact events recorded since the last call, oldest first. Empty when
    /// the world does not report events.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld, SceneEvent};
    /// let mut world = RapierSceneWorld::new();
    /// let snaps = [
    ///     NodeSnapshot { id: 0_u32, position: Point2D::new(0.0, 0.0), radius: 16.0, pinned: false },
    ///     NodeSnapshot { id: 1, position: Point2D::new(20.0, 0.0), radius: 16.0, pinned: false },
    /// ];
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0), NodeAvatarBinding::circle(1, 16.0)], &snaps);
    /// world.step(Vector2D::zero());
    /// assert!(world.read_events().iter().any(|e| matches!(e, SceneEvent::ContactBegin { .. })));
    /// assert!(world.read_events().is_empty(), "drained");
    /// ```
    pub fn read_events(&mut self) -> Vec<SceneEvent<N>> {
        self.events.drain(..).collect()
    }

    /// How many events were dropped because more than [`MAX_PENDING_EVENTS`] waited.
    pub fn dropped_event_count(&self) -> u64 {
        self.dropped_events
    }
}
