//! One Barnes–Hut pass over all points, in groups of neighbours that share one walk of
//! the tree: [`ManyBody::forces`] and the interaction lists it sums. The tree itself is
//! built in `mod.rs`.

use euclid::default::{Point2D, Vector2D};

use super::{ManyBody, Query, NONE};

/// Most points that share one walk in [`ManyBody::forces`]: larger groups walk the tree
/// less often but sum longer lists. 16 was the fastest of 2 to 64 on `n1000_e2500` and
/// `n10000_e25000`.
const GROUP_SIZE: usize = 16;
/// Independent partial sums per force, so the sum runs in vector registers.
const LANES: usize = 8;

impl ManyBody {
    /// The repulsion on every point of the last [`build`](Self::build) for which
    /// `wanted(i)` holds, written to `out[i]` (`out` is resized to the number of
    /// points; other entries are zero).
    ///
    /// Points are taken in groups of at most 16 that share a small cell of the tree.
    /// One walk per group collects the far cells every member may take whole, judged by
    /// the distance from the cell's centre of charge to the *group's* bounding box, and
    /// the points near enough to sum exactly; then each member sums that list in a
    /// vectorised loop. A cell is taken whole only where [`force_on`](Self::force_on)
    /// would take it whole for every member; the group's own cell, the cells holding it
    /// and leaves never are. So the pass opens at least the cells `force_on` opens and
    /// its mean error is no larger (on `n1000_e2500` at theta 0.9, 0.72 % against
    /// 1.10 %; single points can land either side), theta 0 is still the exact sum,
    /// and the pass is about a third cheaper than a walk per point on `n10000_e25000`
    /// (3.0 against 4.5 ms at theta 0.9).
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
        if self.nodes.is_empty() || self.nodes[0].charge <= 0.0 {
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
            if node.charge > GROUP_SIZE as f32 && node.children != NONE {
                stack.extend(self.occupied_children(node.children).rev());
                continue;
            }
            lists.collect_members(self, g, &wanted);
            if lists.members.iter().any(|m| m.wanted) {
                lists.collect_interactions(self, g, &query);
                for m in lists.members.iter().filter(|m| m.wanted) {
                    out[m.index as usize] = lists.sum(self.points[m.index as usize], &query);
                }
            }
        }
        self.stack = stack;
        self.lists = lists;
    }
}

/// A member of the group being summed.
#[derive(Clone, Copy, Debug)]
struct Member {
    index: u32,
    wanted: bool,
}

/// The interaction lists of one group, reused from group to group.
#[derive(Clone, Debug, Default)]
pub(super) struct GroupLists {
    members: Vec<Member>,
    /// Far cells taken whole and points summed exactly (the members among them),
    /// as centres and charges (1 for a point).
    x: Vec<f32>,
    y: Vec<f32>,
    charge: Vec<f32>,
    /// The group's bounding box.
    lo: Point2D<f32>,
    hi: Point2D<f32>,
    /// The cells from the root down to the group's parent: they hold the group.
    holders: Vec<u32>,
    stack: Vec<u32>,
}

impl GroupLists {
    /// The points under cell `g`, and their bounding box.
    fn collect_members(&mut self, tree: &ManyBody, g: u32, wanted: &impl Fn(usize) -> bool) {
        self.members.clear();
        self.lo = Point2D::new(f32::MAX, f32::MAX);
        self.hi = Point2D::new(f32::MIN, f32::MIN);
        self.stack.clear();
        self.stack.push(g);
        while let Some(c) = self.stack.pop() {
            let node = tree.nodes[c as usize];
            if node.children != NONE {
                self.stack.extend(node.children..node.children + 4);
                continue;
            }
            for b in tree.chain(node.body) {
                let p = tree.points[b as usize];
                self.lo = self.lo.min(p);
                self.hi = self.hi.max(p);
                self.members.push(Member {
                    index: b,
                    wanted: wanted(b as usize),
                });
            }
        }
        // The path any member took when it was inserted, found the same way.
        self.holders.clear();
        if let Some(first) = self.members.first() {
            let probe = tree.points[first.index as usize];
            let mut c = 0;
            while c != g && tree.cells[c as usize].children != NONE {
                self.holders.push(c);
                let cell = tree.cells[c as usize];
                c = cell.children + cell.quadrant(probe);
            }
        }
    }

