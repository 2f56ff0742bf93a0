//! Advancing the world: the timestep joints are tuned for, rapier's integration
//! parameters, and one rapier step followed by recovery and event collection.

use std::hash::Hash;

use euclid::default::Vector2D;
use rapier2d::prelude::{IntegrationParameters, Vector};

use super::RapierSceneWorld;
use crate::sanitize::finite_or;

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Sets the length of the next steps, in seconds. Non-finite or non-positive values
    /// are ignored.
    ///
    /// # Example
    /// ```
    /// let mut world = graph_canvas_layout::RapierSceneWorld::<u32>::new();
    /// world.set_timestep(1.0 / 120.0);
    /// assert_eq!(world.integration_parameters().dt, 1.0 / 120.0);
    /// ```
    pub fn set_timestep(&mut self, dt: f32) {
        if dt.is_finite() && dt > 0.0 {
            self.params.dt = dt;
            self.version += 1;
            self.joint_dt = dt;
        }
    }

    /// Rapier's integration parameters (timestep, solver iterations, length unit).
    pub fn integration_parameters(&self) -> &IntegrationParameters {
        &self.params
    }

    /// Rapier's integration parameters, to tune.
    pub fn integration_parameters_mut(&mut self) -> &mut IntegrationParameters {
        &mut self.params
    }

    /// Runs the next step without continuous collision detection: a caller that drives
    /// kinematic bodies knows them even when the check over the awake bodies in
    /// [`step`](Self::step) misses one (a long random session left a dragged body with
    /// the flag).
    pub(crate) fn skip_ccd_next_step(&mut self) {
        self.ccd_off_once = true;
    }

    /// Advances the world by one timestep under `gravity` (world units per second²;
    /// non-finite components count as zero). Contacts are recorded for
    /// [`read_events`](Self::read_events) when the world reports events; bodies whose
    /// state went non-finite are put back, at rest, where rapier last saw them valid.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.step(Vector2D::new(0.0, 600.0));
    /// assert!(world.linear_velocity(&0).unwrap().y > 0.0);
    /// ```
    pub fn step(&mut self, gravity: Vector2D<f32>) {
        let gravity = Vector::new(finite_or(gravity.x, 0.0), finite_or(gravity.y, 0.0));
        // Every body the step can move: awake before it, or after it.
        self.mark_active();
        let events: &dyn rapier2d::pipeline::EventHandler = match &self.collector {
            Some(collector) => collector,
            None => &(),
        };
        // NOTE: rapier keeps a body's "moving fast" CCD flag when the body stops being
        // dynamic (a drag start), and its CCD pass then sweeps that kinematic body against
        // the fixed colliders and clamps its commanded motion at the first one it would
        // touch. While such a body is awake, steps run without CCD.
        let stale_ccd = self.islands.active_bodies().any(|handle| {
            self.bodies
                .get(handle)
                .is_some_and(|body| !body.is_dynamic() && body.is_ccd_active())
        });
        let mut params = self.params;
        if stale_ccd || std::mem::take(&mut self.ccd_off_once) {
            params.max_ccd_substeps = 0;
        }
        self.pipeline.step(
            gravity,
            &params,
            &mut self.islands,
            &mut self.broad_phase,
            &mut self.narrow_phase,
            &mut self.bodies,
            &mut self.colliders,
            &mut self.impulse_joints,
            &mut self.multibody_joints,
            &mut self.soft_bodies,
            &mut self.ccd_solver,
            &(),
            events,
        );
        self.touched = false;
        self.mark_active();
        self.recover_quarantined();
        self.collect_events();
    }
}
