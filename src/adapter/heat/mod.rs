//! The heat stage ([`HeatStage`]), whole: the heat of a cooling layout
//! ([`RapierLayoutConfig::cooling`]), which a disturbance reheats and simulated time
//! cools, and while it is hot its springs re-tuned and (on the first unfolding) its
//! contacts softened or left out (here); the heat a local disturbance spreads to the
//! nodes near it (`spread.rs`); the cold stop at the end of the schedule and the
//! convergence signal (`rest.rs`). The schedule's settings and laws (how the heat
//! falls, what it scales, a heated node's forces: `HeatLaw`) are
//! [`Cooling`](crate::config::Cooling)'s, in `config/cooling.rs`; each node's own heat
//! is kept on its world slot, so that it moves with the body.

mod rest;
mod spread;

pub(super) use rest::Rest;
pub(super) use spread::Disturbances;

use std::hash::Hash;

use super::RapierLayout;
use crate::config::cooling::Cooling;
use crate::config::ContactSoftness;
use crate::config::RapierLayoutConfig;
use crate::simulate::Forces;
use crate::world::RapierSceneWorld;

/// How far the springs' scale may drift from the heat's before every spring is re-tuned
/// (a fraction of the scale): each re-tune touches every joint, so the scale follows the
/// heat in steps, about 140 over a full schedule, and exactly at the floor.
const RETUNE_STEP: f32 = 0.05;

/// A cooling layout's heat and where it is in its schedule.
#[derive(Clone, Copy, Debug, serde::Serialize, serde::Deserialize)]
pub(crate) struct Heat {
    /// The heat, in `(0, 1]`: what forces are multiplied by.
    pub(crate) alpha: f32,
    /// Simulated time the heat has spent at its floor since the last reheat.
    pub(crate) cold_time: f32,
    /// Set by the cold stop (and by the cold start of
    /// [`RapierLayout::at_rest`](crate::RapierLayout::at_rest)): the world is not stepped
    /// until a disturbance, as d3-force stops its timer.
    pub(crate) halted: bool,
    /// The first unfolding: from the first build until the heat first reaches its floor
    /// (or the layout rests), when [`Cooling::first_contact_heat`](crate::config::Cooling) and
    /// [`Cooling::hot_contact_frequency`](crate::config::Cooling) apply.
    pub(crate) unfolding: bool,
    /// The hottest node's own heat after a local disturbance (0 when none is hotter than
    /// the layout).
    pub(crate) hottest: f32,
}

impl Default for Heat {
    fn default() -> Self {
        Self {
            alpha: 1.0,
            cold_time: 0.0,
            halted: false,
            unfolding: false,
            hottest: 0.0,
        }
    }
}

/// The heat stage's state: a cooling layout's heat, what this call disturbed (for a
/// local reheat), and the convergence signal.
#[derive(Debug, Default)]
pub(in crate::adapter) struct HeatStage {
    /// The heat and where it is in its schedule.
    pub(in crate::adapter) state: Heat,
    /// The convergence signal (`rest.rs`).
    pub(in crate::adapter) rest: Rest,
    /// What this call disturbed, and the spread of its heat (`spread.rs`).
    pub(in crate::adapter) spread: Disturbances,
    /// Whether this call stepped the world: false from the call's start until
    /// [`start_frame`](Self::start_frame) lets it step.
    pub(in crate::adapter) stepped: bool,
}

/// What the heat makes of one call's simulation.
#[derive(Clone, Copy, Debug)]
pub(in crate::adapter) struct FrameHeat {
    /// The factor on the body forces (1 without a schedule).
    pub(in crate::adapter) scale: f32,
    /// The contacts of this call.
    pub(in crate::adapter) contact_softness: ContactSoftness,
}

