//! The host's per-node forces ([`NodeForces`]) by world slot, as the forces of one call
//! read them: which slots are pulled toward a target or a ring, which belong to which
//! group, which have an axis locked and at what coordinate. Filled once per call by the
//! adapter (`adapter/node_forces.rs`) from
//! [`LayoutExtras::forces`](crate::LayoutExtras::forces); empty, and free, while the
//! host sets none.

use euclid::default::Vector2D;
use serde::{Deserialize, Serialize};

use super::ForceSums;
use crate::input::node_forces::{AxisLock, NodeForces};

/// A group: its key and its members' slots, in slot order.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct Group {
    pub(crate) key: u32,
    pub(crate) members: Vec<u32>,
}

/// The per-node forces of one call, by world slot.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub(crate) struct NodeTargets {
    /// Every slot's forces (all `None` for a node without an entry); empty while no
    /// node has any.
    pub(crate) by_slot: Vec<NodeForces>,
    /// Slots with a pull toward an x, a y or a ring, in slot order.
    pub(crate) pulled: Vec<u32>,
    /// Groups by ascending key.
    pub(crate) groups: Vec<Group>,
    /// Slots with a locked axis and the coordinate it is held at this call.
    pub(crate) locks: Vec<(u32, AxisLock, f32)>,
    /// Entries this call with a bad value left out.
    pub(crate) problems: usize,
}

impl NodeTargets {
    /// The forces of the node in `slot` (none past the table's end).
    pub(crate) fn at(&self, slot: usize) -> NodeForces {
        self.by_slot.get(slot).copied().unwrap_or_default()
    }

    /// A snapshot's table made ready to read: every entry one a host could set, every
    /// lock on a slot of the table at a finite coordinate, and the pulled slots and
    /// groups sorted again from the entries ([`index`](Self::index)), not read.
    pub(crate) fn restore_index(&mut self) -> Result<(), &'static str> {
        if self.by_slot.iter().any(|f| f.usable() != *f) {
            return Err("forces.targets.by_slot: a value no host could set");
        }
        let slots = self.by_slot.len();
        let held = |&(s, _, at): &(u32, _, f32)| (s as usize) < slots && at.is_finite();
        if !self.locks.iter().all(held) {
            return Err("forces.targets.locks");
        }
        self.index();
        Ok(())
    }

    /// Sorts what `by_slot` holds into the pulled slots and the groups; the locks are
    /// the adapter's, which knows where each body is.
    pub(crate) fn index(&mut self) {
        self.pulled.clear();
        self.groups.clear();
        let mut keyed: Vec<(u32, u32)> = Vec::new();
        for (s, forces) in self.by_slot.iter().enumerate() {
            if forces.x.is_some() || forces.y.is_some() || forces.ring.is_some() {
                self.pulled.push(s as u32);
            }
            if let Some(key) = forces.group {
                keyed.push((key, s as u32));
            }
        }
        // Stable and total: the same groups in the same order every call.
        keyed.sort_unstable();
        for (key, s) in keyed {
            match self.groups.last_mut() {
                Some(group) if group.key == key => group.members.push(s),
                _ => self.groups.push(Group {
                    key,
                    members: vec![s],
                }),
            }
        }
    }
}

/// The pushed bodies with a pull toward an x, a y or a ring: slot, forces and mass.
pub(crate) fn pulled_bodies<'a, N: Clone + Eq + std::hash::Hash>(
    frame: &'a super::ForceContext<'_, N>,
) -> impl Iterator<Item = (usize, NodeForces, f32)> + 'a {
    frame.targets.pulled.iter().filter_map(|&slot| {
        let s = slot as usize;
        frame.pushed[s].then(|| (s, frame.targets.at(s), frame.world.mass_at(s)))
    })
}

/// Adds to `out` the pull on the body in slot `s` of stiffness `k` and damping `c`,
/// stretched by `stretch` and moving away at `speed` along the unit vector `axis`, as one
/// backward Euler step: the force `(k stretch - (c + dt k) speed) axis`, and
/// `(dt² k + dt c) axis axisᵀ` for the implicit division the step takes
/// (`simulate/combine.rs`), which together give
/// `(m + dt c + dt² k) Δv = dt (k stretch - (c + dt k) speed)`: stable and damped at
/// any stiffness (far stiffer than the step resolves, where the edge springs
/// are capped), resting where the forces balance, and leaving motion across `axis` as
/// free as without the pull.
pub(crate) fn add_pull(
    out: &mut ForceSums,
    s: usize,
    (k, c): (f32, f32),
    dt: f32,
    axis: Vector2D<f32>,
    stretch: f32,
    speed: f32,
) {
    let f = axis * (k * stretch - (c + dt * k) * speed);
    let r = dt * dt * k + dt * c;
    if f.is_finite() && r.is_finite() {
        out.springs[s] += f;
        let pulls = &mut out.pulls[s];
        pulls[0] += r * axis.x * axis.x;
        pulls[1] += r * axis.x * axis.y;
        pulls[2] += r * axis.y * axis.y;
    }
}

/// Stiffness and critical damping of a pull of d3-force `strength` on a body of mass
/// `m`, at the springs' current `scale`: `k = m · strength · 3600 · scale` (the share of
/// the distance closed per 1/60 s tick), `c = 2 √(k m)`.
pub(crate) fn pull_constants(strength: f32, m: f32, scale: f32) -> (f32, f32) {
    let k = m * strength * 3600.0 * scale;
    (k, 2.0 * (k * m).sqrt())
}
