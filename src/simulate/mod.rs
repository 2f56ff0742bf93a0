//! One substep's own physics beside rapier's: the forces of `forces/` run in the order
//! of their registry (`registry.rs`), each body's sum taken through the implicit step
//! on its own stiffness (`combine.rs`) and set on the body, the disk separation's passes
//! (`contacts/`), and a stress layout's balance at rest (`stress/rest_bias.rs`). What of
//! it a snapshot keeps is `saved.rs`.
//!
//! [`Forces::apply`] runs before each rapier step, [`Forces::settle`] after it.

use std::hash::Hash;

use euclid::default::Point2D;
use rapier2d::prelude::Vector;

use crate::config::cooling::HeatLaw;
use crate::config::{ContactSoftness, RapierLayoutConfig};
use crate::contacts::Collide;
use crate::forces::targets::NodeTargets;
use crate::forces::{Bodies, ForceSums};
use crate::profile::{StepProfile, Stopwatch};
use crate::stress::{RestBias, StressForce};
use crate::world::RapierSceneWorld;

mod combine;
mod registry;
mod saved;

use registry::Registry;
pub(crate) use saved::SavedForces;

/// The forces of a layout, with the buffers one substep sums them in.
pub(crate) struct Forces<N> {
    /// Every force, in the order the sums add up.
    registry: Registry,
    bodies: Bodies,
    sums: ForceSums,
    collide: Collide,
    /// The host's per-node forces for this call (`adapter/node_forces.rs` fills it).
    pub(crate) targets: NodeTargets,
    /// Whether the last substep set forces on bodies: rapier keeps a body's force until
    /// it is reset, so when no force is active any more they are cleared once.
    applied: bool,
    /// A stress layout's springs at its last cold stop (`stress/rest_bias.rs`).
    rest_bias: RestBias,
    /// Where the calls' time went, while the host measures it.
    pub(crate) profile: Option<StepProfile>,
    /// Whether the hard constraints keep every body apart this call (a flow in layers
    /// with every body in a layer): the disk contacts would find no pair, and are not
    /// searched for. Set before each call's substeps.
    pub(crate) held_apart: bool,
    _ids: std::marker::PhantomData<fn() -> N>,
}

impl<N> Default for Forces<N> {
    fn default() -> Self {
        Self {
            registry: Registry::default(),
            bodies: Bodies::default(),
            sums: ForceSums::default(),
            collide: Collide::default(),
            targets: NodeTargets::default(),
            applied: false,
            rest_bias: RestBias::default(),
            profile: None,
            held_apart: false,
            _ids: std::marker::PhantomData,
        }
    }
}

impl<N> std::fmt::Debug for Forces<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Forces")
            .field("applied", &self.applied)
            .finish_non_exhaustive()
    }
}

impl<N: Clone + Eq + Hash> Forces<N> {
    /// The stress terms, for the start that hands them the model it built.
    pub(crate) fn stress_mut(&mut self) -> &mut StressForce {
        &mut self.registry.stress
    }

    /// Whether `config` asks for any force on bodies, or for the layout's own disk
    /// separation.
    pub(crate) fn any_active(&mut self, config: &RapierLayoutConfig) -> bool {
        config.contacts.separates_disks() || self.registry.any_active::<N>(config, &self.targets)
    }

    /// What the forces keep of every body's position and sleep, if anything
    /// ([`Bodies::kept`]).
    pub(crate) fn kept_bodies(&self) -> Option<(&[Point2D<f32>], &[bool])> {
        self.bodies.kept()
    }

    /// Before the world forgets its changes (`sync_out`): reads the changed bodies into
    /// what the forces keep of every body.
    pub(crate) fn catch_up(&mut self, world: &RapierSceneWorld<N>) {
        self.bodies.catch_up(world);
    }

    /// Clears the forces the last substeps left on bodies, once, after the last active
    /// force went away (a host's last pull removed, a configuration without forces):
    /// without it a body would keep being pushed by a force nobody applies.
    pub(crate) fn release(&mut self, world: &mut RapierSceneWorld<N>) {
        if !std::mem::take(&mut self.applied) {
            return;
        }
        for s in 0..world.slot_count() {
            // NOTE: read first: a mutable access marks the body as modified for rapier.
            if world.body_at(s).user_force() != Vector::ZERO {
                world.body_at_mut(s).reset_forces(false);
            }
        }
    }

    /// Forgets every force's cache (the world was dropped or built anew).
    pub(crate) fn reset(&mut self) {
        self.targets = NodeTargets::default();
        self.bodies.forget();
        self.collide.forget_shapes();
        self.applied = false;
        for force in self.registry.each::<N>() {
            force.reset();
        }
        // A new world counts its versions from 0 again.
        self.rest_bias = crate::stress::RestBias::default();
    }

    /// Sets every awake dynamic body's force to the sum of the active forces at `heat`
    /// for a substep of `dt` seconds, then (with the layout's own disk separation) the
    /// velocity changes that keep disks apart. Skipped while nothing is awake, so a
    /// resting layout stays cheap. Call [`settle`](Self::settle) after the step.
    pub(crate) fn apply(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        law: HeatLaw,
        contacts: ContactSoftness,
        dt: f32,
    ) {
        if !world.may_move() {
            return;
        }
        self.applied = true;
        let heat = law.alpha;
        let n = world.slot_count();
        let watch = Stopwatch::start(&self.profile);
        self.bodies.gather(world);
        let hold_cold = self.rest_bias.holds(world, n);
        self.sum_forces(world, config, heat, dt, hold_cold);
        watch.stop(&mut self.profile, |p| &mut p.forces);
        self.rest_bias.take_from(
            world,
            &self.bodies.pushed,
            &mut self.sums.springs,
            &mut self.sums.forces,
        );
        let separate =
            config.contacts.separates_disks() && world.contacts_enabled() && !self.held_apart;
        self.combine(world, law, separate.then_some(dt));
        if separate {
            let watch = Stopwatch::start(&self.profile);
            self.collide.resolve(world, &self.bodies, contacts, dt);
            watch.stop(&mut self.profile, |p| &mut p.contacts);
        }
        self.put_on_bodies(world, separate);
    }

    /// Forgets the rest's balance: the whole layout is laid out again.
    pub(crate) fn forget_rest(&mut self) {
        self.rest_bias = crate::stress::RestBias::default();
    }

    /// Before the world halts: projects the overlaps the disk separation still holds
    /// apart on positions. Returns the largest distance a body moved (world units).
    pub(crate) fn part_overlaps(&mut self, world: &mut RapierSceneWorld<N>) -> f32 {
        self.collide.part_overlaps(world)
    }

    /// After the step: what the disk separation does once the bodies have moved.
    pub(crate) fn settle(&mut self, world: &mut RapierSceneWorld<N>, dt: f32) {
        let watch = Stopwatch::start(&self.profile);
        self.collide.relax(world, dt);
        watch.stop(&mut self.profile, |p| &mut p.contacts);
    }
}
