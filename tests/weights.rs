//! Edge weights drive the layout: a heavier edge pulls harder (or, mapped to length,
//! draws longer), weight 0 keeps the edge as topology only, a weight edit re-tunes its
//! joint in place, and a bad weight is bad input.

mod common;

use common::*;
use graph_canvas_layout::config::{Contacts, Springs};
use graph_canvas_layout::config::{EdgeWeight, SpringModel};
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, EdgeJoint, LayoutError, RapierLayoutConfig, RapierLayoutState,
};

/// Anchors 0 and 2 pinned 400 units apart, node 1 free between them on the axis, edges
/// 0–1 of weight `w1` and 1–2 of weight `w2`.
fn between(w1: f32, w2: f32, config: RapierLayoutConfig) -> Host<u32> {
    let mut edges = vec![edge(0, 1), edge(1, 2)];
    edges[0].weight = w1;
    edges[1].weight = w2;
    let scene = CanvasSceneInput::new(
        vec![node(0, 0.0, 0.0), node(1, 200.0, 0.0), node(2, 400.0, 0.0)],
        edges,
    );
    let mut host = Host::new(scene, config);
    host.extras.pinned.extend([0, 2]);
    host
}

fn springs_only() -> RapierLayoutConfig {
    // Collisions off: only the two springs act on the free node. Stiff and well damped,
    // so the node settles before rapier puts it to sleep (under 5 units/s for 0.5 s): a
    // soft spring of stiffness 50 would leave it asleep 2 units short of its balance.
    // Springs as forces rest where the forces balance (within 0.01 units here); rapier's
    // spring joints, solved one after the other, rest 1.2 units off it even with equal
    // weights, so the exact checks use forces.
    RapierLayoutConfig {
        contacts: Contacts {
            enabled: false,
            ..Default::default()
        },
        springs: Springs {
            model: SpringModel::Forces,
            ..Default::default()
        },
        edge_joint: EdgeJoint::Spring {
            rest_length: 100.0,
            stiffness: 2_000.0,
            damping: 40.0,
        },
        ..Default::default()
    }
}

#[test]
fn a_node_between_two_anchors_rests_nearer_the_heavier_edge() {
    // EdgeWeight::Strength: w1 (x - L) = w2 (D - x - L), so x = (w1 L + w2 (D - L)) /
    // (w1 + w2) = (2·100 + 300) / 3 with L = 100, D = 400.
    let expected = (2.0 * 100.0 + 300.0) / 3.0;
    // Forces: within 0.05 units. Joints: within 2 units, rapier's solver bias (see
    // `springs_only`).
    for (model, tolerance) in [(SpringModel::Forces, 0.05), (SpringModel::Joints, 2.0)] {
        let mut host = between(
            2.0,
            1.0,
            RapierLayoutConfig {
                springs: Springs {
                    model,
                    ..springs_only().springs
                },
                ..springs_only()
            },
        );
        host.frames(900);
        let x = host.pos(&1).x;
        assert!(
            (x - expected).abs() < tolerance,
            "{model:?}: the node rests at {x}, the formula says {expected}"
        );
    }
}

#[test]
fn mapped_to_length_a_heavier_edge_draws_longer() {
    // EdgeWeight::Length: rest lengths 2·100 and 1·100 at one stiffness, so
    // x - 200 = 400 - x - 100: x = 250.
    let config = RapierLayoutConfig {
        springs: Springs {
            weight: EdgeWeight::Length,
            ..springs_only().springs
        },
        ..springs_only()
    };
    let mut host = between(2.0, 1.0, config);
    host.frames(900);
    let x = host.pos(&1).x;
    assert!(
        (x - 250.0).abs() < 0.05,
        "the node rests at {x}, expected 250"
    );
    // A rod's length follows the weight as well.
    let rod = RapierLayoutConfig {
        edge_joint: EdgeJoint::Distance { length: 150.0 },
        springs: Springs {
            weight: EdgeWeight::Length,
            ..springs_only().springs
        },
        ..springs_only()
    };
    let mut edges = vec![edge(0, 1)];
    edges[0].weight = 2.0;
    let scene = CanvasSceneInput::new(vec![node(0, 0.0, 0.0), node(1, 200.0, 0.0)], edges);
    let mut host = Host::new(scene, rod);
    host.extras.pinned.insert(0);
    host.frames(120);
    let d = dist(host.pos(&0), host.pos(&1));
    assert!(
        (d - 300.0).abs() < 1.0,
        "a rod of weight 2 holds {d}, expected 300"
    );
}

