//! The sparse stress model (Ortmann, Klimenta & Brandes, GD 2016): the pairs whose graph
//! distance a layout keeps, and how much each weighs.
//!
//! Stress is `Σ w_ij (‖x_i − x_j‖ − L·d_ij)²` with `d_ij` the hop distance, `L` the length
//! of a hop and `w_ij = d_ij⁻²`: a spring between every two nodes. This model keeps it
//! near linear in the graph's size:
//! - **exact terms** for the pairs within a few hops ([`SparseStress::near`], up to
//!   [`MAX_NEAR`] a node, nearest first), edges aside (they are the world's springs);
//! - **pivot terms** for the rest: each component gets pivots chosen max-min (each the
//!   node farthest from those chosen), every node a term to every pivot of its component
//!   at their hop distance, weighted `s / d²` where `s` counts the nodes of the pivot's
//!   region (the nodes nearer to it than to any other pivot) within `d / 2` hops of it:
//!   the pivot stands for them. A term moves its node only.
//!
//! A component no larger than its share of pivots has every node a pivot, each its own
//! region: the terms are then exactly the full stress (every pair, `s = 1`).

use crate::graph::{Graph, UNREACHED};

/// Most exact terms a node keeps (the nearest ones, in breadth-first order): a hub's
/// two-hop neighbourhood can hold the whole graph.
pub(crate) const MAX_NEAR: usize = 48;

/// Breadth-first searches whose hops are gathered before they go into the table.
const COLUMN_BLOCK: usize = 16;

/// The terms of one graph's sparse stress model.
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub(crate) struct SparseStress {
    /// Each node's component.
    pub(crate) component: Vec<u32>,
    /// The pivots, component by component (`pivot_range[c]` are component `c`'s).
    pub(crate) pivots: Vec<u32>,
    pub(crate) pivot_range: Vec<(u32, u32)>,
    /// Hops from each node to each pivot of its component: node `i`'s are
    /// `hops[row[i]..row[i] + its component's pivot count]`, in pivot order.
    pub(crate) hops: Vec<u16>,
    pub(crate) row: Vec<u32>,
    /// Each pivot's weight by hop distance `d`: `s(d) / d²` (index `d`), 0 up to the
    /// cutoff ([`pivot_cutoff`](Self::pivot_cutoff)) and past the component's longest
    /// distance; `stride[c]` entries a pivot of component `c`.
    weight_start: Vec<u32>,
    weights: Vec<f32>,
    pub(crate) stride: Vec<u32>,
    /// Exact terms: node `i`'s are `near[near_start[i]..near_start[i + 1]]` with their
    /// hop distance in `near_hops`.
    pub(crate) near_start: Vec<u32>,
    pub(crate) near: Vec<u32>,
    pub(crate) near_hops: Vec<u16>,
    /// Per node, how many exact terms each of its kept ones stands for (1 unless its
    /// near nodes were more than [`MAX_NEAR`]).
    pub(crate) near_scale: Vec<f32>,
    /// Per component: whether every node is a pivot (the full stress).
    pub(crate) full: Vec<bool>,
    /// The exact terms reach this many hops in components that are not full; pivot
    /// terms start beyond it (beyond one hop in full components).
    pub(crate) exact_hops: u16,
    /// Each component's size.
    pub(crate) sizes: Vec<u32>,
}

impl SparseStress {
    /// The model of `graph` with about `pivots` pivots in all (shared among components
    /// by size; `usize::MAX` for the full stress) and exact terms within `exact_hops`.
    pub(crate) fn new(graph: &Graph, pivots: usize, exact_hops: u16) -> Self {
        let n = graph.len();
        let (component, count) = graph.components();
        let mut members: Vec<Vec<u32>> = vec![Vec::new(); count];
        for (i, &c) in component.iter().enumerate() {
            members[c as usize].push(i as u32);
        }
        let mut model = Self {
            component,
            row: vec![0; n],
            exact_hops: exact_hops.max(1),
            sizes: members.iter().map(|m| m.len() as u32).collect(),
            ..Self::default()
        };
        let mut hops = vec![UNREACHED; n];
        let mut queue = Vec::new();
        for nodes in &members {
            let share = if pivots >= n {
                nodes.len()
            } else {
                let share = (pivots as f64 * nodes.len() as f64 / n as f64).round() as usize;
                share.clamp(1, nodes.len())
            };
            let full = share >= nodes.len();
            model.add_component(graph, nodes, share, full, &mut hops, &mut queue);
        }
        model.near_terms(graph);
        model
    }

