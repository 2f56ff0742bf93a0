//! The simulation of one call: the frame time as equal substeps
//! ([`StepPlan`], split further by [`Accuracy`](crate::Accuracy)), rapier's solver
//! parameters for this call, and per substep the kinematic drives, the body forces and
//! one rapier step.

use std::hash::Hash;

use euclid::default::Vector2D;

use super::drag::drive_kinematic_bodies;
use super::state::RapierLayoutState;
use super::RapierLayout;
use crate::sanitize::positive_or;
use crate::timestep::{fixed_timestep, StepPlan};

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// The substeps of a call of frame time `dt`. Accuracy presets split every step
    /// further; an unusable `dt` is still one whole fixed step. New joints are tuned for
    /// the longest substep this configuration takes.
    pub(super) fn plan_frame(&mut self, state: &RapierLayoutState, dt: f32) -> StepPlan {
        let substeps = self.config.accuracy.solver_settings().substeps;
        let mut plan = StepPlan::new(
            dt,
            state.dt,
            self.config.max_frame_time,
            self.config.max_substeps,
        );
        plan.substeps = plan.substeps.saturating_mul(substeps);
        plan.substep_dt /= substeps as f32;
        self.joint_dt = fixed_timestep(state.dt) / substeps as f32;
        plan
    }

    /// Runs the call's substeps under `gravity`.
    pub(super) fn simulate(&mut self, plan: &StepPlan, gravity: Vector2D<f32>) {
        let heat = self.heat_world();
        let config = &self.config;
        let Some(world) = self.world.as_mut() else {
            return;
        };
        let length_unit = positive_or(config.length_unit, 1.0);
        let solver = config.accuracy.solver_settings();
        let params = world.integration_parameters_mut();
        params.dt = plan.substep_dt;
        params.length_unit = length_unit;
        params.normalized_max_linear_velocity = if config.max_speed > 0.0 {
            config.max_speed / length_unit
        } else {
            f32::MAX
        };
        params.num_solver_iterations = solver.solver_iterations;
        params.num_internal_pgs_iterations = solver.internal_pgs_iterations;
        params.contact_softness = heat.contact_softness.coefficients();
        params.static_contact_softness = heat.contact_softness.static_coefficients();
        let forces_on = self.forces.any_active(config);
        for k in 0..plan.substeps {
            drive_kinematic_bodies(world, &self.drives, k, plan.substeps);
            if forces_on {
                self.forces.apply(world, config, heat.scale);
            }
            world.step(gravity);
        }
    }

    /// Takes the nodes rapier quarantined during this call's steps.
    pub(super) fn collect_recovered(&mut self) {
        self.recovered.clear();
        if let Some(world) = self.world.as_mut() {
            self.recovered.extend(world.take_recovered_nodes());
        }
    }
}