#[test]
fn weight_zero_keeps_the_edge_as_topology_only() {
    let mut host = between(0.0, 1.0, springs_only());
    host.frames(900);
    let world = host.layout.world().unwrap();
    assert_eq!(world.joint_count(), 1, "no joint for the weight-0 edge");
    // Only the other spring pulls: the node rests at its rest length from anchor 2.
    // Within a quarter unit: one spring alone lets the node fall asleep a little short.
    let x = host.pos(&1).x;
    assert!(
        (x - 300.0).abs() < 0.25,
        "the node rests at {x}, expected 300"
    );
    // The edge is still part of the topology: its hash is the weight-1 graph's.
    let weighted = between(1.0, 1.0, springs_only());
    assert_eq!(
        graph_canvas_layout::scene::topology_hash(&host.scene, &host.extras),
        graph_canvas_layout::scene::topology_hash(&weighted.scene, &weighted.extras)
    );
}

#[test]
fn a_weight_edit_retunes_in_place_and_keeps_everybodys_motion() {
    // The pair between the anchors, and a separate pair far away moving on its own.
    let make = || {
        let mut host = between(1.0, 1.0, springs_only());
        host.scene
            .nodes
            .extend([node(10, 2000.0, 0.0), node(11, 2300.0, 0.0)]);
        host.scene.edges.push(edge(10, 11));
        host.frames(20);
        host
    };
    let (mut edited, mut control) = (make(), make());
    edited.scene.edges[0].weight = 3.0;
    for _ in 0..30 {
        edited.frame(FRAME);
        control.frame(FRAME);
    }
    assert_eq!(edited.layout.rebuild_count(), 1, "no rebuild");
    let world = edited.layout.world().unwrap();
    assert_eq!(world.joint_count(), 3);
    // The far pair never noticed: bit for bit the control's.
    for id in [10, 11] {
        let (a, b) = (edited.pos(&id), control.pos(&id));
        assert_eq!(
            (a.x.to_bits(), a.y.to_bits()),
            (b.x.to_bits(), b.y.to_bits()),
            "node {id}: {a:?} against {b:?}"
        );
    }
    // And the edited pair moves toward its new balance, x = (3·100 + 300) / 4.
    edited.frames(900);
    let x = edited.pos(&1).x;
    assert!((x - 150.0).abs() < 0.05, "rests at {x}, expected 150");
}

#[test]
fn a_bad_weight_is_rejected_by_try_step_and_left_out_by_step() {
    for bad in [-1.0, f32::NAN, f32::INFINITY] {
        let mut host = between(bad, 1.0, springs_only());
        let mut state = RapierLayoutState::default();
        let err = host.layout.try_step(
            &host.scene,
            &mut state,
            FRAME,
            &CanvasViewport::default(),
            &host.extras,
        );
        match err {
            Err(LayoutError::InvalidEdgeWeight {
                edge: 0,
                source: 0,
                target: 1,
                weight,
            }) => assert_eq!(weight.to_bits(), bad.to_bits()),
            other => panic!("weight {bad}: {other:?}"),
        }
        assert!(!host.layout.has_world(), "a rejected call changes nothing");
        assert_eq!(state.step_count, 0);
        // `step` leaves that edge's force out, as weight 0 would, and keeps the rest.
        let mut zero = between(0.0, 1.0, springs_only());
        host.frames(120);
        zero.frames(120);
        let (a, b) = (host.pos(&1), zero.pos(&1));
        assert_eq!(
            (a.x.to_bits(), a.y.to_bits()),
            (b.x.to_bits(), b.y.to_bits()),
            "weight {bad}"
        );
        // Fixed, the edge pulls again.
        host.scene.edges[0].weight = 1.0;
        host.frames(900);
        let x = host.pos(&1).x;
        assert!((x - 200.0).abs() < 0.05, "weight {bad} fixed: rests at {x}");
    }
}

#[test]
fn weights_scale_force_directed_springs_too() {
    // Springs applied as forces with the preset's degree share (every edge has an end of
    // degree 1: no share) and its cooling, repulsion and contacts left out so only the
    // springs act: at rest x = (4·100 + 300) / 5. A spring is capped at what the step
    // resolves (7,200 here, the preset's stiffness), so while hot the heavier one pulls
    // no harder; cooled (springs at heat^0.7) it pulls four times as hard.
    let mut config = RapierLayoutConfig::force_directed();
    config.repulsion = None;
    config.contacts.enabled = false;
    let mut host = between(4.0, 1.0, config);
    host.settle(900);
    let x = host.pos(&1).x;
    assert!(
        (x - 140.0).abs() < 1.0,
        "the node rests at {x}, expected 140"
    );
}
