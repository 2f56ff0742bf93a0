//! The contacts group ([`Contacts`]): whether nodes collide, who keeps them apart
//! ([`ContactModel`]), whether contact events are recorded and how firmly contacts push
//! ([`ContactSoftness`]). Read where the world is built (`adapter/reconfigure.rs`), by
//! the heat (which softens contacts while hot) and by the disk separation
//! (`contacts/`).

use serde::{Deserialize, Serialize};

#[cfg(doc)]
use crate::BodyKindPolicy;

/// Whether and how nodes collide. A change between calls that adds or removes rapier's
/// colliders or contact events (`enabled` or `model` with rapier's contacts, `events`)
/// rebuilds the world: every body starts again at rest. Turning the layout's own disk
/// separation on or off, and `softness`, take effect at the next call.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::{ContactModel, Contacts};
/// use graph_canvas_layout::RapierLayoutConfig;
/// let config = RapierLayoutConfig {
///     contacts: Contacts { model: ContactModel::Disks, ..Contacts::default() },
///     ..RapierLayoutConfig::default()
/// };
/// assert!(config.contacts.enabled && !config.contacts.events);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Contacts {
    /// Whether nodes collide. Off, the world holds no colliders at all (bodies get their
    /// mass directly), which saves the broad and narrow phases. Default: `true`.
    pub enabled: bool,
    /// Who keeps nodes apart: rapier's colliders or the layout's own disk separation
    /// ([`ContactModel`], where the trade is described). Default:
    /// [`ContactModel::Rapier`].
    pub model: ContactModel,
    /// Whether the world records contact begin/end events for
    /// [`RapierLayout::drain_events`](crate::RapierLayout::drain_events). On, contacts
    /// are rapier's whatever `model` says. Off, no event is produced or stored.
    /// Default: `false`.
    pub events: bool,
    /// How firmly contacts push overlapping nodes apart; see [`ContactSoftness`].
    /// Default: [`ContactSoftness::default`], rapier's 30 Hz, ζ = 10
    /// ([`force_directed`](crate::RapierLayoutConfig::force_directed) uses 240 Hz, ζ = 1).
    pub softness: ContactSoftness,
}

impl Default for Contacts {
    fn default() -> Self {
        Self {
            enabled: true,
            model: ContactModel::Rapier,
            events: false,
            softness: ContactSoftness::default(),
        }
    }
}

impl Contacts {
    /// Whether nodes collide through the layout's own disk separation.
    pub(crate) fn separates_disks(&self) -> bool {
        self.enabled && self.model == ContactModel::Disks && !self.events
    }

    /// Whether nodes collide through rapier's colliders.
    pub(crate) fn rapier_colliders(&self) -> bool {
        self.enabled && !self.separates_disks()
    }
}

/// How firmly contacts between nodes push overlapping disks apart: rapier's contact
/// softness, a spring per contact with this natural frequency and damping ratio.
///
/// A contact removes a fraction `erp = ω dt / (ω dt + 2ζ)` of the overlap per step
/// (`ω = 2π × natural_frequency`). Rapier's default (30 Hz, ζ = 10) removes 14 % per
/// 1/60 s step: soft, forgiving contacts that let stiff springs press disks into each
/// other. 240 Hz with ζ = 1 removes 93 %: nearly rigid, so no spring can squeeze two
/// nodes together, at the price of livelier collisions. Contacts with fixed bodies
/// (pinned nodes under [`BodyKindPolicy::PinnedStatic`]) get twice the frequency, as
/// rapier's own defaults do (60 Hz against 30 Hz).
///
/// # Example
/// ```
/// use graph_canvas_layout::config::ContactSoftness;
/// let firm = ContactSoftness { natural_frequency: 240.0, damping_ratio: 1.0 };
/// assert!(firm.overlap_removed_per_step(1.0 / 60.0) > 0.9);
/// assert!(ContactSoftness::default().overlap_removed_per_step(1.0 / 60.0) < 0.15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ContactSoftness {
    /// Natural frequency of the contact spring, in Hz. Higher is firmer. Default: `30.0`.
    pub natural_frequency: f32,
    /// Damping ratio of the contact spring. Lower corrects overlap faster and bounces
    /// more. Default: `10.0`.
    pub damping_ratio: f32,
}

impl Default for ContactSoftness {
    /// Rapier's own contact softness: 30 Hz, ζ = 10.
    fn default() -> Self {
        Self {
            natural_frequency: 30.0,
            damping_ratio: 10.0,
        }
    }
}

impl ContactSoftness {
    /// The fraction of an overlap one step of `dt` seconds removes (rapier's ERP).
    pub fn overlap_removed_per_step(self, dt: f32) -> f32 {
        self.coefficients().erp(dt)
    }

    /// Rapier's coefficients for contacts with fixed bodies: twice the frequency.
    pub(crate) fn static_coefficients(self) -> rapier2d::prelude::SpringCoefficients<f32> {
        let c = self.coefficients();
        rapier2d::prelude::SpringCoefficients::new(c.natural_frequency * 2.0, c.damping_ratio)
    }

    /// Rapier's coefficients, with unusable values replaced by rapier's defaults.
    pub(crate) fn coefficients(self) -> rapier2d::prelude::SpringCoefficients<f32> {
        let defaults = Self::default();
        let frequency = if self.natural_frequency.is_finite() && self.natural_frequency > 0.0 {
            // Rapier's own rigid joints use 1e6; beyond, 2π f overflows towards infinity.
            self.natural_frequency.min(1.0e6)
        } else {
            defaults.natural_frequency
        };
        let ratio = if self.damping_ratio.is_finite() && self.damping_ratio >= 0.0 {
            self.damping_ratio.min(1.0e6)
        } else {
            defaults.damping_ratio
        };
        rapier2d::prelude::SpringCoefficients::new(frequency, ratio)
    }
}

/// Who keeps nodes from overlapping when [`Contacts::enabled`] is on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
pub enum ContactModel {
    /// Rapier's colliders and contact constraints: any shape a host builds through the
    /// world wrapper, contact events, friction and restitution, contacts solved together
    /// with rapier joints. Rapier keeps pair bookkeeping for every two disks that meet
    /// or part, which dominates the step of a large graph in motion.
    #[default]
    Rapier,
    /// The layout's own disk separation (d3-force's `forceCollide`, made firm): every
    /// substep the pairs of disks that may touch are found on a uniform grid and solved
    /// as soft contacts the way Box2D v3 solves its own (warm-started impulses, up to
    /// eight passes before the step and four after it that take out the push's speed,
    /// so parted disks stop instead of flying apart), at the frequency and damping of
    /// [`ContactSoftness`]. Impulses only push. Dragged and pinned nodes push and do not
    /// give way; a sleeping node pressed into wakes. When a cooling schedule halts the
    /// world, the overlaps still held are projected apart on positions first. No
    /// colliders exist in rapier, so its broad and narrow phases have nothing to do: a
    /// large graph in motion steps in a fraction of the time it takes with rapier's
    /// contacts, and rests with fewer overlapping pairs (`docs/performance.md` measures
    /// both).
    /// Disks and label boxes ([`NodeShape`](crate::NodeShape)) are parted by their
    /// outlines (a box with boxes costs more than a disk with disks, `docs/shapes.md`).
    /// The trade: no
    /// friction, restitution or contact events (with
    /// [`Contacts::events`] on, contacts are rapier's), and contacts are not solved together with rapier
    /// joints (ropes and rods) in the same pass.
    Disks,
}
