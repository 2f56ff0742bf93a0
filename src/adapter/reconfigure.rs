//! Configuration changes between calls, and dropping the world: what a changed
//! [`RapierLayoutConfig`] costs. Material, shape and collision changes drop the world
//! (the next call builds a new one, losing all motion); joint changes replace the joints
//! in place; everything else takes effect at once.

use std::hash::Hash;

use super::heat::Rest;
use super::RapierLayout;
use crate::config::{RapierLayoutConfig, SpringModel, StressStart};
use crate::world::WorldOptions;

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Applies what changed in [`RapierLayout::config`] since the world was built.
    /// Returns whether anything changed: a new configuration is a disturbance, since it
    /// may move what was at rest.
    pub(super) fn apply_config_changes(&mut self) -> bool {
        let Some(applied) = &self.built.applied else {
            return false;
        };
        if *applied == self.config {
            return false;
        }
        let structural = applied.material != self.config.material
            || applied.contacts.rapier_colliders() != self.config.contacts.rapier_colliders()
            || applied.contacts.events != self.config.contacts.events
            || applied.default_radius.to_bits() != self.config.default_radius.to_bits();
        if self.forces.any_active(applied) && !self.forces.any_active(&self.config) {
            // Forces stay on bodies until reset: drop the last ones.
            if let Some(world) = self.world.as_mut() {
                world.reset_forces();
            }
        }
        if applied.cooling.is_some() != self.config.cooling.is_some() {
            // A schedule starts hot; without one the springs have their full stiffness.
            self.heat.state.alpha = 1.0;
            if let Some(world) = self.world.as_mut() {
                world.set_spring_scale(1.0);
            }
        }
        // The layers turned off: a layered picture is no stress layout, and the forces
        // settling from it tangle (`tests/regression_layers_off_starts_anew.rs`). The
        // old world stays until the new one is built from it (drags, unusable nodes).
        let start_again = leaves_layers(applied, &self.config);
        if structural || start_again {
            if structural {
                self.world = None;
            }
            self.built.topology_hash = 0;
            self.built.start_again |= start_again;
        } else if applied.edge_joint != self.config.edge_joint
            || applied.springs.weight != self.config.springs.weight
            || applied.springs.model != self.config.springs.model
            || applied.springs.degree_exponent.to_bits()
                != self.config.springs.degree_exponent.to_bits()
        {
            if let Some(world) = self.world.as_mut() {
                world.clear_edge_joints();
                world.set_springs_as_forces(self.config.springs.model == SpringModel::Forces);
            }
            // Forces the topology pass to re-insert every joint.
            self.built.topology_hash = 0;
            self.matching.forget_edges();
        }
        self.built.applied = Some(self.config.clone());
        true
    }

    /// The scene became empty: no world until the next non-empty scene.
    pub(super) fn drop_world(&mut self) {
        self.world = None;
        self.built.topology_hash = 0;
        self.built.applied = None;
        self.matching.forget_edges();
        self.heat.rest = Rest::default();
        self.heat.state.halted = false;
        self.forces.reset();
    }

    /// What the world models under this configuration.
    pub(super) fn world_options(&self) -> WorldOptions {
        WorldOptions {
            collisions: self.config.contacts.rapier_colliders(),
            contact_events: self.config.contacts.events,
        }
    }
}

/// Whether `config` turns off the layers `applied` held, on a stress layout that makes
/// its own start: the next world starts anew, as the first one did.
fn leaves_layers(applied: &RapierLayoutConfig, config: &RapierLayoutConfig) -> bool {
    let layered = |c: &RapierLayoutConfig| c.flow.is_some_and(|f| f.layered());
    let starts = config
        .stress
        .is_some_and(|s| s.start == StressStart::Global);
    layered(applied) && !layered(config) && starts
}
