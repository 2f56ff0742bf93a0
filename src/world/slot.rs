//! The bookkeeping the world keeps beside rapier's bodies and joints: per node its
//! body, shape, mass and anchor, plus the adapter's sync state ([`HostSync`]), which
//! moves with the slot when a removal swaps another node into its place; per joint its
//! key and the [`EdgeJoint`] it was built as.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::{
    ColliderHandle, ImpulseJointHandle, RigidBody, RigidBodyHandle, RigidBodySet,
};
use serde::{Deserialize, Serialize};

use super::RapierSceneWorld;
use crate::input::node_forces::AxisLock;
use crate::world::bindings::ColliderSpec;
use crate::world::EdgeJoint;

/// One node's body and the bookkeeping kept for it; its id is kept apart
/// (`RapierSceneWorld::ids`, same index), so that the slots, free of the host's id
/// type, can be read side by side under `parallel` ([`SlotsView`]).
#[derive(Clone, Debug)]
pub(crate) struct NodeSlot {
    /// Never reused: names the node in joint keys across swaps and removals.
    pub(crate) serial: u64,
    pub(crate) body: RigidBodyHandle,
    pub(crate) collider: Option<ColliderHandle>,
    pub(crate) shape: ColliderSpec,
    pub(crate) mass: f32,
    /// The anchor `read_positions` measures from.
    pub(crate) anchor: Point2D<f32>,
    /// What the adapter knows of the host's side of this node.
    pub(crate) host: HostSync,
}

/// What [`RapierLayout`](crate::RapierLayout) keeps per node between calls: what it
/// told the host, the node's pin and drag state, and whether the next sync can skip it.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
pub(crate) struct HostSync {
    /// Where the host should have the node after adding the last delta it was given:
    /// a host position elsewhere is a host edit.
    pub(crate) told: Point2D<f32>,
    /// Call number in which the adapter last saw this node in the scene.
    pub(crate) stamp: u64,
    /// Whether the node was pinned when last matched (the match compares against it).
    pub(crate) pinned: bool,
    pub(crate) dragging: bool,
    /// The host's position of a dragged node at the last call, the pointer's velocity
    /// over its last move (what a release throws the node with), and the seconds since
    /// that move.
    pub(crate) drag_position: Point2D<f32>,
    pub(crate) drag_velocity: Vector2D<f32>,
    pub(crate) drag_still: f32,
    /// Inserted during this call: its body may sit off the host's position (coincident
    /// nodes are spread), which is not a host move.
    pub(crate) fresh: bool,
    /// The last sync left this body dynamic and free (not dragged, pinned or frozen):
    /// while the host keeps the position it was told, the next sync has nothing to do.
    pub(crate) synced: bool,
    /// The node's own heat after a local disturbance
    /// ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)), or 0 while it has the
    /// layout's.
    pub(crate) heat: f32,
    /// The node's per-node forces as the last call applied them
    /// (a hash of its values), 0 for none: a change wakes the node.
    pub(crate) forces_key: u64,
    /// The axis the body's rapier flags lock, as the last call set them.
    pub(crate) lock: Option<AxisLock>,
}

impl HostSync {
    /// A node just inserted at `position`.
    pub(crate) fn new(position: Point2D<f32>) -> Self {
        Self {
            told: position,
            stamp: 0,
            pinned: false,
            dragging: false,
            drag_position: position,
            drag_velocity: Vector2D::zero(),
            drag_still: 0.0,
            fresh: true,
            synced: false,
            heat: 0.0,
            forces_key: 0,
            lock: None,
        }
    }
}

/// One joint and the edge it stands for.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct JointSlot<N> {
    pub(crate) key: (u64, u64),
    /// The rapier joint, or `None` for a spring applied as forces
    /// ([`SpringModel::Forces`](crate::config::SpringModel::Forces)).
    pub(crate) handle: Option<ImpulseJointHandle>,
    pub(crate) a: N,
    pub(crate) b: N,
    /// What the joint was built as: a re-tune to the same kind is skipped.
    pub(crate) kind: EdgeJoint,
    /// The host's weight of its edge (1 for joints inserted without one).
    pub(crate) weight: f32,
}

/// One spring as the forces read it: its two bodies' slots, its parameters as inserted
/// (before the world's spring scale) and the stiffness the joint timestep resolves for
/// the two bodies ([`max_resolved_stiffness`](crate::world::max_resolved_stiffness)).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpringView {
    pub(crate) a: usize,
    pub(crate) b: usize,
    pub(crate) rest_length: f32,
    pub(crate) stiffness: f32,
    pub(crate) damping: f32,
    pub(crate) cap: f32,
}

/// The key of the joint between the nodes of serials `a` and `b`, in either order.
pub(crate) fn joint_key(a: u64, b: u64) -> (u64, u64) {
    (a.min(b), a.max(b))
}

// ── the adapter's access to a slot ────────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// The node in `slot`.
    pub(crate) fn id_at(&self, slot: usize) -> &N {
        &self.ids[slot]
    }

    /// The adapter's sync state of the node in `slot`.
    pub(crate) fn host_at(&self, slot: usize) -> &HostSync {
        self.slots_view().host_at(slot)
    }

    /// The adapter's sync state of the node in `slot`, to update.
    pub(crate) fn host_at_mut(&mut self, slot: usize) -> &mut HostSync {
        &mut self.slots[slot].host
    }

    /// The adapter's sync state and the anchor of the node in `slot`, to update both
    /// with one lookup (the per-node path of a resting layout).
    pub(crate) fn host_and_anchor_mut(
        &mut self,
        slot: usize,
    ) -> (&mut HostSync, &mut Point2D<f32>) {
        let slot = &mut self.slots[slot];
        (&mut slot.host, &mut slot.anchor)
    }

    /// The anchor of the node in `slot`: where `read_positions` measures from.
    pub(crate) fn anchor_at(&self, slot: usize) -> Point2D<f32> {
        self.slots[slot].anchor
    }

    /// Moves the anchor of the node in `slot` (what `rebase_initial_position` does by id).
    pub(crate) fn set_anchor_at(&mut self, slot: usize, anchor: Point2D<f32>) {
        self.slots[slot].anchor = anchor;
    }

    /// The mass of the body in `slot`.
    pub(crate) fn mass_at(&self, slot: usize) -> f32 {
        self.slots_view().mass_at(slot)
    }

    /// The shape of the node in `slot`.
    pub(crate) fn shape_at(&self, slot: usize) -> ColliderSpec {
        self.slots[slot].shape
    }
}

/// The world's bodies and slots without the host's ids: `Sync` whatever the id type,
/// so the forces read them side by side under `parallel`.
#[derive(Clone, Copy)]
pub(crate) struct SlotsView<'a> {
    bodies: &'a RigidBodySet,
    slots: &'a [NodeSlot],
}

impl<'a> SlotsView<'a> {
    /// The body in `slot`.
    pub(crate) fn body_at(&self, slot: usize) -> &'a RigidBody {
        &self.bodies[self.slots[slot].body]
    }

    /// The mass of the body in `slot`.
    pub(crate) fn mass_at(&self, slot: usize) -> f32 {
        self.slots[slot].mass
    }

    /// The adapter's sync state of the node in `slot`.
    pub(crate) fn host_at(&self, slot: usize) -> &'a HostSync {
        &self.slots[slot].host
    }
}

impl<N> RapierSceneWorld<N> {
    /// The bodies and slots, to read side by side.
    pub(crate) fn slots_view(&self) -> SlotsView<'_> {
        SlotsView {
            bodies: &self.bodies,
            slots: &self.slots,
        }
    }
}
