//! A flow in layers ([`Flow::in_layers`](crate::config::Flow::in_layers)): the Sugiyama
//! picture held live. Each node of a flow's edges gets a layer (a rank along the flow),
//! each layer a row on one line, and each layer an order across the flow, held as
//! separations between neighbours. Ranks: the longest path from the sources or to the
//! sinks, whichever makes the edges shorter in all, then each node moved toward the side
//! with more of its edges. Order: a depth-first order (on a tree, free of crossings),
//! then barycentre sweeps, keeping the order with the fewest crossings between
//! neighbouring layers. Computed when the flow's edges are compiled, not every call.
//! (Sugiyama's virtual nodes on the edges that pass layers, tried for the order, gave
//! more crossings drawn, not fewer: the edges are drawn straight, not through them.)

use super::{Row, Separation};
use crate::input::constraints::Axis;

/// Rounds of barycentre sweeps (one down, one up each).
const SWEEPS: usize = 8;

/// A flow's layers: a row per layer of two or more nodes, and the separations that keep
/// each layer's order across the flow.
pub(super) struct Layers {
    pub(super) rows: Vec<Row>,
    pub(super) order: Vec<Separation>,
}

/// The layers of the `bodies` world slots under the edges `ends` (`(first, second)` by
/// slot, `second` beyond `first` along `axis`; acyclic), each layer at least `gap`
/// beyond the one before. A body without an edge has a layer too (an end one), so that
/// every body is in a layer. Neighbours in a layer keep `extent(a) + extent(b) + spacing`
/// apart across the flow (`extent`: a body's half size across it).
pub(super) fn layers(
    bodies: usize,
    ends: &[(u32, u32)],
    (axis, gap): (Axis, f32),
    spacing: f32,
    extent: impl Fn(u32) -> f32,
) -> Layers {
    let edges: Vec<(usize, usize)> = ends
        .iter()
        .map(|&(a, b)| (a as usize, b as usize))
        .filter(|&(a, b)| a != b && a < bodies && b < bodies)
        .collect();
    let graph = Graph::new(bodies, &edges);
    let rank = graph.ranks();
    let depth = rank.iter().copied().max().map_or(0, |r| r + 1);
    let mut layers = vec![Vec::new(); depth];
    for v in graph.depth_first() {
        layers[rank[v]].push(v);
    }
    order_layers(&graph, &rank, &mut layers);
    let across = match axis {
        Axis::X => Axis::Y,
        Axis::Y => Axis::X,
    };
    let mut out = Layers {
        rows: Vec::new(),
        order: Vec::new(),
    };
    let slot = |v: &usize| *v as u32;
    // Each layer a gap beyond the one before, whether or not an edge joins them (the
    // rows keep the rest of each layer on its first node's line).
    let firsts: Vec<u32> = layers.iter().filter_map(|l| l.first()).map(slot).collect();
    out.order.extend(firsts.windows(2).map(|w| Separation {
        first: w[0],
        second: w[1],
        axis,
        gap,
    }));
    for layer in layers.iter().filter(|layer| layer.len() > 1) {
        out.rows.push(Row {
            axis,
            slots: layer.iter().map(slot).collect(),
        });
        out.order.extend(layer.windows(2).map(|w| {
            let (first, second) = (slot(&w[0]), slot(&w[1]));
            Separation {
                first,
                second,
                axis: across,
                gap: extent(first) + extent(second) + spacing,
            }
        }));
    }
    out
}

/// The edges between `n` nodes as lists of children and parents, in the edges' order.
struct Graph {
    children: Vec<Vec<usize>>,
    parents: Vec<Vec<usize>>,
}

impl Graph {
    fn new(n: usize, edges: &[(usize, usize)]) -> Self {
        let mut graph = Self {
            children: vec![Vec::new(); n],
            parents: vec![Vec::new(); n],
        };
        for &(a, b) in edges {
            graph.children[a].push(b);
            graph.parents[b].push(a);
        }
        graph
    }

    /// The nodes in a topological order (Kahn's, by index); nodes on a cycle, which an
    /// acyclic flow has none of, after the rest.
    fn topological(&self) -> Vec<usize> {
        let n = self.children.len();
        let mut indegree: Vec<usize> = self.parents.iter().map(Vec::len).collect();
        let mut order: Vec<usize> = (0..n).filter(|&v| indegree[v] == 0).collect();
        let mut head = 0;
        while let Some(&v) = order.get(head) {
            head += 1;
            for &c in &self.children[v] {
                indegree[c] -= 1;
                if indegree[c] == 0 {
                    order.push(c);
                }
            }
        }
        let mut seen = vec![false; n];
        order.iter().for_each(|&v| seen[v] = true);
        order.extend((0..n).filter(|&v| !seen[v]));
        order
    }

