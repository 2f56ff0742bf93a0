//! Many-body repulsion: a Barnes–Hut quadtree over node positions.
//!
//! Every node pushes every other with a force of magnitude `strength / d` along their
//! separation (2-D Coulomb, as d3-force's many-body force), softened below
//! `min_distance` and with no cut-off (cut-offs make limit cycles). Far groups of nodes
//! act through their centre of charge when `cell width / distance < theta`; `theta = 0`
//! is the exact O(n²) sum.

use euclid::default::{Point2D, Vector2D};
use serde::{Deserialize, Serialize};

/// Many-body repulsion and centre pull, applied as forces on every substep.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Repulsion {
    /// Force between two nodes `d` apart is `strength / d` (force × length). Larger
    /// values spread the graph out; springs balance it at the edge length where
    /// `stiffness × stretch = strength × neighbours / length`. Default: `430_000.0`
    /// (d3-force's many-body strength −30 for a default node of mass 4 at 60 ticks per
    /// second: `30 × 4 × 60²`).
    pub strength: f32,
    /// Barnes–Hut opening ratio: a cell of width `w` at distance `d` counts as one body
    /// when `w / d < theta`. 0 is the exact sum; larger is cheaper and coarser (see the
    /// README's error/time table). Default: `0.9` (d3-force's default).
    pub theta: f32,
    /// Distances below this count as this, so coincident nodes get a finite push.
    /// Default: `8.0`.
    pub min_distance: f32,
    /// Pull toward `center`, in force per unit of distance, so disconnected parts do not
    /// drift away for ever. Default: `0.5`.
    pub center_pull: f32,
    /// The point the centre pull aims at. Default: the origin.
    pub center: Point2D<f32>,
}

impl Default for Repulsion {
    fn default() -> Self {
        Self {
            strength: 430_000.0,
            theta: 0.9,
            min_distance: 8.0,
            center_pull: 0.5,
            center: Point2D::origin(),
        }
    }
}

const NONE: u32 = u32::MAX;
/// Most points that share one walk in [`ManyBody::forces`]: larger groups walk the tree
/// less often but sum longer lists. 16 was the fastest of 2 to 64 on `n1000_e2500` and
/// `n10000_e25000`.
const GROUP_SIZE: usize = 16;
/// Independent partial sums per force, so the sum runs in vector registers.
const LANES: usize = 8;
/// Deeper than this, points share a leaf (they are closer than the root width / 2^24,
/// below f32 resolution anyway).
const MAX_DEPTH: u32 = 24;

/// A square of the tree while it is built.
#[derive(Clone, Copy, Debug)]
struct Cell {
    /// Centre and half width of the square.
    cx: f32,
    cy: f32,
    half: f32,
    /// First child (4 consecutive cells) or `NONE` for a leaf.
    children: u32,
    /// First body of a leaf's chain, or `NONE`.
    body: u32,
}

impl Cell {
    fn new(cx: f32, cy: f32, half: f32) -> Self {
        Self {
            cx,
            cy,
            half,
            children: NONE,
            body: NONE,
        }
    }

    fn quadrant(&self, p: Point2D<f32>) -> u32 {
        u32::from(p.x >= self.cx) | (u32::from(p.y >= self.cy) << 1)
    }
}

/// What a force query reads of a cell, packed into 24 bytes (same index as [`Cell`]).
#[derive(Clone, Copy, Debug, Default)]
struct Node {
    /// Charge-weighted centre and total charge.
    mx: f32,
    my: f32,
    charge: f32,
    /// Squared width of the square: the cell counts as one body when
    /// `width_sq < theta² × d²`.
    width_sq: f32,
    children: u32,
    body: u32,
}

/// A reusable Barnes–Hut quadtree: build it over positions, then ask for forces.
/// Buffers are kept between calls, so a per-substep rebuild allocates nothing once warm.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, ManyBody};
/// let points = [Point2D::new(0.0, 0.0), Point2D::new(10.0, 0.0)];
/// let mut tree = ManyBody::default();
/// tree.build(&points);
/// let f = tree.force_on(0, 100.0, 0.9, 1.0);
/// assert!((f.x + 10.0).abs() < 1e-4 && f.y == 0.0, "pushed away along -x with 100 / 10: {f:?}");
/// ```
#[derive(Clone, Debug, Default)]
pub struct ManyBody {
    cells: Vec<Cell>,
    nodes: Vec<Node>,
    next: Vec<u32>,
    points: Vec<Point2D<f32>>,
    stack: Vec<u32>,
    lists: GroupLists,
}

