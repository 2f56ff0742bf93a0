//! Rest: when a layout says it is converged, and the cold stop that ends a cooling
//! schedule by halting the world until the next disturbance.

use std::hash::Hash;

use super::{Heat, HeatStage};
use crate::adapter::state::RapierLayoutState;
use crate::adapter::sync_out::FrameReport;
use crate::adapter::RapierLayout;
use crate::config::RapierLayoutConfig;
use crate::config::REST_TIME;
use crate::input::layout::DeltaMap;
use crate::simulate::Forces;
use crate::timestep::StepPlan;
use crate::world::RapierSceneWorld;

/// The convergence signal.
#[derive(Clone, Copy, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct Rest {
    /// Simulated time since the last disturbance or fast body.
    pub(crate) calm_time: f32,
    /// What [`Layout::is_converged`](crate::Layout::is_converged) reports.
    pub(crate) converged: bool,
}

impl HeatStage {
    /// At rest: calm for [`REST_TIME`] and every dynamic body asleep, so a converged
    /// layout reports no motion at all until something disturbs it; or halted by the
    /// cold stop.
    pub(in crate::adapter) fn track_rest<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        disturbed: bool,
        report: &FrameReport<N>,
        simulated: f32,
        world: Option<&mut RapierSceneWorld<N>>,
    ) {
        let calm = report.max_speed.is_finite() && report.max_speed <= config.rest.speed;
        if disturbed || !calm {
            self.rest.calm_time = 0.0;
        } else {
            self.rest.calm_time += simulated;
        }
        self.rest.converged = self.rest.calm_time >= REST_TIME && report.awake == 0;
        if self.rest.converged && self.end_unfolding(world) {
            // At rest before the heat let contacts in: rest again once any overlap they
            // find is parted.
            self.rest.converged = false;
        }
        self.rest.converged |= self.state.halted;
        if self.rest.converged {
            // At rest, the schedule is over: what disturbs the layout later meets its
            // coldest forces (as after the cold stop).
            if let Some(cooling) = config.cooling {
                self.state.alpha = self.state.alpha.min(cooling.floor());
            }
        }
    }

    /// The end of a cooling schedule: once the heat has stayed at its floor for
    /// [`REST_TIME`], every dynamic body is halted (velocity zeroed) and the world is not
    /// stepped again until a disturbance, like d3-force stopping its simulation at
    /// `alphaMin`. Forces are a thousandth of their strength by then, but in a large
    /// connected graph a few bodies jostling in contact would otherwise keep the whole
    /// graph (one rapier island) awake for ever.
    pub(in crate::adapter) fn stop_when_cold<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        floor: f32,
        simulated: f32,
        world: Option<&mut RapierSceneWorld<N>>,
        forces: &mut Forces<N>,
        in_flight: bool,
    ) {
        let heat: &mut Heat = &mut self.state;
        // NOTE: a thrown node still on its way keeps the layout going.
        if heat.alpha > floor || heat.hottest > floor || in_flight {
            heat.cold_time = 0.0;
            return;
        }
        heat.cold_time += simulated;
        if let Some(world) = world {
            if heat.cold_time >= REST_TIME {
                if config.contacts.separates_disks() && world.contacts_enabled() {
                    // No overlap is left standing.
                    forces.part_overlaps(world);
                    crate::adapter::node_forces::hold_locked_axes(world, &forces.targets.locks);
                }
                world.halt_dynamic_bodies();
                let dt = world.integration_parameters().dt;
                forces.capture_rest(world, config, heat.alpha, dt);
                // Asleep, so that a later local disturbance wakes only what it reaches.
                world.sleep_dynamic_bodies_now();
                heat.halted = true;
            }
        }
    }
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// A call on a halted layout: nothing moves until the next disturbance.
    pub(in crate::adapter) fn halted_frame(
        &mut self,
        state: &mut RapierLayoutState,
        plan: &StepPlan,
    ) -> DeltaMap<N> {
        state.simulated_time += f64::from(plan.simulated());
        self.report.recovered.clear();
        self.heat.rest.converged = true;
        DeltaMap::default()
    }
}