    /// Pivots, hops and weights of one component.
    fn add_component(
        &mut self,
        graph: &Graph,
        nodes: &[u32],
        share: usize,
        full: bool,
        hops: &mut [u16],
        queue: &mut Vec<u32>,
    ) {
        let first = self.pivots.len() as u32;
        let base = self.hops.len();
        for (k, &i) in nodes.iter().enumerate() {
            self.row[i as usize] = (base + k * share) as u32;
        }
        self.hops.resize(base + nodes.len() * share, UNREACHED);
        // Max-min: each next pivot the node farthest from those chosen (the lowest index
        // among ties), starting from the component's first node.
        let mut nearest = vec![u16::MAX; nodes.len()];
        let mut pivot = nodes[0];
        let mut rng = crate::stress::sgd::Rng::new(0x2545_f491 ^ u64::from(nodes[0]));
        // Searches' results a block of pivots at a time, one column each, written into
        // the node-major table a block at a time: a column written straight into it
        // would touch a cache line per node, from memory on a large graph
        // (`docs/performance.md` gives the time).
        let len = nodes.len();
        let mut columns = vec![UNREACHED; COLUMN_BLOCK.min(share) * len];
        for k in 0..share {
            let p = if full { nodes[k] } else { pivot };
            self.pivots.push(p);
            graph.bfs(p as usize, hops, queue);
            let column = &mut columns[(k % COLUMN_BLOCK) * len..(k % COLUMN_BLOCK + 1) * len];
            for ((m, &i), out) in nodes.iter().enumerate().zip(column.iter_mut()) {
                let h = hops[i as usize];
                *out = h;
                nearest[m] = nearest[m].min(h);
            }
            if k % COLUMN_BLOCK == COLUMN_BLOCK - 1 || k + 1 == share {
                let first_column = k - k % COLUMN_BLOCK;
                let filled = k - first_column + 1;
                for m in 0..len {
                    let row = base + m * share + first_column;
                    for (b, out) in self.hops[row..row + filled].iter_mut().enumerate() {
                        *out = columns[b * len + m];
                    }
                }
            }
            if !full {
                pivot = nodes[next_pivot(&nearest, &mut rng)];
            }
        }
        self.pivot_range.push((first, first + share as u32));
        self.full.push(full);
        // Regions: each node belongs to its nearest pivot (the first among ties); a
        // pivot's weight at distance d counts its region within d / 2 hops.
        let mut counts: Vec<Vec<u32>> = vec![Vec::new(); share];
        for m in 0..nodes.len() {
            let row = &self.hops[base + m * share..base + (m + 1) * share];
            let Some((k, &h)) = row.iter().enumerate().min_by_key(|&(k, &h)| (h, k)) else {
                continue;
            };
            if h == UNREACHED {
                continue;
            }
            let c = &mut counts[k];
            if c.len() <= h as usize {
                c.resize(h as usize + 1, 0);
            }
            c[h as usize] += 1;
        }
        let longest = self.hops[base..]
            .iter()
            .filter(|&&h| h != UNREACHED)
            .max()
            .copied()
            .unwrap_or(0) as usize;
        // Terms as near as the cutoff are the edges' and the exact terms' (weight 0),
        // and a last 0 stands for every distance beyond the longest (a node no path
        // reaches).
        let cutoff = if full { 1 } else { self.exact_hops as usize };
        self.stride.push(longest as u32 + 2);
        for count in &counts {
            self.weight_start.push(self.weights.len() as u32);
            let mut within = 0_u32;
            let mut cumulative = Vec::with_capacity(longest / 2 + 1);
            for h in 0..=longest / 2 {
                within += count.get(h).copied().unwrap_or(0);
                cumulative.push(within);
            }
            self.weights.extend((0..=longest).map(|d| {
                if d <= cutoff {
                    0.0
                } else {
                    cumulative[d / 2] as f32 / (d * d) as f32
                }
            }));
            self.weights.push(0.0);
        }
    }

