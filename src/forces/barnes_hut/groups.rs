//! One Barnes–Hut pass over all points, in groups of neighbours that share one walk of
//! the tree: [`ManyBody::forces`] and the interaction lists it sums. The tree itself is
//! built in `mod.rs`.

use std::ops::Range;

use euclid::default::{Point2D, Vector2D};

use super::{ManyBody, Query, NONE};

/// Most points that share one walk in [`ManyBody::forces`]: larger groups walk the tree
/// less often but sum longer lists. 64 was the fastest of 8 to 256 on `n10000_e25000`
/// and the 100,000-node generated graph (2.5 and 29 ms a pass, against 3.2 and 42 at 16).
const GROUP_SIZE: usize = 64;
/// Independent partial sums per force, so the sum runs in vector registers.
const LANES: usize = 8;

impl ManyBody {
    /// The repulsion on every point of the last [`build`](Self::build) for which
    /// `wanted(i)` holds, written to `out[i]` (`out` is resized to the number of
    /// points; other entries are zero).
    ///
    /// Points are taken in groups of at most 64 that share a cell of the tree (a run of
    /// the tree's order). One walk per group collects the far cells every member may
    /// take whole, judged by the distance from the cell's centre of charge to the
    /// *group's* bounding box, and the points near enough to sum exactly; then each
    /// member sums that list in a vectorised loop. A cell is taken whole only where
    /// [`force_on`](Self::force_on) would take it whole for every member; the cells
    /// holding a member and leaves never are. So the pass opens at least the cells
    /// `force_on` opens and its mean error is no larger (on `n10000_e25000` at theta 0.9,
    /// 0.59 % against 0.83 %; single points can land either side), theta 0 is still the
    /// exact sum, and on `n10000_e25000` at theta 0.9 a build and a pass take 1.9 ms
    /// (README).
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
        let mut lists = std::mem::take(&mut self.lists);
        let mut stack = std::mem::take(&mut self.stack);
        // The groups: the largest cells holding at most GROUP_SIZE points, depth first.
        stack.clear();
        stack.push(0);
        while let Some(g) = stack.pop() {
            let node = self.nodes[g as usize];
            if node.count as usize > GROUP_SIZE && node.children != NONE {
                stack.extend(self.occupied_children(node.children).rev());
                continue;
            }
            let members = node.points();
            if !members.clone().any(|k| wanted(self.index[k] as usize)) {
                continue;
            }
            lists.collect_interactions(self, members.clone(), &query);
            for k in members {
                let i = self.index[k] as usize;
                if wanted(i) {
                    out[i] = lists.sum(self.sorted[k], &query);
                }
            }
        }
        self.stack = stack;
        self.lists = lists;
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
    /// Each entry's term in the force on the member being summed.
    terms_x: Vec<f32>,
    terms_y: Vec<f32>,
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

    /// The force on point `p` from the lists: each entry's term in one loop (which the
    /// compiler vectorises, divisions included), then the terms summed in [`LANES`]
    /// independent sums, so the sum runs in vector registers too (a fixed order, so
    /// results repeat bit for bit). The lists are padded to whole lanes with zero
    /// charges.
    fn sum(&mut self, p: Point2D<f32>, query: &Query) -> Vector2D<f32> {
        let n = self.x.len();
        // Every term below is written before it is read: the buffers only grow.
        if self.terms_x.len() < n {
            self.terms_x.resize(n, 0.0);
            self.terms_y.resize(n, 0.0);
        }
        let (terms_x, terms_y) = (&mut self.terms_x[..n], &mut self.terms_y[..n]);
        let entries = self.x.iter().zip(&self.y).zip(&self.charge);
        let terms = terms_x.iter_mut().zip(terms_y.iter_mut());
        for (((x, y), charge), (tx, ty)) in entries.zip(terms) {
            // Branch-free (selects). The point itself and any coincident one add
            // nothing, nor one so close that its squared distance underflows to zero
            // (as in `force_on`): its offset would be divided by the smallest softening.
            let (dx, dy) = (p.x - x, p.y - y);
            let d_sq = dx * dx + dy * dy;
            let soft = if d_sq > query.min_sq {
                d_sq
            } else {
                query.min_sq
            };
            let s = if d_sq > 0.0 { charge / soft } else { 0.0 };
            (*tx, *ty) = (dx * s, dy * s);
        }
        let (mut fx, mut fy) = ([0.0_f32; LANES], [0.0_f32; LANES]);
        let lanes = terms_x.chunks_exact(LANES).zip(terms_y.chunks_exact(LANES));
        for (tx, ty) in lanes {
            for l in 0..LANES {
                fx[l] += tx[l];
                fy[l] += ty[l];
            }
        }
        Vector2D::new(fx.iter().sum(), fy.iter().sum()) * query.strength
    }
}
