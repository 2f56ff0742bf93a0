//! Contact events: what the world reports and how it collects them from rapier without
//! channels.

use std::sync::Mutex;

use rapier2d::prelude::{
    ColliderSet, CollisionEvent, ContactPair, EventHandler, Real, RigidBodySet, SoftBodySet,
    SoftBodyTearEvent,
};
use serde::{Deserialize, Serialize};

/// Something that happened in the world, named by node ids.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
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
