//! Drag, throw, pins and host edits: what a user feels with the pointer.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::rapier2d::prelude::RigidBodyType;
use graph_canvas_layout::{BodyKindPolicy, CanvasSceneInput, RapierLayoutConfig};

fn pair() -> CanvasSceneInput<u32> {
    CanvasSceneInput::new(
        vec![node(0, 0.0, 0.0), node(1, 100.0, 0.0)],
        vec![edge(0, 1)],
    )
}

#[test]
fn drag_release_throws_at_the_pointer_speed() {
    let scene = CanvasSceneInput::new(vec![node(7_u32, 0.0, 0.0)], vec![]);
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frame(FRAME);
    host.extras.dragging.insert(7);
    for x in [0.0, 20.0, 40.0] {
        host.set_pos(&7, Point2D::new(x, 0.0));
        let d = host.frame(FRAME);
        assert!(!d.contains_key(&7), "a dragged node never gets a delta");
        assert_eq!(
            host.world_pos(&7),
            Point2D::new(x, 0.0),
            "dragged body sits at the pointer"
        );
    }
    host.extras.dragging.clear();
    host.frame(FRAME);
    let world = host.layout.world().unwrap();
    assert_eq!(world.body_type(&7), Some(RigidBodyType::Dynamic));
    let v = world.linear_velocity(&7).unwrap();
    // 20 units in 1/60 s = 1200 units/s, less one frame of the default damping (1/s).
    assert!(
        (v.x - 1200.0).abs() < 1200.0 * 0.03 && v.y.abs() < 1e-3,
        "release velocity {v:?}, expected ~(1200, 0)"
    );
    let start = host.pos(&7).x;
    host.frames(30);
    let flown = host.pos(&7).x - start;
    assert!(
        flown > 300.0,
        "flew only {flown} units in 0.5 s after a 1200 units/s throw"
    );
    assert_eq!(
        host.layout.rebuild_count(),
        1,
        "drag start and release flip in place"
    );
}

#[test]
fn drag_velocity_is_measured_against_the_real_frame_time() {
    let scene = CanvasSceneInput::new(vec![node(1_u32, 0.0, 0.0)], vec![]);
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frame(FRAME);
    host.extras.dragging.insert(1);
    host.frame(0.05);
    host.set_pos(&1, Point2D::new(0.0, 30.0));
    host.frame(0.05); // 30 units in 50 ms: 600 units/s
    host.extras.dragging.clear();
    host.frame(0.05);
    let v = host.layout.world().unwrap().linear_velocity(&1).unwrap();
    assert!(
        (v.y - 600.0).abs() < 600.0 * 0.06,
        "release velocity {v:?}, expected ~(0, 600)"
    );
}

#[test]
fn drag_start_flips_the_body_to_kinematic_without_a_rebuild() {
    let mut host = Host::new(pair(), RapierLayoutConfig::default());
    host.frame(FRAME);
    let hash = host.layout.current_topology_hash();
    host.extras.dragging.insert(0);
    host.frame(FRAME);
    let world = host.layout.world().unwrap();
    assert_eq!(
        world.body_type(&0),
        Some(RigidBodyType::KinematicPositionBased)
    );
    assert_eq!(
        host.layout.current_topology_hash(),
        hash,
        "dragging is not topology"
    );
    assert_eq!(
        (host.layout.rebuild_count(), host.layout.patch_count()),
        (1, 0)
    );
}

#[test]
fn dragged_node_drags_its_neighbour_along() {
    let mut host = Host::new(pair(), RapierLayoutConfig::default());
    host.frame(FRAME);
    host.extras.dragging.insert(0);
    for i in 1..=60 {
        host.set_pos(&0, Point2D::new(-5.0 * i as f32, 0.0));
        host.frame(FRAME);
        assert_eq!(
            host.world_pos(&0),
            host.pos(&0),
            "frame {i}: dragged body left the pointer"
        );
    }
    assert!(
        host.pos(&1).x < 50.0,
        "the spring pulled node 1 after the dragged node: x = {}",
        host.pos(&1).x
    );
}

