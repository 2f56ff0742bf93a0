//! The reports of what cannot hold pointed at the wrong entries after the host reordered
//! its list at rest. `violated_constraints()` gives indices into the host's list; a
//! reordered list (or a bad constraint inserted at its front) is no disturbance, so a
//! layout at rest stayed halted and kept the indices of the old order. The reports are
//! now checked again whenever the list moved under them, also at rest; and the
//! clusters' list likewise.

mod common;

use common::{edge, node, Host};
use graph_canvas_layout::scene::{Axis, Cluster, Constraint};
use graph_canvas_layout::{CanvasSceneInput, Layout, RapierLayoutConfig};

/// A path of 6 nodes along x.
fn path() -> CanvasSceneInput<u32> {
    CanvasSceneInput::new(
        (0..6).map(|i| node(i, 80.0 * i as f32, 0.0)).collect(),
        (0..5).map(|i| edge(i, i + 1)).collect(),
    )
}

#[test]
fn a_reordered_constraint_list_at_rest_is_reported_by_its_new_indices() {
    let mut host = Host::new(path(), RapierLayoutConfig::stress());
    let row = Constraint::align(Axis::Y, vec![2, 3]);
    // 0 at least 50 left of 1 and 1 at least 50 left of 0: one of them cannot hold.
    let pair = [
        Constraint::separation(Axis::X, 0, 1, 50.0),
        Constraint::separation(Axis::X, 1, 0, 50.0),
    ];
    host.extras.constraints = vec![pair[0].clone(), pair[1].clone(), row.clone()];
    let frames = host.settle(900);
    assert!(
        host.layout.is_converged(&host.state),
        "not at rest after {frames} frames"
    );
    let before = host.layout.violated_constraints().to_vec();
    assert!(
        !before.is_empty() && before.iter().all(|&c| c < 2),
        "the conflicting pair (0, 1) reported: {before:?}"
    );
    // The row first, and a constraint on a node the scene lacks before everything.
    host.extras.constraints = vec![
        Constraint::separation(Axis::X, 99, 0, 10.0),
        row,
        pair[0].clone(),
        pair[1].clone(),
    ];
    host.frame(common::FRAME);
    let after = host.layout.violated_constraints().to_vec();
    let moved: Vec<usize> = before.iter().map(|&c| c + 2).collect();
    assert_eq!(
        after, moved,
        "the same conflict, by its new indices (was {before:?})"
    );
}

#[test]
fn a_reordered_cluster_list_at_rest_is_reported_by_its_new_indices() {
    // Clusters 0 and 1 held overlapping by pins, and a third far off that holds.
    let mut host = common::clusters_held_overlapping();
    host.scene
        .nodes
        .extend([node(4, 600.0, 600.0), node(5, 700.0, 600.0)]);
    host.scene.edges.extend([edge(4, 5), edge(3, 4)]);
    host.extras.clusters.push(Cluster::new(vec![4, 5]));
    let (a, b, free) = match &host.extras.clusters[..] {
        [a, b, free] => (a.clone(), b.clone(), free.clone()),
        listed => panic!("three clusters, not {listed:?}"),
    };
    let frames = host.settle(900);
    assert_eq!(
        host.layout.violated_clusters(),
        &[0, 1],
        "the pinned overlap, at rest after {frames} frames"
    );
    host.extras.clusters = vec![free, a, b];
    host.frame(common::FRAME);
    assert_eq!(
        host.layout.violated_clusters(),
        &[1, 2],
        "the same overlap, by its new indices"
    );
}