    /// One walk for the whole group `g`: each cell far from the group's bounding box
    /// goes to the list whole, and the points of every leaf opened and of the group
    /// itself one by one.
    fn collect_interactions(&mut self, tree: &ManyBody, g: u32, query: &Query) {
        self.x.clear();
        self.y.clear();
        self.charge.clear();
        self.stack.clear();
        self.stack.push(0);
        while let Some(c) = self.stack.pop() {
            if c == g {
                // The members themselves, exactly.
                for i in 0..self.members.len() {
                    self.push(tree.points[self.members[i].index as usize], 1.0);
                }
                continue;
            }
            let node = tree.nodes[c as usize];
            // A cell holding the group is always opened (taking it whole would count
            // the members' own charge), and a leaf is summed point by point, as
            // `force_on` does.
            if node.children != NONE && !self.holders.contains(&c) {
                let dx = (self.lo.x - node.mx).max(node.mx - self.hi.x).max(0.0);
                let dy = (self.lo.y - node.my).max(node.my - self.hi.y).max(0.0);
                if node.width_sq < query.theta_sq * (dx * dx + dy * dy) {
                    self.push(Point2D::new(node.mx, node.my), node.charge);
                    continue;
                }
            }
            if node.children != NONE {
                self.stack.extend(tree.occupied_children(node.children));
                continue;
            }
            for b in tree.chain(node.body) {
                self.push(tree.points[b as usize], 1.0);
            }
        }
    }

    /// Adds a charge at `at` to the list.
    fn push(&mut self, at: Point2D<f32>, charge: f32) {
        self.x.push(at.x);
        self.y.push(at.y);
        self.charge.push(charge);
    }

    /// The force on point `p` from the lists, in [`LANES`] independent sums (so the
    /// loop runs in SIMD registers; a fixed order, so results repeat bit for bit).
    fn sum(&self, p: Point2D<f32>, query: &Query) -> Vector2D<f32> {
        // Branch-free, so the compiler keeps the lanes in vector registers: the point
        // itself (and any coincident one, d² = 0) adds nothing, as in `walk`.
        let term = |x: f32, y: f32, charge: f32| {
            let (dx, dy) = (p.x - x, p.y - y);
            let d_sq = dx * dx + dy * dy;
            let soft = if d_sq > query.min_sq {
                d_sq
            } else {
                query.min_sq
            };
            let s = if d_sq > 0.0 {
                query.strength * charge / soft
            } else {
                0.0
            };
            (dx * s, dy * s)
        };
        let (mut fx, mut fy) = ([0.0_f32; LANES], [0.0_f32; LANES]);
        let xs = self.x.chunks_exact(LANES);
        let ys = self.y.chunks_exact(LANES);
        let charges = self.charge.chunks_exact(LANES);
        let tail = (xs.remainder(), ys.remainder(), charges.remainder());
        for ((x, y), charge) in xs.zip(ys).zip(charges) {
            let (x, y, charge): (&[f32; LANES], &[f32; LANES], &[f32; LANES]) = (
                x.try_into().expect("exact chunk"),
                y.try_into().expect("exact chunk"),
                charge.try_into().expect("exact chunk"),
            );
            for l in 0..LANES {
                let (tx, ty) = term(x[l], y[l], charge[l]);
                fx[l] += tx;
                fy[l] += ty;
            }
        }
        for ((&x, &y), &charge) in tail.0.iter().zip(tail.1).zip(tail.2) {
            let (tx, ty) = term(x, y, charge);
            fx[0] += tx;
            fy[0] += ty;
        }
        Vector2D::new(fx.iter().sum(), fy.iter().sum())
    }
}
