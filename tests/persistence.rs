//! The plan's §5 validation items and the persistent-world contract: momentum across
//! frames, topology-driven world changes, no rebuild when nothing changed, and no drift
//! between the host's positions and the world's.

mod common;

use common::*;
use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    CanvasSceneInput, EdgeJoint, NodeAvatarBinding, NodeSnapshot, RapierLayoutConfig,
    RapierSceneWorld,
};

fn no_damping() -> RapierLayoutConfig {
    let mut config = RapierLayoutConfig::default();
    config.material.linear_damping = 0.0;
    config
}

#[test]
fn impulse_momentum_carries_over_many_steps() {
    let mut world = RapierSceneWorld::new();
    let snap = NodeSnapshot {
        id: 0_u32,
        position: Point2D::origin(),
        radius: 16.0,
        pinned: false,
    };
    let mut binding = NodeAvatarBinding::circle(0, 16.0);
    binding.material.linear_damping = 0.0;
    world.build_bodies(&[binding], &[snap]);
    let mass = 0.005 * std::f32::consts::PI * 16.0 * 16.0;
    world.apply_impulse(&0, Vector2D::new(300.0 * mass, 0.0)); // 300 units/s
    let mut xs = Vec::new();
    for _ in 0..30 {
        world.step(Vector2D::zero());
        xs.push(world.get_position(&0).unwrap().x);
    }
    // Without damping the body coasts 5 units per 1/60 s step, every step.
    for (i, pair) in xs.windows(2).enumerate() {
        let step = pair[1] - pair[0];
        assert!(
            (step - 5.0).abs() < 0.01,
            "step {i}: moved {step}, expected 5 (positions {xs:?})"
        );
    }
}

#[test]
fn a_thrown_node_keeps_flying_across_layout_calls() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0)], vec![]);
    let mut host = Host::new(scene, no_damping());
    host.frame(FRAME);
    host.extras.dragging.insert(0);
    host.frame(FRAME);
    host.set_pos(&0, Point2D::new(10.0, 0.0));
    host.frame(FRAME);
    host.extras.dragging.clear();
    let mut per_frame = Vec::new();
    for _ in 0..20 {
        let d = host.frame(FRAME);
        per_frame.push(d.get(&0).map_or(0.0, |v| v.x));
    }
    // 10 units per frame at release, kept for all 20 undamped frames.
    for (i, dx) in per_frame.iter().enumerate() {
        assert!(
            (dx - 10.0).abs() < 0.05,
            "frame {i} after release moved {dx}, expected 10: {per_frame:?}"
        );
    }
}

#[test]
fn adding_and_removing_a_node_grows_and_shrinks_the_world() {
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 100.0, 0.0)],
        vec![edge(0, 1)],
    );
    for mode in [TopologyUpdate::Incremental, TopologyUpdate::Rebuild] {
        let config = RapierLayoutConfig {
            topology_update: mode,
            ..Default::default()
        };
        let mut host = Host::new(scene.clone(), config);
        host.frame(FRAME);
        let w = host.layout.world().unwrap();
        assert_eq!(
            (w.body_count(), w.joint_count()),
            (2, 1),
            "{mode:?} initial"
        );
        host.scene.nodes.push(node(2, 0.0, 100.0));
        host.scene.edges.push(edge(2, 0));
        host.scene.edges.push(edge(2, 1));
        host.frame(FRAME);
        let w = host.layout.world().unwrap();
        assert_eq!(
            (w.body_count(), w.joint_count()),
            (3, 3),
            "{mode:?} after adding node 2"
        );
        assert!(w.contains_node(&2) && w.contains_joint(&1, &2), "{mode:?}");
        host.scene.nodes.retain(|n| n.id != 0);
        host.scene.edges.retain(|e| e.source != 0 && e.target != 0);
        host.frame(FRAME);
        let w = host.layout.world().unwrap();
        assert_eq!(
            (w.body_count(), w.joint_count()),
            (2, 1),
            "{mode:?} after removing node 0"
        );
        assert!(!w.contains_node(&0), "{mode:?}");
    }
}

#[test]
fn unchanged_topology_never_rebuilds() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::default());
    host.frames(200);
    assert_eq!(
        host.layout.rebuild_count(),
        1,
        "one build for 200 unchanged frames"
    );
    assert_eq!(host.layout.patch_count(), 0);
}

#[test]
fn empty_scene_drops_the_world_and_the_next_scene_builds_a_new_one() {
    let mut host = Host::new(load_scene("florentine"), RapierLayoutConfig::default());
    host.frame(FRAME);
    assert!(host.layout.has_world());
    assert_ne!(host.layout.current_topology_hash(), 0);
    let full = std::mem::take(&mut host.scene);
    let deltas = host.frame(FRAME);
    assert!(!host.layout.has_world() && deltas.is_empty());
    assert_eq!(host.layout.current_topology_hash(), 0);
    host.scene = full;
    host.frame(FRAME);
    assert!(host.layout.has_world());
    assert_eq!(host.layout.rebuild_count(), 2);
}

#[test]
fn deltas_sum_to_the_world_positions_without_drift() {
    let mut host = Host::new(load_scene("les_miserables"), RapierLayoutConfig::default());
    let start = positions(&host.scene);
    let mut summed = start.clone();
    for frame in 0..600 {
        let deltas = host.frame(FRAME);
        for (id, d) in &deltas {
            *summed.get_mut(id).unwrap() += *d;
        }
        if frame % 100 == 99 {
            let world = host.layout.world().unwrap();
            let mut worst: f32 = 0.0;
            for n in &host.scene.nodes {
                let w = world.get_position(&n.id).unwrap();
                worst = worst.max(dist(w, summed[&n.id])).max(dist(w, n.position));
            }
            // The report threshold is 1e-4; float rounding of sums near |x| ~ 500 is
            // ~1e-4 per add. Drift would grow with frames; this bound does not.
            assert!(
                worst < 2e-3,
                "frame {frame}: host vs world differ by {worst}"
            );
        }
    }
    let moved = start
        .iter()
        .filter(|(id, p)| dist(**p, host.pos(id)) > 1.0)
        .count();
    assert!(
        moved > 30,
        "the layout moved only {moved} of 77 nodes by more than 1 unit"
    );
}

#[test]
fn edges_with_no_joint_are_topology_only() {
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 300.0, 0.0)],
        vec![edge(0, 1)],
    );
    let config = RapierLayoutConfig {
        edge_joint: EdgeJoint::None,
        ..Default::default()
    };
    let mut host = Host::new(scene, config);
    let hash_with_edge = {
        host.frames(30);
        host.layout.current_topology_hash()
    };
    let w = host.layout.world().unwrap();
    assert_eq!(w.joint_count(), 0);
    assert_eq!(
        host.pos(&1),
        Point2D::new(300.0, 0.0),
        "nothing pulls without a joint"
    );
    host.scene.edges.clear();
    host.frame(FRAME);
    assert_ne!(
        host.layout.current_topology_hash(),
        hash_with_edge,
        "the edge was topology"
    );
}
