//! What the hard constraints and a flow report to the host: the edges a flow leaves
//! free and the constraints a call could not hold. The constraints themselves are
//! compiled and held in `constraints/`; the host's pins and drags reach them in stage 4;
//! at the cold stop they settle here, by turns with the overlaps' parting.

use std::hash::Hash;

use super::node_forces::hold_locked_axes;
use super::RapierLayout;
use crate::profile::Stopwatch;

/// At the cold stop: the most rounds of constraint settling and overlap parting.
const HALT_ROUNDS: usize = 16;

/// The most rounds of passes one settling of the constraints takes.
const SETTLE_ROUNDS: usize = 64;

/// A parting that moved no body farther than this (world units) leaves the rounds.
const PARTED: f32 = 0.01;

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// After the call's substeps: at the cold stop, settles the constraints and parts
    /// the overlaps they leave, by turns, until the parting moves nothing (at most
    /// [`HALT_ROUNDS`]); the constraints have the last word. Then notes which do not
    /// hold.
    pub(super) fn hold_constraints(&mut self) {
        let Some(world) = self.world.as_mut() else {
            return;
        };
        if self.heat.state.halted && !self.constraints.is_empty() {
            let watch = Stopwatch::start(&self.forces.profile);
            let rounds = (self.config.solver.constraint_passes(), SETTLE_ROUNDS);
            let parts = self.config.contacts.separates_disks()
                && world.contacts_enabled()
                && !self
                    .constraints
                    .holds_all_apart(world, &self.forces.targets.locks);
            let locks = std::mem::take(&mut self.forces.targets.locks);
            for _ in 0..HALT_ROUNDS {
                self.constraints.settle(world, rounds, &locks);
                if !parts {
                    break;
                }
                let moved = self.forces.part_overlaps(world);
                hold_locked_axes(world, &locks);
                if moved < PARTED {
                    break;
                }
            }
            self.constraints.settle(world, rounds, &locks);
            self.forces.targets.locks = locks;
            watch.stop(&mut self.forces.profile, |p| &mut p.constraints);
        }
        self.constraints.check(world);
    }

    /// The scene edges (indices into `scene.edges`) a [`Flow`](crate::config::Flow)
    /// leaves free, as of the last call: self-loops and the few edges that close a
    /// directed cycle (a greedy feedback arc set; removing them leaves the graph
    /// acyclic). The same scene gives the same set; it is worked out again when the
    /// topology changes. Empty without a flow.
    pub fn flow_exempt_edges(&self) -> &[usize] {
        self.constraints.exempt()
    }

    /// The host constraints (indices into
    /// [`LayoutExtras::constraints`](crate::LayoutExtras::constraints)) that the last
    /// call left more than a unit from holding: conflicting constraints that cannot all
    /// hold (the layout holds what it can and stays finite), or constraints still being
    /// reached in a layout's first frames. Empty when every constraint holds.
    pub fn violated_constraints(&self) -> &[usize] {
        &self.constraints.violated
    }

    /// The flow's edges (indices into `scene.edges`, exempt ones aside) that the last
    /// call left more than a unit short of the flow's gap.
    pub fn violated_flow_edges(&self) -> &[usize] {
        &self.constraints.violated_edges
    }
}
