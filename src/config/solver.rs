//! The solver's speed/accuracy trade ([`Accuracy`]), who keeps disks apart
//! ([`ContactModel`]) and how firmly rapier's contacts push ([`ContactSoftness`]). The
//! adapter copies them into rapier's integration parameters once per call.

use serde::{Deserialize, Serialize};

#[cfg(doc)]
use crate::BodyKindPolicy;

/// How hard the solver works per step. Each level fixes rapier's solver iterations,
/// internal PGS iterations and substeps per timestep; cost grows about linearly with
/// `solver_iterations × substeps`. `docs/tradeoff.md` (`cargo run --release --example
/// tradeoff`) gives the measured cost and error of each.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Accuracy {
    /// 1 solver iteration, 1 substep per timestep: the cheapest step. Springs and
    /// contacts converge over several frames instead of one; fine for large graphs in
    /// motion, visibly softer contacts in dense clusters.
    Fast,
    /// 2 solver iterations, 1 substep per timestep: the knee of the cost/error curve
    /// on the shipped graphs.
    #[default]
    Balanced,
    /// 8 solver iterations, 2 internal PGS iterations and 2 substeps per timestep:
    /// 8× the solver work of `Balanced` (`docs/tradeoff.md` times it) for the stiffest
    /// constraints and the most faithful trajectories.
    Precise,
    /// Explicit settings.
    Custom {
        /// Rapier's `num_solver_iterations`, from 1 to 256 (a count beyond is
        /// taken as 256: a bound on a frame's cost whatever a configuration says).
        solver_iterations: usize,
        /// Rapier's `num_internal_pgs_iterations`, from 1 to 256.
        internal_pgs_iterations: usize,
        /// Substeps per fixed timestep, from 1 to 64: `k` shortens every
        /// substep `k`-fold.
        substeps: u32,
    },
}

/// The most solver or internal PGS iterations an [`Accuracy::Custom`] asks for: 32
/// times [`Accuracy::Precise`]'s, far past where more iterations change a layout, and a
/// bound on a frame's cost whatever a configuration (or a damaged snapshot) says.
pub(crate) const MAX_ITERATIONS: usize = 256;

/// The most substeps per fixed timestep an [`Accuracy::Custom`] asks for.
pub(crate) const MAX_SUBSTEPS: u32 = 64;

/// What an [`Accuracy`] setting asks of the solver, each at least 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SolverSettings {
    /// Rapier's `num_solver_iterations`.
    pub solver_iterations: usize,
    /// Rapier's `num_internal_pgs_iterations`.
    pub internal_pgs_iterations: usize,
    /// Substeps per fixed timestep.
    pub substeps: u32,
}

impl Accuracy {
    /// What this setting asks of the solver.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::config::{Accuracy, SolverSettings};
    /// let precise = Accuracy::Precise.solver_settings();
    /// assert_eq!(
    ///     precise,
    ///     SolverSettings { solver_iterations: 8, internal_pgs_iterations: 2, substeps: 2 }
    /// );
    /// ```
    pub fn solver_settings(self) -> SolverSettings {
        let (solver_iterations, internal_pgs_iterations, substeps) = self.settings();
        SolverSettings {
            solver_iterations,
            internal_pgs_iterations,
            substeps,
        }
    }

    /// `(solver_iterations, internal_pgs_iterations, substeps)` for this setting; see
    /// [`solver_settings`](Self::solver_settings) for the same with names.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::config::Accuracy;
    /// assert_eq!(Accuracy::Fast.settings(), (1, 1, 1));
    /// ```
    pub fn settings(self) -> (usize, usize, u32) {
        match self {
            Accuracy::Fast => (1, 1, 1),
            Accuracy::Balanced => (2, 1, 1),
            Accuracy::Precise => (8, 2, 2),
            Accuracy::Custom {
                solver_iterations,
                internal_pgs_iterations,
                substeps,
            } => (
                solver_iterations.clamp(1, MAX_ITERATIONS),
                internal_pgs_iterations.clamp(1, MAX_ITERATIONS),
                substeps.clamp(1, MAX_SUBSTEPS),
            ),
        }
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

/// Who keeps nodes from overlapping when
/// [`RapierLayoutConfig::collisions`](crate::RapierLayoutConfig::collisions) is on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
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
    /// colliders exist in rapier, so its broad and narrow phases have nothing to do:
    /// with the other [`force_directed`](crate::RapierLayoutConfig::force_directed)
    /// settings, `n10000_e25000` steps in about a third of the time it takes with
    /// rapier's contacts, and rests with fewer overlapping pairs (`docs/performance.md`).
    /// Disks and label boxes ([`NodeShape`](crate::NodeShape)) are parted by their
    /// outlines (a box with boxes costs more than a disk with disks, `docs/shapes.md`).
    /// The trade: no
    /// friction, restitution or contact events (with
    /// [`RapierLayoutConfig::contact_events`](crate::RapierLayoutConfig::contact_events)
    /// on, contacts are rapier's), and contacts are not solved together with rapier
    /// joints (ropes and rods) in the same pass.
    Disks,
}