impl HeatStage {
    /// Before the simulation: a disturbance during the first unfolding ends it, any
    /// disturbance lifts the cold stop and reheats a cooling layout. Returns whether the
    /// world is to be stepped (false while halted).
    pub(in crate::adapter) fn start_frame<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        disturbed: bool,
        unfolding_before: bool,
        mut world: Option<&mut RapierSceneWorld<N>>,
        forces: &mut Forces<N>,
    ) -> bool {
        if disturbed && unfolding_before {
            // An interaction during the first unfolding: contacts in, and firm.
            self.end_unfolding(world.as_deref_mut());
        }
        if disturbed {
            self.state.halted = false;
            if self.spread.everything() {
                // Laid out again as a whole: toward the stress minimum, not the rest.
                forces.forget_rest();
            }
        }
        if self.state.halted {
            return false;
        }
        self.stepped = true;
        if let Some(cooling) = config.cooling {
            if disturbed {
                match (cooling.reheat_hops, world) {
                    (Some(hops), Some(world)) if !self.spread.everything() => {
                        // Only near what was touched.
                        let heat = cooling.reheated(0.0);
                        let coasting = cooling.coasting_heat();
                        self.spread.spread(world, hops, heat, coasting);
                        self.state.hottest = self.state.hottest.max(heat);
                    }
                    (_, world) => {
                        self.state.alpha = cooling.reheated(self.state.alpha);
                        forces.forget_rest();
                        // All of it: springs applied as forces and the layout's own
                        // disk separation link no rapier island that would wake it.
                        if let Some(world) = world {
                            world.wake_dynamic_bodies();
                        }
                    }
                }
                // Also when the reheat cannot lift the heat off its floor: a disturbed
                // layout gets half a second before it is stopped again.
                self.state.cold_time = 0.0;
            }
        }
        true
    }

    /// [`RapierLayout::reheat`].
    fn reheat<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        alpha: f32,
        world: Option<&mut RapierSceneWorld<N>>,
        forces: &mut Forces<N>,
    ) {
        if let Some(cooling) = config.cooling {
            let alpha = if alpha.is_finite() { alpha } else { 1.0 };
            self.state.alpha = self.state.alpha.max(alpha.clamp(cooling.floor(), 1.0));
            self.state.cold_time = 0.0;
        }
        self.state.halted = false;
        forces.forget_rest();
        self.rest.converged = false;
        self.rest.calm_time = 0.0;
        if let Some(world) = world {
            world.wake_dynamic_bodies();
        }
    }

    /// The heat's effect on this call, applied to the world: springs re-tuned to the
    /// heat (in steps of 5 %, each re-tune touching every joint; a graph far from its
    /// rest lengths lets them fade toward the heat itself, blended by its median stretch),
    /// and during the first unfolding contacts softened by the heat and let in once it
    /// has fallen to [`Cooling::first_contact_heat`](crate::config::Cooling::first_contact_heat).
    pub(in crate::adapter) fn heat_world<N: Clone + Eq + Hash>(
        &self,
        config: &RapierLayoutConfig,
        world: Option<&mut RapierSceneWorld<N>>,
    ) -> FrameHeat {
        let heat = self.state;
        let mut contact_softness = config.contacts.softness;
        let Some(world) = world else {
            return FrameHeat {
                scale: 1.0,
                contact_softness,
            };
        };
        let scale = match config.cooling {
            Some(cooling) => {
                let target = cooling.spring_scale(heat.alpha);
                let scale = world.spring_scale();
                let at_floor = heat.alpha <= cooling.floor();
                if (target - scale).abs() > RETUNE_STEP * scale || at_floor {
                    let limit = cooling.stretch_limit.unwrap_or(f32::INFINITY);
                    // A no-op when already there.
                    world.set_spring_scale_by_stretch(target, heat.alpha, limit);
                }
                if heat.unfolding {
                    let cold = contact_softness.coefficients().natural_frequency;
                    contact_softness.natural_frequency =
                        cooling.contact_frequency(cold, heat.alpha);
                }
                heat.alpha
            }
            None => 1.0,
        };
        if heat.unfolding && !world.contacts_enabled() {
            // Never below the floor, which the heat would not reach.
            let gate = config.cooling.and_then(|cooling| {
                let gate = cooling.first_contact_heat.filter(|gate| gate.is_finite())?;
                Some(gate.max(cooling.floor()))
            });
            if gate.is_none_or(|gate| scale <= gate) {
                world.set_contacts_enabled(true);
            }
        }
        FrameHeat {
            scale,
            contact_softness,
        }
    }

    /// After the simulation: the heat falls by the simulated time, the cold stop may
    /// halt the world (not while a thrown node is `in_flight`), and the first unfolding
    /// ends at the floor (at once without a schedule).
    pub(in crate::adapter) fn cool<N: Clone + Eq + Hash>(
        &mut self,
        config: &RapierLayoutConfig,
        simulated: f32,
        mut world: Option<&mut RapierSceneWorld<N>>,
        forces: &mut Forces<N>,
        in_flight: bool,
    ) {
        match config.cooling {
            Some(cooling) => {
                self.state.alpha = cooling.cooled(self.state.alpha, simulated);
                self.cool_nodes(cooling, simulated, world.as_deref_mut());
                let floor = cooling.floor();
                self.stop_when_cold(
                    config,
                    floor,
                    simulated,
                    world.as_deref_mut(),
                    forces,
                    in_flight,
                );
                if self.state.alpha <= floor {
                    self.end_unfolding(world);
                }
            }
            None => {
                self.end_unfolding(world);
            }
        }
    }

    /// Cools every node heated by a local disturbance by `simulated` seconds of the
    /// schedule; a node as cold as the layout takes the layout's heat again.
    fn cool_nodes<N: Clone + Eq + Hash>(
        &mut self,
        cooling: Cooling,
        simulated: f32,
        world: Option<&mut RapierSceneWorld<N>>,
    ) {
        if self.state.hottest <= 0.0 {
            return;
        }
        let alpha = self.state.alpha;
        let mut hottest = 0.0_f32;
        if let Some(world) = world {
            for s in 0..world.slot_count() {
                let host = world.host_at_mut(s);
                if host.heat > 0.0 {
                    let heat = cooling.cooled(host.heat, simulated);
                    host.heat = if heat > alpha { heat } else { 0.0 };
                    hottest = hottest.max(host.heat);
                }
            }
        }
        self.state.hottest = hottest;
    }

    /// Ends the first unfolding: contacts in (if they were left out) and firm from here
    /// on, so interactions always push. Returns whether contacts were let in.
    pub(in crate::adapter) fn end_unfolding<N: Clone + Eq + Hash>(
        &mut self,
        world: Option<&mut RapierSceneWorld<N>>,
    ) -> bool {
        if !self.state.unfolding {
            return false;
        }
        self.state.unfolding = false;
        match world {
            Some(world) if !world.contacts_enabled() => {
                world.set_contacts_enabled(true);
                true
            }
            _ => false,
        }
    }
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Heats the whole layout to at least `alpha`, clamped to the schedule's floor and to
    /// 1, and wakes every body, as d3-force's `simulation.alpha(a).restart()`: the next
    /// calls lay the graph out again from where it is, the way a "relayout" button
    /// wants, whatever [`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops) says.
    /// Without a cooling schedule only wakes the bodies.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode,
    ///     CanvasSceneInput, Layout, LayoutExtras, RapierLayout, RapierLayoutConfig,
    ///     RapierLayoutState};
    /// let mut scene = CanvasSceneInput::new(
    ///     vec![CanvasNode::new(1_u32, Point2D::origin()), CanvasNode::new(2, Point2D::new(300.0, 0.0))],
    ///     vec![CanvasEdge::new(1, 2)],
    /// );
    /// let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
    /// let (mut state, extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// let mut frame = |layout: &mut RapierLayout<u32>, scene: &mut CanvasSceneInput<u32>| {
    ///     let deltas = layout.step(scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    ///     scene.apply_deltas(&deltas);
    ///     deltas
    /// };
    /// while !layout.is_converged(&RapierLayoutState::default()) {
    ///     frame(&mut layout, &mut scene);
    /// }
    /// assert!(frame(&mut layout, &mut scene).is_empty(), "at rest");
    /// layout.reheat(1.0);
    /// assert_eq!(layout.heat(), Some(1.0));
    /// assert!(!layout.is_converged(&RapierLayoutState::default()));
    /// ```
    pub fn reheat(&mut self, alpha: f32) {
        self.heat
            .reheat(&self.config, alpha, self.world.as_mut(), &mut self.forces);
    }
}
