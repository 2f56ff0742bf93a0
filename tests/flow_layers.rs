//! A flow in layers (`Flow::in_layers`): each node on its layer's line, each layer in an
//! order across the flow that crosses no edge of a tree, every node apart, live under a
//! drag.

mod common;

use common::{edge, node, Host};
use graph_canvas_layout::config::{Flow, StressStart};
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::quality::edge_crossings;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

const GAP: f32 = 60.0;

/// A binary tree of `depth` levels, edges parent -> child, placed on a scrambled grid so
/// that every edge first points anywhere.
fn scrambled_tree(depth: u32) -> CanvasSceneInput<u32> {
    let n = (1_u32 << depth) - 1;
    let nodes = (0..n)
        .map(|i| {
            let k = (i * 37) % n;
            node(i, (k % 8) as f32 * 40.0, (k / 8) as f32 * 40.0)
        })
        .collect();
    let edges = (1..n).map(|i| edge((i - 1) / 2, i)).collect();
    CanvasSceneInput::new(nodes, edges)
}

fn depth_of(i: u32) -> u32 {
    31 - (i + 1).leading_zeros()
}

/// The worst overlap between two disks (radius sum less distance; negative: apart).
fn worst_overlap(scene: &CanvasSceneInput<u32>, radius: f32) -> f32 {
    let mut worst = f32::NEG_INFINITY;
    for (k, a) in scene.nodes.iter().enumerate() {
        for b in &scene.nodes[k + 1..] {
            worst = worst.max(2.0 * radius - (a.position - b.position).length());
        }
    }
    worst
}

fn layered() -> RapierLayoutConfig {
    RapierLayoutConfig::stress().with_flow(Flow::down(GAP).in_layers())
}

#[test]
fn a_tree_in_layers_rests_with_each_depth_on_a_line_and_no_edge_crossed() {
    let mut host = Host::new(scrambled_tree(6), layered());
    let frames = host.settle(900);
    let scene = &host.scene;
    let crossings = edge_crossings(scene);
    assert_eq!(crossings, 0, "{crossings} crossings after {frames} frames");
    let y = |i: u32| host.pos(&i).y;
    for i in 1..63 {
        let mate = (1 << depth_of(i)) - 1;
        let off = (y(i) - y(mate)).abs();
        assert!(
            off <= 1.0,
            "node {i} is {off} off its layer's line (node {mate})"
        );
        let drop = y(i) - y((i - 1) / 2);
        assert!(drop >= GAP - 1.0, "edge into {i} drops {drop}");
    }
    let radius = host.layout.config.default_radius;
    let overlap = worst_overlap(scene, radius);
    assert!(overlap <= 0.5, "two disks overlap by {overlap}");
    assert!(host.layout.violated_flow_edges().is_empty());
}

#[test]
fn a_dragged_node_takes_its_layer_along_and_its_neighbours_make_way() {
    let mut host = Host::new(scrambled_tree(5), layered());
    host.settle(900);
    // Node 9 (depth 3) dragged 120 units down and across its layer, 4 units a frame.
    let start = host.pos(&9);
    host.extras.dragging = [9_u32].into_iter().collect();
    for frame in 1..=30 {
        let to = start + Vector2D::new(4.0, 4.0) * frame as f32;
        host.set_pos(&9, to);
        host.frame(1.0 / 60.0);
        if frame <= 10 {
            continue;
        }
        let line = host.pos(&9).y;
        for mate in 7..15 {
            let off = (host.pos(&mate).y - line).abs();
            assert!(
                off <= 1.0,
                "frame {frame}: node {mate} is {off} off the dragged layer"
            );
        }
        for i in 1..31 {
            let drop = host.pos(&i).y - host.pos(&((i - 1) / 2)).y;
            assert!(
                drop >= GAP - 1.0,
                "frame {frame}: edge into {i} drops {drop}"
            );
        }
        let overlap = worst_overlap(&host.scene, 16.0);
        assert!(
            overlap <= 0.5,
            "frame {frame}: two disks overlap by {overlap}"
        );
    }
    let moved = host.pos(&9) - start;
    assert!(
        (moved - Vector2D::new(120.0, 120.0)).length() <= 1.0,
        "the dragged node is where the host put it: moved {moved:?}"
    );
}