    /// The exact terms: every node within `exact_hops` of each node of a component that
    /// is not full, two hops or more (`near_of`).
    fn near_terms(&mut self, graph: &Graph) {
        let n = graph.len();
        self.near_start = Vec::with_capacity(n + 1);
        self.near_start.push(0);
        self.near_scale = Vec::with_capacity(n);
        let mut reach = Reach::new(n);
        for i in 0..n {
            self.push_near_of(graph, i, &mut reach);
        }
    }

    /// Appends node `i`'s exact terms: every node within `exact_hops` of it, two hops or
    /// more, when its component is not full. A node with more than [`MAX_NEAR`] (a hub's
    /// neighbours see the whole graph within two hops) keeps [`MAX_NEAR`] spread evenly
    /// over them in breadth-first order, each weighing for the ones left out
    /// (`near_scale`).
    fn push_near_of(&mut self, graph: &Graph, i: usize, reach: &mut Reach) {
        let mut scale = 1.0;
        if self.exact_hops >= 2 && !self.full[self.component[i] as usize] {
            let found = reach.within(graph, i, self.exact_hops);
            let (count, keep) = (found.len(), found.len().min(MAX_NEAR));
            if count > keep {
                scale = count as f32 / keep as f32;
            }
            for k in 0..keep {
                let (v, h) = found[k * count / keep];
                self.near.push(v);
                self.near_hops.push(h);
            }
        }
        self.near_scale.push(scale);
        self.near_start.push(self.near.len() as u32);
    }

    /// Adds node `leaf` (the next node, joined to `parent` only) without searching the
    /// graph again: its hops to the pivots are its parent's plus one, its exact terms
    /// those within reach of it in `graph` (which holds it). The other nodes keep their
    /// terms (none of their distances changed; their pull toward the leaf is left to
    /// the next full build), and the pivots their regions.
    pub(crate) fn add_leaf(
        &mut self,
        graph: &Graph,
        leaf: usize,
        parent: usize,
        reach: &mut Reach,
    ) {
        debug_assert_eq!(leaf, self.component.len());
        let c = self.component[parent] as usize;
        self.component.push(c as u32);
        self.sizes[c] += 1;
        let count = (self.pivot_range[c].1 - self.pivot_range[c].0) as usize;
        let from = self.row[parent] as usize;
        self.row.push(self.hops.len() as u32);
        for k in 0..count {
            let h = self.hops[from + k];
            self.hops
                .push(if h >= UNREACHED - 1 { UNREACHED } else { h + 1 });
        }
        self.push_near_of(graph, leaf, reach);
    }

    /// The pivots of node `i`'s component, with node `i`'s hops to each.
    pub(crate) fn pivot_terms(&self, i: usize) -> (&[u32], &[u16]) {
        let c = self.component[i] as usize;
        let (a, b) = self.pivot_range[c];
        let row = self.row[i] as usize;
        let count = (b - a) as usize;
        (
            &self.pivots[a as usize..b as usize],
            &self.hops[row..row + count],
        )
    }

    /// The weight (`s / d²`) of a term to the `k`-th pivot at `d` hops (0 within the
    /// cutoff and for unreached nodes).
    pub(crate) fn pivot_weight(&self, k: usize, d: u16) -> f32 {
        let table = self.pivot_weights(k);
        table[(d as usize).min(table.len() - 1)]
    }

    /// The weights of the `k`-th pivot, by hop distance (the last entry, 0, for every
    /// distance beyond).
    pub(crate) fn pivot_weights(&self, k: usize) -> &[f32] {
        let start = self.weight_start[k] as usize;
        let end = self
            .weight_start
            .get(k + 1)
            .map_or(self.weights.len(), |&e| e as usize);
        &self.weights[start..end]
    }

    /// The weight tables of component `c`'s pivots, one after the other, each of
    /// `stride[c]` entries.
    pub(crate) fn component_weights(&self, c: usize) -> &[f32] {
        let (a, b) = self.pivot_range[c];
        let start = self.weight_start.get(a as usize).map_or(0, |&s| s as usize);
        let end = self
            .weight_start
            .get(b as usize)
            .map_or(self.weights.len(), |&e| e as usize);
        &self.weights[start..end]
    }

