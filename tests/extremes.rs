//! Trust at the extremes: huge coordinates, stiff springs, coincident nodes, absurd
//! frame times, violent throws, odd radii. Each stays finite and bounded.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    CanvasSceneInput, EdgeJoint, NodeAvatarBinding, NodeSnapshot, RapierLayoutConfig,
    RapierSceneWorld,
};

/// The largest distance of a node of `host`'s scene from `center`.
fn farthest_from(host: &Host<u32>, center: Point2D<f32>) -> f32 {
    host.scene
        .nodes
        .iter()
        .map(|n| (n.position - center).length())
        .fold(0.0, f32::max)
}

/// Runs `frames` frames and returns the largest per-frame displacement seen; panics on
/// any non-finite delta or position.
fn run_checked(host: &mut Host<u32>, frames: usize, dt: f32, what: &str) -> f32 {
    let mut largest: f32 = 0.0;
    for frame in 0..frames {
        let deltas = host.frame(dt);
        for (id, d) in &deltas {
            assert!(
                d.x.is_finite() && d.y.is_finite(),
                "{what}, frame {frame}: node {id} delta {d:?}"
            );
            largest = largest.max(d.length());
        }
        for n in &host.scene.nodes {
            assert!(
                n.position.x.is_finite() && n.position.y.is_finite(),
                "{what}, frame {frame}: node {} at {:?}",
                n.id,
                n.position
            );
        }
    }
    largest
}

#[test]
fn huge_coordinates_stay_finite_and_calm() {
    for offset in [1e5_f32, 1e6, 1e7] {
        let mut scene = load_scene("karate");
        for n in &mut scene.nodes {
            n.position += Vector2D::new(offset, -offset);
        }
        let mut host = Host::new(scene, RapierLayoutConfig::default());
        let largest = run_checked(&mut host, 300, FRAME, &format!("offset {offset:e}"));
        assert!(
            largest < 300.0,
            "offset {offset:e}: a node moved {largest} units in one frame"
        );
        let far = farthest_from(&host, Point2D::new(offset, -offset));
        assert!(
            far < 2000.0,
            "offset {offset:e}: a node drifted {far} units from the graph's origin"
        );
    }
}

#[test]
fn stiff_springs_do_not_explode() {
    for stiffness in [1e4_f32, 1e5, 1e6, 1e7, 1e8, 1e9] {
        let config = RapierLayoutConfig {
            edge_joint: EdgeJoint::Spring {
                rest_length: 100.0,
                stiffness,
                damping: 1.0,
            },
            ..Default::default()
        };
        let mut host = Host::new(load_scene("karate"), config);
        let largest = run_checked(&mut host, 240, FRAME, &format!("stiffness {stiffness:e}"));
        assert!(
            largest < 400.0,
            "stiffness {stiffness:e}: a node jumped {largest} in one frame"
        );
        let extent = farthest_from(&host, Point2D::origin());
        assert!(
            extent < 5000.0,
            "stiffness {stiffness:e}: the graph spread to radius {extent}"
        );
    }
}

#[test]
fn coincident_nodes_come_apart_without_exploding() {
    let nodes = (0..50).map(|i| node(i, 0.0, 0.0)).collect();
    let mut host = Host::new(
        CanvasSceneInput::new(nodes, vec![]),
        RapierLayoutConfig::default(),
    );
    let largest = run_checked(&mut host, 300, FRAME, "50 coincident nodes");
    assert!(
        largest < 100.0,
        "a coincident node shot off {largest} units in one frame"
    );
    let mut closest = f32::MAX;
    for (i, a) in host.scene.nodes.iter().enumerate() {
        for b in &host.scene.nodes[i + 1..] {
            closest = closest.min(dist(a.position, b.position));
        }
    }
    let extent = farthest_from(&host, Point2D::origin());
    assert!(
        closest > 20.0,
        "after 5 s two of the 50 nodes are still {closest} apart (radius 16)"
    );
    assert!(extent < 1000.0, "the 50 nodes spread to radius {extent}");
}

#[test]
fn absurd_frame_times_stay_finite_and_bounded() {
    let dts = [
        1e-7_f32,
        1e-4,
        0.5,
        10.0,
        1e9,
        f32::MAX,
        f32::INFINITY,
        f32::NAN,
        -1.0,
        -f32::MAX,
        0.0,
    ];
    for dt in dts {
        let mut host = Host::new(load_scene("florentine"), RapierLayoutConfig::default());
        host.frames(5);
        let largest = run_checked(&mut host, 20, dt, &format!("dt {dt}"));
        // At most max_frame_time (0.25 s) per call at the speed cap.
        assert!(
            largest < 0.25 * 40_000.0,
            "dt {dt}: a node moved {largest} in one call"
        );
        assert!(host.state.simulated_time.is_finite(), "dt {dt}");
    }
}

