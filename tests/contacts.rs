//! Disks collide: overlaps are pushed apart, and contacts are reported when asked for.

mod common;

use common::*;
use graph_canvas_layout::config::ContactModel;
use graph_canvas_layout::config::Contacts;
use graph_canvas_layout::euclid::default::Point2D;
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
        contacts: Contacts {
            enabled: false,
            ..Default::default()
        },
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
        contacts: Contacts {
            events: true,
            ..Default::default()
        },
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

fn disks() -> RapierLayoutConfig {
    RapierLayoutConfig {
        contacts: Contacts {
            model: ContactModel::Disks,
            ..Default::default()
        },
        ..Default::default()
    }
}

#[test]
fn the_layouts_own_disk_separation_parts_overlaps_without_colliders() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 10.0, 0.0)], vec![]);
    let mut host = Host::new(scene, disks());
    host.frames(60);
    let g = dist(host.pos(&0), host.pos(&1));
    // Touching at 32, within the quarter unit the separation leaves under no load, and
    // stopped there: the push does not fling them apart.
    assert!((31.75..34.0).contains(&g), "gap {g} after 1 s");
    assert_eq!(host.layout.world().unwrap().collider_count(), 0);
}

#[test]
fn coincident_disks_part_too() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 5.0, 5.0), node(1, 5.0, 5.0)], vec![]);
    let mut host = Host::new(scene, disks());
    host.frames(60);
    let g = dist(host.pos(&0), host.pos(&1));
    assert!((31.75..34.0).contains(&g), "gap {g} after 1 s");
}

#[test]
fn a_dragged_disk_pushes_resting_ones_aside_and_a_pinned_one_holds() {
    let scene = CanvasSceneInput::new(
        vec![
            node(0_u32, 0.0, 0.0),
            node(1, 100.0, 0.0),
            node(2, 200.0, 40.0),
        ],
        vec![],
    );
    let mut host = Host::new(scene, disks());
    host.extras.pinned.insert(2);
    host.settle(600);
    // Node 0 is dragged through node 1's place and on through the pinned node's.
    host.extras.dragging.insert(0);
    let mut deepest = 0.0_f32;
    for k in 1..=60 {
        host.set_pos(&0, Point2D::new(5.0 * k as f32, 0.0));
        host.frame(FRAME);
        deepest = deepest.max(32.0 - dist(host.pos(&0), host.pos(&1)));
    }
    assert!(
        dist(host.pos(&1), Point2D::new(100.0, 0.0)) > 100.0,
        "node 1 was not pushed along: {:?}",
        host.pos(&1)
    );
    assert!(
        deepest < 2.0,
        "the drag pressed {deepest} units into node 1"
    );
    assert_eq!(host.pos(&2), Point2D::new(200.0, 40.0), "the pin held");
    assert_eq!(
        host.pos(&0),
        Point2D::new(300.0, 0.0),
        "the dragged node is where the host put it"
    );
}

#[test]
fn contact_events_keep_rapier_colliders_under_the_disk_model() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 20.0, 0.0)], vec![]);
    let config = RapierLayoutConfig {
        contacts: Contacts {
            events: true,
            ..disks().contacts
        },
        ..disks()
    };
    let mut host = Host::new(scene, config);
    host.frame(FRAME);
    assert_eq!(host.layout.world().unwrap().collider_count(), 2);
    assert!(
        !host.layout.drain_events().is_empty(),
        "the overlap is reported"
    );
}
