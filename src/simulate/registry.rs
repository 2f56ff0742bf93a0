//! The registry: every force the layout puts on bodies, in the one order their sums add
//! up in (which keeps replays bit for bit), and the substep's sum of them.
//!
//! The order is many-body repulsion, springs, centre pull, the host's position, radial
//! and group pulls, and the stress terms. Each force's [`Lane`] says where it runs:
//! the repulsion and the stress terms work from positions alone, beside the springs
//! (side by side under `parallel`); the host's pulls add in order after both; the stress
//! terms add what they worked out last.

use std::hash::Hash;

use euclid::default::Vector2D;

use super::Forces;
use crate::config::RapierLayoutConfig;
use crate::forces::center::CenterPull;
use crate::forces::group::GroupPull;
use crate::forces::many_body::ManyBodyForce;
use crate::forces::position::PositionPull;
use crate::forces::radial::RadialPull;
use crate::forces::springs::SpringForce;
use crate::forces::targets::NodeTargets;
use crate::forces::{BodyForce, ForceContext, ForceSums, Lane, SpareFrame};
use crate::stress::{RestBias, StressForce};
use crate::world::RapierSceneWorld;

/// Every force, each kept as its own type (the start hands the stress terms their
/// model); [`each`](Self::each) lists them in order.
#[derive(Default)]
pub(super) struct Registry {
    many_body: ManyBodyForce,
    springs: SpringForce,
    center: CenterPull,
    position: PositionPull,
    radial: RadialPull,
    group: GroupPull,
    pub(super) stress: StressForce,
}

impl Registry {
    /// The forces in the order their sums add up.
    // NOTE: order matters for the float sums (and bit-exact replays).
    pub(super) fn each<N: Clone + Eq + Hash>(&mut self) -> [&mut dyn BodyForce<N>; 7] {
        [
            &mut self.many_body,
            &mut self.springs,
            &mut self.center,
            &mut self.position,
            &mut self.radial,
            &mut self.group,
            &mut self.stress,
        ]
    }

    /// The forces `config` and the host's `targets` ask for, in order.
    fn active<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        targets: &NodeTargets,
    ) -> Vec<&mut dyn BodyForce<N>> {
        let mut forces: Vec<&mut dyn BodyForce<N>> = self.each().into();
        forces.retain(|force| force.is_active(config, targets));
        forces
    }

    /// Whether `config` and the host's `targets` ask for any force.
    pub(super) fn any_active<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        targets: &NodeTargets,
    ) -> bool {
        self.each::<N>()
            .iter()
            .any(|force| force.is_active(config, targets))
    }
}

impl<N: Clone + Eq + Hash> Forces<N> {
    /// At a stress layout's cold stop: what every dynamic body's springs (edges and
    /// stress terms) pull with where it rests, kept so that from here on the rest is
    /// their balance (`stress/rest_bias.rs`). Forgets it for other layouts.
    pub(crate) fn capture_rest(
        &mut self,
        world: &RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        heat: f32,
        dt: f32,
    ) {
        self.rest_bias = RestBias::default();
        if config.stress.is_none() || config.cooling.is_none() {
            // Without a schedule no node is ever heated, so the held pivot terms would
            // never be worked out again.
            return;
        }
        self.bodies.gather(world);
        // Every dynamic body counts as pushed here; what is kept of rapier's state is
        // put back after.
        let mut dynamic: Vec<bool> = (0..world.slot_count())
            .map(|s| world.body_at(s).is_dynamic())
            .collect();
        std::mem::swap(&mut self.bodies.pushed, &mut dynamic);
        // Every pivot term worked out afresh at the rest positions.
        self.registry.stress.renew_pivot_terms();
        self.sum_forces(world, config, heat, dt, false);
        self.rest_bias = RestBias::capture(
            world,
            &self.bodies.pushed,
            &self.sums.springs,
            &self.sums.forces,
        );
        std::mem::swap(&mut self.bodies.pushed, &mut dynamic);
    }

    /// Clears the sums and adds every active force's pull on the bodies `self.bodies`
    /// (gathered) marks as pushed, in the registry's order, holding the pivot terms of
    /// nodes not heated when `hold_cold`.
    pub(super) fn sum_forces(
        &mut self,
        world: &RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        heat: f32,
        dt: f32,
        hold_cold: bool,
    ) {
        let n = world.slot_count();
        for sums in [&mut self.sums.forces, &mut self.sums.springs] {
            sums.clear();
            sums.resize(n, Vector2D::zero());
        }
        self.sums.resistance.clear();
        self.sums.resistance.resize(n, 0.0);
        self.sums.pulls.clear();
        self.sums.pulls.resize(n, [0.0; 3]);
        let frame = ForceContext {
            world,
            config,
            points: &self.bodies.points,
            velocities: &self.bodies.velocities,
            pushed: &self.bodies.pushed,
            heat,
            dt,
            targets: &self.targets,
        };
        self.registry.stress.hold_cold = hold_cold;
        let mut forces = self.registry.active::<N>(config, &self.targets);
        // The stress terms read the world first.
        for force in forces.iter_mut() {
            force.prepare(&frame);
        }
        // Then the spare lane (the repulsion, the stress terms: on another thread, if one
        // is free) beside the springs' lane (on this one: they read the world), each
        // into sums of its own.
        let mut spare_sums = ForceSums {
            forces: std::mem::take(&mut self.sums.forces),
            ..ForceSums::default()
        };
        let mut spring_sums = ForceSums {
            springs: std::mem::take(&mut self.sums.springs),
            resistance: std::mem::take(&mut self.sums.resistance),
            ..ForceSums::default()
        };
        let spare_frame = SpareFrame {
            config,
            points: frame.points,
            pushed: frame.pushed,
            heat,
        };
        let (mut spare, mut others): (Vec<_>, Vec<_>) = forces
            .iter_mut()
            .partition(|force| force.lane() == Lane::Spare);
        crate::parallel::beside(
            || {
                for force in spare.iter_mut() {
                    force.apply_spare(&spare_frame, &mut spare_sums);
                }
            },
            || {
                for force in others.iter_mut().filter(|f| f.lane() == Lane::Springs) {
                    force.apply(&frame, &mut spring_sums);
                }
            },
        );
        self.sums.forces = spare_sums.forces;
        (self.sums.springs, self.sums.resistance) = (spring_sums.springs, spring_sums.resistance);
        for force in others.iter_mut().filter(|f| f.lane() == Lane::InOrder) {
            force.apply(&frame, &mut self.sums);
        }
        // Last, in the registry's order: what the spare lane held (the stress terms), so
        // the sums' bits do not depend on where it was worked out.
        for force in forces.iter_mut() {
            force.finish(&mut self.sums);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_registry_runs_repulsion_and_stress_beside_the_springs_and_pulls_in_order() {
        let mut registry = Registry::default();
        let lanes = registry.each::<u32>().map(|force| force.lane());
        // Many-body, springs, centre, position, radial, group, stress: the order the
        // sums add up in, and where each runs.
        assert_eq!(
            lanes,
            [
                Lane::Spare,
                Lane::Springs,
                Lane::InOrder,
                Lane::InOrder,
                Lane::InOrder,
                Lane::InOrder,
                Lane::Spare
            ],
            "lanes {lanes:?}"
        );
    }
}
