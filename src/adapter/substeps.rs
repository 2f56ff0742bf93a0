//! The simulation of one call: the frame time as equal substeps
//! ([`StepPlan`], split further by [`Accuracy`](crate::config::Accuracy)), rapier's solver
//! parameters for this call, and per substep the kinematic drives, the body forces and
//! one rapier step.

use std::hash::Hash;

use euclid::default::Vector2D;

use super::drag::{drive_kinematic_bodies, land_driven_bodies, stale_ccd_in, Drive};
use super::heat::FrameHeat;
use super::node_forces::hold_locked_axes;
use super::state::RapierLayoutState;
use crate::clusters::Clusters;
use crate::config::cooling::HeatLaw;
use crate::config::{RapierLayoutConfig, SolverSettings};
use crate::constraints::Compiled;
use crate::profile::Stopwatch;
use crate::sanitize::positive_or;
use crate::simulate::Forces;
use crate::timestep::{fixed_timestep, StepPlan};
use crate::world::RapierSceneWorld;

/// Partings of the clusters' levels after each substep, at most (fewer when one moves
/// nothing): boxes squeezed between a dragged box and their neighbours overlapped by 8
/// units through a drag with 2, by 2.7 with 4, not at all with 8 (`docs/clusters.md`).
const CLUSTER_ROUNDS: usize = 8;

/// How far one parting moves two clusters' items that both give way, at most, as a
/// share of the bodies' mean half size (2 units for disks of radius 16): they part over
/// a few frames, without swinging into each other (`clusters/part.rs`).
const CLUSTER_STEP: f32 = 0.125;

/// The substeps of a call of frame time `dt`, and the timestep new joints are tuned
/// for. Accuracy presets split every step further; an unusable `dt` is still one whole
/// fixed step. New joints are tuned for the longest substep this configuration takes.
pub(super) fn plan_frame(
    config: &RapierLayoutConfig,
    state: &RapierLayoutState,
    dt: f32,
) -> (StepPlan, f32) {
    let substeps = solver_settings(config).substeps;
    let mut plan = StepPlan::new(
        dt,
        state.dt,
        config.frame.max_frame_time,
        config.frame.max_substeps,
    );
    plan.substeps = plan.substeps.saturating_mul(substeps);
    plan.substep_dt /= substeps as f32;
    (plan, fixed_timestep(state.dt) / substeps as f32)
}

/// What this call asks of rapier's solver. With the layout's own disk separation,
/// rapier's solver iterations become substeps of the layout's, so that contacts (and
/// the other forces) are worked out anew for each.
fn solver_settings(config: &RapierLayoutConfig) -> SolverSettings {
    let settings = config.solver.accuracy.solver_settings();
    if config.contacts.separates_disks() {
        SolverSettings {
            solver_iterations: 1,
            substeps: settings
                .substeps
                .saturating_mul(settings.solver_iterations as u32),
            ..settings
        }
    } else {
        settings
    }
}

/// What the simulation of one call borrows.
pub(super) struct Substeps<'a, N> {
    pub(super) config: &'a RapierLayoutConfig,
    pub(super) world: &'a mut RapierSceneWorld<N>,
    pub(super) forces: &'a mut Forces<N>,
    /// Kinematic bodies moving to the host's positions over the substeps.
    pub(super) drives: &'a [Drive],
    /// The hard constraints, held after each step.
    pub(super) constraints: &'a mut Compiled<N>,
    /// The clusters, parted after the constraints.
    pub(super) clusters: &'a mut Clusters<N>,
    /// [`RapierLayout::set_pool_awake`].
    pub(super) pool_awake: bool,
}

impl<N: Clone + Eq + Hash> Substeps<'_, N> {
    /// Runs the call's substeps under `gravity`, at the call's `heat`.
    pub(super) fn run(self, plan: &StepPlan, gravity: Vector2D<f32>, heat: FrameHeat) {
        let Self {
            config,
            world,
            forces,
            drives,
            constraints,
            clusters,
            pool_awake,
        } = self;
        let solver = solver_settings(config);
        let passes = config.solver.constraint_passes();
        forces.held_apart = constraints.holds_all_apart(world, &forces.targets.locks);
        let length_unit = positive_or(config.solver.length_unit, 1.0);
        let params = world.integration_parameters_mut();
        params.dt = plan.substep_dt;
        params.length_unit = length_unit;
        params.normalized_max_linear_velocity = if config.solver.max_speed > 0.0 {
            config.solver.max_speed / length_unit
        } else {
            f32::MAX
        };
        params.num_solver_iterations = solver.solver_iterations;
        params.num_internal_pgs_iterations = solver.internal_pgs_iterations;
        params.contact_softness = heat.contact_softness.coefficients();
        params.static_contact_softness = heat.contact_softness.static_coefficients();
        let forces_on = forces.any_active(config);
        if !forces_on {
            forces.release(world);
        }
        if let Some(profile) = forces.profile.as_mut() {
            profile.substeps += u64::from(plan.substeps);
        }
        // Under `parallel`, another thread of the pool waits for each substep's parts
        // awake (`parallel/awake.rs`; `RapierLayout::set_pool_awake`).
        let awake = if pool_awake {
            world.awake_body_count()
        } else {
            0
        };
        for k in 0..plan.substeps {
            crate::parallel::with_pool_awake(awake, || {
                drive_kinematic_bodies(world, drives, k, plan.substeps);
                if forces_on {
                    let law = HeatLaw {
                        alpha: heat.scale,
                        cooling: config.cooling,
                        blend: world.spring_blend(),
                    };
                    forces.apply(world, config, law, heat.contact_softness, plan.substep_dt);
                }
                if stale_ccd_in(world, drives) {
                    world.skip_ccd_next_step();
                }
                let watch = Stopwatch::start(&forces.profile);
                world.step(gravity);
                watch.stop(&mut forces.profile, |p| &mut p.rapier);
                forces.settle(world, plan.substep_dt);
                let watch = Stopwatch::start(&forces.profile);
                constraints.project(world, passes, &forces.targets.locks);
                let parting = (CLUSTER_ROUNDS, Some(CLUSTER_STEP));
                clusters.project(world, &forces.targets.locks, parting);
                watch.stop(&mut forces.profile, |p| &mut p.constraints);
                if !forces.targets.locks.is_empty() {
                    hold_locked_axes(world, &forces.targets.locks);
                }
            });
        }
        land_driven_bodies(world, drives);
    }
}
