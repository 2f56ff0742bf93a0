//! Sibling boxes kept apart in the physics by a wall between them, not by moving them
//! whole. Two boxes that overlap meet at a wall across the axis they overlap least,
//! set in the overlap by how much each box gives way (at the edge of one that does not),
//! and the members of each that reach past it move back to it: a cluster stretched
//! toward its neighbours by their edges is held at its side of the wall, as a disk by a
//! contact, and only the members at the wall move. Moved whole, two units a parting,
//! the boxes came apart more slowly than the forces stretched them, overlapping by
//! hundreds of units while the layout moved, and the cold stop parted them at once.

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
    let (g_behind, g_ahead) = (
        ctx.give(Item::Cluster(behind), axis),
        ctx.give(Item::Cluster(ahead), axis),
    );
    // The overlap runs from the ahead box's low edge to the behind box's high edge.
    let (low, high) = (
        ctx.bounds(Item::Cluster(ahead))[0][axis],
        ctx.bounds(Item::Cluster(behind))[1][axis],
    );
    let at = high - (high - low) * g_behind / (g_behind + g_ahead);
    let behind_moved = ctx.hold_side(behind as usize, axis, at, -1.0);
    let ahead_moved = ctx.hold_side(ahead as usize, axis, at, 1.0);
    behind_moved.max(ahead_moved)
}

impl Ctx<'_> {
    /// Moves every member of cluster `c` that gives way along `axis` and reaches past
    /// the wall at `at` (on the side `way` points away from) back to it. Returns how far
    /// one moved, at most.
    fn hold_side(&mut self, c: usize, axis: usize, at: f32, way: f32) -> f32 {
        let mut moved = 0.0_f32;
        let mut slots = Vec::new();
        self.tree.for_each_slot(c, |s| slots.push(s));
        // The box's edge toward the wall lies its padding (its nested boxes' too) beyond
        // its farthest member's outline: that member stops as far short of the wall.
        let edge = |o: super::boxes::Bounds| if way < 0.0 { o[1][axis] } else { o[0][axis] };
        let toward = -way;
        let reach = slots
            .iter()
            .map(|&s| toward * edge(self.bodies.outline(s)))
            .fold(f32::NEG_INFINITY, f32::max);
        let padding = (toward * edge(self.bounds(Item::Cluster(c as u32))) - reach).max(0.0);
        let at = at + way * padding;
        for s in slots {
            if !self.bodies.free[s][axis] {
                continue;
            }
            let outline = self.bodies.outline(s);
            // The member's edge toward the wall, and how far past it it reaches.
            let (edge, past) = if way < 0.0 {
                (outline[1][axis], outline[1][axis] - at)
            } else {
                (outline[0][axis], at - outline[0][axis])
            };
            if past > 0.0 && edge.is_finite() {
                let mut by = [0.0; 2];
                by[axis] = way * past;
                let mut parted = [false; 2];
                parted[axis] = true;
                self.push_body(s, by, parted);
                moved = moved.max(past);
            }
        }
        moved
    }
}
