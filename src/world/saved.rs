//! The world as a snapshot keeps it ([`SavedWorld`]): rapier's own state (bodies with
//! their velocities, forces and sleep, colliders, joints with their warm-start impulses,
//! islands, the broad phase's tree and pairs, the narrow phase's contacts, CCD) and the
//! scene mapping beside it, so that a world built back from it steps bit for bit as the
//! one it was taken of. What only speeds a step up (rapier's pipeline workspace, the
//! id lookups, the springs' stretch cache) is not kept: it is built again from the rest.

use std::collections::{HashMap, VecDeque};
use std::hash::Hash;

use euclid::default::Point2D;
use rapier2d::prelude::{
    BroadPhaseBvh, CCDSolver, ColliderHandle, ColliderSet, ImpulseJointSet, IntegrationParameters,
    IslandManager, MultibodyJointSet, NarrowPhase, PhysicsPipeline, RigidBodyHandle, RigidBodySet,
    SoftBodySet,
};
use serde::{Deserialize, Serialize};

use super::bindings::ColliderSpec;
use super::events::{CollisionCollector, SceneEvent};
use super::seal::seal_of;
use super::slot::{HostSync, JointSlot, NodeSlot};
use super::spring_scale::{SpringScale, StretchCache};
use super::{RapierSceneWorld, WorldOptions};
use crate::input::layout::IdHasher;
use crate::input::snapshot_error::{check_counters, SnapshotError};

/// Everything a world needs to continue where it was. Written with the seals of
/// rapier's sets (hashed as it is written: a snapshot kept in memory pays nothing for
/// them), read back with the seals as written.
#[derive(Clone, Deserialize)]
#[serde(bound(deserialize = "N: Deserialize<'de>"))]
pub(crate) struct SavedWorld<N> {
    bodies: RigidBodySet,
    colliders: ColliderSet,
    impulse_joints: ImpulseJointSet,
    multibody_joints: MultibodyJointSet,
    soft_bodies: SoftBodySet,
    islands: IslandManager,
    broad_phase: BroadPhaseBvh,
    narrow_phase: NarrowPhase,
    ccd_solver: CCDSolver,
    params: IntegrationParameters,
    pub(crate) slots: Vec<SavedSlot<N>>,
    next_serial: u64,
    joints: Vec<JointSlot<N>>,
    options: WorldOptions,
    events: VecDeque<SceneEvent<N>>,
    dropped_events: u64,
    recovered: Vec<N>,
    topology_hash: u64,
    spring_scale: SpringScale,
    joint_dt: f32,
    version: u64,
    spring_forces: bool,
    touched: bool,
    ccd_off_once: bool,
    contacts_enabled: bool,
    #[serde(default)]
    hop_length: Option<f32>,
    /// Rapier's sets' seals as they were written (`seal.rs`). None in a format-1
    /// snapshot, which the format check refuses before the seals are read, and in one
    /// taken in this process.
    #[serde(default)]
    seals: Option<RapierSeals>,
    /// Taken by [`RapierSceneWorld::save`] in this process and never written: rapier's
    /// sets are the world's own, with nothing to check them against. Never read back.
    #[serde(skip)]
    taken_here: bool,
}

/// Writes every field as the derived `Deserialize` reads it, with the seals worked out
/// now for a snapshot taken in this process.
macro_rules! write_fields {
    ($world:ident, $out:ident, $seals:ident: $($field:ident),*) => {{
        let mut out = $out.serialize_struct("SavedWorld", [$(stringify!($field)),*].len() + 1)?;
        $(out.serialize_field(stringify!($field), &$world.$field)?;)*
        out.serialize_field("seals", &Some($seals))?;
        out.end()
    }};
}

impl<N: Serialize> Serialize for SavedWorld<N> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let seals = self.seals.unwrap_or_else(|| RapierSeals::of(self));
        write_fields!(self, serializer, seals: bodies, colliders, impulse_joints,
            multibody_joints, soft_bodies, islands, broad_phase, narrow_phase, ccd_solver,
            params, slots, next_serial, joints, options, events, dropped_events, recovered,
            topology_hash, spring_scale, joint_dt, version, spring_forces, touched,
            ccd_off_once, contacts_enabled, hop_length)
    }
}

/// One seal per rapier set ([`seal_of`]), in the order of [`SavedWorld`]'s fields.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
struct RapierSeals([u64; 10]);

