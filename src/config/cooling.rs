//! Cooling: a schedule that brings a force-directed layout to rest in bounded time.
//!
//! Many-body repulsion reaches its equilibrium slowly: the last unfolding of a tree or
//! a grid takes minutes of simulated time while the picture hardly changes. d3-force
//! stops that by scaling every force with a decaying `alpha`, and so does this crate:
//! the layout's *heat* falls geometrically from 1 to [`Cooling::min_alpha`] over
//! [`Cooling::duration`], and spring stiffness and damping, repulsion and centre pull
//! are all multiplied by it. Their ratio, and so the shape they balance at, stays the
//! same; only the push toward it fades, and the material's damping brings the bodies to
//! a stop. Half a second after the heat reaches its floor every body is halted and the
//! world is no longer stepped until a disturbance, as d3-force stops at `alphaMin`. Contacts are not scaled, so nodes never end up
//! overlapping; on the first unfolding they can be left out while the layout is hot
//! ([`Cooling::first_contact_heat`]) and start soft ([`Cooling::hot_contact_frequency`]).
//! Any disturbance (a drag, a release, a host move, a
//! topology change) heats the layout again to [`Cooling::reheat`]: all of it, or with
//! [`Cooling::reheat_hops`] only the nodes near the disturbance.
//!
//! Springs are re-tuned in place whenever the heat has moved 5 % away from the
//! stiffness they have (about 140 times over a full schedule), never while the layout
//! rests.

use serde::{Deserialize, Serialize};

use crate::sanitize::finite_or;
use crate::world::spring_scale::blended;

