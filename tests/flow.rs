//! Directed flow and hard constraints: edges point along the flow at rest, separations
//! and rows hold, a held node does not give way, bad constraints are refused or left out.

mod common;

use common::{load_scene, Host};
use graph_canvas_layout::config::Flow;
use graph_canvas_layout::scene::{Axis, Constraint};
use graph_canvas_layout::{
    euclid, euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput, LayoutError,
    LayoutExtras, RapierLayoutConfig,
};

/// A binary tree of `depth` levels with edges parent -> child, placed on a grid so that
/// every edge first points up (against a downward flow).
fn upside_down_tree(depth: u32) -> CanvasSceneInput<u32> {
    let n = (1_u32 << depth) - 1;
    let nodes = (0..n)
        .map(|i| {
            let level = 32 - (i + 1).leading_zeros();
            CanvasNode::new(i, Point2D::new(i as f32 * 7.0, -(level as f32) * 40.0))
        })
        .collect();
    let edges = (1..n).map(|i| CanvasEdge::new((i - 1) / 2, i)).collect();
    CanvasSceneInput::new(nodes, edges)
}

/// The shortest `target.y - source.y` over the scene's edges.
fn least_drop(scene: &CanvasSceneInput<u32>) -> f32 {
    let y = |id: u32| scene.nodes.iter().find(|n| n.id == id).unwrap().position.y;
    scene
        .edges
        .iter()
        .map(|e| y(e.target) - y(e.source))
        .fold(f32::INFINITY, f32::min)
}

#[test]
fn a_tree_drawn_upside_down_comes_to_rest_with_every_edge_pointing_down() {
    let gap = 60.0;
    for (name, config) in [
        ("stress", RapierLayoutConfig::stress()),
        ("force_directed", RapierLayoutConfig::force_directed()),
    ] {
        let mut host = Host::new(upside_down_tree(6), config.with_flow(Flow::down(gap)));
        let frames = host.settle(900);
        let drop = least_drop(&host.scene);
        assert!(
            drop >= gap - 1.0,
            "{name}: an edge drops only {drop} (gap {gap}) after {frames} frames"
        );
    }
}

#[test]
fn a_cycle_leaves_one_edge_free_and_the_others_point_down() {
    // 0 -> 1 -> 2 -> 0: one edge must be exempt.
    let nodes = (0..3)
        .map(|i| CanvasNode::new(i, Point2D::new(i as f32 * 50.0, 0.0)))
        .collect();
    let edges = vec![
        CanvasEdge::new(0, 1),
        CanvasEdge::new(1, 2),
        CanvasEdge::new(2, 0),
    ];
    let scene = CanvasSceneInput::new(nodes, edges);
    let mut host = Host::new(
        scene,
        RapierLayoutConfig::stress().with_flow(Flow::down(40.0)),
    );
    host.settle(900);
    let y = |id: u32| host.scene.nodes[id as usize].position.y;
    let drops = [y(1) - y(0), y(2) - y(1), y(0) - y(2)];
    let down = drops.iter().filter(|&&d| d >= 39.0).count();
    assert_eq!(down, 2, "two of three edges point down: drops {drops:?}");
    assert!(drops.iter().all(|d| d.is_finite()), "{drops:?}");
}

#[test]
fn separations_and_rows_hold_at_rest_and_a_pinned_node_does_not_give_way() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::stress());
    let pinned_before = host.scene.nodes[0].position;
    host.extras = LayoutExtras {
        pinned: [0_u32].into_iter().collect(),
        constraints: vec![
            Constraint::separation(Axis::X, 0, 33, 200.0),
            Constraint::align(Axis::Y, vec![0, 5, 6, 10]),
        ],
        ..Default::default()
    };
    host.settle(900);
    let p = |id: u32| {
        host.scene
            .nodes
            .iter()
            .find(|n| n.id == id)
            .unwrap()
            .position
    };
    assert_eq!(p(0), pinned_before, "the pinned node stays where it was");
    let apart = p(33).x - p(0).x;
    assert!(apart >= 199.0, "33 is {apart} right of 0 (at least 200)");
    for id in [5, 6, 10] {
        let off = (p(id).y - p(0).y).abs();
        assert!(off <= 1.0, "node {id} is {off} off the pinned node's row");
    }
}

#[test]
fn a_constraint_naming_a_missing_node_or_a_bad_gap_is_refused_by_try_step_and_left_out_by_step() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::stress());
    host.extras.constraints = vec![
        Constraint::separation(Axis::Y, 0, 999, 10.0),
        Constraint::separation(Axis::Y, 0, 1, f32::NAN),
    ];
    let before: Vec<_> = host.scene.nodes.iter().map(|n| n.position).collect();
    let error = host.try_frame(1.0 / 60.0).unwrap_err();
    assert_eq!(
        error,
        LayoutError::UnknownConstraintNode {
            constraint: 0,
            node: 999
        }
    );
    let after: Vec<_> = host.scene.nodes.iter().map(|n| n.position).collect();
    assert_eq!(before, after, "a refused call changes nothing");
    host.frame(1.0 / 60.0);
    let skipped = host.layout.skipped().to_vec();
    assert_eq!(skipped.len(), 2, "both left out and listed: {skipped:?}");
    assert!(
        matches!(skipped[1], LayoutError::InvalidConstraintGap { constraint: 1, gap } if gap.is_nan()),
        "{skipped:?}"
    );
}

#[test]
fn dragging_the_head_of_a_row_carries_the_row_along() {
    // A path of five, its nodes on one vertical line (Axis::X), the first dragged right.
    let nodes = (0..5)
        .map(|i| CanvasNode::new(i, Point2D::new(0.0, i as f32 * 60.0)))
        .collect();
    let edges = (0..4).map(|i| CanvasEdge::new(i, i + 1)).collect();
    let mut host = Host::new(
        CanvasSceneInput::new(nodes, edges),
        RapierLayoutConfig::stress(),
    );
    host.extras.constraints = vec![Constraint::align(Axis::X, vec![0, 1, 2, 3, 4])];
    host.settle(900);
    host.extras.dragging = [0_u32].into_iter().collect();
    for frame in 1..=40 {
        let head = host.pos(&0) + euclid::default::Vector2D::new(5.0, 0.0);
        host.set_pos(&0, head);
        host.frame(1.0 / 60.0);
        if frame > 10 {
            for id in 1..5 {
                let off = (host.pos(&id).x - host.pos(&0).x).abs();
                assert!(
                    off <= 1.0,
                    "frame {frame}: node {id} is {off} off the dragged head's line"
                );
            }
        }
    }
    assert!(
        host.pos(&0).x >= 199.0,
        "the head moved: {:?}",
        host.pos(&0)
    );
}
