//! Joints in, re-tuned and out, keyed by the serials of their two nodes (never reused),
//! visited in insertion order so the same calls give the same world. What each kind
//! becomes in rapier is `rapier_joint.rs`; the factor every spring is scaled by is
//! `spring_scale.rs`.

use std::hash::Hash;

use rapier2d::prelude::GenericJoint;

use super::rapier_joint::{max_resolved_stiffness, rapier_joint, scaled_spring};
use super::slot::{joint_key, JointSlot, SpringView};
use super::RapierSceneWorld;
use crate::graph::Graph;
use crate::world::bindings::EdgeJointSpec;
use crate::world::EdgeJoint;

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// Builds one spring joint per edge. Edges naming a node without a body, self-loops
    /// and repeats of an existing pair (in either direction) are skipped.
    pub fn build_edge_joints(&mut self, edges: &[(N, N, EdgeJointSpec)]) {
        for (a, b, spec) in edges {
            self.insert_edge_joint(a, b, &EdgeJoint::from(*spec));
        }
    }

    /// Inserts the joint `kind` between `a` and `b` and returns whether one was
    /// inserted: not for [`EdgeJoint::None`], a self-loop, a missing node, or a pair that
    /// already has a joint.
    pub fn insert_edge_joint(&mut self, a: &N, b: &N, kind: &EdgeJoint) -> bool {
        self.insert_weighted_edge_joint(a, b, kind, 1.0)
    }

    /// Makes room for `additional` more joints, so a graph's first build does not grow
    /// the joint table step by step.
    pub(crate) fn reserve_joints(&mut self, additional: usize) {
        self.joints.reserve(additional);
        self.joint_index.reserve(additional);
    }

    /// [`insert_edge_joint`](Self::insert_edge_joint) for an edge of weight `weight`
    /// (`kind` is already weighted; the weight is kept to tell a later weight edit).
    pub(crate) fn insert_weighted_edge_joint(
        &mut self,
        a: &N,
        b: &N,
        kind: &EdgeJoint,
        weight: f32,
    ) -> bool {
        let (Some(&ia), Some(&ib)) = (self.index.get(a), self.index.get(b)) else {
            return false;
        };
        if ia == ib {
            return false;
        }
        let (sa, sb) = (&self.slots[ia as usize], &self.slots[ib as usize]);
        let key = joint_key(sa.serial, sb.serial);
        let (body_a, body_b) = (sa.body, sb.body);
        let Some(joint) = self.joint_data(ia, ib, kind, self.spring_scale.applied) else {
            return false;
        };
        let in_rapier = self.in_rapier(kind);
        // One probe of the table for both the check and the insert.
        let std::collections::hash_map::Entry::Vacant(entry) = self.joint_index.entry(key) else {
            return false;
        };
        entry.insert(self.joints.len() as u32);
        let handle = in_rapier.then(|| self.impulse_joints.insert(body_a, body_b, joint, true));
        self.joints.push(JointSlot {
            key,
            handle,
            a: a.clone(),
            b: b.clone(),
            kind: *kind,
            weight,
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
                (Some(&ia), Some(&ib)) => self.joint_data(ia, ib, &kind, self.spring_scale.applied),
                _ => None,
            };
            match built {
                Some(data) => {
                    self.rebuild_joint_at(i, kind, data);
                    i += 1;
                }
                None => self.remove_joint_at(i, true),
            }
        }
        changed
    }

    /// Records each joint's edge weight as `weight_of(a, b)` says, calling
    /// `changed(a, b)` for every joint whose weight differs from the one it has. Joints
    /// keep their kind: re-tune them afterwards.
    pub(crate) fn update_joint_weights(
        &mut self,
        mut weight_of: impl FnMut(&N, &N) -> f32,
        mut changed: impl FnMut(&N, &N),
    ) {
        for joint in &mut self.joints {
            let weight = weight_of(&joint.a, &joint.b);
            if weight.to_bits() != joint.weight.to_bits() {
                joint.weight = weight;
                changed(&joint.a, &joint.b);
            }
        }
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

    pub(super) fn remove_joint_at(&mut self, i: usize, remove_from_rapier: bool) {
        self.version += 1;
        let removed = self.joints.swap_remove(i);
        self.joint_index.remove(&removed.key);
        if let Some(handle) = removed.handle.filter(|_| remove_from_rapier) {
            self.impulse_joints.remove(handle, true);
        }
        if let Some(moved) = self.joints.get(i) {
            self.joint_index.insert(moved.key, i as u32);
        }
    }

    /// Keeps only the joints for which `keep(a, b)` is true, visiting them in insertion
    /// order (swap removals aside), so the same calls give the same world.
    pub(crate) fn retain_edge_joints(&mut self, mut keep: impl FnMut(&N, &N) -> bool) {
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
    pub(crate) fn clear_edge_joints(&mut self) {
        self.version += 1;
        for joint in self.joints.drain(..) {
            if let Some(handle) = joint.handle {
                self.impulse_joints.remove(handle, true);
            }
        }
        self.joint_index.clear();
    }

    /// Whether the pair (either order) has a joint.
    pub fn contains_joint(&self, a: &N, b: &N) -> bool {
        self.edge_joint(a, b).is_some()
    }

    /// The joint between `a` and `b` (either order) as it was built, before the
    /// stiffness limit: with
    /// [`RapierLayoutConfig::springs.degree_exponent`](crate::config::Springs::degree_exponent)
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

    /// The two bodies' slots of every joint, in joint order. Valid until
    /// [`version`](Self::version) changes.
    pub(crate) fn joint_ends(&self) -> impl Iterator<Item = (usize, usize)> + Clone + '_ {
        self.joints.iter().filter_map(|joint| {
            Some((
                *self.index.get(&joint.a)? as usize,
                *self.index.get(&joint.b)? as usize,
            ))
        })
    }

    /// The joints as a graph of the world's slots ([`Graph`]), in joint order: what
    /// the stress model measures hops on and a disturbance's heat spreads along.
    pub(crate) fn joint_graph(&self) -> Graph {
        Graph::new(self.slot_count(), self.joint_ends())
    }

    /// Every spring, rapier joint or forces, in joint order. Valid until
    /// [`version`](Self::version) changes.
    pub(crate) fn springs(&self) -> impl Iterator<Item = SpringView> + '_ {
        self.joints.iter().filter_map(|joint| {
            let EdgeJoint::Spring {
                rest_length,
                stiffness,
                damping,
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
            Some(SpringView {
                a,
                b,
                rest_length,
                stiffness,
                damping,
                cap,
            })
        })
    }

    /// Whether a joint of `kind` is a rapier joint in this world (every kind but a spring
    /// applied as forces).
    fn in_rapier(&self, kind: &EdgeJoint) -> bool {
        !(self.spring_forces && matches!(kind, EdgeJoint::Spring { .. }))
    }

    /// Gives joint `i` the kind `kind`, built as `data`: the rapier joint is re-tuned in
    /// place when it stays one, inserted or removed when the kind moves between rapier
    /// and forces.
    fn rebuild_joint_at(&mut self, i: usize, kind: EdgeJoint, data: GenericJoint) {
        let wanted = self.in_rapier(&kind);
        let slot = &self.joints[i];
        let handle = match (slot.handle, wanted) {
            (Some(handle), true) => {
                if let Some(joint) = self.impulse_joints.get_mut(handle, true) {
                    joint.data = data;
                }
                Some(handle)
            }
            (Some(handle), false) => {
                self.impulse_joints.remove(handle, true);
                None
            }
            (None, true) => {
                let bodies = (self.index.get(&slot.a), self.index.get(&slot.b));
                match bodies {
                    (Some(&ia), Some(&ib)) => {
                        let (ba, bb) = (self.slots[ia as usize].body, self.slots[ib as usize].body);
                        Some(self.impulse_joints.insert(ba, bb, data, true))
                    }
                    _ => None,
                }
            }
            (None, false) => None,
        };
        let slot = &mut self.joints[i];
        slot.kind = kind;
        slot.handle = handle;
    }

    /// Applies springs as forces of the layout's own (`true`) or as rapier joints
    /// (`false`), moving the existing springs in place; bodies keep their motion. See
    /// [`SpringModel`](crate::config::SpringModel).
    pub(crate) fn set_springs_as_forces(&mut self, forces: bool) {
        if forces == self.spring_forces {
            return;
        }
        self.spring_forces = forces;
        self.version += 1;
        for i in 0..self.joints.len() {
            let kind = self.joints[i].kind;
            if !matches!(kind, EdgeJoint::Spring { .. }) {
                continue;
            }
            let (Some(&ia), Some(&ib)) = (
                self.index.get(&self.joints[i].a),
                self.index.get(&self.joints[i].b),
            ) else {
                continue;
            };
            if let Some(data) = self.joint_data(ia, ib, &kind, self.spring_scale.applied) {
                self.rebuild_joint_at(i, kind, data);
            }
        }
    }

    /// Whether springs are applied as forces (see
    /// [`set_springs_as_forces`](Self::set_springs_as_forces)).
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn springs_as_forces(&self) -> bool {
        self.spring_forces
    }

    /// The rapier joint for `kind` between the bodies in slots `a` and `b`: springs
    /// scaled by `scale` and capped for the bodies' reduced mass at the joint timestep.
    pub(super) fn joint_data(
        &self,
        a: u32,
        b: u32,
        kind: &EdgeJoint,
        scale: f32,
    ) -> Option<GenericJoint> {
        let (ma, mb) = (self.slots[a as usize].mass, self.slots[b as usize].mass);
        let built = scaled_spring(kind, |x| x * scale);
        rapier_joint(&built, ma * mb / (ma + mb), self.joint_dt)
    }
}
