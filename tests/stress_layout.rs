//! The stress layout as a host meets it: the first frame already shows the graph's
//! shape, components sit side by side and stay apart, pins hold and the start turns to
//! meet them, the host's positions can be the start instead, and the length of a hop
//! seats a hub's leaves.

mod common;

use common::*;
use graph_canvas_layout::config::{StressModel, StressStart};
use graph_canvas_layout::euclid::default::{Box2D, Point2D};
use graph_canvas_layout::{quality, CanvasSceneInput, RapierLayoutConfig};

fn stress_with(model: StressModel) -> RapierLayoutConfig {
    RapierLayoutConfig {
        stress: Some(model),
        ..RapierLayoutConfig::stress()
    }
}

#[test]
fn the_first_frame_already_shows_the_graphs_shape() {
    // From d3's spiral, a grid is drawn flat in the first call: its stress then is
    // within 5 % of its stress at rest (0.0122, stress SGD's).
    let mut host = Host::new(load_scene("grid_30x30"), RapierLayoutConfig::stress());
    let spiral = quality::normalized_stress(&host.scene).unwrap();
    host.frame(FRAME);
    let first = quality::normalized_stress(&host.scene).unwrap();
    assert!(
        first < 0.0122 * 1.05,
        "first frame's stress {first} (the spiral's {spiral})"
    );
    // Every node one call from the file: also those it starts at one point.
    let mut scene = load_scene("karate");
    for n in &mut scene.nodes {
        n.position = Point2D::origin();
    }
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    host.frame(FRAME);
    let first = quality::normalized_stress(&host.scene).unwrap();
    assert!(first < 0.0678 * 1.10, "karate from one point: {first}");
}

/// The mean position of the nodes with ids in `ids`.
fn centroid(scene: &CanvasSceneInput<u32>, ids: std::ops::Range<u32>) -> Point2D<f32> {
    let chosen: Vec<Point2D<f32>> = scene
        .nodes
        .iter()
        .filter(|n| ids.contains(&n.id))
        .map(|n| n.position)
        .collect();
    let sum = chosen
        .iter()
        .fold(Point2D::origin(), |s, p| s + p.to_vector());
    (sum.to_vector() / chosen.len() as f32).to_point()
}

/// The bounding box of the nodes with ids in `ids`.
fn bounds(scene: &CanvasSceneInput<u32>, ids: std::ops::Range<u32>) -> Box2D<f32> {
    let points: Vec<Point2D<f32>> = scene
        .nodes
        .iter()
        .filter(|n| ids.contains(&n.id))
        .map(|n| n.position)
        .collect();
    Box2D::from_points(points)
}

#[test]
fn components_sit_side_by_side_and_stay_apart() {
    // Three copies of karate (ids 0.., 100.., 200..) and five lone nodes, all at the
    // origin.
    let karate = load_scene("karate");
    let mut scene = CanvasSceneInput::new(Vec::new(), Vec::new());
    for copy in 0..3_u32 {
        for n in &karate.nodes {
            scene.nodes.push(node(n.id + 100 * copy, 0.0, 0.0));
        }
        for e in &karate.edges {
            scene
                .edges
                .push(edge(e.source + 100 * copy, e.target + 100 * copy));
        }
    }
    for lone in 0..5 {
        scene.nodes.push(node(1_000 + lone, 0.0, 0.0));
    }
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    host.frame(FRAME);
    let packed: Vec<Point2D<f32>> = (0..3)
        .map(|c| centroid(&host.scene, c * 100..c * 100 + 34))
        .collect();

    let frames = host.settle(300);
    for (c, before) in packed.iter().enumerate() {
        let after = bounds(&host.scene, c as u32 * 100..c as u32 * 100 + 34);
        for other in c + 1..3 {
            let them = bounds(&host.scene, other as u32 * 100..other as u32 * 100 + 34);
            assert!(
                !after.intersects(&them),
                "components {c} and {other} overlap at rest: {after:?} {them:?}"
            );
        }
        // Nothing pulls one component toward another: each keeps its centre of mass
        // (a unit for the contacts' and pivot terms' rounding).
        let drift = (centroid(&host.scene, c as u32 * 100..c as u32 * 100 + 34) - *before).length();
        assert!(
            drift < 1.0,
            "component {c} drifted {drift} units from where it was packed ({frames} frames)"
        );
    }
    assert_eq!(quality::overlapping_pairs(&host.scene, 16.0, 0.5), 0);
    let stress = quality::normalized_stress(&host.scene).unwrap();
    assert!(
        stress < 0.0678 * 1.10,
        "each copy laid out as karate alone: {stress}"
    );
}

