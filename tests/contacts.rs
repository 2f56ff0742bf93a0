//! Disks collide: overlaps are pushed apart, and contacts are reported when asked for.

mod common;

use common::*;
use graph_canvas_layout::{CanvasSceneInput, EdgeJoint, RapierLayoutConfig, SceneEvent};

#[test]
fn overlapping_disks_are_pushed_apart() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 10.0, 0.0)], vec![]);
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frames(60);
    let g = dist(host.pos(&0), host.pos(&1));
    // Two radius-16 disks touch at 32; rapier allows ~0.5 % of length_unit of overlap.
    assert!(
        g > 31.0,
        "overlapping disks still overlap after 1 s: gap {g}"
    );
    assert!(g < 200.0, "the push exploded: gap {g}");
}

#[test]
fn no_collider_when_collisions_are_off() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 10.0, 0.0)], vec![]);
    let config = RapierLayoutConfig {
        collisions: false,
        ..Default::default()
    };
    let mut host = Host::new(scene, config);
    host.frames(30);
    assert_eq!(host.layout.world().unwrap().collider_count(), 0);
    assert_eq!(
        host.pos(&1),
        graph_canvas_layout::euclid::default::Point2D::new(10.0, 0.0),
        "nothing collides without colliders"
    );
}

#[test]
fn contact_begin_and_end_are_reported_by_node_id() {
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 20.0, 0.0)],
        vec![edge(0, 1)],
    );
    let config = RapierLayoutConfig {
        contact_events: true,
        edge_joint: EdgeJoint::Distance { length: 200.0 },
        ..Default::default()
    };
    let mut host = Host::new(scene, config);
    host.frame(FRAME);
    let first = host.layout.drain_events();
    assert!(
        first.iter().any(|e| matches!(e, SceneEvent::ContactBegin { a, b } if (*a, *b) == (0, 1) || (*a, *b) == (1, 0))),
        "no ContactBegin for the overlapping pair: {first:?}"
    );
    host.frames(60); // the rod separates them to 200
    let later = host.layout.drain_events();
    assert!(
        later
            .iter()
            .any(|e| matches!(e, SceneEvent::ContactEnd { .. })),
        "no ContactEnd once the rod pushed them apart (gap {}): {later:?}",
        dist(host.pos(&0), host.pos(&1))
    );
    assert!(host.layout.drain_events().is_empty(), "events are drained");
}

#[test]
fn no_events_are_recorded_unless_asked_for() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 20.0, 0.0)], vec![]);
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frames(10);
    assert!(host.layout.drain_events().is_empty());
}
