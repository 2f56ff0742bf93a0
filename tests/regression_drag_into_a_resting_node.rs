//! Regression: rapier does not wake a sleeping body that a kinematic or fixed body is
//! moved into. Once a layout had come to rest (its bodies asleep), a node dragged onto
//! another, or a pinned node the host moved onto one, passed through it: the resting
//! node did not move at all. The host move now wakes the sleeping bodies in its path.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

/// Two unconnected nodes 500 apart, at rest; then node 2 is moved by the host over 20
/// frames to 10 units right of node 0, dragged or pinned. Returns how far node 0 moved
/// and whether it was asleep in rapier before the move.
fn push_after_rest(config: RapierLayoutConfig, pinned: bool) -> (f32, bool) {
    let scene = CanvasSceneInput {
        nodes: vec![node(0, 0.0, 0.0), node(2, 500.0, 0.0)],
        ..Default::default()
    };
    let mut host = Host::new(scene, config);
    host.settle(900);
    let asleep = host.layout.world().unwrap().is_sleeping(&0) == Some(true);
    let before = host.pos(&0);
    if pinned {
        host.extras.pinned.insert(2);
    } else {
        host.extras.dragging.insert(2);
    }
    let start = host.pos(&2);
    let target = Point2D::new(before.x + 10.0, before.y);
    for k in 1..=20 {
        host.set_pos(&2, start.lerp(target, k as f32 / 20.0));
        host.frame(FRAME);
    }
    host.frames(5);
    (dist(host.pos(&0), before), asleep)
}

#[test]
fn a_dragged_node_pushes_a_node_at_rest() {
    for (name, config) in [
        ("default", RapierLayoutConfig::default()),
        ("force_directed", RapierLayoutConfig::force_directed()),
    ] {
        let (pushed, _) = push_after_rest(config, false);
        // Overlapping by 22 units with a disk held in place: pushed about that far.
        assert!(pushed > 5.0, "{name}: the resting node moved {pushed}");
    }
}

#[test]
fn a_pinned_node_moved_by_the_host_pushes_a_node_at_rest() {
    let (pushed, asleep) = push_after_rest(RapierLayoutConfig::default(), true);
    // Without a cooling schedule rest is rapier's sleep: the case rapier gets wrong.
    assert!(asleep, "node 0 was not asleep at rest");
    assert!(pushed > 5.0, "the resting node moved {pushed}");
}
