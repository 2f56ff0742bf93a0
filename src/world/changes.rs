//! Which bodies may have changed since the layout last read them all: every body the
//! world handed out to change, and every body rapier simulated in a step (awake before
//! it or after it). A settled graph disturbed in one place changes a few dozen bodies
//! a step; the layout reads those instead of all of them (`forces/bodies.rs`, the
//! deltas in `adapter/sync_out.rs`, a drag's sweep in `world/activity.rs`).

use std::hash::Hash;

use rapier2d::prelude::RigidBodyHandle;

use super::RapierSceneWorld;

/// Past this share of the bodies (one in eight) the log gives up and reports every
/// body: reading them all in order is then about as cheap.
const MOST_A_BODY: usize = 8;

/// The slots changed since the log was last cleared, each once, or every slot.
#[derive(Clone, Debug)]
pub(crate) struct Changes {
    slots: Vec<u32>,
    /// By slot: in `slots`.
    marked: Vec<bool>,
    /// Every slot may have changed (a new world, a node added or removed, a long log).
    all: bool,
}

impl Default for Changes {
    fn default() -> Self {
        Self {
            slots: Vec::new(),
            marked: Vec::new(),
            all: true,
        }
    }
}

impl Changes {
    /// Notes that the body in `slot` may have changed.
    pub(crate) fn mark(&mut self, slot: usize, slot_count: usize) {
        if self.all {
            return;
        }
        let Some(marked) = self.marked.get_mut(slot) else {
            self.all = true;
            return;
        };
        if !*marked {
            *marked = true;
            self.slots.push(slot as u32);
            if self.slots.len() * MOST_A_BODY > slot_count {
                self.all = true;
            }
        }
    }

    /// Notes that every body may have changed.
    pub(crate) fn mark_all(&mut self) {
        self.all = true;
    }

    /// The slots that may have changed, in the order they were first marked; `None`
    /// when every slot may have.
    pub(crate) fn slots(&self) -> Option<&[u32]> {
        (!self.all).then_some(&self.slots)
    }

    /// Forgets every change: the layout has read what it needs.
    pub(crate) fn clear(&mut self, slot_count: usize) {
        if self.all {
            self.marked.clear();
        } else {
            for &s in &self.slots {
                self.marked[s as usize] = false;
            }
        }
        self.marked.resize(slot_count, false);
        self.slots.clear();
        self.all = false;
    }
}

impl<N: Clone + Eq + Hash> RapierSceneWorld<N> {
    /// The slots whose bodies may have changed since
    /// [`forget_changes`](Self::forget_changes), or `None` for every slot.
    pub(crate) fn changed_slots(&self) -> Option<&[u32]> {
        self.changes.slots()
    }

    /// Whether the body in `slot` may have changed since
    /// [`forget_changes`](Self::forget_changes).
    pub(crate) fn is_changed(&self, slot: usize) -> bool {
        self.changes.all || self.changes.marked.get(slot).is_none_or(|&m| m)
    }

    /// Forgets the changes: the caller has read every changed body.
    pub(crate) fn forget_changes(&mut self) {
        self.changes.clear(self.slots.len());
    }

    /// Notes that the body in `slot` may have changed.
    pub(crate) fn mark_changed(&mut self, slot: usize) {
        self.changes.mark(slot, self.slots.len());
    }

    /// Notes the bodies rapier simulates: those awake before a step and after it are
    /// every body the step can move.
    pub(super) fn mark_active(&mut self) {
        if self.changes.all {
            return;
        }
        let n = self.slots.len();
        for handle in self.islands.active_bodies() {
            self.changes.mark(slot_of(&self.bodies, handle), n);
        }
    }
}

/// The slot a body records in its user data (`usize::MAX`, which marks every slot, for
/// a handle without a body).
fn slot_of(bodies: &rapier2d::prelude::RigidBodySet, handle: RigidBodyHandle) -> usize {
    bodies
        .get(handle)
        .map_or(usize::MAX, |body| body.user_data as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A slot marked twice is reported once, in the order first marked; past one slot
    /// in eight, or for a slot beyond the world's, every slot is; a new log and a
    /// cleared one of every slot start over.
    #[test]
    fn the_log_reports_each_changed_slot_once_or_every_slot() {
        let mut changes = Changes::default();
        assert_eq!(changes.slots(), None, "a new world: every body is new");
        changes.clear(64);
        for s in [5, 3, 5, 9, 3] {
            changes.mark(s, 64);
        }
        assert_eq!(changes.slots(), Some(&[5, 3, 9][..]));
        for s in 10..15 {
            changes.mark(s, 64);
        }
        assert_eq!(changes.slots().map(<[u32]>::len), Some(8), "8 of 64: kept");
        changes.mark(40, 64);
        assert_eq!(changes.slots(), None, "9 of 64: every slot");
        changes.clear(64);
        assert_eq!(changes.slots(), Some(&[][..]), "cleared");
        changes.mark(3, 64);
        assert_eq!(
            changes.slots(),
            Some(&[3][..]),
            "marks cleared with the log"
        );
        changes.mark(64, 64);
        assert_eq!(changes.slots(), None, "a slot the log was not sized for");
    }
}