    /// Pivot terms of node `i` start beyond this many hops (exact terms and edges cover
    /// the nearer pairs).
    pub(crate) fn pivot_cutoff(&self, i: usize) -> u16 {
        if self.full[self.component[i] as usize] {
            1
        } else {
            self.exact_hops
        }
    }

    /// Node `i`'s exact terms: the other nodes and their hop distances.
    pub(crate) fn near_terms_of(&self, i: usize) -> (&[u32], &[u16]) {
        let (a, b) = (self.near_start[i] as usize, self.near_start[i + 1] as usize);
        (&self.near[a..b], &self.near_hops[a..b])
    }
}

impl SparseStress {
    /// Whether these terms can be the model of a graph of `n` nodes: every index in
    /// range, every run where its start says, every weight finite and not negative, and
    /// each component's size its count of nodes. What a snapshot's model is checked
    /// against before the layout reads it; `Err` names the first part that disagrees.
    pub(crate) fn check(&self, n: usize) -> Result<(), &'static str> {
        let components = self.sizes.len();
        let lengths = [self.component.len(), self.row.len(), self.near_scale.len()];
        if lengths != [n; 3] || self.near_start.len() != n + 1 {
            return Err("node counts");
        }
        let per_component = [self.pivot_range.len(), self.full.len(), self.stride.len()];
        if per_component != [components; 3] || self.weight_start.len() != self.pivots.len() {
            return Err("component counts");
        }
        let mut sizes = vec![0_u32; components];
        for &c in &self.component {
            *sizes.get_mut(c as usize).ok_or("component")? += 1;
        }
        if sizes != self.sizes {
            return Err("sizes");
        }
        if self.weight_start.windows(2).any(|w| w[0] >= w[1])
            || self
                .weight_start
                .last()
                .is_some_and(|&s| s as usize >= self.weights.len())
        {
            return Err("weight_start");
        }
        let mut end = 0;
        for (c, &(a, b)) in self.pivot_range.iter().enumerate() {
            let fits = a == end && a <= b && b as usize <= self.pivots.len();
            let stride = self.stride[c] as usize;
            if !fits || (b - a) as usize > self.sizes[c] as usize || stride == 0 {
                return Err("pivot_range");
            }
            end = b;
            // As `component_weights` reads them (within `weights`, by the check above).
            let at = |k: u32| self.weight_start.get(k as usize).map(|&s| s as usize);
            let table = at(a).unwrap_or(0)..at(b).unwrap_or(self.weights.len());
            if !self.full[c] && table.len() != (b - a) as usize * stride {
                return Err("stride");
            }
        }
        if end as usize != self.pivots.len() || self.pivots.iter().any(|&p| p as usize >= n) {
            return Err("pivots");
        }
        if !self.weights.iter().all(|w| w.is_finite() && *w >= 0.0) {
            return Err("weights");
        }
        for (i, &c) in self.component.iter().enumerate() {
            let (a, b) = self.pivot_range[c as usize];
            let row = self.row[i] as usize;
            if row + (b - a) as usize > self.hops.len() {
                return Err("row");
            }
        }
        let near = self.near.len();
        if self.near_start[0] != 0
            || self.near_start.windows(2).any(|w| w[0] > w[1])
            || self.near_start[n] as usize != near
            || self.near_hops.len() != near
        {
            return Err("near_start");
        }
        if self.near.iter().any(|&j| j as usize >= n) || self.near_hops.contains(&0) {
            return Err("near");
        }
        if !self.near_scale.iter().all(|s| s.is_finite() && *s >= 0.0) {
            return Err("near_scale");
        }
        Ok(())
    }
}

/// A bounded breadth-first search's scratch: hops by node, reset after each search for
/// the nodes it reached only.
pub(crate) struct Reach {
    seen: Vec<u16>,
    queue: Vec<u32>,
    found: Vec<(u32, u16)>,
}

impl Reach {
    pub(crate) fn new(n: usize) -> Self {
        Self {
            seen: vec![UNREACHED; n],
            queue: Vec::new(),
            found: Vec::new(),
        }
    }

