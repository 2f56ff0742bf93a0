//! Hard constraints held every substep beside the forces: the host's separations and
//! rows ([`Constraint`](crate::scene::Constraint)) and a directed flow's edges
//! ([`Flow`](crate::config::Flow)), compiled to world slots once per call
//! (`compile.rs`, the flow's edges in `flow.rs`) and projected after each rapier step
//! (`project.rs`): a violated separation moves its two bodies apart along its axis in
//! inverse proportion to their masses and takes out their closing speed, a row moves its
//! bodies onto one line. A body that is not dynamic (pinned, dragged, frozen) does not
//! give way: its partners move. Gauss–Seidel passes, as the disk separation's contacts,
//! so a chain of constraints settles over a few substeps and holds at rest.

use serde::{Deserialize, Serialize};

use crate::input::constraints::Axis;

mod compile;
mod flow;
mod layers;
mod local;
mod order;
mod passes;
mod project;
mod saved;
mod sweep;
mod watch;

pub(crate) use compile::Compiled;
pub(crate) use saved::SavedConstraints;

/// `second`'s coordinate on `axis` at least `first`'s plus `gap`, by world slot.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Separation {
    pub(crate) first: u32,
    pub(crate) second: u32,
    pub(crate) axis: Axis,
    pub(crate) gap: f32,
}

/// Bodies that share one coordinate on `axis`, by world slot.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct Row {
    pub(crate) axis: Axis,
    pub(crate) slots: Vec<u32>,
}

/// How far from holding a constraint may rest and still count as held (world units).
pub(crate) const HELD_WITHIN: f32 = 1.0;

/// The index of `axis` in a point's `[x, y]`.
fn index(axis: Axis) -> usize {
    match axis {
        Axis::X => 0,
        Axis::Y => 1,
    }
}

/// Adds to `edit` the slots of the rows in one list and not the other.
fn changed_rows(before: &[Row], after: &[Row], edit: &mut Vec<u32>) {
    for (rows, others) in [(before, after), (after, before)] {
        for row in rows.iter().filter(|row| !others.contains(row)) {
            edit.extend(&row.slots);
        }
    }
}

/// Adds to `edit` the slots of the separations in one list and not the other.
fn changed_slots(before: &[Separation], after: &[Separation], edit: &mut Vec<u32>) {
    let key = |c: &Separation| (c.first, c.second, c.axis as u8, c.gap.to_bits());
    let sorted = |list: &[Separation]| {
        let mut keys: Vec<_> = list.iter().map(key).collect();
        keys.sort_unstable();
        keys
    };
    let (before, after) = (sorted(before), sorted(after));
    let (mut i, mut j) = (0, 0);
    while i < before.len() || j < after.len() {
        match (before.get(i), after.get(j)) {
            (Some(a), Some(b)) if a == b => (i, j) = (i + 1, j + 1),
            (Some(a), Some(b)) if a < b => {
                edit.extend([a.0, a.1]);
                i += 1;
            }
            (Some(_), Some(b)) | (None, Some(b)) => {
                edit.extend([b.0, b.1]);
                j += 1;
            }
            (Some(a), None) => {
                edit.extend([a.0, a.1]);
                i += 1;
            }
            (None, None) => break,
        }
    }
}