    /// Each node's layer: every edge goes at least one layer on.
    fn ranks(&self) -> Vec<usize> {
        let n = self.children.len();
        let order = self.topological();
        // As soon as possible (longest path from the sources) and as late as possible
        // (longest path to the sinks, from the bottom): the one with shorter edges.
        let mut early = vec![0_usize; n];
        for &v in &order {
            for &c in &self.children[v] {
                early[c] = early[c].max(early[v] + 1);
            }
        }
        let top = early.iter().copied().max().unwrap_or(0);
        let mut late = vec![top; n];
        for &v in order.iter().rev() {
            if let Some(m) = self.children[v].iter().map(|&c| late[c]).min() {
                late[v] = m.saturating_sub(1).min(late[v]);
            }
        }
        let mut rank = if self.span(&late) < self.span(&early) {
            late
        } else {
            early
        };
        // Each node toward the side with more edges, as far as its neighbours allow.
        for _ in 0..4 {
            for &v in &order {
                let low = self.parents[v].iter().map(|&p| rank[p] + 1).max();
                let high = self.children[v]
                    .iter()
                    .map(|&c| rank[c].saturating_sub(1))
                    .min();
                let (up, down) = (self.parents[v].len(), self.children[v].len());
                rank[v] = match (low, high) {
                    (Some(low), _) if up > down => low,
                    (_, Some(high)) if down > up => high,
                    (None, Some(high)) => high,
                    _ => rank[v],
                };
            }
        }
        let least = rank.iter().copied().min().unwrap_or(0);
        rank.iter_mut().for_each(|r| *r -= least);
        rank
    }

    /// The edges' lengths in layers, all told.
    fn span(&self, rank: &[usize]) -> usize {
        (0..rank.len())
            .flat_map(|v| self.children[v].iter().map(move |&c| (v, c)))
            .map(|(v, c)| rank[c].abs_diff(rank[v]))
            .sum()
    }

    /// The nodes in depth-first preorder from the sources (by index), children in the
    /// edges' order.
    fn depth_first(&self) -> Vec<usize> {
        let n = self.children.len();
        let mut seen = vec![false; n];
        let mut order = Vec::with_capacity(n);
        let roots = (0..n).filter(|&v| self.parents[v].is_empty());
        for root in roots.chain(0..n) {
            let mut stack = vec![root];
            while let Some(v) = stack.pop() {
                if std::mem::replace(&mut seen[v], true) {
                    continue;
                }
                order.push(v);
                stack.extend(self.children[v].iter().rev().filter(|&&c| !seen[c]));
            }
        }
        order
    }
}

/// Orders each layer by barycentre sweeps from the given order, keeping the order with
/// the fewest crossings between neighbouring layers (the first on a tie).
fn order_layers(graph: &Graph, rank: &[usize], layers: &mut [Vec<usize>]) {
    let mut place = vec![0.0_f64; rank.len()];
    for layer in layers.iter() {
        for (k, &v) in layer.iter().enumerate() {
            place[v] = (k as f64 + 0.5) / layer.len() as f64;
        }
    }
    let mut best = (crossings(graph, rank, layers, &place), layers.to_vec());
    for round in 0..2 * SWEEPS {
        let down = round % 2 == 0;
        let sequence: Vec<usize> = if down {
            (1..layers.len()).collect()
        } else {
            (0..layers.len().saturating_sub(1)).rev().collect()
        };
        for k in sequence {
            let keys: Vec<f64> = layers[k]
                .iter()
                .map(|&v| {
                    let near = if down {
                        &graph.parents[v]
                    } else {
                        &graph.children[v]
                    };
                    if near.is_empty() {
                        place[v]
                    } else {
                        near.iter().map(|&u| place[u]).sum::<f64>() / near.len() as f64
                    }
                })
                .collect();
            let mut sorted: Vec<usize> = (0..layers[k].len()).collect();
            sorted.sort_by(|&i, &j| keys[i].total_cmp(&keys[j]));
            let layer: Vec<usize> = sorted.iter().map(|&i| layers[k][i]).collect();
            for (i, &v) in layer.iter().enumerate() {
                place[v] = (i as f64 + 0.5) / layer.len() as f64;
            }
            layers[k] = layer;
        }
        let count = crossings(graph, rank, layers, &place);
        if count < best.0 {
            best = (count, layers.to_vec());
        }
    }
    layers.clone_from_slice(&best.1);
}