    /// The nodes 2 to `hops` hops from `from`, in breadth-first order, with their hops.
    fn within(&mut self, graph: &Graph, from: usize, hops: u16) -> &[(u32, u16)] {
        self.seen.resize(graph.len(), UNREACHED);
        self.found.clear();
        let reached = graph.search([from], &mut self.seen, &mut self.queue, |_, h| h < hops);
        let seen = &mut self.seen;
        self.found.extend(
            reached
                .iter()
                .map(|&v| (v, seen[v as usize]))
                .filter(|&(_, h)| h >= 2),
        );
        for &v in reached {
            seen[v as usize] = UNREACHED;
        }
        &self.found
    }
}

/// The next pivot of a max-min choice: a node drawn with a chance in proportion to its
/// hops to the nearest pivot chosen so far (s_gd2's `maxmin_random_sp`), so pivots
/// spread over the component without all going to its outskirts.
fn next_pivot(nearest: &[u16], rng: &mut crate::stress::sgd::Rng) -> usize {
    let reach = |h: u16| if h == UNREACHED { 0 } else { u64::from(h) };
    let total: u64 = nearest.iter().map(|&h| reach(h)).sum();
    if total == 0 {
        return 0;
    }
    let mut pick = rng.next() % total;
    for (m, &h) in nearest.iter().enumerate() {
        let h = reach(h);
        if pick < h {
            return m;
        }
        pick -= h;
    }
    nearest.len() - 1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_component_is_the_full_stress() {
        // A path of 5: every node a pivot, each pair weighted 1 / d².
        let g = Graph::new(5, (0..4).map(|i| (i, i + 1)));
        let m = SparseStress::new(&g, 200, 2);
        assert_eq!(m.full, [true]);
        let (pivots, hops) = m.pivot_terms(0);
        assert_eq!(pivots, [0, 1, 2, 3, 4]);
        assert_eq!(hops, [0, 1, 2, 3, 4]);
        for k in 0..5 {
            assert!((m.pivot_weight(k, 2) - 0.25).abs() < 1e-7, "pivot {k}");
        }
        assert_eq!(m.pivot_cutoff(0), 1);
        assert!(m.near.is_empty(), "no exact terms in a full component");
    }

    #[test]
    fn a_large_component_gets_spread_pivots_and_near_terms() {
        // A path of 101 nodes with 2 pivots: the first node, then one drawn with a
        // chance in proportion to its distance from it.
        let g = Graph::new(101, (0..100).map(|i| (i, i + 1)));
        let m = SparseStress::new(&g, 2, 2);
        assert_eq!(m.full, [false]);
        let (pivots, hops) = m.pivot_terms(10);
        assert_eq!(pivots[0], 0);
        let q = pivots[1] as usize;
        assert!(q > 1, "the second pivot is away from the first: {q}");
        assert_eq!(hops, [10, q.abs_diff(10) as u16]);
        // Pivot 0's region is the nodes nearer to it than to the second (ties to the
        // first): at 8 hops it stands for the 5 within 4 hops.
        assert!((m.pivot_weight(0, 8) - 5.0 / 64.0).abs() < 1e-7);
        assert!(m.pivot_weight(0, 2) == 0.0, "within the exact terms");
        assert!(
            m.pivot_weight(0, 1_000) == 0.0,
            "beyond the longest distance"
        );
        assert_eq!(m.near_terms_of(10), (&[8, 12][..], &[2, 2][..]));
        assert_eq!(m.pivot_cutoff(10), 2);
    }

    #[test]
    fn a_leaf_added_in_place_has_the_distances_a_search_would_give() {
        // A path of 101 nodes, 3 pivots; then node 101 joined to node 40.
        let g = Graph::new(101, (0..100).map(|i| (i, i + 1)));
        let mut m = SparseStress::new(&g, 3, 2);
        let grown = Graph::new(102, (0..100).map(|i| (i, i + 1)).chain([(40, 101)]));
        m.add_leaf(&grown, 101, 40, &mut Reach::new(102));
        let (pivots, hops) = m.pivot_terms(101);
        let mut searched = vec![0; 102];
        let mut queue = Vec::new();
        for (&p, &h) in pivots.iter().zip(hops) {
            grown.bfs(p as usize, &mut searched, &mut queue);
            assert_eq!(h, searched[101], "hops to pivot {p}");
        }
        // Its exact terms: 39 and 41, two hops away.
        assert_eq!(m.near_terms_of(101), (&[39, 41][..], &[2, 2][..]));
        assert_eq!(m.sizes, [102]);
    }
}
