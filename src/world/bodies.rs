//! The host's per-node calls: read displacements, drive kinematic bodies, teleport,
//! flip body kinds in place (drag start and release), impulses, and what a body is doing.
//! Unknown nodes and non-finite values are ignored.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::{RigidBodyType, Vector};

use super::{to_vector, RapierSceneWorld, POSITION_EPSILON};
use crate::input::layout::{DeltaMap, IdHasher};
use crate::sanitize::finite_or;

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Per node, the displacement since its anchor (the build position, or the last
    /// [`rebase_initial_position`](Self::rebase_initial_position)), for displacements
    /// longer than [`POSITION_EPSILON`].
    pub fn read_positions(&self) -> DeltaMap<N> {
        let mut out = DeltaMap::with_capacity_and_hasher(self.slots.len(), IdHasher::default());
        for (i, (slot, id)) in self.slots.iter().zip(&self.ids).enumerate() {
            let delta = self.position_at(i) - slot.anchor;
            if delta.square_length() > POSITION_EPSILON * POSITION_EPSILON && delta.is_finite() {
                out.insert(id.clone(), delta);
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
                self.slots[slot].anchor = position;
                self.mark_changed(slot);
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

    /// Clears the forces added to every body (they persist across steps until cleared).
    pub(crate) fn reset_forces(&mut self) {
        for slot in 0..self.slots.len() {
            self.body_at_mut(slot).reset_forces(true);
        }
    }
}
