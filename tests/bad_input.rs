//! Bad input: `try_step` names it and changes nothing; `step` leaves it out, keeps the
//! rest simulating and never lets a non-finite number out.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, LayoutError, LayoutExtras, RapierLayout, RapierLayoutConfig,
    RapierLayoutState,
};

fn triangle() -> CanvasSceneInput<u32> {
    CanvasSceneInput::new(
        vec![node(0, 0.0, 0.0), node(1, 300.0, 0.0), node(2, 0.0, 300.0)],
        vec![edge(0, 1), edge(1, 2), edge(2, 0)],
    )
}

fn try_once(
    layout: &mut RapierLayout<u32>,
    state: &mut RapierLayoutState,
    scene: &CanvasSceneInput<u32>,
) -> Result<graph_canvas_layout::DeltaMap<u32>, LayoutError<u32>> {
    layout.try_step(
        scene,
        state,
        FRAME,
        &CanvasViewport::default(),
        &LayoutExtras::default(),
    )
}

#[test]
fn try_step_names_the_bad_element_and_changes_nothing() {
    let mut layout = RapierLayout::default();
    let mut state = RapierLayoutState::default();
    let good = triangle();
    try_once(&mut layout, &mut state, &good).unwrap();
    let world_before = layout.world().unwrap().get_position(&1).unwrap();
    let (hash, steps, rebuilds) = (
        layout.current_topology_hash(),
        state.step_count,
        layout.rebuild_count(),
    );

    let mut nan = good.clone();
    nan.nodes[1].position.x = f32::NAN;
    let mut radius = good.clone();
    radius.nodes[2].radius = f32::INFINITY;
    let mut negative = good.clone();
    negative.nodes[2].radius = -1.0;
    let mut dup = good.clone();
    dup.nodes.push(node(0, 1.0, 1.0));
    let mut dangling = good.clone();
    dangling.edges.push(edge(2, 77));
    let mut far = good.clone();
    far.nodes[1].position.y = -2.0e9;
    let cases = [
        (nan, "node 1 has a non-finite position"),
        (far, "node 1 has a position (300, -2000000000) beyond ±1e9"),
        (radius, "node 2 has an invalid radius inf"),
        (negative, "node 2 has an invalid radius -1"),
        (
            dup,
            "node id 0 appears twice in the scene (nodes[0] and nodes[3])",
        ),
        (
            dangling,
            "edge 3 (2 -> 77) names node 77, which is not in the scene",
        ),
    ];
    for (scene, message) in cases {
        let err = try_once(&mut layout, &mut state, &scene).expect_err(message);
        let text = err.to_string();
        assert!(
            text.starts_with(message),
            "error text {text:?}, expected it to start with {message:?}"
        );
        assert_eq!(state.step_count, steps, "{message}: the state changed");
        assert_eq!(
            layout.current_topology_hash(),
            hash,
            "{message}: the topology changed"
        );
        assert_eq!(layout.rebuild_count(), rebuilds);
        assert_eq!(
            layout.world().unwrap().get_position(&1).unwrap(),
            world_before,
            "{message}: the world moved"
        );
    }
}

#[test]
fn step_freezes_a_nan_node_and_takes_it_back_when_fixed() {
    let mut host = Host::new(triangle(), RapierLayoutConfig::default());
    host.frames(5);
    let held = host.world_pos(&1);
    host.set_pos(&1, Point2D::new(f32::NAN, 3.0));
    for frame in 0..30 {
        let d = host.frame(FRAME);
        assert!(
            !d.contains_key(&1),
            "frame {frame}: the NaN node got a delta"
        );
        for (id, v) in &d {
            assert!(
                v.x.is_finite() && v.y.is_finite(),
                "frame {frame}: node {id} delta {v:?}"
            );
        }
        assert_eq!(
            host.world_pos(&1),
            held,
            "frame {frame}: the frozen body moved"
        );
    }
    // Nodes 0 and 2 started 300 apart on a spring of rest length 100.
    let gap = dist(host.pos(&0), host.pos(&2));
    assert!(
        gap < 250.0,
        "the rest kept simulating: gap {gap}, started at 300"
    );
    host.set_pos(&1, held);
    host.frames(60);
    let w = host.world_pos(&1);
    assert!(
        dist(w, held) > 1.0,
        "node 1 did not resume after its position was fixed: {w:?}"
    );
    assert!(w.x.is_finite() && w.y.is_finite());
}

#[test]
fn step_ignores_dangling_edges_duplicates_and_new_bad_nodes() {
    let mut scene = triangle();
    scene.edges.push(edge(0, 99));
    scene.nodes.push(node(1, 5.0, 5.0)); // repeat of id 1
    scene.nodes.push(node(3, f32::INFINITY, 0.0)); // new and unusable
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frames(10);
    let w = host.layout.world().unwrap();
    assert_eq!((w.body_count(), w.joint_count()), (3, 3));
    assert!(!w.contains_node(&3));
    host.scene.nodes[4].position = Point2D::new(500.0, 500.0);
    host.frame(FRAME);
    assert!(
        host.layout.world().unwrap().contains_node(&3),
        "a fixed new node joins the world"
    );
}
