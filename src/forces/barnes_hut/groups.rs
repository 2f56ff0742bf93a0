//! One Barnes–Hut pass over all points, in groups of neighbours that share one walk of
//! the tree: [`ManyBody::forces`] and the interaction lists it sums. The tree itself is
//! built in `mod.rs`.

use std::ops::Range;

use euclid::default::{Point2D, Vector2D};

use super::{ManyBody, Query, NONE};
use crate::parallel;

/// Most points that share one walk in [`ManyBody::forces`]: larger groups walk the tree
/// less often but sum longer lists. 64 was chosen by timing the sizes from 8 to 256
/// (`docs/performance.md` gives the times and the command).
const GROUP_SIZE: usize = 64;
/// Independent partial sums per force, so the sum runs in vector registers.
const LANES: usize = 8;
/// Points summed in one pass over a group's lists (see [`GroupLists::sum`]).
const BLOCK: usize = 2;

impl ManyBody {
    /// The repulsion on every point of the last [`build`](Self::build) for which
    /// `wanted(i)` holds, written to `out[i]` (`out` is resized to the number of
    /// points; other entries are zero).
    ///
    /// Points are taken in groups of at most 64 that share a cell of the tree (a run of
    /// the tree's order). One walk per group collects the far cells every member may
    /// take whole, judged by the distance from the cell's centre of charge to the
    /// *group's* bounding box, and the points near enough to sum exactly; then the
    /// members sum that list two at a time in a vectorised loop. A cell is taken whole
    /// only where [`force_on`](Self::force_on) would take it whole for every member;
    /// the cells holding a member and leaves never are. So the pass opens at least the
    /// cells `force_on` opens and its mean error is no larger (single points can land
    /// either side), theta 0 is still the exact sum (`docs/performance.md` measures the
    /// error and times a build and a pass).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, ManyBody};
    /// let points = [Point2D::new(0.0, 0.0), Point2D::new(10.0, 0.0), Point2D::new(5.0, 9.0)];
    /// let mut tree = ManyBody::default();
    /// tree.build(&points);
    /// let mut all = Vec::new();
    /// tree.forces(100.0, 0.9, 1.0, |i| i != 2, &mut all);
    /// for i in 0..2 {
    ///     let one = tree.force_on(i, 100.0, 0.9, 1.0);
    ///     assert!((all[i] - one).length() < 1e-4 * one.length(), "{:?} vs {one:?}", all[i]);
    /// }
    /// assert_eq!(all[2], Vector2D::zero(), "not wanted");
    /// ```
    pub fn forces(
        &mut self,
        strength: f32,
        theta: f32,
        min_distance: f32,
        wanted: impl Fn(usize) -> bool,
        out: &mut Vec<Vector2D<f32>>,
    ) {
        out.clear();
        out.resize(self.points.len(), Vector2D::zero());
        if self.nodes.is_empty() || self.nodes[0].count == 0 {
            return;
        }
        let query = Query::new(strength, theta, min_distance);
        // Asked once per point, in the tree's order.
        let mut wanted_k = std::mem::take(&mut self.wanted);
        wanted_k.clear();
        wanted_k.extend(self.index.iter().map(|&i| wanted(i as usize)));
        // The groups: the largest cells holding at most GROUP_SIZE points, depth first
        // (so in the tree's order), those with a wanted member.
        let mut groups = std::mem::take(&mut self.groups);
        groups.clear();
        let mut stack = std::mem::take(&mut self.stack);
        stack.clear();
        stack.push(0);
        while let Some(g) = stack.pop() {
            let node = self.nodes[g as usize];
            if node.count as usize > GROUP_SIZE && node.children != NONE {
                stack.extend(self.occupied_children(node.children).rev());
                continue;
            }
            let members = node.points();
            if wanted_k[members.clone()].contains(&true) {
                groups.push(members);
            }
        }
        self.stack = stack;
        // Each group's forces in the tree's order, the groups side by side under
        // `parallel`: a point's force is its group's sum alone, on any thread.
        let mut by_k = std::mem::take(&mut self.by_k);
        by_k.clear();
        by_k.resize(self.sorted.len(), Vector2D::zero());
        {
            let tree = &*self;
            let mut jobs = parallel::split_ranges(&mut by_k, groups.iter().cloned());
            parallel::for_each(
                &mut jobs,
                GroupLists::default,
                |lists, (members, forces)| {
                    lists.collect_interactions(tree, members.clone(), &query);
                    let wanted_members = members.clone().filter(|&k| wanted_k[k]);
                    lists.sum_for(tree, wanted_members, members.start, &query, forces);
                },
            );
        }
        for members in &groups {
            for k in members.clone().filter(|&k| wanted_k[k]) {
                out[self.index[k] as usize] = by_k[k];
            }
        }
        self.groups = groups;
        self.by_k = by_k;
        self.wanted = wanted_k;
    }
}

