//! Configuration of the Rapier layout: [`RapierLayoutConfig`], every field with its
//! effect, its trade-off and its default.
//!
//! The parts live beside it: what edges and pins become (`edge_joint`), the solver and
//! contacts (`solver`), the cooling schedule (`cooling`), groups (`groups`) and the presets for laying
//! graphs out (`presets`). The adapter reads the configuration once per call and decides
//! there what a change costs (a rebuild, new joints, or nothing).

use serde::{Deserialize, Serialize};

use crate::world::bindings::PhysicsMaterial;

pub(crate) mod cooling;
pub(crate) mod edge_joint;
pub(crate) mod groups;
mod presets;
pub(crate) mod solver;
pub(crate) mod stress;

pub use edge_joint::{BodyKindPolicy, EdgeJoint, EdgeWeight, SpringModel};
pub use groups::GroupForce;
pub use solver::{Accuracy, ContactModel, ContactSoftness, SolverSettings};
pub use stress::{StressModel, StressStart};

pub use crate::adapter::REST_TIME;
pub use crate::forces::many_body::Repulsion;
pub use cooling::Cooling;

/// What to do when the topology hash changes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum TopologyUpdate {
    /// Insert and remove only the bodies and joints that changed; untouched bodies keep
    /// their position and velocity. Costs the change plus an O(n + e) diff.
    #[default]
    Incremental,
    /// Build the whole world again from the host's positions (all motion is lost).
    /// Costs O(n + e) body and joint constructions.
    Rebuild,
}

/// Configuration of [`RapierLayout`](crate::RapierLayout). Every field has a default;
/// build one with `RapierLayoutConfig { field: value, ..Default::default() }`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RapierLayoutConfig {
    /// Radius, in world units, of the disk of every node whose `radius` is `0.0`: the
    /// size contacts keep nodes apart at, and with the material's density its mass
    /// (`density × π r²`), so a larger default also makes nodes heavier and slower to
    /// follow springs. Label boxes ([`NodeShape::Rect`](crate::NodeShape::Rect)) weigh
    /// what a disk of this radius weighs, whatever their size. Changing it between calls rebuilds the world: every body starts
    /// again at rest. Default: `16.0`.
    pub default_radius: f32,
    /// What each edge becomes: a spring, a rope, a rod or nothing ([`EdgeJoint`]).
    /// Changing it between calls replaces every joint in place; bodies keep their
    /// motion. Default: [`EdgeJoint::default`], a spring of rest length 100 and
    /// stiffness 50.
    pub edge_joint: EdgeJoint,
    /// How spring edges are solved: as rapier joints, or as forces of the layout's own
    /// ([`SpringModel`], where the trade is described). Changing it between calls
    /// replaces every joint in place; bodies keep their motion. Default:
    /// [`SpringModel::Joints`].
    pub spring_model: SpringModel,
    /// What each edge's [`CanvasEdge::weight`](crate::CanvasEdge::weight) scales: the
    /// joint's strength or its length ([`EdgeWeight`], with the formulas and when to
    /// pick which). Changing it between calls replaces every joint in place; bodies
    /// keep their motion. Costs nothing while every weight is 1. Default:
    /// [`EdgeWeight::Strength`].
    pub edge_weight: EdgeWeight,
    /// Body kinds for pinned and free nodes: anchors, kinematic pins, or nothing
    /// simulated at all ([`BodyKindPolicy`]). Default: [`BodyKindPolicy::PinnedStatic`].
    pub body_kind_policy: BodyKindPolicy,
    /// Material of every node: density (mass), friction, restitution and damping
    /// ([`PhysicsMaterial`]). Higher damping settles sooner and shortens throws. Changing
    /// it between calls rebuilds the world: every body starts again at rest.
    /// Default: [`PhysicsMaterial::default`].
    pub material: PhysicsMaterial,
    /// Longest frame time simulated in one call, in seconds; time beyond it is dropped
    /// (after a stall the layout resumes instead of fast-forwarding). Default: `0.25`.
    pub max_frame_time: f32,
    /// Most substeps one call runs. With the default 1/60 s timestep, 16 substeps cover
    /// the default `max_frame_time`. Lower it to bound the worst-case cost of a call;
    /// simulated time beyond `max_substeps × timestep` is dropped. At most 1,024 (a
    /// larger count is taken as 1,024). Default: `16`.
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
    /// How long, in seconds, a dragged node's pointer may go without reporting motion
    /// and still count as moving. A release throws the node with the pointer's velocity
    /// over its last reported move: the move's length over the time since the report
    /// before it, which takes in the frames without motion that pointers leave when they
    /// report at their own rate (a 60 Hz mouse on a 120 Hz display moves a drag every
    /// other frame), or over the move's own frame after a pause longer than the window
    /// (a flick from rest). A release after the pointer stood still for longer than the
    /// window throws nothing. Frame times are the real `dt` passed to
    /// [`step`](crate::Layout::step) (the fixed timestep when it is unusable). Longer
    /// windows bridge longer gaps between reports and still throw a node the hand paused
    /// on briefly before letting go; `0` counts only a move in the frame just before the
    /// release. Default: `0.05` (three frames at 60 Hz).
    pub throw_window: f32,
    /// Whether nodes collide. Off, the world holds no colliders at all (bodies get their
    /// mass directly), which saves the broad and narrow phases. Default: `true`.
    pub collisions: bool,
    /// Who keeps nodes apart: rapier's colliders or the layout's own disk separation
    /// ([`ContactModel`], where the trade is described). Changing it between calls
    /// rebuilds the world: every body starts again at rest. Default:
    /// [`ContactModel::Rapier`].
    pub contact_model: ContactModel,
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
    /// (CV) on `tree_1023` from 0.52 to 0.44 (ten-start means, `docs/performance.md`); lower still pulls dense cores into piles of
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
    /// the spring force in total, as at 0), so a leaf is drawn to its hub harder than
    /// the hub to the leaf, and hubs are not dragged about by their many leaves. The
    /// difference is an extra force on each end, applied with the body forces every
    /// substep; it does not conserve momentum (the centre pull of [`Repulsion`] keeps
    /// the graph in place). With the other `force_directed()` settings, 1 takes the
    /// edge-length CV of `tree_1023` from 0.48 to 0.44 and of `les_miserables` from 0.30
    /// to 0.29, and leaves `karate`'s at 0.19 (ten-start means, `docs/performance.md`).
    /// Costs one pass over the springs per substep. Clamped to `[0, 1]` (higher gains
    /// are explicit forces stiffer than the step resolves); not finite counts as 0.
    /// Default: `0.0` ([`RapierLayoutConfig::force_directed`] uses `1.0`).
    pub link_bias: f32,
    /// Linear damping, per second, of a thrown node from its release until it turns
    /// back toward where it was let go (or slows below
    /// [`rest_speed`](Self::rest_speed)), instead of the material's; `None` keeps the
    /// material's throughout. A layout damped as heavily as d3-force (20 per second in
    /// [`force_directed`](Self::force_directed)) stops a throw of 1,800 units/s within
    /// 90 units; with little damping in flight the node flies until its springs turn it,
    /// and the material's damping then brings it back without overshoot. Lower flies
    /// further; the material's own value turns the feature off. Costs nothing but a
    /// check per thrown node per call. Default: `None`
    /// ([`RapierLayoutConfig::force_directed`] uses `1.0`).
    pub flight_damping: Option<f32>,
    /// How nodes with a group key ([`NodeForces::group`](crate::NodeForces::group))
    /// hold together and keep apart ([`GroupForce`]). Does nothing while no node has a
    /// group. Default: [`GroupForce::default`].
    pub groups: GroupForce,
    /// The stress model: every two nodes pulled toward their graph distance (the best
    /// layouts of a graph's structure are those of least stress), with a global start
    /// that is already such a layout ([`StressModel`]). `None` for edges and the other
    /// forces alone. Costs a pass over each node's exact and pivot terms per substep
    /// (O(n·(pivots + exact terms))) and hop distances from every pivot when the graph
    /// changes. Default: `None` ([`RapierLayoutConfig::stress`] turns it on).
    pub stress: Option<StressModel>,
}