/// The cooling schedule of [`RapierLayoutConfig::cooling`](crate::RapierLayoutConfig::cooling).
///
/// # Example
/// ```
/// use graph_canvas_layout::config::Cooling;
/// let cooling = Cooling::default();
/// // After the whole duration the heat is at its floor.
/// let alpha = cooling.cooled(1.0, cooling.duration);
/// assert!((alpha - cooling.min_alpha).abs() < 1e-6, "{alpha}");
/// // Half way it is the geometric mean of 1 and the floor.
/// let half = cooling.cooled(1.0, cooling.duration / 2.0);
/// assert!((half - cooling.min_alpha.sqrt()).abs() < 1e-4, "{half}");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Cooling {
    /// Simulated seconds from full heat (`alpha = 1`) to [`min_alpha`](Self::min_alpha),
    /// falling geometrically. Shorter settles sooner and leaves the layout further from
    /// its force equilibrium; longer gets closer to it and keeps it moving longer.
    /// Default: `5.0` (d3-force's 300 ticks at 60 frames per second). The layout
    /// presets set their own: `4.5` under
    /// [`force_directed`](crate::RapierLayoutConfig::force_directed) (every shipped graph
    /// at rest within d3's 300 ticks) and `2.0` under
    /// [`stress`](crate::RapierLayoutConfig::stress) (its start is already a layout).
    pub duration: f32,
    /// The floor of the heat: at it, forces are this fraction of their full strength,
    /// too weak to move anything against the material's damping. Default: `0.001`
    /// (d3-force's `alphaMin`).
    pub min_alpha: f32,
    /// The heat a disturbance (drag, release, host move, topology change) raises the
    /// layout to. The first build always starts at 1. Lower keeps a settled layout
    /// calmer around an edit; higher lets it reorganise more. Default: `1.0`.
    pub reheat: f32,
    /// Springs scale with `heat^spring_exponent` while repulsion and centre pull scale
    /// with the heat itself. At 1 they fade together and the shape they balance at stays
    /// the same. Below 1 springs outlast repulsion as the layout cools and edges draw
    /// toward their rest length at the end: with the other
    /// [`force_directed`](crate::RapierLayoutConfig::force_directed) settings, 0.7
    /// narrows the edge-length spread of trees and grids most (`docs/performance.md`,
    /// At scale, measures each setting). The price is pressure: the final pull presses
    /// large graphs together, so contacts are busier and need more than one solver pass
    /// to hold it, and a graph that cannot reach its rest lengths jams
    /// ([`stretch_limit`](Self::stretch_limit) lets such graphs out); lower exponents
    /// compact the layout further. Values outside `[0, 1]`, or not finite, count as 1.
    /// Default: `1.0`
    /// ([`RapierLayoutConfig::force_directed`](crate::RapierLayoutConfig::force_directed)
    /// uses `0.7`).
    pub spring_exponent: f32,
    /// The springs' median stretch (length over rest length) above which a graph counts
    /// as one that cannot be drawn at its rest lengths: its springs then fade with the
    /// heat itself, like repulsion, instead of `heat^spring_exponent` (fully once the
    /// median is twice the limit, geometrically blended in between), so they no longer
    /// outlast repulsion. `None` always uses `heat^spring_exponent`. The median is read
    /// at each re-tune. Without it a dense random graph, whose edges end several times
    /// their rest length, is pulled together by its long springs as the layout cools,
    /// tighter than contacts can hold it. With the other
    /// [`force_directed`](crate::RapierLayoutConfig::force_directed) settings, 2 leaves
    /// such a graph far fewer overlapping pairs at rest and a cheaper 95th-percentile
    /// step, at much the same edge-length spread; graphs that reach their rest lengths
    /// stay below the limit and hardly change (`docs/performance.md` gives the figures).
    /// Costs one length per spring and a median at each re-tune. Has no effect at
    /// `spring_exponent` 1. Values that are not finite and positive count as `None`.
    /// Default: `None`
    /// ([`RapierLayoutConfig::force_directed`](crate::RapierLayoutConfig::force_directed)
    /// uses 2).
    pub stretch_limit: Option<f32>,
    /// The contacts' natural frequency, in hertz, at full heat during the layout's first
    /// unfolding, or `None` for contacts as firm as
    /// [`ContactSoftness`](crate::config::ContactSoftness) says throughout. The first unfolding
    /// runs from the first build until the heat first reaches its floor; during it the
    /// contacts start this soft and firm up geometrically with the heat, reaching
    /// [`ContactSoftness::natural_frequency`](crate::config::ContactSoftness) at the floor, so
    /// nodes slip past each other instead of jamming while the graph spreads, and no
    /// overlap remains at rest. Later reheats (drags, edits) keep contacts firm, so a
    /// dragged node always pushes. With the other `force_directed()` settings, 5 Hz made
    /// random graphs' steps cheaper and their edge-length spread narrower, and left the
    /// small graphs as they were (`docs/performance.md` gives the figures and the
    /// configuration they were measured in). Costs nothing per step. Default: `None`
    /// ([`RapierLayoutConfig::force_directed`](crate::RapierLayoutConfig::force_directed)
    /// uses 5 Hz).
    pub hot_contact_frequency: Option<f32>,
    /// During the layout's first unfolding, contacts are left out until the heat first
    /// falls to this (never below the floor); `None` keeps them from the start. A fresh
    /// scatter collapses under full-strength springs into many overlapping
    /// pairs, which cost rapier's broad and narrow phases most of the step: on a large
    /// graph, 0.3 makes the first second's steps much cheaper and the whole layout
    /// faster (`docs/performance.md` gives the times). If the layout rests before,
    /// contacts come in then. Later reheats (drags, edits, topology changes) keep
    /// contacts on, so an interaction never lets nodes pass through each other. The
    /// trade: a graph that starts without contacts untangles differently; with the other
    /// `force_directed()` settings its edge lengths spread less than with contacts from
    /// the start (`docs/performance.md`, At scale, measures each setting). No contact events
    /// are reported while contacts are left out. Default: `None`
    /// ([`RapierLayoutConfig::force_directed`](crate::RapierLayoutConfig::force_directed)
    /// uses `0.3`).
    pub first_contact_heat: Option<f32>,
    /// How far a disturbance (a drag, a release, a host move, a pin, a topology edit)
    /// reheats the layout. `None` reheats all of it to [`reheat`](Self::reheat), as
    /// d3-force does: the whole picture reorganises, and nodes far from the edit move as
    /// much as near ones. `Some(h)` heats only what was touched and its neighbours up to
    /// `h` hops away, each hop half as hot as the one before (a dragged or thrown node
    /// itself stays cold, so a throw coasts and its springs bring it back gently): the
    /// forces on a heated node are multiplied by its heat over the layout's, which
    /// speeds it toward the same balance the rest of the layout rests at, and the nodes
    /// beyond stay asleep where they were. The heat of each node cools on the same
    /// schedule. Larger reaches let an edit reorganise more of its surroundings and
    /// wake more nodes; a host that wants a full relayout calls
    /// [`RapierLayout::reheat`](crate::RapierLayout::reheat). Only forces of the
    /// layout's own are multiplied: with
    /// [`SpringModel::Joints`](crate::config::SpringModel::Joints) springs keep the layout's
    /// heat. Values are counted from the first build on; a configuration or gravity
    /// change reheats all of the layout either way. Default: `None`
    /// ([`RapierLayoutConfig::force_directed`](crate::RapierLayoutConfig::force_directed)
    /// uses `Some(1)`).
    pub reheat_hops: Option<u32>,
    /// With [`reheat_hops`](Self::reheat_hops), the share of their full strength the
    /// springs of a dragged or thrown node pull it with once it is let go (its heat is
    /// set to the heat at which springs have this share, and cools from there). Higher
    /// draws a throw back sooner and flies it less far; lower lets it coast further and
    /// come back more slowly, and too low leaves it where it landed when the schedule
    /// ends. Under `force_directed()` 0.01 lets a throw fly on and draws it back; under
    /// `force_directed_fast()`, whose springs fade with the heat itself, 0.01 leaves a
    /// thrown node where it landed, and 0.05 draws it back (`docs/feel.md` and
    /// `docs/performance.md` give the distances and speeds). Values outside `[0, 1]`
    /// are clamped, non-finite ones count as 0 (the floor). Default: `0.01`
    /// ([`RapierLayoutConfig::force_directed_fast`](crate::RapierLayoutConfig::force_directed_fast)
    /// uses `0.05`).
    pub coasting_spring_scale: f32,
}