impl ManyBody {
    /// Builds the tree over `points` (non-finite points are left out). O(n log n).
    pub fn build(&mut self, points: &[Point2D<f32>]) {
        self.cells.clear();
        self.nodes.clear();
        self.points.clear();
        self.points.extend_from_slice(points);
        self.next.clear();
        self.next.resize(points.len(), NONE);
        let (mut lo, mut hi) = (
            Point2D::new(f32::MAX, f32::MAX),
            Point2D::new(f32::MIN, f32::MIN),
        );
        for p in points.iter().filter(|p| p.x.is_finite() && p.y.is_finite()) {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
        if lo.x > hi.x {
            return;
        }
        let half = ((hi.x - lo.x).max(hi.y - lo.y) * 0.5).max(1.0) * 1.0001;
        self.cells
            .push(Cell::new((lo.x + hi.x) * 0.5, (lo.y + hi.y) * 0.5, half));
        for (i, &p) in points.iter().enumerate() {
            if p.x.is_finite() && p.y.is_finite() {
                self.insert(i as u32, p);
            }
        }
        // Children are created after their parents: a reverse sweep sums bottom-up.
        self.nodes.resize(self.cells.len(), Node::default());
        for c in (0..self.cells.len()).rev() {
            let cell = self.cells[c];
            let (mut q, mut mx, mut my) = (0.0_f32, 0.0_f32, 0.0_f32);
            if cell.children == NONE {
                for b in self.chain(cell.body) {
                    let p = self.points[b as usize];
                    q += 1.0;
                    mx += p.x;
                    my += p.y;
                }
            } else {
                for k in 0..4 {
                    let child = self.nodes[(cell.children + k) as usize];
                    q += child.charge;
                    mx += child.mx * child.charge;
                    my += child.my * child.charge;
                }
            }
            let width = 2.0 * cell.half;
            self.nodes[c] = Node {
                mx: if q > 0.0 { mx / q } else { 0.0 },
                my: if q > 0.0 { my / q } else { 0.0 },
                charge: q,
                width_sq: width * width,
                children: cell.children,
                body: cell.body,
            };
        }
    }

    fn insert(&mut self, body: u32, p: Point2D<f32>) {
        let mut c = 0_usize;
        let mut depth = 0;
        loop {
            let cell = self.cells[c];
            if cell.children != NONE {
                c = (cell.children + cell.quadrant(p)) as usize;
                depth += 1;
                continue;
            }
            if cell.body == NONE || depth >= MAX_DEPTH {
                self.next[body as usize] = cell.body;
                self.cells[c].body = body;
                return;
            }
            // Split the leaf and push its chain down one level.
            let first = self.cells.len() as u32;
            let h = cell.half * 0.5;
            for k in 0..4_u32 {
                let cx = if k & 1 == 1 { cell.cx + h } else { cell.cx - h };
                let cy = if k & 2 == 2 { cell.cy + h } else { cell.cy - h };
                self.cells.push(Cell::new(cx, cy, h));
            }
            self.cells[c].children = first;
            let mut b = cell.body;
            self.cells[c].body = NONE;
            while b != NONE {
                let following = self.next[b as usize];
                let q = self.cells[c].quadrant(self.points[b as usize]) + first;
                let child = &mut self.cells[q as usize];
                self.next[b as usize] = child.body;
                child.body = b;
                b = following;
            }
            // Chains of coincident points may land in one child again: loop on.
        }
    }

    /// The repulsion on point `i` of the last [`build`](Self::build): the sum over
    /// every other point `j` of `strength × (pᵢ − pⱼ) / max(d², min_distance²)`, with
    /// far cells taken whole when `width / d < theta`.
    ///
    /// # Panics
    /// If `i` is not an index of the points given to the last `build`.
    pub fn force_on(
        &mut self,
        i: usize,
        strength: f32,
        theta: f32,
        min_distance: f32,
    ) -> Vector2D<f32> {
        let query = Query::new(strength, theta, min_distance);
        let mut stack = std::mem::take(&mut self.stack);
        let f = self.walk(i, &query, &mut stack);
        self.stack = stack;
        f
    }

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

    fn walk(&self, i: usize, query: &Query, stack: &mut Vec<u32>) -> Vector2D<f32> {
        let p = self.points[i];
        let mut f = Vector2D::zero();
        if self.nodes.is_empty() || !(p.x.is_finite() && p.y.is_finite()) {
            return f;
        }
        stack.clear();
        if self.nodes[0].charge > 0.0 {
            stack.push(0);
        }
        while let Some(c) = stack.pop() {
            let node = self.nodes[c as usize];
            let dx = p.x - node.mx;
            let dy = p.y - node.my;
            let d_sq = dx * dx + dy * dy;
            if node.children != NONE {
                if node.width_sq < query.theta_sq * d_sq {
                    let s = query.strength * node.charge / d_sq.max(query.min_sq);
                    f += Vector2D::new(dx, dy) * s;
                } else {
                    stack.extend(self.occupied_children(node.children));
                }
                continue;
            }
            for b in self.chain(node.body) {
                if b as usize != i {
                    let q = self.points[b as usize];
                    let (dx, dy) = (p.x - q.x, p.y - q.y);
                    let d_sq = dx * dx + dy * dy;
                    if d_sq > 0.0 {
                        f += Vector2D::new(dx, dy) * (query.strength / d_sq.max(query.min_sq));
                    }
                }
            }
        }
        f
    }

    /// The points of the leaf chain starting at `first`.
    fn chain(&self, first: u32) -> impl Iterator<Item = u32> + '_ {
        std::iter::successors((first != NONE).then_some(first), move |&b| {
            let next = self.next[b as usize];
            (next != NONE).then_some(next)
        })
    }

    /// The children (first at `children`) that hold a point: empty quadrants add
    /// nothing and are never visited.
    fn occupied_children(&self, children: u32) -> impl DoubleEndedIterator<Item = u32> + '_ {
        (children..children + 4).filter(move |&k| self.nodes[k as usize].charge > 0.0)
    }
}

/// The constants of one force query.
struct Query {
    strength: f32,
    theta_sq: f32,
    min_sq: f32,
}

impl Query {
    fn new(strength: f32, theta: f32, min_distance: f32) -> Self {
        // NaN softens nothing, in both `walk` (whose `max` skips it) and `sum`.
        let min_distance = if min_distance.is_nan() {
            0.0
        } else {
            min_distance
        };
        Self {
            strength,
            theta_sq: theta * theta,
            min_sq: min_distance * min_distance,
        }
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
struct GroupLists {
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
