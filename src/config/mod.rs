//! Configuration of the Rapier layout: [`RapierLayoutConfig`], every field with its
//! effect, its trade-off and its default.
//!
//! The configuration is grouped by what travels together, each group in its own file:
//! how springs are solved and tuned ([`Springs`]), contacts ([`Contacts`]), what one
//! call may simulate ([`FrameLimits`]), the solver ([`Solver`]), throws ([`Throw`]),
//! rest detection ([`RestDetection`]), which body kind a node gets (`body_kind`), and
//! the optional models: many-body repulsion ([`Repulsion`]), stress ([`StressModel`]),
//! cooling ([`Cooling`]) and groups ([`GroupForce`]). The presets for laying graphs
//! out are in `presets`. The adapter compares the configuration with the one the world
//! was built with once per call and decides there what a change costs (a rebuild, new
//! joints, or nothing: `adapter/reconfigure.rs`).

use serde::{Deserialize, Serialize};

use crate::world::bindings::PhysicsMaterial;

mod body_kind;
mod contacts;
pub(crate) mod cooling;
mod flow;
mod frame;
pub(crate) mod groups;
mod presets;
mod repulsion;
mod rest;
pub(crate) mod solver;
mod springs;
pub(crate) mod stress;
mod throw;

pub use crate::world::EdgeJoint;
pub use body_kind::BodyKindPolicy;
pub use contacts::{ContactModel, ContactSoftness, Contacts};
pub use flow::Flow;
pub use frame::FrameLimits;
pub use groups::GroupForce;
pub use repulsion::Repulsion;
pub use rest::{RestDetection, REST_TIME};
pub use solver::{Accuracy, Solver, SolverSettings};
pub use springs::{EdgeWeight, SpringModel, Springs};
pub use stress::{StressModel, StressStart};
pub use throw::Throw;

pub use cooling::Cooling;