#[test]
fn pinned_nodes_hold_under_gravity_and_spring_pull() {
    for policy in [
        BodyKindPolicy::PinnedStatic,
        BodyKindPolicy::PinnedKinematic,
    ] {
        let scene = CanvasSceneInput::new(
            vec![node(0_u32, 0.0, 0.0), node(1, 400.0, 0.0)],
            vec![edge(0, 1)],
        );
        let config = RapierLayoutConfig {
            body_kind_policy: policy,
            ..Default::default()
        };
        let mut host = Host::new(scene, config);
        host.state.gravity_y = 981.0;
        host.extras.pinned.insert(0);
        for frame in 0..300 {
            let d = host.frame(FRAME);
            assert!(
                !d.contains_key(&0),
                "{policy:?} frame {frame}: pinned node got a delta"
            );
            assert_eq!(
                host.world_pos(&0),
                Point2D::new(0.0, 0.0),
                "{policy:?} frame {frame}"
            );
        }
        let hang = host.pos(&1);
        assert!(
            hang.y > 100.0,
            "{policy:?}: the free node fell under gravity only to {hang:?}"
        );
    }
}

#[test]
fn pinned_static_stays_an_anchor_while_dragged() {
    let mut host = Host::new(pair(), RapierLayoutConfig::default());
    host.extras.pinned.insert(0);
    host.frame(FRAME);
    host.extras.dragging.insert(0);
    for i in 1..=10 {
        host.set_pos(&0, Point2D::new(0.0, 10.0 * i as f32));
        host.frame(FRAME);
        let world = host.layout.world().unwrap();
        assert_eq!(
            world.body_type(&0),
            Some(RigidBodyType::Fixed),
            "drag frame {i}"
        );
        assert_eq!(host.world_pos(&0), host.pos(&0), "drag frame {i}");
    }
    host.extras.dragging.clear();
    host.frames(10);
    let world = host.layout.world().unwrap();
    assert_eq!(world.body_type(&0), Some(RigidBodyType::Fixed));
    assert_eq!(
        world.linear_velocity(&0),
        Some(graph_canvas_layout::euclid::default::Vector2D::zero()),
        "an anchor is not thrown"
    );
    assert_eq!(
        host.pos(&0),
        Point2D::new(0.0, 100.0),
        "the pin stays where it was dropped"
    );
}

#[test]
fn pin_and_unpin_change_the_hash_and_flip_in_place() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::default());
    host.frames(5);
    let before = host.layout.current_topology_hash();
    host.extras.pinned.insert(0);
    host.frame(FRAME);
    let pinned = host.layout.current_topology_hash();
    assert_ne!(before, pinned, "pins are part of the topology hash");
    assert_eq!(
        host.layout.world().unwrap().body_type(&0),
        Some(RigidBodyType::Fixed)
    );
    host.extras.pinned.clear();
    host.frame(FRAME);
    assert_eq!(host.layout.current_topology_hash(), before);
    assert_eq!(
        host.layout.world().unwrap().body_type(&0),
        Some(RigidBodyType::Dynamic)
    );
    assert_eq!(host.layout.rebuild_count(), 1, "pin changes flip in place");
}

#[test]
fn a_host_move_of_a_free_node_is_honoured() {
    let mut host = Host::new(pair(), RapierLayoutConfig::default());
    host.frames(10);
    host.set_pos(&1, Point2D::new(500.0, 500.0)); // undo, snap, layout switch
    let d = host.frame(FRAME);
    let moved = d.get(&1).copied().unwrap_or_default();
    // One frame of spring pull from the new place, not a jump back (~700 units).
    assert!(
        moved.length() < 20.0,
        "after a host move the node jumped by {moved:?}"
    );
    let w = host.world_pos(&1);
    assert!(
        dist(w, host.pos(&1)) < 1e-3,
        "world {w:?} vs host {:?}",
        host.pos(&1)
    );
    assert!(
        dist(w, Point2D::new(500.0, 500.0)) < 20.0,
        "world {w:?} far from where the host put it"
    );
}

#[test]
fn unknown_ids_in_pinned_or_dragging_are_ignored() {
    let mut host = Host::new(pair(), RapierLayoutConfig::default());
    host.extras.pinned.insert(99);
    host.extras.dragging.insert(98);
    host.frames(3);
    let w = host.layout.world().unwrap();
    assert_eq!(w.body_count(), 2);
    assert_eq!(w.body_type(&0), Some(RigidBodyType::Dynamic));
}

#[test]
fn all_kinematic_follows_the_host_and_reports_nothing() {
    let config = RapierLayoutConfig {
        body_kind_policy: BodyKindPolicy::AllKinematic,
        ..Default::default()
    };
    let mut host = Host::new(load_scene("karate"), config);
    for _ in 0..30 {
        let d = host.frame(FRAME);
        assert!(d.is_empty(), "AllKinematic produced deltas: {}", d.len());
    }
    host.set_pos(&3, Point2D::new(1000.0, 0.0));
    host.frame(FRAME);
    assert_eq!(host.world_pos(&3), Point2D::new(1000.0, 0.0));
}
