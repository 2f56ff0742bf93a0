//! The projection after each rapier step: Gauss–Seidel passes over the separations and
//! rows on the constrained bodies' own arrays (`local.rs`, `passes.rs`), moving dynamic
//! bodies only; and how far a host constraint is from holding, read from the world.

use std::hash::Hash;

use super::{index, Compiled, Row, Separation, HELD_WITHIN};
use crate::input::node_forces::AxisLock;
use crate::world::RapierSceneWorld;

/// A settling round that takes less than this share off the worst shortfall ends the
/// settling: what is left cannot hold (conflicting constraints).
const STALLED: f32 = 0.01;

impl<N: Clone + Eq + Hash> Compiled<N> {
    /// Projects every constraint onto `world`'s bodies: `passes` passes, the rows, the
    /// sweep. A body's axis held by one of `locks` does not give way along it.
    pub(crate) fn project(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        passes: usize,
        locks: &[(u32, AxisLock, f32)],
    ) {
        if self.local.is_empty() {
            return;
        }
        self.local.gather(world, locks);
        self.round(passes);
        self.local.scatter(world);
    }

    /// `passes` passes over the separations a hot body is in, the rows on their lines,
    /// then the sweep (`sweep.rs`): the separations have the last word, so a flow's
    /// edges hold after every substep, and a row a push crosses spreads until the next.
    fn round(&mut self, passes: usize) {
        let mut active = std::mem::take(&mut self.active);
        self.local.active_links(&mut active, &mut self.active_bits);
        for k in 0..passes {
            self.local.pass(&active, k % 2 == 1);
        }
        self.active = active;
        self.local.line_up_rows();
        self.local.sweep();
    }

    /// Projects every constraint onto `points` (by slot, `unit` world units each; a
    /// start layout's positions before there are bodies to move), `passes` times, every
    /// body free to move.
    pub(crate) fn project_points(&mut self, points: &mut [[f32; 2]], unit: f32, passes: usize) {
        if self.local.is_empty() || !(unit.is_finite() && unit > 0.0) {
            return;
        }
        self.local.gather_points(points, unit);
        self.round(passes);
        self.local.scatter_points(points, unit);
    }

    /// Projects until every constraint the bodies can move holds within a tenth of
    /// [`HELD_WITHIN`], until a round stops bringing the worst nearer (a conflict), or
    /// `rounds` rounds: what the world rests with when it halts.
    pub(crate) fn settle(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        (passes, rounds): (usize, usize),
        locks: &[(u32, AxisLock, f32)],
    ) {
        if self.local.is_empty() {
            return;
        }
        self.local.gather(world, locks);
        self.local.heat_all();
        let mut last = f32::INFINITY;
        for _ in 0..rounds {
            let worst = self.local.worst();
            if worst <= 0.1 * HELD_WITHIN || worst > (1.0 - STALLED) * last {
                break;
            }
            last = worst;
            self.round(passes);
        }
        self.local.scatter(world);
    }
}

/// The coordinate of the body in `slot` on `axis`.
fn at<N: Clone + Eq + Hash>(world: &RapierSceneWorld<N>, slot: u32, axis: usize) -> f32 {
    let t = world.body_at(slot as usize).translation();
    [t.x, t.y][axis]
}

impl Separation {
    /// How far its second body is short of the gap (0 or less when it holds).
    pub(crate) fn shortfall<N: Clone + Eq + Hash>(&self, world: &RapierSceneWorld<N>) -> f32 {
        let axis = index(self.axis);
        self.gap - (at(world, self.second, axis) - at(world, self.first, axis))
    }
}

impl Row {
    /// The distance between the row's two farthest bodies across its line.
    pub(crate) fn spread<N: Clone + Eq + Hash>(&self, world: &RapierSceneWorld<N>) -> f32 {
        let axis = index(self.axis);
        let (low, high) =
            self.slots
                .iter()
                .fold((f32::INFINITY, f32::NEG_INFINITY), |(low, high), &s| {
                    let x = at(world, s, axis);
                    (low.min(x), high.max(x))
                });
        (high - low).max(0.0)
    }
}
