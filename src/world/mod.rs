//! The world wrapper: one persistent rapier world whose bodies and joints are named by
//! the host's node ids.
//!
//! [`RapierSceneWorld`] owns every rapier set and pipeline, maps node ids to bodies, and
//! keeps per node the anchor that [`read_positions`](RapierSceneWorld::read_positions)
//! measures from. [`RapierLayout`](crate::RapierLayout) drives it once per frame; hosts
//! that want the low-level API can drive it directly. Each part of it is a file of
//! its own, adding its own `impl RapierSceneWorld`:
//!
//! - `bindings.rs`: what bodies are built from (shape, material, kind, snapshots);
//! - `slot.rs`: the per-node and per-joint bookkeeping;
//! - `nodes.rs`: inserting and removing bodies, radius edits;
//! - `edges.rs`: inserting, re-tuning and removing joints; `rapier_joint.rs`: what each
//!   [`EdgeJoint`] becomes in rapier; `spring_scale.rs`: every spring
//!   scaled at once (cooling);
//! - `bodies.rs`: the host's per-node calls (read, drive, teleport, flip kinds, impulses);
//! - `activity.rs`: sleep, wake, halt, and contacts on or off;
//! - `stepping.rs`: the timestep and the step; `recovery.rs`: bodies rapier quarantined;
//!   `events.rs`: contact events.

use std::collections::HashMap;
use std::hash::Hash;

use euclid::default::Point2D;
use rapier2d::prelude::{
    BroadPhaseBvh, CCDSolver, ColliderSet, CollisionEvent, ImpulseJointSet, IntegrationParameters,
    IslandManager, MultibodyJointSet, NarrowPhase, PhysicsPipeline, RigidBody, RigidBodySet,
    SoftBodySet, Vector,
};

use crate::input::layout::IdHasher;

mod activity;
pub(crate) mod bindings;
mod bodies;
mod changes;
mod edge_joint;
mod edges;
pub(crate) mod events;
pub(crate) mod nodes;
pub(crate) mod rapier_joint;
mod recovery;
pub(crate) mod saved;
mod seal;
pub(crate) mod slot;
pub(crate) use slot::SlotsView;

pub use bindings::{
    ColliderSpec, EdgeJointSpec, NodeAvatarBinding, NodeSnapshot, PhysicsMaterial, SceneBodyKind,
};
pub use edge_joint::EdgeJoint;
pub use events::SceneEvent;
pub use rapier_joint::max_resolved_stiffness;
pub(crate) mod spring_scale;
mod stepping;

use events::CollisionCollector;
use slot::{JointSlot, NodeSlot};
use spring_scale::{SpringScale, StretchCache};

/// Displacements shorter than this are left out of [`RapierSceneWorld::read_positions`].
pub const POSITION_EPSILON: f32 = 1.0e-4;
/// Most events kept between two [`RapierSceneWorld::read_events`] calls; older ones are
/// dropped (and counted) so a host that never reads cannot grow the buffer for ever.
pub const MAX_PENDING_EVENTS: usize = 65_536;
/// Lightest body the world builds, so a zero-radius node still has a finite inverse mass.
pub const MIN_BODY_MASS: f32 = 1.0e-3;

/// What the world models beyond bodies and joints.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct WorldOptions {
    /// Give each node a collider. Off, bodies get their mass directly and nothing
    /// collides: the broad and narrow phases have nothing to do.
    pub collisions: bool,
    /// Record contact begin/end events for [`RapierSceneWorld::read_events`]. Off, no
    /// collider asks rapier for events and no event handler runs.
    pub contact_events: bool,
}

impl Default for WorldOptions {
    /// Collisions and contact events on, as the world wrapper's low-level API has them.
    fn default() -> Self {
        Self {
            collisions: true,
            contact_events: true,
        }
    }
}

fn to_vector(p: Point2D<f32>) -> Vector {
    Vector::new(p.x, p.y)
}

fn to_point(v: Vector) -> Point2D<f32> {
    Point2D::new(v.x, v.y)
}