#[test]
fn pins_hold_and_the_start_turns_to_meet_them() {
    // Two opposite corners of a grid pinned where the host has them: the grid starts
    // flat between them, and they do not move.
    let mut host = Host::new(load_scene("grid_30x30"), RapierLayoutConfig::stress());
    let (a, b) = (0_u32, 899_u32);
    host.set_pos(&a, Point2D::new(-1_500.0, -1_500.0));
    host.set_pos(&b, Point2D::new(1_500.0, 1_500.0));
    host.extras.pinned.extend([a, b]);
    host.frame(FRAME);
    host.settle(300);
    assert_eq!(host.pos(&a), Point2D::new(-1_500.0, -1_500.0));
    assert_eq!(host.pos(&b), Point2D::new(1_500.0, 1_500.0));
    let stress = quality::normalized_stress(&host.scene).unwrap();
    assert!(
        stress < 0.0122 * 1.10,
        "the grid folded between its pins: stress {stress}"
    );
}

#[test]
fn the_hosts_positions_can_be_the_start() {
    let model = StressModel {
        start: StressStart::HostPositions,
        ..StressModel::default()
    };
    let scene = load_scene("les_miserables");
    let mut global = Host::new(scene.clone(), RapierLayoutConfig::stress());
    global.frame(FRAME);
    let mut host = Host::new(scene.clone(), stress_with(model));
    host.frame(FRAME);
    // The first call moves nodes by the physics only, not onto a start of its own.
    let (moved, jumped) = (
        farthest_moved(&host.scene, &positions(&scene)),
        farthest_moved(&global.scene, &positions(&scene)),
    );
    assert!(
        moved < jumped / 4.0,
        "the first call moved a node {moved} units (onto the global start: {jumped})"
    );
    host.settle(600);
    let stress = quality::normalized_stress(&host.scene).unwrap();
    assert!(stress < 0.12, "laid out from the host's spiral: {stress}");
}

#[test]
fn the_hop_is_long_enough_to_seat_a_hubs_leaves() {
    // 60 leaves on one hub: at 100 units a hop they could not sit round it.
    let mut scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0)], Vec::new());
    for leaf in 1..=60 {
        scene.nodes.push(node(leaf, 0.0, 0.0));
        scene.edges.push(edge(0, leaf));
    }
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    host.settle(300);
    assert_eq!(quality::overlapping_pairs(&host.scene, 16.0, 0.5), 0);
    let hop = match host.layout.world().unwrap().edge_joint(&0, &1).unwrap() {
        graph_canvas_layout::EdgeJoint::Spring { rest_length, .. } => rest_length,
        other => panic!("{other:?}"),
    };
    // In the start, the leaves' nearest neighbours are a tenth of a hop apart or more:
    // the hop grew until their disks (32 units) sit clear of each other.
    assert!(hop > 150.0, "a hop of {hop} units");
    let fixed = stress_with(StressModel {
        fit_length: false,
        ..StressModel::default()
    });
    let mut host = Host::new(host.scene.clone(), fixed);
    host.frame(FRAME);
    let edge = host.layout.world().unwrap().edge_joint(&0, &1).unwrap();
    assert!(
        matches!(edge, graph_canvas_layout::EdgeJoint::Spring { rest_length, .. } if rest_length.to_bits() == 100.0_f32.to_bits()),
        "a fixed hop is the configured length: {edge:?}"
    );
}
