//! Hard constraints held every substep beside the forces: the host's separations and
//! rows ([`Constraint`]) and a directed flow's edges ([`Flow`]), compiled to world slots
//! once per call (`compile.rs`) and projected after each rapier step (`project.rs`):
//! a violated separation moves its two bodies apart along its axis in inverse
//! proportion to their masses and takes out their closing speed, a row moves its bodies
//! onto one line. A body that is not dynamic (pinned, dragged, frozen) does not give way:
//! its partners move. Gauss–Seidel passes, as the disk separation's contacts, so a chain
//! of constraints settles over a few substeps and holds at rest.

use crate::input::constraints::Axis;

mod compile;
mod project;

pub(crate) use compile::Compiled;

/// `second`'s coordinate on `axis` at least `first`'s plus `gap`, by world slot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Separation {
    pub(crate) first: u32,
    pub(crate) second: u32,
    pub(crate) axis: Axis,
    pub(crate) gap: f32,
}

/// Bodies that share one coordinate on `axis`, by world slot.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Row {
    pub(crate) axis: Axis,
    pub(crate) slots: Vec<u32>,
}

/// Projection passes over every constraint per substep.
const PASSES: usize = 8;

/// The coordinate of `v` on `axis`.
fn along(axis: Axis, x: f32, y: f32) -> f32 {
    match axis {
        Axis::X => x,
        Axis::Y => y,
    }
}
