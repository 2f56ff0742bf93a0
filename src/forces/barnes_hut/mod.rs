//! The Barnes–Hut quadtree behind many-body repulsion: [`ManyBody`] builds a tree over
//! points and answers "what is the repulsion on this point" for one point
//! ([`ManyBody::force_on`]) or, walking once per group of neighbours, for all of them
//! (`groups.rs`, [`ManyBody::forces`]).
//!
//! Every point pushes every other with a force of magnitude `strength / d` along their
//! separation (2-D Coulomb, as d3-force's many-body force), softened below
//! `min_distance` and with no cut-off (cut-offs make limit cycles). Far groups of points
//! act through their centre of charge when `cell width / distance < theta`; `theta = 0`
//! is the exact O(n²) sum. The tree knows nothing of bodies, heat or configuration:
//! `forces/many_body.rs` turns it into a force on bodies.

use euclid::default::{Point2D, Vector2D};

mod groups;

use groups::GroupLists;

const NONE: u32 = u32::MAX;
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
