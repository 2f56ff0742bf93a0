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

use crate::parallel;
use euclid::default::{Point2D, Vector2D};

mod groups;
mod order;

const NONE: u32 = u32::MAX;
/// The place of a point of the root square (`x`, `y` in `[0, 1)`) on the Z-order
/// curve: the quadrant it falls in at every depth down to [`MAX_DEPTH`], the deepest
/// last (x in the low bit of each pair, y in the high one, as children are numbered).
fn z_order(x: f32, y: f32) -> u64 {
    let scale = (1_u32 << MAX_DEPTH) as f32;
    let limit = (1_u64 << MAX_DEPTH) - 1;
    // The bits of the cell index, each followed by a zero.
    let spread = |v: f32| {
        let mut q = ((v * scale) as u64).min(limit);
        q = (q | (q << 16)) & 0x0000_ffff_0000_ffff;
        q = (q | (q << 8)) & 0x00ff_00ff_00ff_00ff;
        q = (q | (q << 4)) & 0x0f0f_0f0f_0f0f_0f0f;
        q = (q | (q << 2)) & 0x3333_3333_3333_3333;
        (q | (q << 1)) & 0x5555_5555_5555_5555
    };
    spread(x) | (spread(y) << 1)
}

/// Deeper than this, points share a leaf (they are closer than the root width / 2^24,
/// below f32 resolution anyway).
const MAX_DEPTH: u32 = 24;

/// What a force query reads of a cell, packed into 24 bytes.
#[derive(Clone, Copy, Debug, Default)]
struct Node {
    /// Charge-weighted centre.
    mx: f32,
    my: f32,
    /// The number of points under the cell: its charge.
    count: u32,
    /// Squared width of the square: the cell counts as one body when
    /// `width_sq < theta² × d²`.
    width_sq: f32,
    children: u32,
    /// The cell's points are `count` consecutive entries of the tree order from here.
    first: u32,
}

impl Node {
    /// The cell's points, as positions in the tree order.
    fn points(&self) -> std::ops::Range<usize> {
        let first = self.first as usize;
        first..first + self.count as usize
    }

    /// A leaf of half width `half`, its points and centre of charge to be filled in.
    fn square(half: f32) -> Self {
        let width = 2.0 * half;
        Self {
            width_sq: width * width,
            children: NONE,
            ..Self::default()
        }
    }

    /// The cell's total charge: one per point.
    fn charge(&self) -> f32 {
        self.count as f32
    }
}

/// A cell still to split: (cell, first entry, entries, depth, half width).
type Work = (u32, u32, u32, u32, f32);

/// From this many points on, the tree's build splits the cells at [`SUBTREE_DEPTH`] as
/// subtrees of their own (side by side under `parallel`).
const SUBTREES_FROM: usize = 8_192;
/// The depth of those subtrees' roots (up to 4³ = 64 of them).
const SUBTREE_DEPTH: u32 = 3;

/// Splits the cells of `work` depth first: a cell's quadrants are the four runs of its
/// points by the code's two bits at its depth; their cells go at the end of `nodes`.
/// Cells at depth `stop` are left whole and listed in `subtrees` from `*listed` on (each
/// with a buffer for its own cells, kept from earlier builds where there is one).
fn split_cells(
    entries: &[(u64, u32)],
    nodes: &mut Vec<Node>,
    work: &mut Vec<Work>,
    stop: u32,
    subtrees: &mut Vec<(Work, Vec<Node>)>,
    listed: &mut usize,
) {
    while let Some((c, first, count, depth, half)) = work.pop() {
        nodes[c as usize].first = first;
        nodes[c as usize].count = count;
        if count < 2 || depth >= MAX_DEPTH {
            continue;
        }
        if depth == stop {
            let root = (c, first, count, depth, half);
            match subtrees.get_mut(*listed) {
                Some(subtree) => subtree.0 = root,
                None => subtrees.push((root, Vec::new())),
            }
            *listed += 1;
            continue;
        }
        let shift = 2 * (MAX_DEPTH - 1 - depth);
        let run = &entries[first as usize..(first + count) as usize];
        let quadrant = |e: &(u64, u32)| ((e.0 >> shift) & 3) as u32;
        let mut starts = [0_u32, 0, 0, 0, count];
        for (q, start) in (1_u32..).zip(&mut starts[1..4]) {
            *start = run.partition_point(|e| quadrant(e) < q) as u32;
        }
        let children = nodes.len() as u32;
        nodes[c as usize].children = children;
        let h = half * 0.5;
        nodes.extend([Node::square(h); 4]);
        // The first quadrant on top of the stack: its cells follow its parent's.
        for k in (0..4).rev() {
            let (start, end) = (starts[k], starts[k + 1]);
            work.push((
                children + k as u32,
                first + start,
                end - start,
                depth + 1,
                h,
            ));
        }
    }
}

