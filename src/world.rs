//! The world wrapper: one persistent rapier world whose bodies and joints are named by
//! the host's node ids.
//!
//! [`RapierSceneWorld`] owns every rapier set and pipeline, maps node ids to bodies, and
//! keeps per node the anchor that [`read_positions`](RapierSceneWorld::read_positions)
//! measures from. [`RapierLayout`](crate::RapierLayout) drives it once per frame; hosts
//! that want the plan's low-level API can drive it directly.

use std::collections::HashMap;
use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::{
    ActiveEvents, BroadPhaseBvh, CCDSolver, ColliderBuilder, ColliderHandle, ColliderSet,
    CollisionEvent, GenericJoint, ImpulseJointHandle, ImpulseJointSet, IntegrationParameters,
    IslandManager, MultibodyJointSet, NarrowPhase, PhysicsPipeline, RigidBodyBuilder,
    RigidBodyHandle, RigidBodySet, RigidBodyType, SharedShape, SoftBodySet, Vector,
};

use crate::bindings::{ColliderSpec, EdgeJointSpec, NodeAvatarBinding, NodeSnapshot};
use crate::config::EdgeJoint;
use crate::events::{CollisionCollector, SceneEvent};
use crate::joints::{max_resolved_stiffness, rapier_joint, scaled_spring};
use crate::layout::{DeltaMap, IdHasher};
use crate::sanitize::finite_or;

/// Displacements shorter than this are left out of [`RapierSceneWorld::read_positions`].
pub const POSITION_EPSILON: f32 = 1.0e-4;
/// Most events kept between two [`RapierSceneWorld::read_events`] calls; older ones are
/// dropped (and counted) so a host that never reads cannot grow the buffer for ever.
pub const MAX_PENDING_EVENTS: usize = 65_536;
/// Lightest body the world builds, so a zero-radius node still has a finite inverse mass.
pub const MIN_BODY_MASS: f32 = 1.0e-3;

/// What the world models beyond bodies and joints.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorldOptions {
    /// Give each node a collider. Off, bodies get their mass directly and nothing
    /// collides: the broad and narrow phases have nothing to do.
    pub collisions: bool,
    /// Record contact begin/end events for [`RapierSceneWorld::read_events`]. Off, no
    /// collider asks rapier for events and no event handler runs.
    pub contact_events: bool,
}