/// The interaction lists of one group, reused from group to group.
#[derive(Clone, Debug, Default)]
pub(super) struct GroupLists {
    /// Far cells taken whole and points summed exactly (the members among them),
    /// as centres and charges (1 for a point).
    x: Vec<f32>,
    y: Vec<f32>,
    charge: Vec<f32>,
    stack: Vec<u32>,
}

impl GroupLists {
    /// One walk for the group of points `members` (positions in the tree order): each
    /// cell far from the group's bounding box goes to the list whole, and the points of
    /// every leaf opened one by one (the members' own among them).
    fn collect_interactions(&mut self, tree: &ManyBody, members: Range<usize>, query: &Query) {
        let (mut lo, mut hi) = (tree.sorted[members.start], tree.sorted[members.start]);
        for &p in &tree.sorted[members.clone()] {
            lo = lo.min(p);
            hi = hi.max(p);
        }
        let (first, end) = (members.start as u32, members.end as u32);
        self.x.clear();
        self.y.clear();
        self.charge.clear();
        self.stack.clear();
        self.stack.push(0);
        while let Some(c) = self.stack.pop() {
            let node = tree.nodes[c as usize];
            if node.children == NONE {
                for &p in &tree.sorted[node.points()] {
                    self.push(p, 1.0);
                }
                continue;
            }
            // A cell holding a member is always opened: taking it whole would count the
            // member's own charge.
            let holds = node.first < end && first < node.first + node.count;
            if !holds {
                let dx = (lo.x - node.mx).max(node.mx - hi.x).max(0.0);
                let dy = (lo.y - node.my).max(node.my - hi.y).max(0.0);
                if node.width_sq < query.theta_sq * (dx * dx + dy * dy) {
                    self.push(Point2D::new(node.mx, node.my), node.charge());
                    continue;
                }
            }
            self.stack.extend(tree.occupied_children(node.children));
        }
        while self.x.len() % LANES != 0 {
            self.push(Point2D::origin(), 0.0);
        }
    }

    /// Adds a charge at `at` to the list.
    fn push(&mut self, at: Point2D<f32>, charge: f32) {
        self.x.push(at.x);
        self.y.push(at.y);
        self.charge.push(charge);
    }

    /// The force on each of `members` (positions in the tree order), written to
    /// `out[k - first]`: [`BLOCK`] points a pass over the lists (a last block short of
    /// members repeats its last one).
    fn sum_for(
        &self,
        tree: &ManyBody,
        members: impl Iterator<Item = usize>,
        first: usize,
        query: &Query,
        out: &mut [Vector2D<f32>],
    ) {
        let mut block = [0_usize; BLOCK];
        let mut members = members.peekable();
        while members.peek().is_some() {
            let mut filled = 0;
            for k in members.by_ref().take(BLOCK) {
                block[filled] = k;
                filled += 1;
            }
            let last = block[filled - 1];
            block[filled..].fill(last);
            let forces = self.sum(block.map(|k| tree.sorted[k]), query);
            for (&k, f) in block.iter().zip(forces).take(filled) {
                out[k - first] = f;
            }
        }
    }

    /// The forces on the points `p` from the lists, in one pass over them: each entry's
    /// term, summed in [`LANES`] independent sums per point (a fixed order, so results
    /// repeat bit for bit). The lists are padded to whole lanes with zero charges.
    ///
    /// NOTE: written for the vectoriser of the baseline x86-64 target (SSE2): the
    /// division is taken for every entry and its result selected after (a select around
    /// the division kept the loop scalar), and the points are indexed, two of them (one
    /// point, or an iterator over the two, left the loop scalar; with four the 64 sums
    /// overflow the 16 vector registers). `docs/performance.md` gives the times.
    fn sum(&self, p: [Point2D<f32>; BLOCK], query: &Query) -> [Vector2D<f32>; BLOCK] {
        let (mut fx, mut fy) = ([[0.0_f32; LANES]; BLOCK], [[0.0_f32; LANES]; BLOCK]);
        let chunks = self.x.chunks_exact(LANES).zip(self.y.chunks_exact(LANES));
        for ((x, y), charge) in chunks.zip(self.charge.chunks_exact(LANES)) {
            for m in 0..BLOCK {
                for l in 0..LANES {
                    // The point itself and any coincident one add nothing, nor one so
                    // close that its squared distance underflows to zero (as in
                    // `force_on`): its offset would be divided by the smallest softening.
                    let (dx, dy) = (p[m].x - x[l], p[m].y - y[l]);
                    let d_sq = dx * dx + dy * dy;
                    let pull = charge[l] / d_sq.max(query.min_sq);
                    let s = if d_sq > 0.0 { pull } else { 0.0 };
                    fx[m][l] += dx * s;
                    fy[m][l] += dy * s;
                }
            }
        }
        std::array::from_fn(|m| {
            Vector2D::new(fx[m].iter().sum(), fy[m].iter().sum()) * query.strength
        })
    }
}