/// `node` of a subtree, its children moved by `offset`.
fn moved(node: &Node, offset: u32) -> Node {
    Node {
        children: if node.children == NONE {
            NONE
        } else {
            node.children + offset
        },
        ..*node
    }
}

/// Centres of charge of the cells `range` of `nodes`, bottom up: children come after
/// their parents, so a reverse sweep sums each cell after its children (cells past the
/// range are summed already). `sorted` holds the points in tree order.
fn sum_charges(nodes: &mut [Node], sorted: &[Point2D<f32>], range: std::ops::Range<usize>) {
    for c in range.rev() {
        let (mut mx, mut my) = (0.0_f32, 0.0_f32);
        let node = nodes[c];
        if node.children == NONE {
            for p in &sorted[node.points()] {
                mx += p.x;
                my += p.y;
            }
        } else {
            for k in 0..4 {
                let child = nodes[(node.children + k) as usize];
                mx += child.mx * child.charge();
                my += child.my * child.charge();
            }
        }
        let q = node.charge();
        let node = &mut nodes[c];
        (node.mx, node.my) = if q > 0.0 {
            (mx / q, my / q)
        } else {
            (0.0, 0.0)
        };
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
    nodes: Vec<Node>,
    /// The given points, by their index.
    points: Vec<Point2D<f32>>,
    /// The finite points in tree order, and the index each was given at.
    sorted: Vec<Point2D<f32>>,
    index: Vec<u32>,
    /// Every finite point's Z-order code and index, sorted (`order.rs`), and the
    /// sort's buffers.
    entries: Vec<(u64, u32)>,
    scratch: Vec<(u64, u32)>,
    ends: Vec<u32>,
    /// The cells still to split.
    work: Vec<Work>,
    /// The subtrees of a large tree, each with its own cells.
    subtrees: Vec<(Work, Vec<Node>)>,
    stack: Vec<u32>,
    /// Scratch of [`forces`](Self::forces): the groups, whether each point (in the
    /// tree's order) is wanted, and the forces in that order.
    groups: Vec<std::ops::Range<usize>>,
    wanted: Vec<bool>,
    by_k: Vec<Vector2D<f32>>,
}

impl ManyBody {
    /// Builds the tree over `points` (non-finite points are left out). O(n log n).
    ///
    /// A cell is split into four while it holds two points or more, down to depth 24
    /// (deeper, points are closer than f32 resolves anyway). The points are sorted once
    /// by their place on a Z-order curve over the root square (the quadrant at every
    /// depth, 24 bits each way), so every cell's points are one run of the order and its
    /// quadrants four runs of it.
    pub fn build(&mut self, points: &[Point2D<f32>]) {
        self.build_in_subtrees_from(points, SUBTREES_FROM);
    }

    /// [`build`](Self::build), in subtrees from `subtrees_from` points on.
    fn build_in_subtrees_from(&mut self, points: &[Point2D<f32>], subtrees_from: usize) {
        self.nodes.clear();
        let same_points = points.len() == self.points.len();
        self.points.clear();
        self.points.extend_from_slice(points);
        self.gather_entries(same_points);
        self.sorted.clear();
        self.index.clear();
        let finite = self.entries.iter().map(|&(_, i)| self.points[i as usize]);
        let Some((lo, hi)) =
            finite.fold(None, |bounds: Option<(Point2D<f32>, Point2D<f32>)>, p| {
                Some(bounds.map_or((p, p), |(lo, hi)| (lo.min(p), hi.max(p))))
            })
        else {
            return;
        };
        let half = ((hi.x - lo.x).max(hi.y - lo.y) * 0.5).max(1.0) * 1.0001;
        self.nodes.push(Node::square(half));
        let (cx, cy) = ((lo.x + hi.x) * 0.5, (lo.y + hi.y) * 0.5);
        let (x0, y0, side) = (cx - half, cy - half, 2.0 * half);
        let points = &self.points;
        parallel::for_each(
            &mut self.entries,
            || (),
            |(), entry| {
                let p = points[entry.1 as usize];
                entry.0 = z_order((p.x - x0) / side, (p.y - y0) / side);
            },
        );
        // Adaptive: the last build's order is nearly this one. Codes tie only within a
        // deepest leaf, whose points then go in index order, whatever the last order
        // (and the entries are unique, so any sort gives the same order).
        order::sort_entries(&mut self.entries, &mut self.scratch, &mut self.ends);
        self.index.extend(self.entries.iter().map(|e| e.1));
        self.sorted
            .extend(self.index.iter().map(|&i| points[i as usize]));
        self.split(half, subtrees_from);
    }

    /// The finite points' indices (codes to be filled in): the last build's entries, in
    /// its tree order, when the same points are still finite (the sort below then finds
    /// them nearly sorted), else in index order. The tree does not depend on which.
    fn gather_entries(&mut self, same_points: bool) {
        let finite = |p: &Point2D<f32>| p.x.is_finite() && p.y.is_finite();
        let points = &self.points;
        if same_points
            && points.iter().filter(|p| finite(p)).count() == self.entries.len()
            && self
                .entries
                .iter()
                .all(|&(_, i)| finite(&points[i as usize]))
        {
            return;
        }
        self.entries.clear();
        self.entries.extend(
            points
                .iter()
                .enumerate()
                .filter(|(_, p)| finite(p))
                .map(|(i, _)| (0, i as u32)),
        );
    }

    /// Splits the root (of half width `half`) and its descendants, and sums their
    /// centres of charge. From `subtrees_from` points on ([`SUBTREES_FROM`]), the cells at depth
    /// [`SUBTREE_DEPTH`] are split and summed as subtrees of their own (side by side
    /// under `parallel`) and appended in order: the same cells, numbered otherwise, and
    /// every centre the same sum.
    fn split(&mut self, half: f32, subtrees_from: usize) {
        let mut work = std::mem::take(&mut self.work);
        work.clear();
        work.push((0_u32, 0_u32, self.entries.len() as u32, 0_u32, half));
        let stop = if self.entries.len() >= subtrees_from {
            SUBTREE_DEPTH
        } else {
            u32::MAX
        };
        let mut subtrees = std::mem::take(&mut self.subtrees);
        let mut listed = 0;
        split_cells(
            &self.entries,
            &mut self.nodes,
            &mut work,
            stop,
            &mut subtrees,
            &mut listed,
        );
        subtrees.truncate(listed);
        self.work = work;
        let top = self.nodes.len();
        let (entries, sorted) = (&self.entries, &self.sorted);
        parallel::for_each(&mut subtrees, Vec::new, |work, (root, nodes)| {
            let (_, first, count, depth, half) = *root;
            nodes.clear();
            nodes.push(Node {
                first,
                count,
                ..Node::square(half)
            });
            work.clear();
            work.push((0, first, count, depth, half));
            split_cells(entries, nodes, work, u32::MAX, &mut Vec::new(), &mut 0);
            let all = 0..nodes.len();
            sum_charges(nodes, sorted, all);
        });
        // Local cell `i > 0` of a subtree goes to `offset + i`, the subtrees' cells in
        // order after the top's; copied side by side.
        let mut offsets = Vec::with_capacity(subtrees.len());
        let mut end = top;
        for (_, local) in &subtrees {
            offsets.push(end as u32 - 1);
            end += local.len() - 1;
        }
        self.nodes.resize(end, Node::default());
        let ranges = offsets
            .iter()
            .zip(&subtrees)
            .map(|(&offset, (_, local))| offset as usize + 1..offset as usize + local.len());
        let mut copies: Vec<_> = parallel::split_ranges(&mut self.nodes, ranges)
            .into_iter()
            .zip(&subtrees)
            .zip(&offsets)
            .collect();
        parallel::for_each(
            &mut copies,
            || (),
            |(), (((_, to), (_, local)), offset)| {
                for (to, node) in to.iter_mut().zip(&local[1..]) {
                    *to = moved(node, **offset);
                }
            },
        );
        for (((c, ..), local), &offset) in subtrees.iter().zip(&offsets) {
            self.nodes[*c as usize] = moved(&local[0], offset);
        }
        self.subtrees = subtrees;
        sum_charges(&mut self.nodes, &self.sorted, 0..top);
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
        if self.nodes[0].count > 0 {
            stack.push(0);
        }
        while let Some(c) = stack.pop() {
            let node = self.nodes[c as usize];
            let dx = p.x - node.mx;
            let dy = p.y - node.my;
            let d_sq = dx * dx + dy * dy;
            if node.children != NONE {
                if node.width_sq < query.theta_sq * d_sq {
                    let s = query.strength * node.charge() / d_sq.max(query.min_sq);
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
        (children..children + 4).filter(move |&k| self.nodes[k as usize].count > 0)
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
            // Positive, so no term divides by zero (a point's own term, at offset zero,
            // is selected away in `sum` and skipped in `force_on`).
            min_sq: (min_distance * min_distance).max(f32::MIN_POSITIVE),
        }
    }
}

#[cfg(test)]
mod tests;
