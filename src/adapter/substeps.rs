//! The simulation of one call: the frame time as equal substeps
//! ([`StepPlan`], split further by [`Accuracy`](crate::config::Accuracy)), rapier's solver
//! parameters for this call, and per substep the kinematic drives, the body forces and
//! one rapier step.

use std::hash::Hash;

use euclid::default::Vector2D;

use super::drag::{drive_kinematic_bodies, stale_ccd_in};
use super::node_forces::hold_locked_axes;
use super::state::RapierLayoutState;
use super::RapierLayout;
use crate::config::cooling::HeatLaw;
use crate::config::SolverSettings;
use crate::profile::Stopwatch;
use crate::sanitize::positive_or;
use crate::timestep::{fixed_timestep, StepPlan};

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// The substeps of a call of frame time `dt`. Accuracy presets split every step
    /// further; an unusable `dt` is still one whole fixed step. New joints are tuned for
    /// the longest substep this configuration takes.
    pub(super) fn plan_frame(&mut self, state: &RapierLayoutState, dt: f32) -> StepPlan {
        let substeps = self.solver_settings().substeps;
        let mut plan = StepPlan::new(
            dt,
            state.dt,
            self.config.frame.max_frame_time,
            self.config.frame.max_substeps,
        );
        plan.substeps = plan.substeps.saturating_mul(substeps);
        plan.substep_dt /= substeps as f32;
        self.built.joint_dt = fixed_timestep(state.dt) / substeps as f32;
        plan
    }

    /// What this call asks of rapier's solver. With the layout's own disk separation,
    /// rapier's solver iterations become substeps of the layout's, so that contacts
    /// (and the other forces) are worked out anew for each.
    fn solver_settings(&self) -> SolverSettings {
        let settings = self.config.solver.accuracy.solver_settings();
        if self.config.contacts.separates_disks() {
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

    /// Runs the call's substeps under `gravity`.
    pub(super) fn simulate(&mut self, plan: &StepPlan, gravity: Vector2D<f32>) {
        let heat = self.heat_world();
        let solver = self.solver_settings();
        let config = &self.config;
        let Some(world) = self.world.as_mut() else {
            return;
        };
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
        let forces_on = self.forces.any_active(config);
        if !forces_on {
            self.forces.release(world);
        }
        if let Some(profile) = self.forces.profile.as_mut() {
            profile.substeps += u64::from(plan.substeps);
        }
        // Under `parallel`, another thread of the pool waits for each substep's parts
        // awake (`parallel/awake.rs`; `RapierLayout::set_pool_awake`).
        let awake = if self.pool_awake {
            world.awake_body_count()
        } else {
            0
        };
        for k in 0..plan.substeps {
            crate::parallel::with_pool_awake(awake, || {
                drive_kinematic_bodies(world, &self.host.drives, k, plan.substeps);
                if forces_on {
                    let law = HeatLaw {
                        alpha: heat.scale,
                        cooling: config.cooling,
                        blend: world.spring_blend(),
                    };
                    self.forces
                        .apply(world, config, law, heat.contact_softness, plan.substep_dt);
                }
                if stale_ccd_in(world, &self.host.drives) {
                    world.skip_ccd_next_step();
                }
                let watch = Stopwatch::start(&self.forces.profile);
                world.step(gravity);
                watch.stop(&mut self.forces.profile, |p| &mut p.rapier);
                self.forces.settle(world, plan.substep_dt);
                if !self.forces.targets.locks.is_empty() {
                    hold_locked_axes(world, &self.forces.targets.locks);
                }
            });
        }
    }

    /// Takes the nodes rapier quarantined during this call's steps.
    pub(super) fn collect_recovered(&mut self) {
        self.report.recovered.clear();
        if let Some(world) = self.world.as_mut() {
            self.report.recovered.extend(world.take_recovered_nodes());
        }
    }
}
