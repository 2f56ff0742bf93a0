//! Configuration of the Rapier layout: joints, body kinds, materials, time stepping and
//! what the world models.

use serde::{Deserialize, Serialize};

use crate::bindings::{EdgeJointSpec, PhysicsMaterial};
use crate::cooling::Cooling;
use crate::repulsion::Repulsion;

/// What each edge becomes in the physics world.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum EdgeJoint {
    /// A spring that pulls toward `rest_length` from both sides: stretched, it pulls
    /// the ends together; compressed, it pushes them apart.
    ///
    /// `stiffness` is force per unit of stretch and `damping` force per unit of
    /// relative speed, with mass from density × disk area. The spring is solved
    /// implicitly. A stiffness above what the timestep resolves,
    /// [`max_resolved_stiffness`](crate::max_resolved_stiffness) `= m / dt²` (about 7,200
    /// for two default nodes at 1/60 s), acts as that limit: stiffer springs would
    /// correct their whole stretch within one step and fight each other in any graph
    /// whose edges cannot all have their rest length. The limit is taken when the joint
    /// is built, from the masses and the timestep of that call.
    Spring {
        /// Length at which the spring exerts no force.
        rest_length: f32,
        /// Force per unit of stretch.
        stiffness: f32,
        /// Force per unit of relative speed along the edge.
        damping: f32,
    },
    /// A rope: no force at all while the ends are closer than `max_length`; past it, a
    /// limit resists further stretching with `stiffness` (force per unit of stretch,
    /// critically damped, so the stretch is dissipated, not bounced). A very large
    /// stiffness makes it inextensible.
    Rope {
        /// Length at which the rope becomes taut.
        max_length: f32,
        /// Force per unit of stretch past `max_length`.
        stiffness: f32,
    },
    /// A rod: holds the ends at `length` both ways (a stiff, critically damped
    /// constraint).
    Distance {
        /// The held distance.
        length: f32,
    },
    /// No joint at all: the edge is topology only (it still counts in the topology
    /// hash), and the world models nothing for it.
    None,
}

impl Default for EdgeJoint {
    /// `Spring { rest_length: 100, stiffness: 50, damping: 1 }`.
    fn default() -> Self {
        EdgeJoint::Spring {
            rest_length: 100.0,
            stiffness: 50.0,
            damping: 1.0,
        }
    }
}

impl From<EdgeJointSpec> for EdgeJoint {
    fn from(spec: EdgeJointSpec) -> Self {
        EdgeJoint::Spring {
            rest_length: spec.rest_length,
            stiffness: spec.stiffness,
            damping: spec.damping,
        }
    }
}

/// Which body kind pinned (and all) nodes get. Dragged nodes are always driven
/// kinematically to the host's position, except pinned nodes under
/// [`PinnedStatic`](BodyKindPolicy::PinnedStatic), which stay anchors while the host
/// moves them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum BodyKindPolicy {
    /// Pinned nodes are static bodies: anchors that other bodies rest against and that
    /// joints pull on without moving them. Free nodes are dynamic.
    #[default]
    PinnedStatic,
    /// Pinned nodes are kinematic bodies that follow the host's position and push what
    /// they meet with the speed of that motion. Free nodes are dynamic.
    PinnedKinematic,
    /// Every node is kinematic: the layout only follows the host (no physics motion,
    /// no deltas). Useful to keep a world for contact queries without simulating.
    AllKinematic,
}

/// How hard the solver works per step. Each preset fixes rapier's solver iterations,
/// internal PGS iterations and substeps per timestep; cost grows about linearly with
/// `solver_iterations × substeps`. The published table (README, `cargo run --release
/// --example tradeoff`) gives the measured cost and error of each.
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
    /// about 16× the solver work of `Balanced` for the stiffest constraints and the most
    /// faithful trajectories.
    Precise,
    /// Explicit settings.
    Custom {
        /// Rapier's `num_solver_iterations` (at least 1).
        solver_iterations: usize,
        /// Rapier's `num_internal_pgs_iterations` (at least 1).
        internal_pgs_iterations: usize,
        /// Substeps per fixed timestep (at least 1): `k` shortens every substep `k`-fold.
        substeps: u32,
    },
}

impl Accuracy {
    /// `(solver_iterations, internal_pgs_iterations, substeps)` for this setting.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::Accuracy;
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
                solver_iterations.max(1),
                internal_pgs_iterations.max(1),
                substeps.max(1),
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
/// use graph_canvas_layout::ContactSoftness;
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

/// What to do when the topology hash changes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum TopologyUpdate {
    /// Insert and remove only the bodies and joints that changed; untouched bodies keep
    /// their position and velocity. Costs the change plus an O(n + e) diff.
    #[default]
    Incremental,
    /// Build the whole world again from the host's positions (all motion is lost).
    /// The plan's original behaviour; costs O(n + e) body and joint constructions.
    Rebuild,
}

