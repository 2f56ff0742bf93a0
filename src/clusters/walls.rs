//! Sibling boxes kept apart in the physics by a wall between them, not by moving them
//! whole. Two boxes that overlap meet at a wall across the axis they overlap least,
//! halfway through the overlap, and the members of each that reach past it move back
//! to it: a cluster stretched
//! toward its neighbours by their edges is held at its side of the wall, as a disk by a
//! contact, and only the members at the wall move. Moved whole, two units a parting,
//! the boxes came apart more slowly than the forces stretched them, overlapping by
//! hundreds of units while the layout moved, and the cold stop parted them at once.

use super::boxes::Bounds;
use super::part::{Ctx, Item};

/// Holds boxes `a` and `b` (clusters of one level) apart by a wall if they overlap.
/// Returns how far a member moved, at most.
pub(super) fn wall(ctx: &mut Ctx<'_>, a: Item, b: Item) -> f32 {
    let o = super::boxes::overlap(ctx.bounds(a), ctx.bounds(b));
    if !(o[0] > 0.0 && o[1] > 0.0) {
        return 0.0;
    }
    let (Item::Cluster(a), Item::Cluster(b), Some((axis, sign))) = (a, b, ctx.parting(a, b, o))
    else {
        return 0.0;
    };
    let (behind, ahead) = if sign > 0.0 { (a, b) } else { (b, a) };
    // The overlap runs from the ahead box's low edge to the behind box's high edge; the
    // wall halves it. (Both boxes give way: `Level::part` parts one that does not
    // whole.) Divided by the boxes' sizes instead, a small cluster beside a large one
    // took almost the whole overlap, its members jumped into the next box, and
    // `1138_bus` overlapped by up to 52 units in 86 of the 148 frames of its first
    // settling; halved, by 3.6 in one.
    let (low, high) = (
        ctx.bounds(Item::Cluster(ahead))[0][axis],
        ctx.bounds(Item::Cluster(behind))[1][axis],
    );
    let at = 0.5 * (low + high);
    let behind_moved = ctx.hold_side(behind as usize, axis, at, -1.0);
    let ahead_moved = ctx.hold_side(ahead as usize, axis, at, 1.0);
    behind_moved.max(ahead_moved)
}

impl Ctx<'_> {
    /// Moves every member of cluster `c` that gives way along `axis` and reaches past
    /// the wall at `at` (on the side `way` points away from) back to it. Returns how far
    /// a member moved, at most.
    fn hold_side(&mut self, c: usize, axis: usize, at: f32, way: f32) -> f32 {
        // The box's edge toward the wall lies its padding beyond its farthest member's
        // outline: that member stops as far short of the wall. (A member of a nested
        // cluster needs the nested padding too; what that leaves is parted next round.)
        let toward = -way;
        let edge = move |o: Bounds| if way < 0.0 { o[1][axis] } else { o[0][axis] };
        let mut reach = f32::NEG_INFINITY;
        let bodies = &*self.bodies;
        self.tree
            .for_each_slot(c, |s| reach = reach.max(toward * edge(bodies.outline(s))));
        let box_edge = toward * edge(self.boxes.bounds[c]);
        let padding = (box_edge - reach).max(0.0);
        let stop = at + way * padding;
        let mut moved = 0.0_f32;
        let (bodies, moves) = (&mut *self.bodies, &mut *self.moves);
        self.tree.for_each_slot(c, |s| {
            let outline = bodies.outline(s);
            let past = toward * (edge(outline) - stop);
            if past > 0.0 && bodies.free[s][axis] && past.is_finite() {
                let mut by = [0.0; 2];
                by[axis] = way * past;
                let mut parted = [false; 2];
                parted[axis] = true;
                moves.body(bodies, s, by, parted);
                moved = moved.max(past);
            }
        });
        // The box keeps its edge until the next round makes the boxes again: a pair met
        // later in this round sees it as it was, and its wall holds the members a
        // margin further back. Brought to the members at once, the boxes of
        // `1138_bus` overlapped in 147 of 148 frames of its first settling, not 86.
        moved
    }
}