impl Default for WorldOptions {
    /// Collisions and contact events on, as the plan's world wrapper has them.
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

/// One node's body and the bookkeeping the layout keeps for it.
#[derive(Clone, Debug)]
pub(crate) struct NodeSlot<N> {
    pub(crate) id: N,
    /// Never reused: names the node in joint keys across swaps and removals.
    pub(crate) serial: u64,
    pub(crate) body: RigidBodyHandle,
    pub(crate) collider: Option<ColliderHandle>,
    pub(crate) shape: ColliderSpec,
    pub(crate) mass: f32,
    /// The anchor `read_positions` measures from.
    pub(crate) initial: Point2D<f32>,
    /// Where the host should have the node after adding the last delta it was given:
    /// a host position elsewhere is a host edit.
    pub(crate) told: Point2D<f32>,
    /// Call number in which the adapter last saw this node in the scene.
    pub(crate) stamp: u64,
    pub(crate) pinned: bool,
    pub(crate) dragging: bool,
    pub(crate) drag_position: Point2D<f32>,
    pub(crate) drag_velocity: Vector2D<f32>,
    /// Inserted during this call: its body may sit off the host's position (coincident
    /// nodes are spread), which is not a host move.
    pub(crate) fresh: bool,
    /// The last sync left this body dynamic and free (not dragged, pinned or frozen):
    /// while the host keeps the position it was told, the next sync has nothing to do.
    pub(crate) synced: bool,
}

#[derive(Clone, Debug)]
struct JointSlot<N> {
    key: (u64, u64),
    handle: ImpulseJointHandle,
    a: N,
    b: N,
    /// What the joint was built as: a re-tune to the same kind is skipped.
    kind: EdgeJoint,
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
    pub(crate) slots: Vec<NodeSlot<N>>,
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
    /// The factors of the last [`RapierSceneWorld::set_spring_scale_by_stretch`]: `near`,
    /// `far`, the stretch limit, and the factor on every spring's stiffness and damping
    /// they gave (a cooling layout's heat).
    spring_scale: f32,
    far_spring_scale: f32,
    stretch_limit: f32,
    applied_spring_scale: f32,
    /// [`version`](RapierSceneWorld::version) when the median stretch was last read: an
    /// edit re-reads it even at unchanged factors.
    spring_scale_version: u64,
    /// The timestep joints are tuned for: the last [`set_timestep`](Self::set_timestep),
    /// not the substep a call happens to run (a short frame must not stiffen springs
    /// re-tuned during it).
    joint_dt: f32,
    /// Bumped by every change to bodies, joints, masses or the joint timestep, so caches
    /// over them (the link bias) know when to rebuild.
    version: u64,
    /// Whether colliders take part in the simulation (see
    /// [`set_contacts_enabled`](RapierSceneWorld::set_contacts_enabled)).
    contacts_enabled: bool,
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

// ── construction ──────────────────────────────────────────────────────────────────────
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
    /// use graph_canvas_layout::{RapierSceneWorld, WorldOptions};
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
            spring_scale: 1.0,
            far_spring_scale: 1.0,
            stretch_limit: f32::INFINITY,
            applied_spring_scale: 1.0,
            spring_scale_version: 0,
            joint_dt: IntegrationParameters::default().dt,
            version: 0,
            contacts_enabled: true,
        }
    }

    /// What this world models.
    pub fn options(&self) -> WorldOptions {
        self.options
    }

    /// Builds one body per binding, at the position of the snapshot with the same id
    /// (the origin when there is none), in the order of `bindings`. A node that already
    /// has a body is rebuilt. A snapshot marked `pinned` makes a dynamic binding static.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: "a", position: Point2D::new(5.0, 6.0), radius: 16.0, pinned: true };
    /// world.build_bodies(&[NodeAvatarBinding::circle("a", 16.0)], &[snap]);
    /// assert_eq!(world.get_position(&"a"), Some(Point2D::new(5.0, 6.0)));
    /// assert_eq!(world.body_type(&"a"), Some(graph_canvas_layout::rapier2d::prelude::RigidBodyType::Fixed));
    /// ```
    pub fn build_bodies(
        &mut self,
        bindings: &[NodeAvatarBinding<N>],
        snapshots: &[NodeSnapshot<N>],
    ) {
        for (i, binding) in bindings.iter().enumerate() {
            let snapshot = snapshots
                .get(i)
                .filter(|s| s.id == binding.node_id)
                .or_else(|| snapshots.iter().find(|s| s.id == binding.node_id));
            let position = snapshot.map_or(Point2D::origin(), |s| s.position);
            let mut binding = binding.clone();
            if snapshot.is_some_and(|s| s.pinned)
                && binding.body_kind == crate::SceneBodyKind::Dynamic
            {
                binding.body_kind = crate::SceneBodyKind::Static;
            }
            self.remove_node(&binding.node_id);
            self.insert_node(&binding, position);
        }
    }

    /// Builds one spring joint per edge. Edges naming a node without a body, self-loops
    /// and repeats of an existing pair (in either direction) are skipped.
    pub fn build_edge_joints(&mut self, edges: &[(N, N, EdgeJointSpec)]) {
        for (a, b, spec) in edges {
            self.insert_edge_joint(a, b, &EdgeJoint::from(*spec));
        }
    }

    /// Inserts a body for `binding` at `position` and returns whether it was inserted
    /// (false when the node already has one or a value is not finite).
    pub fn insert_node(&mut self, binding: &NodeAvatarBinding<N>, position: Point2D<f32>) -> bool {
        if self.index.contains_key(&binding.node_id)
            || !position.x.is_finite()
            || !position.y.is_finite()
        {
            return false;
        }
        let shape = sanitize_shape(binding.collider);
        let material = binding.material;
        let mass = body_mass(shape, material.density);
        let slot_index = self.slots.len();
        let body = RigidBodyBuilder::new(binding.body_kind.rigid_body_type())
            .translation(to_vector(position))
            .lock_rotations()
            .linear_damping(finite_or(material.linear_damping, 0.0).max(0.0))
            .angular_damping(finite_or(material.angular_damping, 0.0).max(0.0))
            .gravity_scale(finite_or(material.gravity_scale, 1.0))
            .additional_mass(mass)
            .user_data(slot_index as u128)
            .build();
        let body = self.bodies.insert(body);
        let collider = self.options.collisions.then(|| {
            let events = if self.options.contact_events {
                ActiveEvents::COLLISION_EVENTS
            } else {
                ActiveEvents::empty()
            };
            let collider = ColliderBuilder::new(shared_shape(shape))
                .density(0.0)
                .friction(finite_or(material.friction, 0.0).max(0.0))
                .restitution(finite_or(material.restitution, 0.0).clamp(0.0, 1.0))
                .active_events(events)
                .enabled(self.contacts_enabled)
                .build();
            self.colliders
                .insert_with_parent(collider, body, &mut self.bodies)
        });
        self.index
            .insert(binding.node_id.clone(), slot_index as u32);
        self.slots.push(NodeSlot {
            id: binding.node_id.clone(),
            serial: self.next_serial,
            body,
            collider,
            shape,
            mass,
            initial: position,
            told: position,
            stamp: 0,
            pinned: false,
            dragging: false,
            drag_position: position,
            drag_velocity: Vector2D::zero(),
            fresh: true,
            synced: false,
        });
        self.next_serial += 1;
        self.version += 1;
        true
    }

    /// Removes a node's body, its collider and every joint attached to it. Returns
    /// whether the node had a body.
    pub fn remove_node(&mut self, node: &N) -> bool {
        let Some(slot_index) = self.index.remove(node) else {
            return false;
        };
        self.version += 1;
        let slot_index = slot_index as usize;
        let removed = self.slots.swap_remove(slot_index);
        let serial = removed.serial;
        // Our own joint bookkeeping first; rapier drops the joints with the body.
        let mut i = 0;
        while i < self.joints.len() {
            let key = self.joints[i].key;
            if key.0 == serial || key.1 == serial {
                self.remove_joint_at(i, false);
            } else {
                i += 1;
            }
        }
        self.bodies.remove(
            removed.body,
            &mut self.islands,
            &mut self.colliders,
            &mut self.impulse_joints,
            &mut self.multibody_joints,
            &mut self.soft_bodies,
            true,
        );
        if slot_index < self.slots.len() {
            let moved = &self.slots[slot_index];
            self.index.insert(moved.id.clone(), slot_index as u32);
            if let Some(body) = self.bodies.get_mut(moved.body) {
                body.user_data = slot_index as u128;
            }
        }
        true
    }

    /// Inserts the joint `kind` between `a` and `b` and returns whether one was
    /// inserted: not for [`EdgeJoint::None`], a self-loop, a missing node, or a pair that
    /// already has a joint.
    pub fn insert_edge_joint(&mut self, a: &N, b: &N, kind: &EdgeJoint) -> bool {
        let (Some(&ia), Some(&ib)) = (self.index.get(a), self.index.get(b)) else {
            return false;
        };
        if ia == ib {
            return false;
        }
        let (sa, sb) = (&self.slots[ia as usize], &self.slots[ib as usize]);
        let key = joint_key(sa.serial, sb.serial);
        if self.joint_index.contains_key(&key) {
            return false;
        }
        let (body_a, body_b) = (sa.body, sb.body);
        let Some(joint) = self.joint_data(ia, ib, kind, self.applied_spring_scale) else {
            return false;
        };
        let handle = self.impulse_joints.insert(body_a, body_b, joint, true);
        self.joint_index.insert(key, self.joints.len() as u32);
        self.joints.push(JointSlot {
            key,
            handle,
            a: a.clone(),
            b: b.clone(),
            kind: *kind,
        });
        self.version += 1;
        true
    }

    /// Gives every joint the kind `kind_of(a, b)` names, in place: bodies keep their
    /// motion, and joints already of that kind are left untouched. A joint whose new
    /// kind is [`EdgeJoint::None`] is removed. Joints are visited in insertion order.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, EdgeJoint, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// world.build_bodies(
    ///     &[NodeAvatarBinding::circle(0_u32, 16.0), NodeAvatarBinding::circle(1, 16.0)],
    ///     &[snap(0, 0.0), snap(1, 300.0)],
    /// );
    /// world.insert_edge_joint(&0, &1, &EdgeJoint::default());
    /// let softer = EdgeJoint::Spring { rest_length: 100.0, stiffness: 5.0, damping: 1.0 };
    /// assert_eq!(world.retune_edge_joints(|_, _| softer), 1);
    /// assert_eq!(world.retune_edge_joints(|_, _| softer), 0, "already that kind");
    /// assert_eq!(world.joint_count(), 1);
    /// ```
    pub fn retune_edge_joints(&mut self, mut kind_of: impl FnMut(&N, &N) -> EdgeJoint) -> usize {
        let mut changed = 0;
        let mut i = 0;
        while i < self.joints.len() {
            let kind = kind_of(&self.joints[i].a, &self.joints[i].b);
            if kind == self.joints[i].kind {
                i += 1;
                continue;
            }
            changed += 1;
            self.version += 1;
            let ends = (
                self.index.get(&self.joints[i].a),
                self.index.get(&self.joints[i].b),
            );
            let built = match ends {
                (Some(&ia), Some(&ib)) => self.joint_data(ia, ib, &kind, self.applied_spring_scale),
                _ => None,
            };
            match built {
                Some(data) => {
                    let slot = &mut self.joints[i];
                    slot.kind = kind;
                    if let Some(joint) = self.impulse_joints.get_mut(slot.handle, true) {
                        joint.data = data;
                    }
                    i += 1;
                }
                None => self.remove_joint_at(i, true),
            }
        }
        changed
    }

    /// Multiplies every spring's stiffness and damping by `scale` (relative to the kind
    /// it was inserted as), in place and without waking anything; new springs take the
    /// factor too. A cooling layout passes its spring factor through
    /// [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch). Non-finite or negative values
    /// count as 0. Returns how many joints changed.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, EdgeJoint, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// world.build_bodies(
    ///     &[NodeAvatarBinding::circle(0_u32, 16.0), NodeAvatarBinding::circle(1, 16.0)],
    ///     &[snap(0, 0.0), snap(1, 300.0)],
    /// );
    /// world.insert_edge_joint(&0, &1, &EdgeJoint::default());
    /// assert_eq!(world.set_spring_scale(0.5), 1);
    /// assert_eq!(world.spring_scale(), 0.5);
    /// assert_eq!(world.edge_joint(&0, &1), Some(EdgeJoint::default()), "the kind is unscaled");
    /// ```
    pub fn set_spring_scale(&mut self, scale: f32) -> usize {
        self.set_spring_scale_by_stretch(scale, scale, f32::INFINITY)
    }

    /// Like [`set_spring_scale`](Self::set_spring_scale), choosing the factor by how far
    /// the graph is from its rest lengths: every spring is scaled by `near` while the
    /// springs' median stretch (length over rest length, read now) is at most
    /// `stretch_limit`, by `far` once it is twice that or more, and by a geometric blend
    /// of the two in between. A non-finite or non-positive limit always gives `near`.
    /// A cooling layout passes `heat^spring_exponent`, the heat and
    /// [`Cooling::stretch_limit`](crate::Cooling::stretch_limit). Calls with the same three
    /// values as the last are skipped unless bodies or joints changed since (the median
    /// is read again then). Returns how many joints changed.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, EdgeJoint, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// let bind = |id| NodeAvatarBinding::circle(id, 16.0);
    /// world.build_bodies(&[bind(0_u32), bind(1)], &[snap(0, 0.0), snap(1, 450.0)]);
    /// world.insert_edge_joint(&0, &1, &EdgeJoint::default()); // rest length 100
    /// // Stretched 4.5 times: half way from a limit of 3 to twice it.
    /// assert_eq!(world.set_spring_scale_by_stretch(0.04, 0.01, 3.0), 1);
    /// assert!((world.applied_spring_scale() - 0.02).abs() < 1e-6, "{}", world.applied_spring_scale());
    /// // Within 10 times its rest length: `near`.
    /// world.set_spring_scale_by_stretch(0.04, 0.01, 10.0);
    /// assert_eq!(world.applied_spring_scale(), 0.04);
    /// ```
    pub fn set_spring_scale_by_stretch(
        &mut self,
        near: f32,
        far: f32,
        stretch_limit: f32,
    ) -> usize {
        let near = finite_or(near, 0.0).max(0.0);
        let far = finite_or(far, 0.0).max(0.0);
        let limit = if stretch_limit.is_finite() && stretch_limit > 0.0 {
            stretch_limit
        } else {
            f32::INFINITY
        };
        // The median matters only between two different factors.
        let by_stretch = limit.is_finite() && near.to_bits() != far.to_bits();
        if (near, far, limit) == (self.spring_scale, self.far_spring_scale, self.stretch_limit)
            && (!by_stretch || self.spring_scale_version == self.version)
        {
            return 0;
        }
        self.spring_scale = near;
        self.far_spring_scale = far;
        self.stretch_limit = limit;
        self.spring_scale_version = self.version;
        let blend = if by_stretch {
            (self.median_spring_stretch() / limit - 1.0).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let scale = if blend > 0.0 {
            finite_or(near.powf(1.0 - blend) * far.powf(blend), near)
        } else {
            near
        };
        if scale.to_bits() == self.applied_spring_scale.to_bits() {
            return 0;
        }
        self.applied_spring_scale = scale;
        let mut changed = 0;
        for joint in &self.joints {
            if !matches!(joint.kind, EdgeJoint::Spring { .. }) {
                continue;
            }
            let (Some(&ia), Some(&ib)) = (self.index.get(&joint.a), self.index.get(&joint.b))
            else {
                continue;
            };
            if let (Some(data), Some(rapier)) = (
                self.joint_data(ia, ib, &joint.kind, scale),
                self.impulse_joints.get_mut(joint.handle, false),
            ) {
                rapier.data = data;
                changed += 1;
            }
        }
        changed
    }

    /// The median of length over rest length across the springs (0 without any).
    fn median_spring_stretch(&self) -> f32 {
        let mut stretches: Vec<f32> = self
            .springs()
            // A rest length that is not finite and positive builds a joint of rest 0
            // (infinitely stretched): left out, as it says nothing about the layout.
            .filter(|&(_, _, rest_length, _, _)| rest_length.is_finite() && rest_length > 0.0)
            .filter_map(|(a, b, rest_length, _, _)| {
                let length = (self.position_at(a) - self.position_at(b)).length();
                let stretch = length / rest_length;
                stretch.is_finite().then_some(stretch)
            })
            .collect();
        if stretches.is_empty() {
            return 0.0;
        }
        let mid = stretches.len() / 2;
        *stretches.select_nth_unstable_by(mid, f32::total_cmp).1
    }

    /// The rapier joint for `kind` between the bodies in slots `a` and `b`: springs
    /// scaled by `scale` and capped for the bodies' reduced mass at the joint timestep.
    fn joint_data(&self, a: u32, b: u32, kind: &EdgeJoint, scale: f32) -> Option<GenericJoint> {
        let (ma, mb) = (self.slots[a as usize].mass, self.slots[b as usize].mass);
        let built = scaled_spring(kind, |x| x * scale);
        rapier_joint(&built, ma * mb / (ma + mb), self.joint_dt)
    }

    /// The factor [`set_spring_scale`](Self::set_spring_scale) last set, or the `near`
    /// factor of [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch)
    /// (1 by default).
    pub fn spring_scale(&self) -> f32 {
        self.spring_scale
    }

    /// The factor every spring's stiffness and damping has now: what the last
    /// [`set_spring_scale_by_stretch`](Self::set_spring_scale_by_stretch) chose (1 by
    /// default).
    pub fn applied_spring_scale(&self) -> f32 {
        self.applied_spring_scale
    }

    /// Every spring joint as `(slot a, slot b, rest length, stiffness, stiffness cap)`,
    /// in joint order: the stiffness as inserted (before the spring scale), the cap what
    /// the joint timestep resolves for the two bodies. Valid until
    /// [`version`](Self::version) changes.
    pub(crate) fn springs(&self) -> impl Iterator<Item = (usize, usize, f32, f32, f32)> + '_ {
        self.joints.iter().filter_map(|joint| {
            let EdgeJoint::Spring {
                rest_length,
                stiffness,
                ..
            } = joint.kind
            else {
                return None;
            };
            let (a, b) = (
                *self.index.get(&joint.a)? as usize,
                *self.index.get(&joint.b)? as usize,
            );
            let (ma, mb) = (self.slots[a].mass, self.slots[b].mass);
            let cap = max_resolved_stiffness(ma * mb / (ma + mb), self.joint_dt);
            Some((a, b, rest_length, stiffness, cap))
        })
    }

    /// A counter bumped by every change to bodies, joints, masses or the joint timestep.
    pub(crate) fn version(&self) -> u64 {
        self.version
    }

    /// Removes the joint between `a` and `b` (either order). Returns whether there was one.
    pub fn remove_edge_joint(&mut self, a: &N, b: &N) -> bool {
        let (Some(&ia), Some(&ib)) = (self.index.get(a), self.index.get(b)) else {
            return false;
        };
        let key = joint_key(
            self.slots[ia as usize].serial,
            self.slots[ib as usize].serial,
        );
        match self.joint_index.get(&key) {
            Some(&i) => {
                self.remove_joint_at(i as usize, true);
                true
            }
            None => false,
        }
    }

    fn remove_joint_at(&mut self, i: usize, remove_from_rapier: bool) {
        self.version += 1;
        let removed = self.joints.swap_remove(i);
        self.joint_index.remove(&removed.key);
        if remove_from_rapier {
            self.impulse_joints.remove(removed.handle, true);
        }
        if let Some(moved) = self.joints.get(i) {
            self.joint_index.insert(moved.key, i as u32);
        }
    }

    /// Keeps only the joints for which `keep(a, b)` is true, visiting them in insertion
    /// order (swap removals aside), so the same calls give the same world.
    pub fn retain_edge_joints(&mut self, mut keep: impl FnMut(&N, &N) -> bool) {
        let mut i = 0;
        while i < self.joints.len() {
            if keep(&self.joints[i].a, &self.joints[i].b) {
                i += 1;
            } else {
                self.remove_joint_at(i, true);
            }
        }
    }

    /// Removes every joint, keeping the bodies and their motion.
    pub fn clear_edge_joints(&mut self) {
        self.version += 1;
        for joint in self.joints.drain(..) {
            self.impulse_joints.remove(joint.handle, true);
        }
        self.joint_index.clear();
    }
}

