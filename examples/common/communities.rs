//! Communities of a graph that carries none, for the clusters example's pictures of real
//! graphs: the Louvain method (Blondel et al. 2008), greedy modularity moves node by
//! node, then the communities merged into nodes and moved again, until no move gains.
//! Deterministic: nodes are visited in the scene's order and ties keep the lower index.

use std::collections::HashMap;

use graph_canvas_layout::CanvasSceneInput;

/// A weighted undirected graph: each node's (neighbour, weight) list, self-loops once.
type Adjacency = Vec<Vec<(usize, f64)>>;

/// Each node's community (an index from 0, in the order communities are first met in
/// the scene's node order), by Louvain on `scene`'s edges (weight 1 each; repeats add).
pub fn louvain(scene: &CanvasSceneInput<u32>) -> Vec<usize> {
    let mut adjacency: Adjacency = vec![Vec::new(); scene.nodes.len()];
    for (a, b) in super::edge_ends(scene) {
        adjacency[a].push((b, 1.0));
        if a != b {
            adjacency[b].push((a, 1.0));
        }
    }
    // Each original node's community, refined level by level.
    let mut of: Vec<usize> = (0..scene.nodes.len()).collect();
    loop {
        let (moved, community) = one_level(&adjacency);
        let (renumbered, count) = renumber(&community);
        for c in &mut of {
            *c = renumbered[*c];
        }
        if !moved || count == adjacency.len() {
            return of;
        }
        adjacency = merged(&adjacency, &renumbered, count);
    }
}

/// Moves each node to the neighbouring community that gains the most modularity, pass
/// after pass, until a pass moves none. Returns whether any node moved, and each node's
/// community.
fn one_level(adjacency: &Adjacency) -> (bool, Vec<usize>) {
    let n = adjacency.len();
    let degree: Vec<f64> = adjacency
        .iter()
        .enumerate()
        .map(|(i, row)| {
            row.iter()
                .map(|&(j, w)| if i == j { 2.0 * w } else { w })
                .sum()
        })
        .collect();
    let two_m: f64 = degree.iter().sum();
    let mut community: Vec<usize> = (0..n).collect();
    let mut total = degree.clone();
    if two_m == 0.0 {
        return (false, community);
    }
    let mut links: Vec<f64> = vec![0.0; n];
    let mut touched: Vec<usize> = Vec::new();
    let mut any = false;
    loop {
        let mut moved = false;
        for i in 0..n {
            let own = community[i];
            for &(j, w) in &adjacency[i] {
                if j != i {
                    let c = community[j];
                    if links[c] == 0.0 {
                        touched.push(c);
                    }
                    links[c] += w;
                }
            }
            total[own] -= degree[i];
            // Gain of joining c, up to a constant: links to c - total(c) × degree / 2m.
            let gain = |c: usize, links: &[f64]| links[c] - total[c] * degree[i] / two_m;
            let mut best = (own, gain(own, &links));
            touched.sort_unstable();
            for &c in &touched {
                let g = gain(c, &links);
                if g > best.1 + 1e-12 {
                    best = (c, g);
                }
            }
            for &c in &touched {
                links[c] = 0.0;
            }
            touched.clear();
            total[best.0] += degree[i];
            if best.0 != own {
                community[i] = best.0;
                moved = true;
                any = true;
            }
        }
        if !moved {
            return (any, community);
        }
    }
}

/// Community labels renumbered 0.. in order of first appearance; and their count.
fn renumber(community: &[usize]) -> (Vec<usize>, usize) {
    let mut new = vec![usize::MAX; community.len()];
    let mut count = 0;
    let mut out = vec![0; community.len()];
    for (i, &c) in community.iter().enumerate() {
        if new[c] == usize::MAX {
            new[c] = count;
            count += 1;
        }
        out[i] = new[c];
    }
    (out, count)
}

/// The graph of communities: one node each, edge weights summed, inner edges as a
/// self-loop.
fn merged(adjacency: &Adjacency, community: &[usize], count: usize) -> Adjacency {
    let mut weights: Vec<HashMap<usize, f64>> = vec![HashMap::new(); count];
    for (i, row) in adjacency.iter().enumerate() {
        for &(j, w) in row {
            let (a, b) = (community[i], community[j]);
            // Each undirected edge is listed from both ends (a self-loop once).
            let w = if i == j { w } else { w / 2.0 };
            if a == b {
                *weights[a].entry(a).or_default() += w;
            } else {
                *weights[a].entry(b).or_default() += w;
                *weights[b].entry(a).or_default() += w;
            }
        }
    }
    weights
        .into_iter()
        .map(|row| {
            let mut row: Vec<(usize, f64)> = row.into_iter().collect();
            row.sort_unstable_by_key(|&(j, _)| j);
            row
        })
        .collect()
}