/// A persistent rapier world whose bodies are the nodes of a graph.
///
/// Bodies are inserted in the order they are given (never in hash-map order), so the
/// same calls in the same build give bit-identical worlds.
///
/// # Example
/// ```
/// use graph_canvas_layout::{
///     euclid::default::{Point2D, Vector2D}, EdgeJointSpec, NodeAvatarBinding, NodeSnapshot,
///     RapierSceneWorld,
/// };
/// let mut world = RapierSceneWorld::new();
/// let snapshots = [
///     NodeSnapshot { id: 0_u32, position: Point2D::new(0.0, 0.0), radius: 16.0, pinned: false },
///     NodeSnapshot { id: 1, position: Point2D::new(200.0, 0.0), radius: 16.0, pinned: false },
/// ];
/// let bindings = [NodeAvatarBinding::circle(0, 16.0), NodeAvatarBinding::circle(1, 16.0)];
/// world.build_bodies(&bindings, &snapshots);
/// let spring = EdgeJointSpec { rest_length: 100.0, stiffness: 50.0, damping: 1.0 };
/// world.build_edge_joints(&[(0, 1, spring)]);
/// world.step(Vector2D::zero());
/// let moved = world.read_positions();
/// assert!(moved[&0].x > 0.0 && moved[&1].x < 0.0, "the stretched spring pulls both ends in");
/// ```
pub struct RapierSceneWorld<N> {
    // ── rapier state ──
    bodies: RigidBodySet,
    colliders: ColliderSet,
    impulse_joints: ImpulseJointSet,
    multibody_joints: MultibodyJointSet,
    soft_bodies: SoftBodySet,
    islands: IslandManager,
    broad_phase: BroadPhaseBvh,
    narrow_phase: NarrowPhase,
    ccd_solver: CCDSolver,
    pipeline: PhysicsPipeline,
    params: IntegrationParameters,
    // ── scene mapping ──
    pub(crate) slots: Vec<NodeSlot>,
    /// The node in each slot.
    pub(crate) ids: Vec<N>,
    index: HashMap<N, u32, IdHasher>,
    next_serial: u64,
    joints: Vec<JointSlot<N>>,
    joint_index: HashMap<(u64, u64), u32, IdHasher>,
    // ── options, events, reports ──
    options: WorldOptions,
    collector: Option<CollisionCollector>,
    raw_events: Vec<CollisionEvent>,
    events: std::collections::VecDeque<SceneEvent<N>>,
    dropped_events: u64,
    recovered: Vec<N>,
    topology_hash: u64,
    /// The factor on every spring's stiffness and damping, and what chose it.
    spring_scale: SpringScale,
    /// The springs' slots and rest lengths, for their median stretch.
    stretch: StretchCache,
    /// The timestep joints are tuned for: the last [`set_timestep`](Self::set_timestep),
    /// not the substep a call happens to run (a short frame must not stiffen springs
    /// re-tuned during it).
    joint_dt: f32,
    /// Bumped by every change to bodies, joints, masses or the joint timestep, so caches
    /// over them (the link bias) know when to rebuild.
    version: u64,
    /// Springs are applied as forces of the layout's own instead of rapier joints.
    spring_forces: bool,
    /// A body was inserted or accessed to change since the last step.
    touched: bool,
    /// The bodies that may have changed since the layout last read them.
    changes: changes::Changes,
    /// The next step runs without CCD (see [`RapierSceneWorld::step`]).
    ccd_off_once: bool,
    /// Whether colliders take part in the simulation (see
    /// [`set_contacts_enabled`](RapierSceneWorld::set_contacts_enabled)).
    contacts_enabled: bool,
    /// The length of a hop a stress layout chose for this world (edge springs rest at
    /// it), if any.
    hop_length: Option<f32>,
}

impl<N: Clone + Eq + Hash> Default for RapierSceneWorld<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<N> std::fmt::Debug for RapierSceneWorld<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RapierSceneWorld")
            .field("bodies", &self.bodies.len())
            .field("colliders", &self.colliders.len())
            .field("joints", &self.impulse_joints.len())
            .field("options", &self.options)
            .field("topology_hash", &self.topology_hash)
            .finish_non_exhaustive()
    }
}