// ── simulation ────────────────────────────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Sets the length of the next steps, in seconds. Non-finite or non-positive values
    /// are ignored.
    ///
    /// # Example
    /// ```
    /// let mut world = graph_canvas_layout::RapierSceneWorld::<u32>::new();
    /// world.set_timestep(1.0 / 120.0);
    /// assert_eq!(world.integration_parameters().dt, 1.0 / 120.0);
    /// ```
    pub fn set_timestep(&mut self, dt: f32) {
        if dt.is_finite() && dt > 0.0 {
            self.params.dt = dt;
            self.version += 1;
            self.joint_dt = dt;
        }
    }

    /// Rapier's integration parameters (timestep, solver iterations, length unit).
    pub fn integration_parameters(&self) -> &IntegrationParameters {
        &self.params
    }

    /// Rapier's integration parameters, to tune.
    pub fn integration_parameters_mut(&mut self) -> &mut IntegrationParameters {
        &mut self.params
    }

    /// Advances the world by one timestep under `gravity` (world units per second²;
    /// non-finite components count as zero). Contacts are recorded for
    /// [`read_events`](Self::read_events) when the world reports events; bodies whose
    /// state went non-finite are put back, at rest, where rapier last saw them valid.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.step(Vector2D::new(0.0, 600.0));
    /// assert!(world.linear_velocity(&0).unwrap().y > 0.0);
    /// ```
    pub fn step(&mut self, gravity: Vector2D<f32>) {
        let gravity = Vector::new(finite_or(gravity.x, 0.0), finite_or(gravity.y, 0.0));
        let events: &dyn rapier2d::pipeline::EventHandler = match &self.collector {
            Some(collector) => collector,
            None => &(),
        };
        self.pipeline.step(
            gravity,
            &self.params,
            &mut self.islands,
            &mut self.broad_phase,
            &mut self.narrow_phase,
            &mut self.bodies,
            &mut self.colliders,
            &mut self.impulse_joints,
            &mut self.multibody_joints,
            &mut self.soft_bodies,
            &mut self.ccd_solver,
            &(),
            events,
        );
        self.recover_quarantined();
        self.collect_events();
    }

    /// Rapier disables bodies whose state went non-finite and rolls them back to their
    /// last valid pose. A disabled node would silently stop simulating, so re-enable it
    /// at rest and report it.
    fn recover_quarantined(&mut self) {
        if self.pipeline.quarantine().bodies().is_empty() {
            return;
        }
        let handles: Vec<RigidBodyHandle> = self.pipeline.quarantine().bodies().to_vec();
        for handle in handles {
            let Some(body) = self.bodies.get_mut(handle) else {
                continue;
            };
            let slot = body.user_data as usize;
            let translation = body.translation();
            if !translation.is_finite() {
                let fallback = self
                    .slots
                    .get(slot)
                    .map_or(Point2D::origin(), |s| s.initial);
                body.set_translation(to_vector(fallback), false);
            }
            body.set_linvel(Vector::ZERO, false);
            body.set_enabled(true);
            if let Some(slot) = self.slots.get(slot) {
                self.recovered.push(slot.id.clone());
            }
        }
    }

    fn collect_events(&mut self) {
        let Some(collector) = self.collector.as_mut() else {
            return;
        };
        collector.drain_into(&mut self.raw_events);
        for event in self.raw_events.drain(..) {
            let node_of = |handle: ColliderHandle| {
                let body = self.colliders.get(handle)?.parent()?;
                let slot = self.bodies.get(body)?.user_data as usize;
                self.slots.get(slot).map(|s| s.id.clone())
            };
            let (Some(a), Some(b)) = (node_of(event.collider1()), node_of(event.collider2()))
            else {
                continue;
            };
            if self.events.len() >= MAX_PENDING_EVENTS {
                self.events.pop_front();
                self.dropped_events += 1;
            }
            self.events.push_back(if event.started() {
                SceneEvent::ContactBegin { a, b }
            } else {
                SceneEvent::ContactEnd { a, b }
            });
        }
    }

    /// Drains the contact events recorded since the last call, oldest first. Empty when
    /// the world does not report events.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld, SceneEvent};
    /// let mut world = RapierSceneWorld::new();
    /// let snaps = [
    ///     NodeSnapshot { id: 0_u32, position: Point2D::new(0.0, 0.0), radius: 16.0, pinned: false },
    ///     NodeSnapshot { id: 1, position: Point2D::new(20.0, 0.0), radius: 16.0, pinned: false },
    /// ];
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0), NodeAvatarBinding::circle(1, 16.0)], &snaps);
    /// world.step(Vector2D::zero());
    /// assert!(world.read_events().iter().any(|e| matches!(e, SceneEvent::ContactBegin { .. })));
    /// assert!(world.read_events().is_empty(), "drained");
    /// ```
    pub fn read_events(&mut self) -> Vec<SceneEvent<N>> {
        self.events.drain(..).collect()
    }

    /// How many events were dropped because more than [`MAX_PENDING_EVENTS`] waited.
    pub fn dropped_event_count(&self) -> u64 {
        self.dropped_events
    }

    /// Drains the nodes whose bodies went non-finite and were recovered since the last
    /// call.
    pub fn take_recovered_nodes(&mut self) -> Vec<N> {
        std::mem::take(&mut self.recovered)
    }
}