/// What each seal covers, for the error that names a broken one.
const SEALED: [&str; 10] = [
    "rapier's bodies",
    "rapier's colliders",
    "rapier's impulse joints",
    "rapier's multibody joints",
    "rapier's soft bodies",
    "rapier's islands",
    "rapier's broad phase",
    "rapier's narrow phase",
    "rapier's CCD solver",
    "rapier's integration parameters",
];

impl RapierSeals {
    fn of<N>(world: &SavedWorld<N>) -> Self {
        Self([
            seal_of(&world.bodies),
            seal_of(&world.colliders),
            seal_of(&world.impulse_joints),
            seal_of(&world.multibody_joints),
            seal_of(&world.soft_bodies),
            seal_of(&world.islands),
            seal_of(&world.broad_phase),
            seal_of(&world.narrow_phase),
            seal_of(&world.ccd_solver),
            seal_of(&world.params),
        ])
    }

    /// The first set whose seal `found` does not match.
    fn broken(self, found: Self) -> Option<&'static str> {
        (0..SEALED.len())
            .find(|&k| self.0[k] != found.0[k])
            .map(|k| SEALED[k])
    }
}

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// A copy of everything this world needs to continue where it is.
    pub(crate) fn save(&self) -> SavedWorld<N> {
        SavedWorld {
            bodies: self.bodies.clone(),
            colliders: self.colliders.clone(),
            impulse_joints: self.impulse_joints.clone(),
            multibody_joints: self.multibody_joints.clone(),
            soft_bodies: self.soft_bodies.clone(),
            islands: self.islands.clone(),
            broad_phase: self.broad_phase.clone(),
            narrow_phase: self.narrow_phase.clone(),
            ccd_solver: self.ccd_solver.clone(),
            params: self.params,
            slots: (self.ids.iter().zip(&self.slots))
                .map(|(id, slot)| SavedSlot::of(id.clone(), slot))
                .collect(),
            next_serial: self.next_serial,
            joints: self.joints.clone(),
            options: self.options,
            events: self.events.clone(),
            dropped_events: self.dropped_events,
            recovered: self.recovered.clone(),
            topology_hash: self.topology_hash,
            spring_scale: self.spring_scale,
            joint_dt: self.joint_dt,
            version: self.version,
            spring_forces: self.spring_forces,
            touched: self.touched,
            ccd_off_once: self.ccd_off_once,
            contacts_enabled: self.contacts_enabled,
            hop_length: self.hop_length,
            seals: None,
            taken_here: true,
        }
    }

    /// The world `saved` describes, after checking that its parts agree (every node's
    /// body, collider and joints exist, ids and joints are not repeated, positions are
    /// finite), so that no later call can meet a handle that leads nowhere.
    ///
    /// # Errors
    /// [`SnapshotError::Inconsistent`] naming the first part that does not agree.
    pub(crate) fn from_saved(saved: SavedWorld<N>) -> Result<Self, SnapshotError> {
        let inconsistent = |what: &str| Err(SnapshotError::Inconsistent(what.to_owned()));
        if !saved.taken_here {
            let Some(seals) = saved.seals else {
                return inconsistent("rapier's state is not sealed");
            };
            if let Some(part) = seals.broken(RapierSeals::of(&saved)) {
                return Err(SnapshotError::Inconsistent(format!(
                    "{part} differ from what rapier wrote (the snapshot was damaged, or written by another build of rapier)"
                )));
            }
        }
        check_counters(&[
            (saved.next_serial, "world.next_serial"),
            (saved.version, "world.version"),
            (saved.dropped_events, "world.dropped_events"),
        ])?;
        let mut index: HashMap<N, u32, IdHasher> =
            HashMap::with_capacity_and_hasher(saved.slots.len(), IdHasher::default());
        let mut colliders = 0;
        for (s, slot) in saved.slots.iter().enumerate() {
            let Some(body) = saved.bodies.get(slot.body) else {
                return inconsistent("a node's body is missing");
            };
            if body.user_data != s as u128 {
                return inconsistent("a body is not the one its node names");
            }
            if !(body.translation().is_finite()
                && body.linvel().is_finite()
                && slot.anchor.is_finite())
            {
                return inconsistent("a node's position or velocity is not finite");
            }
            if let Some(collider) = slot.collider {
                if saved.colliders.get(collider).and_then(|c| c.parent()) != Some(slot.body) {
                    return inconsistent("a node's collider is missing or not on its body");
                }
                colliders += 1;
            }
            if slot.serial >= saved.next_serial {
                return inconsistent("a node's serial is not below the next one");
            }
            if index.insert(slot.id.clone(), s as u32).is_some() {
                return inconsistent("a node id is repeated");
            }
        }
        if saved.bodies.len() != saved.slots.len() || saved.colliders.len() != colliders {
            return inconsistent("bodies or colliders that no node owns");
        }
        let mut joint_index: HashMap<(u64, u64), u32, IdHasher> =
            HashMap::with_capacity_and_hasher(saved.joints.len(), IdHasher::default());
        let mut rapier_joints = 0;
        for (i, joint) in saved.joints.iter().enumerate() {
            let (Some(&a), Some(&b)) = (index.get(&joint.a), index.get(&joint.b)) else {
                return inconsistent("a joint names a node that is missing");
            };
            let (sa, sb) = (&saved.slots[a as usize], &saved.slots[b as usize]);
            if super::slot::joint_key(sa.serial, sb.serial) != joint.key {
                return inconsistent("a joint's key does not name its nodes");
            }
            if let Some(handle) = joint.handle {
                let Some(rapier) = saved.impulse_joints.get(handle) else {
                    return inconsistent("a joint's rapier joint is missing");
                };
                let ends = [rapier.body1(), rapier.body2()];
                if ends != [sa.body, sb.body] && ends != [sb.body, sa.body] {
                    return inconsistent("a joint's rapier joint is between other bodies");
                }
                rapier_joints += 1;
            }
            if joint_index.insert(joint.key, i as u32).is_some() {
                return inconsistent("a joint is repeated");
            }
        }
        if saved.impulse_joints.len() != rapier_joints
            || saved.multibody_joints.multibodies().next().is_some()
        {
            return inconsistent("joints that no edge owns");
        }
        let (ids, slots) = saved.slots.into_iter().map(SavedSlot::split).unzip();
        let collector = (saved.options.collisions && saved.options.contact_events)
            .then(CollisionCollector::default);
        Ok(Self {
            bodies: saved.bodies,
            colliders: saved.colliders,
            impulse_joints: saved.impulse_joints,
            multibody_joints: saved.multibody_joints,
            soft_bodies: saved.soft_bodies,
            islands: saved.islands,
            broad_phase: saved.broad_phase,
            narrow_phase: saved.narrow_phase,
            ccd_solver: saved.ccd_solver,
            pipeline: PhysicsPipeline::new(),
            params: saved.params,
            ids,
            slots,
            index,
            next_serial: saved.next_serial,
            joints: saved.joints,
            joint_index,
            options: saved.options,
            collector,
            raw_events: Vec::new(),
            events: saved.events,
            dropped_events: saved.dropped_events,
            recovered: saved.recovered,
            topology_hash: saved.topology_hash,
            spring_scale: saved.spring_scale,
            stretch: StretchCache::default(),
            joint_dt: saved.joint_dt,
            version: saved.version,
            spring_forces: saved.spring_forces,
            touched: saved.touched,
            changes: Default::default(),
            ccd_off_once: saved.ccd_off_once,
            contacts_enabled: saved.contacts_enabled,
            hop_length: saved.hop_length,
        })
    }
}

impl<N> SavedWorld<N> {
    /// How many nodes the world holds.
    pub(crate) fn node_count(&self) -> usize {
        self.slots.len()
    }

    /// How many edge joints the world holds.
    pub(crate) fn joint_count(&self) -> usize {
        self.joints.len()
    }
}

/// One node's slot as a snapshot keeps it: its id, then the slot's fields.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct SavedSlot<N> {
    id: N,
    serial: u64,
    body: RigidBodyHandle,
    collider: Option<ColliderHandle>,
    shape: ColliderSpec,
    mass: f32,
    anchor: Point2D<f32>,
    host: HostSync,
}

impl<N> SavedSlot<N> {
    fn of(id: N, slot: &NodeSlot) -> Self {
        Self {
            id,
            serial: slot.serial,
            body: slot.body,
            collider: slot.collider,
            shape: slot.shape,
            mass: slot.mass,
            anchor: slot.anchor,
            host: slot.host,
        }
    }

    fn split(self) -> (N, NodeSlot) {
        let slot = NodeSlot {
            serial: self.serial,
            body: self.body,
            collider: self.collider,
            shape: self.shape,
            mass: self.mass,
            anchor: self.anchor,
            host: self.host,
        };
        (self.id, slot)
    }
}
