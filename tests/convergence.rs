//! The layout says when it is at rest, goes quiet then, and wakes when the host
//! disturbs it; topology edits keep everybody else's motion.

mod common;

use common::*;
use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, Layout, RapierLayoutConfig};

#[test]
fn not_converged_before_a_world_exists() {
    let host = Host::new(load_scene("karate"), RapierLayoutConfig::default());
    assert!(!host.layout.is_converged(&host.state));
}

#[test]
fn les_miserables_settles_and_then_emits_no_visible_motion() {
    let mut host = Host::new(load_scene("les_miserables"), RapierLayoutConfig::default());
    let frames = host.settle(5000);
    assert!(
        frames > 30,
        "converged after {frames} frames: too early to be real"
    );
    let at_rest = positions(&host.scene);
    let mut largest: f32 = 0.0;
    for _ in 0..600 {
        let deltas = host.frame(FRAME);
        largest = deltas.values().map(|d| d.length()).fold(largest, f32::max);
        assert!(
            host.layout.is_converged(&host.state),
            "left rest without a disturbance"
        );
    }
    let drift = farthest_moved(&host.scene, &at_rest);
    // Sub-pixel: rest speed is 5 units/s, so at most 0.08 units per frame until sleep.
    assert!(
        largest < 0.1,
        "after rest (frame {frames}) a frame still moved a node {largest}"
    );
    assert!(
        drift < 0.5,
        "after rest (frame {frames}) nodes drifted {drift} in 10 s"
    );
    let awake = host.layout.world().unwrap().awake_dynamic_count();
    assert_eq!(awake, 0, "{awake} bodies still awake 10 s after rest");
}

#[test]
fn a_drag_a_host_move_and_a_topology_change_wake_it() {
    let mut host = Host::new(load_scene("florentine"), RapierLayoutConfig::default());
    host.settle(5000);
    host.extras.dragging.insert(3);
    let p = host.pos(&3);
    host.set_pos(
        &3,
        p + graph_canvas_layout::euclid::default::Vector2D::new(40.0, 0.0),
    );
    host.frame(FRAME);
    assert!(
        !host.layout.is_converged(&host.state),
        "a drag did not wake the layout"
    );
    host.extras.dragging.clear();
    host.settle(5000);

    host.set_pos(&5, Point2D::new(900.0, 900.0));
    host.frame(FRAME);
    assert!(
        !host.layout.is_converged(&host.state),
        "a host move did not wake the layout"
    );
    host.settle(5000);

    host.scene.nodes.push(node(100, 0.0, 0.0));
    host.scene.edges.push(edge(100, 0));
    host.frame(FRAME);
    assert!(
        !host.layout.is_converged(&host.state),
        "a topology change did not wake the layout"
    );
}

#[test]
fn adding_a_node_keeps_everybody_elses_motion() {
    // Throw node 1 of a pair, then add an unrelated node mid-flight.
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 100.0, 0.0)], vec![]);
    for (mode, keeps) in [
        (TopologyUpdate::Incremental, true),
        (TopologyUpdate::Rebuild, false),
    ] {
        let mut host = Host::new(
            scene.clone(),
            RapierLayoutConfig {
                topology_update: mode,
                ..Default::default()
            },
        );
        host.frame(FRAME);
        host.extras.dragging.insert(1);
        host.frame(FRAME);
        host.set_pos(&1, Point2D::new(110.0, 0.0));
        host.frame(FRAME);
        host.extras.dragging.clear();
        host.frame(FRAME);
        let before = host.layout.world().unwrap().linear_velocity(&1).unwrap();
        host.scene.nodes.push(node(2, -500.0, -500.0));
        host.frame(FRAME);
        let after = host.layout.world().unwrap().linear_velocity(&1).unwrap();
        let kept = after.x > 0.9 * before.x;
        assert_eq!(
            kept, keeps,
            "{mode:?}: velocity {before:?} -> {after:?} after adding a node"
        );
        if keeps {
            assert_eq!(
                (host.layout.rebuild_count(), host.layout.patch_count()),
                (1, 1)
            );
        }
    }
}

#[test]
fn removing_an_edge_patches_only_that_joint() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::default());
    host.frames(30);
    let joints = host.layout.world().unwrap().joint_count();
    let velocities: Vec<_> = host
        .scene
        .nodes
        .iter()
        .map(|n| host.layout.world().unwrap().linear_velocity(&n.id).unwrap())
        .collect();
    let removed = host.scene.edges.pop().unwrap();
    // Step with dt tiny so velocities barely change: any reset would show.
    host.frame(1e-6);
    let world = host.layout.world().unwrap();
    assert_eq!(world.joint_count(), joints - 1);
    assert!(!world.contains_joint(&removed.source, &removed.target));
    for (n, v) in host.scene.nodes.iter().zip(&velocities) {
        let now = world.linear_velocity(&n.id).unwrap();
        assert!(
            (now - *v).length() < 0.05 * v.length().max(1.0),
            "node {}: velocity {v:?} -> {now:?}",
            n.id
        );
    }
    assert_eq!(host.layout.rebuild_count(), 1);
}

/// The README's host loop: step, apply, then ask whether the layout rests.
fn run_to_rest(host: &mut Host<u32>, budget: usize) -> usize {
    let mut frames = 0;
    loop {
        host.frame(FRAME);
        frames += 1;
        if host.layout.is_converged(&host.state) {
            return frames;
        }
        assert!(frames < budget, "not at rest after {budget} frames");
    }
}

#[test]
fn the_readme_loop_runs_again_after_an_edit() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    run_to_rest(&mut host, 600);
    // `is_converged` speaks of the last call: right after an edit it still says rest.
    host.scene.nodes.push(node(100, 0.0, 0.0));
    host.scene.edges.push(edge(100, 0));
    assert!(host.layout.is_converged(&host.state));
    let frames = run_to_rest(&mut host, 600);
    assert!(
        frames > 1,
        "the loop stopped after {frames} frame(s): the edit was never laid out"
    );
    let edge = dist(host.pos(&100), host.pos(&0));
    assert!(
        (32.0..250.0).contains(&edge),
        "the new node rests {edge} units from its neighbour"
    );
}