/// Configuration of [`RapierLayout`](crate::RapierLayout). Every field has a default;
/// build one with `RapierLayoutConfig { field: value, ..Default::default() }`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RapierLayoutConfig {
    /// Radius given to nodes whose `radius` is `0.0`, in world units. Default: `16.0`.
    pub default_radius: f32,
    /// What each edge becomes. Default: [`EdgeJoint::default`].
    pub edge_joint: EdgeJoint,
    /// Body kinds for pinned and free nodes. Default: [`BodyKindPolicy::PinnedStatic`].
    pub body_kind_policy: BodyKindPolicy,
    /// Material of every node. Default: [`PhysicsMaterial::default`].
    pub material: PhysicsMaterial,
    /// Longest frame time simulated in one call, in seconds; time beyond it is dropped
    /// (after a stall the layout resumes instead of fast-forwarding). Default: `0.25`.
    pub max_frame_time: f32,
    /// Most substeps one call runs. With the default 1/60 s timestep, 16 substeps cover
    /// the default `max_frame_time`. Lower it to bound the worst-case cost of a call;
    /// simulated time beyond `max_substeps × timestep` is dropped. Default: `16`.
    pub max_substeps: u32,
    /// Rapier's `length_unit`: the size of a typical object in world units. Rapier scales
    /// its tolerances (contact slop, sleep threshold, speed cap) by it. Canvas nodes are
    /// about 30 pixels across and edges about 100, so the default suits pixel worlds.
    /// Default: `100.0`.
    pub length_unit: f32,
    /// Speed cap in world units per second; rapier clamps faster bodies each substep.
    /// A throw faster than this flies at the cap. Default: `40_000.0` (rapier's own
    /// 400 lengths/s at `length_unit` 100).
    pub max_speed: f32,
    /// Whether nodes collide. Off, the world holds no colliders at all (bodies get their
    /// mass directly), which saves the broad and narrow phases. Default: `true`.
    pub collisions: bool,
    /// Whether the world records contact begin/end events for
    /// [`RapierLayout::drain_events`](crate::RapierLayout::drain_events). Off, no event
    /// is produced or stored. Default: `false`.
    pub contact_events: bool,
    /// What a topology change does. Default: [`TopologyUpdate::Incremental`].
    pub topology_update: TopologyUpdate,
    /// The speed/accuracy trade of the solver; see [`Accuracy`] for what each preset
    /// costs and buys. Default: [`Accuracy::Balanced`].
    pub accuracy: Accuracy,
    /// Speed, in world units per second, under which a body counts as calm:
    /// [`Layout::is_converged`](crate::Layout::is_converged) reports rest once no
    /// dynamic body was faster for 0.5 s and rapier has put every body to sleep (rapier
    /// sleeps bodies slower than `0.05 × length_unit`, 5 units/s at the default, for
    /// 0.5 s). Default: `5.0`.
    pub rest_speed: f32,
    /// Many-body repulsion (Barnes–Hut) and centre pull, or `None` for springs and
    /// contacts only. Costs one quadtree build and one O(n log n) force pass per substep
    /// while anything is awake. Default: `None` ([`RapierLayoutConfig::force_directed`]
    /// turns it on).
    pub repulsion: Option<Repulsion>,
    /// Displacements shorter than this (world units) are left out of the returned map;
    /// they stay owed to the host and are reported once they add up. Default: `1e-4`.
    pub delta_epsilon: f32,
    /// Divides each [`EdgeJoint::Spring`]'s stiffness and damping by
    /// `min(degree)^exponent`, the smaller degree of its two ends: a hub's many springs
    /// then pull less hard in sum, so hubs do not crush their neighbourhoods. `0` keeps
    /// every spring as configured; `1` is d3-force's link strength `1 / min(degree)`.
    /// Lower exponents stiffen the springs between well-connected nodes, which physical
    /// springs need more than d3's links (a subtree's whole pull reaches its root edge):
    /// 0.6 with the other `force_directed()` settings narrows the edge-length spread
    /// (CV) on `tree_1023` from 0.60 to 0.52; lower still pulls dense cores into piles of
    /// touching disks, compacts the layout and makes large random graphs unfold slower
    /// (contacts). Degrees count distinct neighbours; a topology edit re-tunes the
    /// springs whose ends changed degree. Costs nothing per step. Default: `0.0`
    /// ([`RapierLayoutConfig::force_directed`] uses `0.6`).
    pub spring_degree_exponent: f32,
    /// A cooling schedule that brings the layout to rest in bounded time, or `None` to
    /// let it run to its force equilibrium. With a schedule, springs, repulsion and
    /// centre pull fade together over [`Cooling::duration`] after the last disturbance
    /// and the layout stops near (not at) its equilibrium; see [`Cooling`]. Costs an
    /// in-place re-tune of every spring each time the heat has fallen 5 % (about 140
    /// times over a full schedule), nothing at rest. Default: `None`
    /// ([`RapierLayoutConfig::force_directed`] turns it on).
    pub cooling: Option<Cooling>,
    /// How firmly contacts push overlapping nodes apart; see [`ContactSoftness`].
    /// Default: [`ContactSoftness::default`], rapier's 30 Hz, ζ = 10
    /// ([`RapierLayoutConfig::force_directed`] uses 240 Hz, ζ = 1).
    pub contact_softness: ContactSoftness,
    /// How unevenly a spring pulls its two ends, from 0 to 1. At 0 a spring is a
    /// physical one: equal and opposite pulls. At 1 it shares its pull like d3-force's
    /// link bias: each end takes a part proportional to the *other* end's degree (twice
    /// the spring force in total, as before), so a leaf is drawn to its hub harder than
    /// the hub to the leaf, and hubs are not dragged about by their many leaves. The
    /// difference is an extra force on each end, applied with the body forces every
    /// substep; it does not conserve momentum (the centre pull of [`Repulsion`] keeps
    /// the graph in place). With the other `force_directed()` settings, 1 takes the
    /// edge-length CV of `karate` from 0.19 to 0.17 and of `les_miserables` from 0.31 to
    /// 0.29.
    /// Costs one pass over the springs per substep. Clamped to `[0, 1]` (higher gains
    /// are explicit forces stiffer than the step resolves); not finite counts as 0.
    /// Default: `0.0` ([`RapierLayoutConfig::force_directed`] uses `1.0`).
    pub link_bias: f32,
}

