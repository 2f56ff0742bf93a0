//! What the forces carry from one call to the next, as a snapshot keeps it.

use std::hash::Hash;

use serde::{Deserialize, Serialize};

use super::Forces;
use crate::forces::targets::NodeTargets;
use crate::stress::{RestBias, StressForce};

#[cfg(doc)]
use crate::input::snapshot_error::SnapshotError;

/// What the forces carry from one call to the next, as a snapshot keeps it: the host's
/// per-node forces as the last call read them, whether forces are on the bodies, the
/// disk separation's warm-start impulses and the stress model with its held pivot sums.
/// Everything else they keep is a cache built again from the world.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct SavedForces {
    targets: NodeTargets,
    applied: bool,
    contacts: Vec<(u32, u32, f32)>,
    contacts_version: Option<u64>,
    /// The stress model and its pivot terms' held sums (empty without one).
    #[serde(default)]
    stress: StressForce,
    /// The springs' pull at the last cold stop (empty without one).
    #[serde(default)]
    rest_bias: RestBias,
}

impl<N: Clone + Eq + Hash> Forces<N> {
    /// What the next call needs of these forces to continue bit for bit.
    pub(crate) fn save(&self) -> SavedForces {
        let (contacts, contacts_version) = self.collide.warm_start_state();
        SavedForces {
            targets: self.targets.clone(),
            applied: self.applied,
            contacts,
            contacts_version,
            stress: self.registry.stress.clone(),
            rest_bias: self.rest_bias.clone(),
        }
    }

    /// Forces that continue where `saved` was taken (their caches empty), once each
    /// part has checked what it reads.
    ///
    /// # Errors
    /// The part that does not agree, for [`SnapshotError::Inconsistent`].
    pub(crate) fn from_saved(mut saved: SavedForces) -> Result<Self, String> {
        saved.targets.restore_index()?;
        saved.stress.check()?;
        saved.rest_bias.check()?;
        let mut forces = Self {
            targets: saved.targets,
            applied: saved.applied,
            rest_bias: saved.rest_bias,
            ..Self::default()
        };
        forces.registry.stress = saved.stress;
        forces
            .collide
            .set_warm_start_state(saved.contacts, saved.contacts_version)?;
        Ok(forces)
    }
}