impl RapierLayoutConfig {
    /// The length an edge rests at: a spring's rest length, a rope's or a rod's length,
    /// and twice the default radius for edges without a joint.
    pub(crate) fn edge_length(&self) -> f32 {
        match self.edge_joint {
            EdgeJoint::Spring { rest_length, .. } => rest_length,
            EdgeJoint::Rope { max_length, .. } => max_length,
            EdgeJoint::Distance { length } => length,
            EdgeJoint::None => 2.0 * self.default_radius,
        }
    }

    /// The stiffness of an edge spring as configured (0 for other joints): what the
    /// stress model's terms are measured against.
    pub(crate) fn edge_stiffness(&self) -> f32 {
        match self.edge_joint {
            EdgeJoint::Spring { stiffness, .. } if stiffness.is_finite() => stiffness.max(0.0),
            _ => 0.0,
        }
    }

    /// Whether nodes collide through the layout's own disk separation.
    pub(crate) fn separates_disks(&self) -> bool {
        self.collisions && self.contact_model == ContactModel::Disks && !self.contact_events
    }

    /// Whether nodes collide through rapier's colliders.
    pub(crate) fn rapier_colliders(&self) -> bool {
        self.collisions && !self.separates_disks()
    }
}

impl Default for RapierLayoutConfig {
    fn default() -> Self {
        Self {
            default_radius: 16.0,
            edge_joint: EdgeJoint::default(),
            spring_model: SpringModel::Joints,
            edge_weight: EdgeWeight::Strength,
            body_kind_policy: BodyKindPolicy::PinnedStatic,
            material: PhysicsMaterial::default(),
            max_frame_time: 0.25,
            max_substeps: 16,
            length_unit: 100.0,
            max_speed: 40_000.0,
            throw_window: 0.05,
            collisions: true,
            contact_model: ContactModel::Rapier,
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
            flight_damping: None,
            groups: GroupForce::default(),
            stress: None,
        }
    }
}
