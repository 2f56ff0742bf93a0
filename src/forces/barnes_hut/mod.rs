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
}

impl Cell {
    fn new(cx: f32, cy: f32, half: f32) -> Self {
        Self {
            cx,
            cy,
            half,
            children: NONE,
        }
    }

    fn quadrant(&self, p: Point2D<f32>) -> u32 {
        u32::from(p.x >= self.cx) | (u32::from(p.y >= self.cy) << 1)
    }
}

/// What a force query reads of a cell, packed into 24 bytes (same index as [`Cell`]).
#[derive(Clone, Copy, Debug, Default)]
struct Node {
    /// Charge-weighted centre and total charge (the number of points under the cell).
    mx: f32,
    my: f32,
    charge: f32,
    /// Squared width of the square: the cell counts as one body when
    /// `width_sq < theta² × d²`.
    width_sq: f32,
    children: u32,
    /// The cell's points are `charge` consecutive entries of the tree order from here.
    first: u32,
}

impl Node {
    /// The cell's points, as positions in the tree order.
    fn points(&self) -> std::ops::Range<usize> {
        let first = self.first as usize;
        first..first + self.charge as usize
    }
}

/// A reusable Barnes–Hut quadtree: build it over positions, then ask for forces.
/// Buffers are kept between calls, so a per-substep rebuild allocates nothing once warm.
///
/// The points are kept in the tree's own order (each cell's points consecutive, cells
/// in depth-first order), so a walk reads memory close to where it last read: at
/// 100,000 points the tree and points no longer fit a core's cache.
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
    /// The given points, by their index.
    points: Vec<Point2D<f32>>,
    /// The finite points in tree order, and the index each was given at.
    sorted: Vec<Point2D<f32>>,
    index: Vec<u32>,
    /// Scratch for sorting a cell's points into its quadrants.
    scratch: Vec<(Point2D<f32>, u32)>,
    entries: Vec<(Point2D<f32>, u32)>,
    stack: Vec<u32>,
    lists: GroupLists,
}

impl ManyBody {
    /// Builds the tree over `points` (non-finite points are left out). O(n log n).
    ///
    /// A cell is split into four while it holds two points or more, down to
    /// [`MAX_DEPTH`]; each split sorts the cell's points into its quadrants, top down.
    pub fn build(&mut self, points: &[Point2D<f32>]) {
        self.cells.clear();
        self.nodes.clear();
        let same_points = points.len() == self.points.len();
        self.points.clear();
        self.points.extend_from_slice(points);
        self.gather_entries(same_points);
        let mut entries = std::mem::take(&mut self.entries);
        self.sorted.clear();
        self.index.clear();
        if !entries.is_empty() {
            let (mut lo, mut hi) = (entries[0].0, entries[0].0);
            for (p, _) in &entries {
                lo = lo.min(*p);
                hi = hi.max(*p);
            }
            let half = ((hi.x - lo.x).max(hi.y - lo.y) * 0.5).max(1.0) * 1.0001;
            self.cells
                .push(Cell::new((lo.x + hi.x) * 0.5, (lo.y + hi.y) * 0.5, half));
            self.nodes.push(Node {
                children: NONE,
                ..Node::default()
            });
            self.split(&mut entries);
            self.sorted.extend(entries.iter().map(|e| e.0));
            self.index.extend(entries.iter().map(|e| e.1));
            self.sum_charges();
        }
        self.entries = entries;
    }

    /// The finite points with their indices, in the last build's tree order when the
    /// same points are still finite (points move little from one build to the next, so
    /// most cells are then sorted already), else in index order. The tree does not
    /// depend on which: every cell's points are sorted into its quadrants, and a
    /// deepest leaf's by index.
    fn gather_entries(&mut self, same_points: bool) {
        let finite = |p: &Point2D<f32>| p.x.is_finite() && p.y.is_finite();
        self.entries.clear();
        if same_points && self.points.iter().filter(|p| finite(p)).count() == self.index.len() {
            let points = &self.points;
            self.entries
                .extend(self.index.iter().map(|&i| (points[i as usize], i)));
            if self.entries.iter().all(|(p, _)| finite(p)) {
                return;
            }
            self.entries.clear();
        }
        self.entries.extend(
            self.points
                .iter()
                .enumerate()
                .filter(|(_, p)| finite(p))
                .map(|(i, &p)| (p, i as u32)),
        );
    }