// ── per-node access ───────────────────────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    pub(crate) fn slot_of(&self, node: &N) -> Option<usize> {
        self.index.get(node).map(|&i| i as usize)
    }

    fn body_mut(&mut self, node: &N) -> Option<&mut rapier2d::prelude::RigidBody> {
        let slot = self.slot_of(node)?;
        self.bodies.get_mut(self.slots[slot].body)
    }

    pub(crate) fn body_at(&self, slot: usize) -> &rapier2d::prelude::RigidBody {
        &self.bodies[self.slots[slot].body]
    }

    pub(crate) fn body_at_mut(&mut self, slot: usize) -> &mut rapier2d::prelude::RigidBody {
        &mut self.bodies[self.slots[slot].body]
    }

    /// Number of slots (one per body), the length of every per-slot buffer.
    pub(crate) fn slot_count(&self) -> usize {
        self.slots.len()
    }

    pub(crate) fn position_at(&self, slot: usize) -> Point2D<f32> {
        to_point(self.body_at(slot).translation())
    }

    /// Per node, the displacement since its anchor (the build position, or the last
    /// [`rebase_initial_position`](Self::rebase_initial_position)), for displacements
    /// longer than [`POSITION_EPSILON`].
    pub fn read_positions(&self) -> DeltaMap<N> {
        let mut out = DeltaMap::with_capacity_and_hasher(self.slots.len(), IdHasher::default());
        for (i, slot) in self.slots.iter().enumerate() {
            let delta = self.position_at(i) - slot.initial;
            if delta.square_length() > POSITION_EPSILON * POSITION_EPSILON && delta.is_finite() {
                out.insert(slot.id.clone(), delta);
            }
        }
        out
    }

    /// Adds `impulse` (mass × velocity) to a node's body and wakes it. Ignored for
    /// unknown nodes and non-finite impulses.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.apply_impulse(&0, Vector2D::new(100.0, 0.0));
    /// assert!(world.linear_velocity(&0).unwrap().x > 0.0);
    /// ```
    pub fn apply_impulse(&mut self, node: &N, impulse: Vector2D<f32>) {
        if !impulse.is_finite() {
            return;
        }
        let Some(slot) = self.slot_of(node) else {
            return;
        };
        // Through the node's own mass: rapier's effective mass of a body inserted since
        // the last step is only computed at the next step.
        let mass = self.slots[slot].mass;
        let body = self.body_at_mut(slot);
        if body.is_dynamic() {
            let dv = Vector::new(impulse.x, impulse.y) / mass;
            let v = body.linvel() + dv;
            body.set_linvel(v, true);
        }
    }

    /// Drives a node's body to `position`: a kinematic body reaches it at the next step
    /// (moving at the speed that takes), any other body is put there at once.
    pub fn set_kinematic_position(&mut self, node: &N, position: Point2D<f32>) {
        if !position.is_finite() {
            return;
        }
        if let Some(body) = self.body_mut(node) {
            if body.is_kinematic() {
                body.set_next_kinematic_translation(to_vector(position));
            } else {
                body.set_translation(to_vector(position), true);
            }
        }
    }

    /// Moves a node's anchor to `position` without touching its body, so the next
    /// [`read_positions`](Self::read_positions) reports motion from there.
    pub fn rebase_initial_position(&mut self, node: &N, position: Point2D<f32>) {
        if let Some(slot) = self.slot_of(node) {
            if position.is_finite() {
                self.slots[slot].initial = position;
            }
        }
    }

    /// Teleports a node's body to `position` with its velocity reset (a host edit).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.apply_impulse(&0, Vector2D::new(100.0, 0.0));
    /// world.set_dynamic_position(&0, Point2D::new(50.0, 50.0));
    /// assert_eq!(world.get_position(&0), Some(Point2D::new(50.0, 50.0)));
    /// assert_eq!(world.linear_velocity(&0), Some(Vector2D::zero()));
    /// ```
    pub fn set_dynamic_position(&mut self, node: &N, position: Point2D<f32>) {
        if !position.is_finite() {
            return;
        }
        if let Some(body) = self.body_mut(node) {
            body.set_translation(to_vector(position), true);
            body.set_linvel(Vector::ZERO, true);
        }
    }

    /// Flips a node's body to kinematic (position-based) in place: no rebuild, no change
    /// of position or velocity.
    pub fn mark_body_kinematic(&mut self, node: &N) {
        if let Some(body) = self.body_mut(node) {
            if body.body_type() != RigidBodyType::KinematicPositionBased {
                body.set_body_type(RigidBodyType::KinematicPositionBased, true);
            }
        }
    }

    /// Flips a node's body to dynamic in place and gives it `velocity` (world units per
    /// second; non-finite components count as zero).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding, NodeSnapshot, RapierSceneWorld};
    /// use graph_canvas_layout::rapier2d::prelude::RigidBodyType;
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.mark_body_kinematic(&0);
    /// world.hand_off_kinematic_to_dynamic(&0, Vector2D::new(1200.0, 0.0));
    /// assert_eq!(world.body_type(&0), Some(RigidBodyType::Dynamic));
    /// assert_eq!(world.linear_velocity(&0), Some(Vector2D::new(1200.0, 0.0)));
    /// ```
    pub fn hand_off_kinematic_to_dynamic(&mut self, node: &N, velocity: Vector2D<f32>) {
        if let Some(body) = self.body_mut(node) {
            body.set_body_type(RigidBodyType::Dynamic, true);
            body.set_linvel(
                Vector::new(finite_or(velocity.x, 0.0), finite_or(velocity.y, 0.0)),
                true,
            );
        }
    }

    /// The node's rapier body type, if it has a body.
    pub fn body_type(&self, node: &N) -> Option<RigidBodyType> {
        let slot = self.slot_of(node)?;
        Some(self.body_at(slot).body_type())
    }

    /// Where the node's body is.
    pub fn get_position(&self, node: &N) -> Option<Point2D<f32>> {
        Some(self.position_at(self.slot_of(node)?))
    }

    /// The node's body's velocity in world units per second.
    pub fn linear_velocity(&self, node: &N) -> Option<Vector2D<f32>> {
        let v = self.body_at(self.slot_of(node)?).linvel();
        Some(Vector2D::new(v.x, v.y))
    }

    /// Whether the node's body takes part in the simulation (rapier disables bodies whose
    /// state went non-finite; this world re-enables them at once).
    pub fn is_enabled(&self, node: &N) -> Option<bool> {
        Some(self.body_at(self.slot_of(node)?).is_enabled())
    }

    /// Whether the node's body is asleep (at rest, skipped by the solver).
    pub fn is_sleeping(&self, node: &N) -> Option<bool> {
        Some(self.body_at(self.slot_of(node)?).is_sleeping())
    }

    /// Number of bodies.
    pub fn body_count(&self) -> usize {
        self.bodies.len()
    }

    /// Number of colliders (zero when collisions are off).
    pub fn collider_count(&self) -> usize {
        self.colliders.len()
    }

    /// Number of joints.
    pub fn joint_count(&self) -> usize {
        self.impulse_joints.len()
    }

    /// Whether the node has a body.
    pub fn contains_node(&self, node: &N) -> bool {
        self.index.contains_key(node)
    }

    /// Whether the pair (either order) has a joint.
    pub fn contains_joint(&self, a: &N, b: &N) -> bool {
        self.edge_joint(a, b).is_some()
    }

    /// The joint between `a` and `b` (either order) as it was built, before the
    /// stiffness limit: with
    /// [`RapierLayoutConfig::spring_degree_exponent`](crate::RapierLayoutConfig::spring_degree_exponent)
    /// a spring's share of the configured stiffness shows here. `None` without a joint.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, EdgeJoint, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// world.build_bodies(
    ///     &[NodeAvatarBinding::circle(0_u32, 16.0), NodeAvatarBinding::circle(1, 16.0)],
    ///     &[snap(0, 0.0), snap(1, 300.0)],
    /// );
    /// world.insert_edge_joint(&0, &1, &EdgeJoint::default());
    /// assert_eq!(world.edge_joint(&1, &0), Some(EdgeJoint::default()));
    /// assert_eq!(world.edge_joint(&0, &0), None);
    /// ```
    pub fn edge_joint(&self, a: &N, b: &N) -> Option<EdgeJoint> {
        let (ia, ib) = (self.slot_of(a)?, self.slot_of(b)?);
        let key = joint_key(self.slots[ia].serial, self.slots[ib].serial);
        let &i = self.joint_index.get(&key)?;
        Some(self.joints[i as usize].kind)
    }

    /// The node ids, in body insertion order (removals swap the last node into the gap).
    pub fn node_ids(&self) -> impl Iterator<Item = &N> + '_ {
        self.slots.iter().map(|s| &s.id)
    }

    /// The topology hash this world was built or last patched for (0 when unset).
    pub fn topology_hash(&self) -> u64 {
        self.topology_hash
    }

    /// Records the topology hash this world now stands for.
    pub fn set_topology_hash(&mut self, hash: u64) {
        self.topology_hash = hash;
    }

    /// Clears the forces added to every body (they persist across steps until cleared).
    pub fn reset_forces(&mut self) {
        for slot in 0..self.slots.len() {
            self.body_at_mut(slot).reset_forces(true);
        }
    }

    /// Number of bodies rapier is simulating (awake dynamic and kinematic ones). O(1).
    pub fn awake_body_count(&self) -> usize {
        self.islands.num_active_bodies()
    }

    /// Stops every dynamic body where it is: velocity zeroed and added forces cleared,
    /// without waking anything. Returns how many dynamic bodies there are. A halted body
    /// moves again only if something pushes it in a later [`step`](Self::step) (a joint,
    /// a contact, gravity): [`RapierLayout`](crate::RapierLayout) halts a cooled layout
    /// and then stops stepping it until a disturbance.
    ///
    /// Rapier's own `RigidBody::sleep` is not used for this: it flags the body asleep
    /// without taking its island out of the simulation, so joints and gravity kept moving
    /// the flagged bodies while contacts between them were skipped.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = NodeSnapshot { id: 0_u32, position: Point2D::origin(), radius: 16.0, pinned: false };
    /// world.build_bodies(&[NodeAvatarBinding::circle(0, 16.0)], &[snap]);
    /// world.apply_impulse(&0, Vector2D::new(100.0, 0.0));
    /// assert_eq!(world.halt_dynamic_bodies(), 1);
    /// world.step(Vector2D::zero());
    /// assert_eq!(world.get_position(&0), Some(Point2D::origin()), "halted, it did not fly");
    /// ```
    pub fn halt_dynamic_bodies(&mut self) -> usize {
        let mut halted = 0;
        for s in 0..self.slots.len() {
            let body = self.body_at_mut(s);
            if body.is_dynamic() {
                body.set_linvel(Vector::ZERO, false);
                body.reset_forces(false);
                halted += 1;
            }
        }
        halted
    }

    /// The former name of [`halt_dynamic_bodies`](Self::halt_dynamic_bodies), which it
    /// now calls: rapier's own sleep left the bodies' island simulated.
    #[deprecated(note = "use `halt_dynamic_bodies`: rapier's sleep left the island simulated")]
    pub fn sleep_dynamic_bodies(&mut self) -> usize {
        self.halt_dynamic_bodies()
    }

    /// Turns contacts between nodes off or on, keeping the colliders: off, the broad and
    /// narrow phases skip them (and report no contact events), so nodes pass through
    /// each other. Turning them on wakes every body, so overlaps made meanwhile are
    /// parted. Nodes inserted meanwhile follow the setting. O(n) when it changes, free
    /// otherwise.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, NodeAvatarBinding,
    ///     NodeSnapshot, RapierSceneWorld};
    /// let mut world = RapierSceneWorld::new();
    /// let snap = |id, x| NodeSnapshot { id, position: Point2D::new(x, 0.0), radius: 16.0, pinned: false };
    /// world.build_bodies(
    ///     &[NodeAvatarBinding::circle(0_u32, 16.0), NodeAvatarBinding::circle(1, 16.0)],
    ///     &[snap(0, 0.0), snap(1, 10.0)],
    /// );
    /// world.set_contacts_enabled(false);
    /// world.step(Vector2D::zero());
    /// assert!(world.read_positions().is_empty(), "without contacts the overlap stays");
    /// world.set_contacts_enabled(true);
    /// world.step(Vector2D::zero());
    /// assert_eq!(world.read_positions().len(), 2, "contacts push the pair apart");
    /// ```
    pub fn set_contacts_enabled(&mut self, enabled: bool) {
        if enabled == self.contacts_enabled {
            return;
        }
        self.contacts_enabled = enabled;
        for slot in &self.slots {
            if let Some(collider) = slot.collider.and_then(|c| self.colliders.get_mut(c)) {
                collider.set_enabled(enabled);
            }
        }
        if enabled {
            // A body asleep in an overlap would not notice its new contacts.
            self.wake_dynamic_bodies();
        }
    }

    /// Whether contacts take part in the simulation; see
    /// [`set_contacts_enabled`](Self::set_contacts_enabled).
    pub fn contacts_enabled(&self) -> bool {
        self.contacts_enabled
    }

    /// Wakes every sleeping dynamic body within reach of the node in `slot` as it moves
    /// from `from` to `to` (its bounding disk swept along the segment, plus a tenth of
    /// the two radii). A kinematic or fixed body that the host moves into a sleeping
    /// body does not wake it in rapier, so without this a dragged node passed through
    /// nodes at rest. Returns how many bodies were woken. O(n).
    pub(crate) fn wake_bodies_near_sweep(
        &mut self,
        slot: usize,
        from: Point2D<f32>,
        to: Point2D<f32>,
    ) -> usize {
        let reach = self.slots[slot].shape.bounding_radius();
        let segment = to - from;
        let length_sq = segment.square_length();
        let mut woken = 0;
        for s in 0..self.slots.len() {
            if s == slot {
                continue;
            }
            let handle = self.slots[s].body;
            let Some(body) = self.bodies.get(handle) else {
                continue;
            };
            if !(body.is_dynamic() && body.is_sleeping()) {
                continue;
            }
            let p = self.position_at(s);
            let t = if length_sq > 0.0 {
                ((p - from).dot(segment) / length_sq).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let closest = from + segment * t;
            let within = 1.1 * (reach + self.slots[s].shape.bounding_radius());
            if (p - closest).square_length() <= within * within {
                if let Some(body) = self.bodies.get_mut(handle) {
                    body.wake_up(true);
                    woken += 1;
                }
            }
        }
        woken
    }

    /// Wakes every sleeping dynamic body. Returns how many were woken. O(n).
    pub(crate) fn wake_dynamic_bodies(&mut self) -> usize {
        let mut woken = 0;
        for s in 0..self.slots.len() {
            let body = self.body_at_mut(s);
            if body.is_dynamic() && body.is_sleeping() {
                body.wake_up(true);
                woken += 1;
            }
        }
        woken
    }

    /// Number of dynamic bodies that are awake.
    pub fn awake_dynamic_count(&self) -> usize {
        self.bodies
            .iter()
            .filter(|(_, b)| b.is_dynamic() && !b.is_sleeping())
            .count()
    }

    /// Gives a node a new shape in place (radius edits), keeping its motion; its mass
    /// follows the new area.
    pub(crate) fn set_shape_at(&mut self, slot: usize, shape: ColliderSpec, density: f32) {
        self.version += 1;
        let shape = sanitize_shape(shape);
        let mass = body_mass(shape, density);
        let s = &mut self.slots[slot];
        s.shape = shape;
        s.mass = mass;
        if let Some(collider) = s.collider.and_then(|c| self.colliders.get_mut(c)) {
            collider.set_shape(shared_shape(shape));
        }
        self.bodies[s.body].set_additional_mass(mass, true);
    }
}

fn joint_key(a: u64, b: u64) -> (u64, u64) {
    (a.min(b), a.max(b))
}

/// A shape with finite, non-negative extents.
fn sanitize_shape(shape: ColliderSpec) -> ColliderSpec {
    match shape {
        ColliderSpec::Circle { radius } => ColliderSpec::Circle {
            radius: finite_or(radius, 0.0).max(0.0),
        },
        ColliderSpec::Rect { half_extents } => ColliderSpec::Rect {
            half_extents: Vector2D::new(
                finite_or(half_extents.x, 0.0).max(0.0),
                finite_or(half_extents.y, 0.0).max(0.0),
            ),
        },
    }
}

fn shared_shape(shape: ColliderSpec) -> SharedShape {
    match shape {
        ColliderSpec::Circle { radius } => SharedShape::ball(radius),
        ColliderSpec::Rect { half_extents } => SharedShape::cuboid(half_extents.x, half_extents.y),
    }
}

fn body_mass(shape: ColliderSpec, density: f32) -> f32 {
    let mass = finite_or(density, 0.0).max(0.0) * shape.area();
    if mass.is_finite() {
        mass.max(MIN_BODY_MASS)
    } else {
        f32::MAX.sqrt()
    }
}
