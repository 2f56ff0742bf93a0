//! Bodies whose state went non-finite: rapier quarantines (disables) them and rolls them
//! back; the world puts each back at rest where it last was valid, re-enables it and
//! reports it, so no node silently stops simulating and no NaN reaches the host.

use std::hash::Hash;

use euclid::default::Point2D;
use rapier2d::prelude::{RigidBodyHandle, Vector};

use super::{to_vector, RapierSceneWorld};

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Rapier disables bodies whose state went non-finite and rolls them back to their
    /// last valid pose. A disabled node would silently stop simulating, so re-enable it
    /// at rest and report it.
    pub(super) fn recover_quarantined(&mut self) {
        if self.pipeline.quarantine().bodies().is_empty() {
            return;
        }
        let handles: Vec<RigidBodyHandle> = self.pipeline.quarantine().bodies().to_vec();
        for handle in handles {
            let Some(body) = self.bodies.get_mut(handle) else {
                continue;
            };
            let slot = body.user_data as usize;
            let translation = body.translation();
            if !translation.is_finite() {
                let fallback = self.slots.get(slot).map_or(Point2D::origin(), |s| s.anchor);
                body.set_translation(to_vector(fallback), false);
            }
            body.set_linvel(Vector::ZERO, false);
            body.set_enabled(true);
            self.changes.mark(slot, self.slots.len());
            if let Some(id) = self.ids.get(slot) {
                self.recovered.push(id.clone());
            }
        }
    }

    /// Drains the nodes whose bodies went non-finite and were recovered since the last
    /// call.
    pub fn take_recovered_nodes(&mut self) -> Vec<N> {
        std::mem::take(&mut self.recovered)
    }
}