#[test]
fn a_violent_throw_flies_at_the_speed_cap() {
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 100.0, 0.0)],
        vec![edge(0, 1)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frame(FRAME);
    host.extras.dragging.insert(1);
    host.frame(FRAME);
    host.set_pos(&1, Point2D::new(1e6, 0.0)); // 1e6 units in one frame: 6e7 units/s
    host.frame(FRAME);
    host.extras.dragging.clear();
    let largest = run_checked(&mut host, 120, FRAME, "1e6 units/frame throw");
    let cap_per_frame = 40_000.0 * FRAME;
    assert!(
        largest <= cap_per_frame * 1.001,
        "a frame moved {largest}, cap is {cap_per_frame}"
    );
    let v = host.layout.world().unwrap().linear_velocity(&1).unwrap();
    assert!(
        v.length() <= 40_000.0 * 1.001,
        "speed {} above the cap",
        v.length()
    );
    assert!(
        largest >= cap_per_frame * 0.99,
        "the throw did not fly at the cap: largest frame {largest}, cap {cap_per_frame}"
    );
}

#[test]
fn odd_radii_single_nodes_and_edgeless_scenes() {
    for radius in [0.0_f32, 1e-6, 1e4] {
        let scene = CanvasSceneInput::new(
            vec![
                node(0_u32, 0.0, 0.0).with_radius(radius),
                node(1, 50.0, 0.0).with_radius(radius),
                node(2, 0.0, 50.0),
            ],
            vec![edge(0, 1), edge(1, 2)],
        );
        let mut host = Host::new(scene, RapierLayoutConfig::default());
        let largest = run_checked(&mut host, 120, FRAME, &format!("radius {radius:e}"));
        assert!(
            largest < 500.0,
            "radius {radius:e}: a node moved {largest} in one frame"
        );
    }
    let mut single = Host::new(
        CanvasSceneInput::new(vec![node(5_u32, 3.0, 4.0)], vec![]),
        RapierLayoutConfig::default(),
    );
    let lone = run_checked(&mut single, 60, FRAME, "single node");
    assert!(lone <= 0.0, "a lone node at rest moved {lone} in one frame");
    assert_eq!(
        single.pos(&5),
        Point2D::new(3.0, 4.0),
        "a lone node at rest stays put"
    );
    let mut edgeless = Host::new(
        CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 200.0, 0.0)], vec![]),
        RapierLayoutConfig::default(),
    );
    run_checked(&mut edgeless, 60, FRAME, "no edges");
    assert_eq!(edgeless.layout.world().unwrap().joint_count(), 0);
}

#[test]
fn a_body_that_goes_non_finite_is_recovered_not_left_disabled() {
    let mut world = RapierSceneWorld::new();
    let mut binding = NodeAvatarBinding::circle(0_u32, 16.0);
    binding.material.linear_damping = 0.0;
    let snapshot = NodeSnapshot {
        id: 0_u32,
        position: Point2D::new(f32::MAX, 0.0),
        radius: 16.0,
        pinned: false,
    };
    world.build_bodies(&[binding], &[snapshot]);
    world
        .integration_parameters_mut()
        .normalized_max_linear_velocity = f32::MAX;
    world.apply_impulse(&0, Vector2D::new(f32::MAX, 0.0)); // overflows to +inf on the next step
    world.step(Vector2D::zero());
    let p = world.get_position(&0).unwrap();
    assert!(p.x.is_finite() && p.y.is_finite(), "position {p:?}");
    assert_eq!(
        world.take_recovered_nodes(),
        vec![0],
        "the quarantined body is reported"
    );
    assert_eq!(world.linear_velocity(&0), Some(Vector2D::zero()));
    assert_eq!(
        world.is_enabled(&0),
        Some(true),
        "a quarantined node is not left disabled"
    );
    world.set_dynamic_position(&0, Point2D::new(0.0, 0.0));
    world.apply_impulse(&0, Vector2D::new(-100.0, 0.0));
    world.step(Vector2D::zero());
    let x = world.get_position(&0).unwrap().x;
    assert!(x < 0.0, "the recovered body simulates again: x = {x}");
}