/// Crossings between the edges that join neighbouring layers (inversions, counted by
/// merging).
fn crossings(graph: &Graph, rank: &[usize], layers: &[Vec<usize>], place: &[f64]) -> u64 {
    let mut total = 0;
    for layer in layers {
        let mut pairs: Vec<(f64, f64)> = layer
            .iter()
            .flat_map(|&v| {
                graph.children[v]
                    .iter()
                    .filter(move |&&c| rank[c] == rank[v] + 1)
                    .map(move |&c| (place[v], place[c]))
            })
            .collect();
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let mut below: Vec<f64> = pairs.iter().map(|p| p.1).collect();
        total += inversions(&mut below);
    }
    total
}

/// The pairs out of order in `values` (which ends sorted), by merge sort.
fn inversions(values: &mut [f64]) -> u64 {
    if values.len() < 2 {
        return 0;
    }
    let middle = values.len() / 2;
    let mut count = inversions(&mut values[..middle]) + inversions(&mut values[middle..]);
    let mut merged = Vec::with_capacity(values.len());
    let (mut i, mut j) = (0, middle);
    while i < middle && j < values.len() {
        if values[j] < values[i] {
            count += (middle - i) as u64;
            merged.push(values[j]);
            j += 1;
        } else {
            merged.push(values[i]);
            i += 1;
        }
    }
    merged.extend_from_slice(&values[i..middle]);
    merged.extend_from_slice(&values[j..]);
    values.copy_from_slice(&merged);
    count
}

#[cfg(test)]
mod tests {
    use super::{inversions, layers, Separation};
    use crate::input::constraints::Axis;

    #[test]
    fn inversions_are_counted() {
        let mut values = [3.0, 1.0, 2.0, 0.0];
        assert_eq!(inversions(&mut values), 5, "3>1, 3>2, 3>0, 1>0, 2>0");
        assert!(values.windows(2).all(|w| w[0] < w[1]), "sorted: {values:?}");
    }

    #[test]
    fn a_tree_in_layers_has_its_depths_and_no_crossing_order() {
        // 0 -> {1, 2}, 1 -> {3, 4}, 2 -> {5, 6}, listed so the slots interleave.
        let ends = [(0, 2), (0, 1), (1, 3), (2, 5), (1, 4), (2, 6)];
        let out = layers(7, &ends, (Axis::Y, 60.0), 10.0, |_| 5.0);
        let rows: Vec<Vec<u32>> = out.rows.iter().map(|r| r.slots.clone()).collect();
        assert_eq!(rows, vec![vec![2, 1], vec![5, 6, 3, 4]], "layers by depth");
        let (across, along): (Vec<&Separation>, Vec<_>) =
            out.order.iter().partition(|c| c.axis == Axis::X);
        // 5 + 5 + 10, exact in f32.
        assert!(
            across.iter().all(|c| c.gap.to_bits() == 20.0_f32.to_bits()),
            "{across:?}"
        );
        assert_eq!(across.len(), 4, "{across:?}");
        // Layer to layer: 0 above 2 above 5.
        let along: Vec<_> = along.iter().map(|c| (c.first, c.second, c.gap)).collect();
        assert_eq!(along, vec![(0, 2, 60.0), (2, 5, 60.0)]);
    }

    #[test]
    fn an_in_tree_is_ranked_from_its_sink() {
        // Citations: 3 -> 1 -> 0 and 2 -> 0; ranked from the sources, 2 would sit a layer
        // above its target's other citer and its edge would span two layers.
        let ends = [(1, 0), (2, 0), (3, 1)];
        let out = layers(4, &ends, (Axis::Y, 1.0), 0.0, |_| 1.0);
        let mut rows: Vec<Vec<u32>> = out.rows.iter().map(|r| r.slots.clone()).collect();
        rows.iter_mut().for_each(|r| r.sort_unstable());
        assert_eq!(rows, vec![vec![1, 2]], "2 beside 1, one layer above 0");
    }
}
