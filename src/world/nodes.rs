//! Bodies in and out: [`RapierSceneWorld::build_bodies`], `insert_node`, `remove_node`
//! (which takes the node's joints with it) and in-place shape edits. A body built from a
//! binding weighs `density × area`, never below [`MIN_BODY_MASS`](crate::world::MIN_BODY_MASS);
//! the layout gives its boxes the mass of a default disk instead (`adapter/edits.rs`).

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::{ActiveEvents, ColliderBuilder, RigidBodyBuilder, SharedShape};

use super::slot::{HostSync, NodeSlot};
use super::{to_vector, RapierSceneWorld, MIN_BODY_MASS};
use crate::sanitize::finite_or;
use crate::world::bindings::{ColliderSpec, NodeAvatarBinding, NodeSnapshot};

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
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
        self.ids.push(binding.node_id.clone());
        self.slots.push(NodeSlot {
            serial: self.next_serial,
            body,
            collider,
            shape,
            mass,
            anchor: position,
            host: HostSync::new(position),
        });
        self.next_serial += 1;
        self.version += 1;
        self.touched = true;
        self.changes.mark_all();
        true
    }

    /// Removes a node's body, its collider and every joint attached to it. Returns
    /// whether the node had a body.
    pub fn remove_node(&mut self, node: &N) -> bool {
        let Some(slot_index) = self.index.remove(node) else {
            return false;
        };
        self.version += 1;
        self.changes.mark_all();
        let slot_index = slot_index as usize;
        let removed = self.slots.swap_remove(slot_index);
        self.ids.swap_remove(slot_index);
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
            self.index
                .insert(self.ids[slot_index].clone(), slot_index as u32);
            if let Some(body) = self.bodies.get_mut(moved.body) {
                body.user_data = slot_index as u128;
            }
        }
        true
    }

    /// Gives a node a new shape and mass in place (radius and shape edits), keeping its
    /// motion.
    pub(crate) fn set_shape_at(&mut self, slot: usize, shape: ColliderSpec, mass: f32) {
        self.version += 1;
        let shape = sanitize_shape(shape);
        let mass = sane_mass(mass);
        let s = &mut self.slots[slot];
        s.shape = shape;
        s.mass = mass;
        if let Some(collider) = s.collider.and_then(|c| self.colliders.get_mut(c)) {
            collider.set_shape(shared_shape(shape));
        }
        self.bodies[s.body].set_additional_mass(mass, true);
        self.changes.mark(slot, self.slots.len());
    }

    /// Gives a node a mass of its own in place (the layout's boxes weigh what a default
    /// disk weighs), keeping its motion.
    pub(crate) fn set_mass_at(&mut self, slot: usize, mass: f32) {
        let mass = sane_mass(mass);
        let s = &mut self.slots[slot];
        if s.mass.to_bits() == mass.to_bits() {
            return;
        }
        self.version += 1;
        s.mass = mass;
        self.bodies[s.body].set_additional_mass(mass, true);
        self.changes.mark(slot, self.slots.len());
    }
}

/// A shape with finite, non-negative extents.
fn sanitize_shape(shape: ColliderSpec) -> ColliderSpec {
    match shape {
        ColliderSpec::Circle { radius } => ColliderSpec::Circle {
            radius: finite_or(radius, 0.0).max(0.0),
        },
        ColliderSpec::Rect { half_extents } => ColliderSpec::Rect {
            half_extents: sanitize_extents(half_extents),
        },
        ColliderSpec::RoundRect {
            half_extents,
            corner_radius,
        } => {
            let half_extents = sanitize_extents(half_extents);
            ColliderSpec::RoundRect {
                half_extents,
                corner_radius: finite_or(corner_radius, 0.0)
                    .clamp(0.0, half_extents.x.min(half_extents.y)),
            }
        }
    }
}

fn sanitize_extents(half_extents: Vector2D<f32>) -> Vector2D<f32> {
    Vector2D::new(
        finite_or(half_extents.x, 0.0).max(0.0),
        finite_or(half_extents.y, 0.0).max(0.0),
    )
}

fn shared_shape(shape: ColliderSpec) -> SharedShape {
    match shape {
        ColliderSpec::Circle { radius } => SharedShape::ball(radius),
        ColliderSpec::Rect { half_extents } => SharedShape::cuboid(half_extents.x, half_extents.y),
        ColliderSpec::RoundRect { .. } => {
            let (inner, c) = shape.inner_and_round();
            SharedShape::round_cuboid(inner.x, inner.y, c)
        }
    }
}

/// A body's mass from its shape's area and the material's density.
pub(crate) fn body_mass(shape: ColliderSpec, density: f32) -> f32 {
    sane_mass(finite_or(density, 0.0).max(0.0) * shape.area())
}

/// A usable mass: finite, never below [`MIN_BODY_MASS`].
fn sane_mass(mass: f32) -> f32 {
    if mass.is_finite() {
        mass.max(MIN_BODY_MASS)
    } else {
        f32::MAX.sqrt()
    }
}