/// What to do when the topology hash changes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
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
/// build one with `RapierLayoutConfig { field: value, ..Default::default() }`, or start
/// from a preset ([`stress`](Self::stress), [`force_directed`](Self::force_directed),
/// [`force_directed_fast`](Self::force_directed_fast)).
///
/// The first four fields are the contract's; the groups after them each gather what
/// travels together. What a change between calls costs:
/// - a new world (every body starts again at rest): `default_radius`, `material`, and a
///   [`contacts`](Self::contacts) change that adds or removes rapier's colliders or
///   contact events (`enabled`, `model`, `events`);
/// - every joint replaced in place (bodies keep their motion): `edge_joint`, and
///   [`springs`](Self::springs)' `model`, `weight` and `degree_exponent`;
/// - nothing but the new values from the next call on: everything else.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::{Accuracy, Contacts, Solver};
/// use graph_canvas_layout::RapierLayoutConfig;
/// let config = RapierLayoutConfig {
///     default_radius: 12.0,
///     contacts: Contacts { enabled: false, ..Contacts::default() },
///     solver: Solver { accuracy: Accuracy::Precise, ..Solver::default() },
///     ..RapierLayoutConfig::stress()
/// };
/// assert!(config.stress.is_some() && !config.contacts.enabled);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RapierLayoutConfig {
    /// Radius, in world units, of the disk of every node whose `radius` is `0.0`: the
    /// size contacts keep nodes apart at, and with the material's density its mass
    /// (`density × π r²`), so a larger default also makes nodes heavier and slower to
    /// follow springs. Label boxes ([`NodeShape::Rect`](crate::NodeShape::Rect)) weigh
    /// what a disk of this radius weighs, whatever their size. Changing it between calls
    /// rebuilds the world: every body starts again at rest. Default: `16.0`.
    pub default_radius: f32,
    /// What each edge becomes: a spring, a rope, a rod or nothing ([`EdgeJoint`]).
    /// Changing it between calls replaces every joint in place; bodies keep their
    /// motion. Default: [`EdgeJoint::default`], a spring of rest length 100 and
    /// stiffness 50.
    pub edge_joint: EdgeJoint,
    /// Body kinds for pinned and free nodes: anchors, kinematic pins, or nothing
    /// simulated at all ([`BodyKindPolicy`]). Default: [`BodyKindPolicy::PinnedStatic`].
    pub body_kind_policy: BodyKindPolicy,
    /// Material of every node: density (mass), friction, restitution and damping
    /// ([`PhysicsMaterial`]). Higher damping settles sooner and shortens throws. Changing
    /// it between calls rebuilds the world: every body starts again at rest.
    /// Default: [`PhysicsMaterial::default`].
    pub material: PhysicsMaterial,
    /// How spring edges are solved and tuned: rapier joints or the layout's own forces,
    /// what an edge's weight scales, the hubs' share and the link bias ([`Springs`]).
    /// Default: [`Springs::default`], rapier joints with every spring as configured.
    pub springs: Springs,
    /// Whether and how nodes collide: rapier's colliders or the layout's own disk
    /// separation, contact events, contact softness ([`Contacts`]). Default:
    /// [`Contacts::default`], rapier's colliders without events.
    pub contacts: Contacts,
    /// How much simulated time one call may run ([`FrameLimits`]). Default:
    /// [`FrameLimits::default`], 0.25 s in at most 16 substeps.
    pub frame: FrameLimits,
    /// The solver's speed/accuracy trade, length unit and speed cap ([`Solver`]).
    /// Default: [`Solver::default`], [`Accuracy::Balanced`].
    pub solver: Solver,
    /// What a released drag throws and how the thrown node flies ([`Throw`]). Default:
    /// [`Throw::default`], a 0.05 s window and the material's damping in flight.
    pub throw: Throw,
    /// When the layout counts as at rest, and the smallest displacement it reports
    /// ([`RestDetection`]). Default: [`RestDetection::default`], 5 units/s and 1e-4.
    pub rest: RestDetection,
    /// What a topology change does. Default: [`TopologyUpdate::Incremental`].
    pub topology_update: TopologyUpdate,
    /// Many-body repulsion (Barnes–Hut) and centre pull, or `None` for springs and
    /// contacts only. Costs one quadtree build and one O(n log n) force pass per substep
    /// while anything is awake. Default: `None` ([`RapierLayoutConfig::force_directed`]
    /// turns it on).
    pub repulsion: Option<Repulsion>,
    /// The stress model: every two nodes pulled toward their graph distance (the best
    /// layouts of a graph's structure are those of least stress), with a global start
    /// that is already such a layout ([`StressModel`]). `None` for edges and the other
    /// forces alone. Costs a pass over each node's exact and pivot terms per substep
    /// (O(n·(pivots + exact terms))) and hop distances from every pivot when the graph
    /// changes. Default: `None` ([`RapierLayoutConfig::stress`] turns it on).
    pub stress: Option<StressModel>,
    /// A cooling schedule that brings the layout to rest in bounded time, or `None` to
    /// let it run to its force equilibrium. With a schedule, springs, repulsion and
    /// centre pull fade together over [`Cooling::duration`] after the last disturbance
    /// and the layout stops near (not at) its equilibrium; see [`Cooling`]. Costs an
    /// in-place re-tune of every spring each time the heat has fallen 5 % (about 140
    /// times over a full schedule), nothing at rest. Default: `None`
    /// ([`RapierLayoutConfig::force_directed`] turns it on).
    pub cooling: Option<Cooling>,
    /// How nodes with a group key ([`NodeForces::group`](crate::NodeForces::group))
    /// hold together and keep apart ([`GroupForce`]). Does nothing while no node has a
    /// group. Default: [`GroupForce::default`].
    pub groups: GroupForce,
    /// Which way edges point ([`Flow`]), held as hard separations, or `None` for edges
    /// that point anywhere. Costs a feedback arc set when the edges change and a few
    /// projection passes over the edges per substep. Default: `None`
    /// ([`with_flow`](Self::with_flow) sets it).
    pub flow: Option<Flow>,
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
}

impl Default for RapierLayoutConfig {
    fn default() -> Self {
        Self {
            default_radius: 16.0,
            edge_joint: EdgeJoint::default(),
            body_kind_policy: BodyKindPolicy::PinnedStatic,
            material: PhysicsMaterial::default(),
            springs: Springs::default(),
            contacts: Contacts::default(),
            frame: FrameLimits::default(),
            solver: Solver::default(),
            throw: Throw::default(),
            rest: RestDetection::default(),
            topology_update: TopologyUpdate::Incremental,
            repulsion: None,
            stress: None,
            cooling: None,
            groups: GroupForce::default(),
            flow: None,
        }
    }
}