impl Default for Cooling {
    fn default() -> Self {
        Self {
            duration: 5.0,
            min_alpha: 0.001,
            reheat: 1.0,
            spring_exponent: 1.0,
            stretch_limit: None,
            hot_contact_frequency: None,
            first_contact_heat: None,
            reheat_hops: None,
            coasting_spring_scale: 0.01,
        }
    }
}

impl Cooling {
    /// The floor, made usable: finite and in `[1e-6, 1]`.
    pub(crate) fn floor(&self) -> f32 {
        if self.min_alpha.is_finite() {
            self.min_alpha.clamp(1e-6, 1.0)
        } else {
            0.001
        }
    }

    /// The heat a disturbance raises `alpha` to (never lowers it).
    pub(crate) fn reheated(&self, alpha: f32) -> f32 {
        let reheat = if self.reheat.is_finite() {
            self.reheat.clamp(self.floor(), 1.0)
        } else {
            1.0
        };
        alpha.max(reheat)
    }

    /// The spring scale at heat `alpha`: `alpha^spring_exponent`.
    pub(crate) fn spring_scale(&self, alpha: f32) -> f32 {
        let exponent = self.spring_exponent;
        if exponent.is_finite() && (0.0..1.0).contains(&exponent) {
            alpha.powf(exponent)
        } else {
            alpha
        }
    }

    /// The heat a dragged or thrown node takes after a local disturbance: the heat at
    /// which springs have [`coasting_spring_scale`](Self::coasting_spring_scale) of
    /// their strength, within `[floor, 1]`.
    pub(crate) fn coasting_heat(&self) -> f32 {
        let scale = finite_or(self.coasting_spring_scale, 0.0).clamp(0.0, 1.0);
        let exponent = self.spring_exponent;
        let heat = if exponent.is_finite() && exponent > 0.0 && exponent < 1.0 {
            scale.powf(1.0 / exponent)
        } else {
            scale
        };
        heat.clamp(self.floor(), 1.0)
    }

    /// The contacts' natural frequency at heat `alpha`, given the frequency `cold` they
    /// have at the floor: geometric from
    /// [`hot_contact_frequency`](Self::hot_contact_frequency) at heat 1 to `cold` at the
    /// floor; `cold` throughout without a usable hot frequency.
    pub(crate) fn contact_frequency(&self, cold: f32, alpha: f32) -> f32 {
        let Some(hot) = self.hot_contact_frequency else {
            return cold;
        };
        let floor = self.floor();
        if !(hot.is_finite() && hot > 0.0) || floor >= 1.0 {
            return cold;
        }
        // 0 at full heat, 1 at the floor.
        let cooled = (alpha.clamp(floor, 1.0).ln() / floor.ln()).clamp(0.0, 1.0);
        let frequency = hot * (cold / hot).powf(cooled);
        if frequency.is_finite() && frequency > 0.0 {
            frequency
        } else {
            cold
        }
    }

    /// The heat after `seconds` of simulated time starting from `alpha`: geometric decay
    /// from 1 to [`min_alpha`](Self::min_alpha) over [`duration`](Self::duration),
    /// never below the floor. A non-positive or non-finite duration cools at once.
    pub fn cooled(&self, alpha: f32, seconds: f32) -> f32 {
        let floor = self.floor();
        let duration = self.duration;
        if !(duration.is_finite() && duration > 0.0) {
            return floor;
        }
        let rate = floor.ln() / duration; // negative
        let next = alpha * (rate * seconds.max(0.0)).exp();
        if next.is_finite() {
            next.clamp(floor, 1.0)
        } else {
            floor
        }
    }
}

/// How the forces on a node scale with its own heat after a local disturbance
/// ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)): as they did when the whole
/// layout was that hot, so a heated neighbourhood replays the schedule that laid it out.
#[derive(Clone, Copy, Debug)]
pub(crate) struct HeatLaw {
    /// The layout's heat (1 without a schedule).
    pub(crate) alpha: f32,
    pub(crate) cooling: Option<Cooling>,
    /// The springs' blend from `heat^spring_exponent` toward the heat
    /// ([`Cooling::stretch_limit`](crate::config::Cooling::stretch_limit)).
    pub(crate) blend: f32,
}

impl HeatLaw {
    /// The factors on a node's springs and on its other forces for its own heat `own`:
    /// what its heat gives them over what the layout's gives. `None` for a node no
    /// hotter than the layout.
    pub(crate) fn boosts(&self, own: f32) -> Option<(f32, f32)> {
        let cooling = self.cooling.filter(|_| own > self.alpha)?;
        let springs = |heat: f32| {
            let near = cooling.spring_scale(heat);
            if self.blend > 0.0 {
                blended(near, heat, self.blend)
            } else {
                near
            }
        };
        let boost = springs(own) / springs(self.alpha);
        let boost = if boost.is_finite() { boost } else { 1.0 };
        Some((boost, own / self.alpha))
    }
}