// ── construction and per-slot access ──────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// An empty world with collisions and contact events on, a 1/60 s timestep and
    /// rapier's default parameters.
    ///
    /// # Example
    /// ```
    /// let world = graph_canvas_layout::RapierSceneWorld::<u32>::new();
    /// assert_eq!(world.body_count(), 0);
    /// ```
    pub fn new() -> Self {
        Self::with_options(WorldOptions::default())
    }

    /// An empty world that models only what `options` asks for.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::RapierSceneWorld;
    /// use graph_canvas_layout::world::WorldOptions;
    /// let world = RapierSceneWorld::<u32>::with_options(WorldOptions {
    ///     collisions: false,
    ///     contact_events: false,
    /// });
    /// assert!(!world.options().collisions);
    /// ```
    pub fn with_options(options: WorldOptions) -> Self {
        Self {
            bodies: RigidBodySet::new(),
            colliders: ColliderSet::new(),
            impulse_joints: ImpulseJointSet::new(),
            multibody_joints: MultibodyJointSet::new(),
            soft_bodies: SoftBodySet::new(),
            islands: IslandManager::new(),
            broad_phase: BroadPhaseBvh::new(),
            narrow_phase: NarrowPhase::new(),
            ccd_solver: CCDSolver::new(),
            pipeline: PhysicsPipeline::new(),
            params: IntegrationParameters::default(),
            slots: Vec::new(),
            ids: Vec::new(),
            index: HashMap::with_hasher(IdHasher::default()),
            next_serial: 0,
            joints: Vec::new(),
            joint_index: HashMap::with_hasher(IdHasher::default()),
            collector: (options.collisions && options.contact_events)
                .then(CollisionCollector::default),
            options,
            raw_events: Vec::new(),
            events: std::collections::VecDeque::new(),
            dropped_events: 0,
            recovered: Vec::new(),
            topology_hash: 0,
            spring_scale: SpringScale::default(),
            stretch: StretchCache::default(),
            joint_dt: IntegrationParameters::default().dt,
            version: 0,
            contacts_enabled: true,
            spring_forces: false,
            touched: false,
            changes: changes::Changes::default(),
            ccd_off_once: false,
            hop_length: None,
        }
    }

    /// What this world models.
    pub fn options(&self) -> WorldOptions {
        self.options
    }

    /// Number of bodies.
    pub fn body_count(&self) -> usize {
        self.bodies.len()
    }

    /// Number of colliders (zero when collisions are off).
    pub fn collider_count(&self) -> usize {
        self.colliders.len()
    }

    /// Number of edge joints: one per edge the world models a joint for, whether a rapier
    /// joint or a spring applied as forces ([`SpringModel`](crate::config::SpringModel)).
    pub fn joint_count(&self) -> usize {
        self.joints.len()
    }

    /// Number of rapier joints: [`joint_count`](Self::joint_count) without the springs
    /// applied as forces.
    pub fn rapier_joint_count(&self) -> usize {
        self.impulse_joints.len()
    }

    /// Whether the node has a body.
    pub fn contains_node(&self, node: &N) -> bool {
        self.index.contains_key(node)
    }

    /// The node ids, in body insertion order (removals swap the last node into the gap).
    pub fn node_ids(&self) -> impl Iterator<Item = &N> + '_ {
        self.ids.iter()
    }

    /// The topology hash this world was built or last patched for (0 when unset).
    pub fn topology_hash(&self) -> u64 {
        self.topology_hash
    }

    /// Records the topology hash this world now stands for.
    pub(crate) fn set_topology_hash(&mut self, hash: u64) {
        self.topology_hash = hash;
    }

    /// A counter bumped by every change to bodies, joints, masses or the joint timestep.
    pub(crate) fn version(&self) -> u64 {
        self.version
    }

    pub(crate) fn slot_of(&self, node: &N) -> Option<usize> {
        self.index.get(node).map(|&i| i as usize)
    }

    fn body_mut(&mut self, node: &N) -> Option<&mut RigidBody> {
        let slot = self.slot_of(node)?;
        self.touched = true;
        self.mark_changed(slot);
        self.bodies.get_mut(self.slots[slot].body)
    }

    pub(crate) fn body_at(&self, slot: usize) -> &RigidBody {
        self.slots_view().body_at(slot)
    }

    pub(crate) fn body_at_mut(&mut self, slot: usize) -> &mut RigidBody {
        self.touched = true;
        self.mark_changed(slot);
        &mut self.bodies[self.slots[slot].body]
    }

    /// Whether any body may move in the next step: rapier simulates some, or one was
    /// inserted, woken or changed since the last step (rapier counts those only once it
    /// steps).
    pub(crate) fn may_move(&self) -> bool {
        self.touched || self.awake_body_count() > 0
    }

    /// Number of slots (one per body), the length of every per-slot buffer.
    pub(crate) fn slot_count(&self) -> usize {
        debug_assert_eq!(self.ids.len(), self.slots.len(), "an id for every slot");
        self.slots.len()
    }

    /// The serial of the node in `slot` (never reused).
    pub(crate) fn serial_at(&self, slot: usize) -> u64 {
        self.slots[slot].serial
    }

    /// The length of a hop a stress layout chose for this world.
    pub(crate) fn hop_length(&self) -> Option<f32> {
        self.hop_length
    }

    /// Records the length of a hop chosen for this world.
    pub(crate) fn set_hop_length(&mut self, length: f32) {
        self.hop_length = Some(length);
    }

    pub(crate) fn position_at(&self, slot: usize) -> Point2D<f32> {
        to_point(self.body_at(slot).translation())
    }
}