impl Default for RapierLayoutConfig {
    fn default() -> Self {
        Self {
            default_radius: 16.0,
            edge_joint: EdgeJoint::default(),
            body_kind_policy: BodyKindPolicy::PinnedStatic,
            material: PhysicsMaterial::default(),
            max_frame_time: 0.25,
            max_substeps: 16,
            length_unit: 100.0,
            max_speed: 40_000.0,
            collisions: true,
            contact_events: false,
            topology_update: TopologyUpdate::Incremental,
            accuracy: Accuracy::Balanced,
            rest_speed: 5.0,
            delta_epsilon: 1e-4,
            repulsion: None,
            spring_degree_exponent: 0.0,
            cooling: None,
            contact_softness: ContactSoftness::default(),
            link_bias: 0.0,
        }
    }
}

impl RapierLayoutConfig {
    /// A configuration for laying graphs out: d3-force's default forces converted to
    /// physical units, on colliding disks, cooled to rest in bounded time.
    ///
    /// d3-force moves nodes in units per tick; at 60 ticks per second and the default
    /// node mass (density 0.005 × π 16² ≈ 4.0) its forces become:
    /// - links of distance 100 with strength `1 / min(degree)`: springs of rest length
    ///   100, stiffness 7,200 divided by `min(degree)^0.6`
    ///   ([`spring_degree_exponent`](Self::spring_degree_exponent) 0.6), no spring
    ///   damping. 7,200 is what a 1/60 s step resolves between two default nodes
    ///   ([`max_resolved_stiffness`](crate::max_resolved_stiffness)), d3's link at full
    ///   heat. d3's full share (exponent 1) leaves hub edges too soft here, because
    ///   physical springs pass a subtree's whole pull on to its root edge;
    /// - d3's link bias, the end with fewer neighbours pulled harder
    ///   ([`link_bias`](Self::link_bias) 1);
    /// - many-body strength −30: [`Repulsion`] of strength 430,000 (`30 × m × 60²`),
    ///   theta 0.9, with a gentle centre pull;
    /// - velocity decay 0.4 per tick would be linear damping 40 per second; half of it,
    ///   20, lets tangles slip free before the layout freezes;
    /// - alpha decay: a [`Cooling`] schedule over 8 s (d3 takes 5 s; the longer schedule
    ///   untangles trees and grids further before they freeze) that scales repulsion by
    ///   the heat and springs by `heat^0.7` ([`Cooling::spring_exponent`]), so edges draw
    ///   toward their rest length as the layout cools, unless the springs' median length
    ///   is over twice their rest length ([`Cooling::stretch_limit`] 2; fully like the
    ///   heat from four times, blended in between): such a graph cannot reach its rest
    ///   lengths, and springs that outlast repulsion would only pack it into a creeping
    ///   jam of contacts;
    /// - collide at the node radius: firm contacts (240 Hz, ζ = 1, [`ContactSoftness`])
    ///   that no spring presses through. On the first unfolding only, they are left out
    ///   until the heat falls to 0.3 ([`Cooling::first_contact_heat`]) and then firm up
    ///   from soft ([`Cooling::hot_contact_frequency`] 5 Hz): a fresh scatter collapsing
    ///   into thousands of contact pairs would cost most of the step (d3's collide, too,
    ///   is weak next to its other forces early on). Later reheats keep them firm, so a
    ///   drag always pushes;
    /// - one solver iteration of three PGS passes ([`Accuracy::Custom`] `1, 3, 1`): at
    ///   the end of the schedule the springs press a large graph together into a jammed
    ///   packing, and a single pass ([`Accuracy::Fast`]) leaves up to a hundred slightly
    ///   overlapping pairs on `n1000_e2500` and is slower on `n10000_e25000` (68 ms per
    ///   step: under-resolved contacts make more pairs). Three PGS passes resolve them
    ///   as well as [`Accuracy::Balanced`]'s two solver iterations, without the second
    ///   constraint update and position integration: about 7 % less per step on
    ///   `n1000_e2500` (1.22 against 1.30 ms) and `n10000_e25000`, with no overlaps,
    ///   for a little more spread on karate and trees (README).
    ///
    /// Every shipped graph comes to rest (every body asleep, or halted at the end of the
    /// schedule) within 9 s of simulated time after the last disturbance. Contacts
    /// dominate the step of large random graphs (27.4 ms per step over frames 30–270
    /// at 10,000 nodes, 24 ms averaged until rest); for thousands of nodes
    /// [`force_directed_fast`](Self::force_directed_fast) takes 11 ms. The damping
    /// is d3's: a throw stops within a few frames. For a physical feel (coasting
    /// throws), start from [`RapierLayoutConfig::default`].
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::RapierLayoutConfig;
    /// let config = RapierLayoutConfig::force_directed();
    /// assert!(config.repulsion.is_some() && config.cooling.is_some());
    /// ```
    pub fn force_directed() -> Self {
        let defaults = Self::default();
        Self {
            edge_joint: EdgeJoint::Spring {
                rest_length: 100.0,
                stiffness: 7_200.0,
                damping: 0.0,
            },
            material: PhysicsMaterial {
                linear_damping: 20.0,
                ..defaults.material
            },
            repulsion: Some(Repulsion::default()),
            spring_degree_exponent: 0.6,
            cooling: Some(Cooling {
                duration: 8.0,
                spring_exponent: 0.7,
                stretch_limit: Some(2.0),
                hot_contact_frequency: Some(5.0),
                first_contact_heat: Some(0.3),
                ..Cooling::default()
            }),
            link_bias: 1.0,
            contact_softness: ContactSoftness {
                natural_frequency: 240.0,
                damping_ratio: 1.0,
            },
            accuracy: Accuracy::Custom {
                solver_iterations: 1,
                internal_pgs_iterations: 3,
                substeps: 1,
            },
            ..defaults
        }
    }