    /// Splits the root and its descendants, depth first: each cell's points (a run of
    /// `entries`) are sorted into its four quadrants, whose cells go at the end.
    fn split(&mut self, entries: &mut [(Point2D<f32>, u32)]) {
        // (cell, first entry, entries, depth)
        let mut work = vec![(0_u32, 0_u32, entries.len() as u32, 0_u32)];
        while let Some((c, first, count, depth)) = work.pop() {
            self.nodes[c as usize].first = first;
            self.nodes[c as usize].charge = count as f32;
            let run = &mut entries[first as usize..(first + count) as usize];
            if count < 2 {
                continue;
            }
            if depth >= MAX_DEPTH {
                run.sort_unstable_by_key(|e| e.1);
                continue;
            }
            let cell = self.cells[c as usize];
            let mut counts = [0_u32; 4];
            let (mut last, mut sorted) = (0, true);
            for (p, _) in run.iter() {
                let q = cell.quadrant(*p);
                counts[q as usize] += 1;
                sorted &= q >= last;
                last = q;
            }
            let mut starts = [0_u32, counts[0], counts[0] + counts[1], 0];
            starts[3] = starts[2] + counts[2];
            if !sorted {
                self.scratch.clear();
                self.scratch.extend_from_slice(run);
                let mut at = starts;
                for &(p, i) in &self.scratch {
                    let q = cell.quadrant(p) as usize;
                    run[at[q] as usize] = (p, i);
                    at[q] += 1;
                }
            }
            let children = self.cells.len() as u32;
            self.cells[c as usize].children = children;
            self.nodes[c as usize].children = children;
            let h = cell.half * 0.5;
            for k in 0..4_u32 {
                let cx = if k & 1 == 1 { cell.cx + h } else { cell.cx - h };
                let cy = if k & 2 == 2 { cell.cy + h } else { cell.cy - h };
                self.cells.push(Cell::new(cx, cy, h));
                self.nodes.push(Node {
                    children: NONE,
                    ..Node::default()
                });
            }
            // The first quadrant on top of the stack: its cells follow its parent's.
            for k in (0..4).rev() {
                work.push((
                    children + k,
                    first + starts[k as usize],
                    counts[k as usize],
                    depth + 1,
                ));
            }
        }
    }

    /// Centres and widths, bottom up: children are created after their parents, so a
    /// reverse sweep sums each cell after its children.
    fn sum_charges(&mut self) {
        for c in (0..self.cells.len()).rev() {
            let (mut mx, mut my) = (0.0_f32, 0.0_f32);
            let node = self.nodes[c];
            if node.children == NONE {
                for p in &self.sorted[node.points()] {
                    mx += p.x;
                    my += p.y;
                }
            } else {
                for k in 0..4 {
                    let child = self.nodes[(node.children + k) as usize];
                    mx += child.mx * child.charge;
                    my += child.my * child.charge;
                }
            }
            let q = node.charge;
            let width = 2.0 * self.cells[c].half;
            let node = &mut self.nodes[c];
            (node.mx, node.my) = if q > 0.0 {
                (mx / q, my / q)
            } else {
                (0.0, 0.0)
            };
            node.width_sq = width * width;
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
            for k in node.points() {
                if self.index[k] as usize != i {
                    let q = self.sorted[k];
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
            // Positive, so a point's own term (offset zero) is zero in `sum` without a
            // branch.
            min_sq: (min_distance * min_distance).max(f32::MIN_POSITIVE),
        }
    }
}
