//! Rest: when a layout says it is converged, and the cold stop that ends a cooling
//! schedule by halting the world until the next disturbance.

use std::hash::Hash;

use super::heat::Heat;
use super::state::RapierLayoutState;
use super::sync_out::FrameReport;
use super::RapierLayout;
use crate::config::REST_TIME;
use crate::input::layout::DeltaMap;
use crate::timestep::StepPlan;

/// The convergence signal.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct Rest {
    /// Simulated time since the last disturbance or fast body.
    pub(crate) calm_time: f32,
    /// What [`Layout::is_converged`](crate::Layout::is_converged) reports.
    pub(crate) converged: bool,
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// At rest: calm for [`REST_TIME`] and every dynamic body asleep, so a converged
    /// layout reports no motion at all until something disturbs it; or halted by the
    /// cold stop.
    pub(super) fn track_rest(&mut self, disturbed: bool, report: &FrameReport<N>, simulated: f32) {
        let calm = report.max_speed.is_finite() && report.max_speed <= self.config.rest.speed;
        if disturbed || !calm {
            self.heat.rest.calm_time = 0.0;
        } else {
            self.heat.rest.calm_time += simulated;
        }
        self.heat.rest.converged = self.heat.rest.calm_time >= REST_TIME && report.awake == 0;
        if self.heat.rest.converged && self.end_unfolding() {
            // At rest before the heat let contacts in: rest again once any overlap they
            // find is parted.
            self.heat.rest.converged = false;
        }
        self.heat.rest.converged |= self.heat.state.halted;
        if self.heat.rest.converged {
            // At rest, the schedule is over: what disturbs the layout later meets its
            // coldest forces (as after the cold stop).
            if let Some(cooling) = self.config.cooling {
                self.heat.state.alpha = self.heat.state.alpha.min(cooling.floor());
            }
        }
    }

    /// A call on a halted layout: nothing moves until the next disturbance.
    pub(super) fn halted_frame(
        &mut self,
        state: &mut RapierLayoutState,
        plan: &StepPlan,
    ) -> DeltaMap<N> {
        state.simulated_time += f64::from(plan.simulated());
        self.report.recovered.clear();
        self.heat.rest.converged = true;
        DeltaMap::default()
    }

    /// The end of a cooling schedule: once the heat has stayed at its floor for
    /// [`REST_TIME`], every dynamic body is halted (velocity zeroed) and the world is not
    /// stepped again until a disturbance, like d3-force stopping its simulation at
    /// `alphaMin`. Forces are a thousandth of their strength by then, but in a large
    /// connected graph a few bodies jostling in contact would otherwise keep the whole
    /// graph (one rapier island) awake for ever.
    pub(super) fn stop_when_cold(&mut self, floor: f32, simulated: f32) {
        let heat: &mut Heat = &mut self.heat.state;
        // NOTE: a thrown node still on its way keeps the layout going.
        if heat.alpha > floor || heat.hottest > floor || !self.host.flights.is_empty() {
            heat.cold_time = 0.0;
            return;
        }
        heat.cold_time += simulated;
        if let Some(world) = self.world.as_mut() {
            if heat.cold_time >= REST_TIME {
                if self.config.contacts.separates_disks() && world.contacts_enabled() {
                    // No overlap is left standing.
                    self.forces.part_overlaps(world);
                    super::node_forces::hold_locked_axes(world, &self.forces.targets.locks);
                }
                world.halt_dynamic_bodies();
                let dt = world.integration_parameters().dt;
                self.forces
                    .capture_rest(world, &self.config, heat.alpha, dt);
                // Asleep, so that a later local disturbance wakes only what it reaches.
                world.sleep_dynamic_bodies_now();
                heat.halted = true;
            }
        }
    }
}