    /// [`force_directed`](Self::force_directed) without colliders, with d3's full
    /// degree share (spring exponent 1) and no link bias: the fastest force-directed
    /// setting, for graphs of thousands of nodes. Repulsion alone keeps nodes apart, so
    /// some overlap where springs pull hard (783 pairs on `n1000_e2500`; d3-force leaves
    /// 347); the stiffer hub springs and the bias of `force_directed()` would press
    /// twice as many together without contacts. In exchange the broad and narrow
    /// phases, which dominate the step of a large graph, are gone. Measured on
    /// `n10000_e25000` (README): 11.2 ms per step over frames 30–270, where
    /// `force_directed()` takes 27.4 ms.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{Accuracy, RapierLayoutConfig};
    /// let config = RapierLayoutConfig::force_directed_fast();
    /// assert!(!config.collisions && config.accuracy == Accuracy::Fast);
    /// assert_eq!(config.repulsion, RapierLayoutConfig::force_directed().repulsion);
    /// ```
    pub fn force_directed_fast() -> Self {
        let directed = Self::force_directed();
        Self {
            collisions: false,
            spring_degree_exponent: 1.0,
            link_bias: 0.0,
            cooling: directed.cooling.map(|cooling| Cooling {
                spring_exponent: 1.0,
                ..cooling
            }),
            accuracy: Accuracy::Fast,
            ..directed
        }
    }
}