#[test]
fn nodes_without_an_edge_get_a_layer_and_no_two_nodes_overlap() {
    // A chain of 6 and 10 loose nodes, all started on one point: the layers hold them
    // apart without the disk contacts, the loose ones included.
    let mut nodes: Vec<_> = (0..16).map(|i| node(i, 0.0, 0.0)).collect();
    nodes[3].position = Point2D::new(1.0, 0.5);
    let edges = (0..5).map(|i| edge(i, i + 1)).collect();
    let mut host = Host::new(CanvasSceneInput::new(nodes, edges), layered());
    let frames = host.settle(900);
    let overlap = worst_overlap(&host.scene, 16.0);
    assert!(
        overlap <= 0.5,
        "two disks overlap by {overlap} after {frames} frames"
    );
    for i in 0..5 {
        let drop = host.pos(&(i + 1)).y - host.pos(&i).y;
        assert!(drop >= GAP - 1.0, "edge {i} -> {} drops {drop}", i + 1);
    }
    for p in host.scene.nodes.iter().map(|n| n.position) {
        assert!(p.x.is_finite() && p.y.is_finite(), "{p:?}");
    }
}

#[test]
fn turning_the_layers_off_lifts_the_rows_where_the_layout_does_not_start_anew() {
    // A layout that starts from the host's positions settles on from the layers when
    // they are turned off: three nodes without an edge share layer 0, and with the flow
    // turned off, dragging one down leaves the others where they are.
    let mut config = layered();
    if let Some(stress) = config.stress.as_mut() {
        stress.start = StressStart::HostPositions;
    }
    let nodes = (0..3).map(|i| node(i, i as f32 * 100.0, 0.0)).collect();
    let mut host = Host::new(CanvasSceneInput::new(nodes, Vec::new()), config);
    host.settle(900);
    host.layout.config = RapierLayoutConfig {
        flow: None,
        ..host.layout.config.clone()
    };
    host.frame(1.0 / 60.0);
    let (start, other) = (host.pos(&0), host.pos(&2));
    assert!(
        (start.y - other.y).abs() < 1.0 && (start.x - other.x).abs() > 100.0,
        "nodes 0 and 2 at {start:?} and {other:?}: not side by side in one layer"
    );
    host.extras.dragging = [0_u32].into_iter().collect();
    for frame in 1..=20 {
        host.set_pos(&0, start + Vector2D::new(0.0, 10.0 * frame as f32));
        host.frame(1.0 / 60.0);
    }
    let followed = host.pos(&2).y - other.y;
    assert!(
        followed.abs() < 50.0,
        "node 2 followed the dragged node {followed} units down: a layer outlived its flow"
    );
}

#[test]
fn turning_the_layers_off_lets_the_nodes_go() {
    // Three nodes without an edge share layer 0 under the flow. With the flow turned
    // off (which starts the layout anew), dragging one down leaves the others out of
    // its path where they are; a row outliving its flow would carry them all along.
    let nodes = (0..3).map(|i| node(i, i as f32 * 100.0, 0.0)).collect();
    let mut host = Host::new(CanvasSceneInput::new(nodes, Vec::new()), layered());
    host.settle(900);
    host.layout.config = RapierLayoutConfig {
        flow: None,
        ..host.layout.config.clone()
    };
    host.frame(1.0 / 60.0);
    let start = host.pos(&0);
    // Out of the path: farther across it than two radii.
    let aside: Vec<(u32, Point2D<f32>)> = (1..3)
        .map(|i| (i, host.pos(&i)))
        .filter(|(_, p)| (p.x - start.x).abs() > 33.0)
        .collect();
    assert!(!aside.is_empty(), "no node out of the dragged node's path");
    host.extras.dragging = [0_u32].into_iter().collect();
    for frame in 1..=20 {
        host.set_pos(&0, start + Vector2D::new(0.0, 10.0 * frame as f32));
        host.frame(1.0 / 60.0);
    }
    for (i, was) in aside {
        let followed = host.pos(&i).y - was.y;
        assert!(
            followed.abs() < 50.0,
            "node {i} followed the dragged node {followed} units down: a layer outlived its \
             flow"
        );
    }
}
