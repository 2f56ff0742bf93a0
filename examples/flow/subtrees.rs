//! `--subtrees`: a tree's subtrees as nested clusters, so that sibling subtrees, whose
//! boxes may not overlap, sit side by side and their edges do not cross. Each node's
//! parent is the source of the first edge into it (in the scene's edge order); each node
//! with children gets a cluster of itself and its childless children, nested in its
//! parent's cluster. In a DAG a node with several parents goes with the first, and the
//! edges from the others may cross; nodes reached from no root (a directed cycle) get
//! none.

use std::collections::VecDeque;

use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::CanvasSceneInput;

/// Clusters of `scene`'s subtrees, `padding` units around each.
pub fn clusters(scene: &CanvasSceneInput<u32>, padding: f32) -> Vec<Cluster<u32>> {
    let n = scene.nodes.len();
    let mut parent = vec![usize::MAX; n];
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (s, t) in super::common::edge_ends(scene) {
        if s != t && parent[t] == usize::MAX {
            parent[t] = s;
            children[s].push(t);
        }
    }
    // From the roots down: a parent's cluster is listed before its children's.
    let mut cluster_of = vec![usize::MAX; n];
    let mut clusters = Vec::new();
    let mut queue: VecDeque<usize> = (0..n).filter(|&i| parent[i] == usize::MAX).collect();
    while let Some(v) = queue.pop_front() {
        if children[v].is_empty() {
            continue;
        }
        let mut members = vec![scene.nodes[v].id];
        members.extend(
            children[v]
                .iter()
                .filter(|&&c| children[c].is_empty())
                .map(|&c| scene.nodes[c].id),
        );
        let mut cluster = Cluster::new(members).with_padding(padding);
        if let Some(&outer) = cluster_of.get(parent[v]) {
            cluster = cluster.inside(outer);
        }
        cluster_of[v] = clusters.len();
        clusters.push(cluster);
        queue.extend(children[v].iter().copied());
    }
    clusters
}
