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

/// A scene with one of each problem `step` leaves out, in scene order.
fn faulty() -> (CanvasSceneInput<u32>, LayoutExtras<u32>) {
    let mut scene = triangle();
    scene.nodes.push(node(3, f32::NAN, 0.0));
    scene.nodes.push(node(1, 50.0, 50.0)); // a repeat
    scene.edges.push(edge(0, 9)); // stale
    scene.edges.push(edge(0, 2).with_weight(-1.0));
    let mut extras = LayoutExtras::default();
    extras.forces.insert(
        2,
        graph_canvas_layout::NodeForces::default().toward_y(f32::INFINITY, 1.0),
    );
    (scene, extras)
}

/// The kinds of `errors`, in order, with the node or edge each names.
fn kinds(errors: &[LayoutError<u32>]) -> Vec<String> {
    errors
        .iter()
        .map(|e| match e {
            LayoutError::NonFinitePosition { node, .. } => format!("position {node}"),
            LayoutError::DuplicateNode { node, .. } => format!("repeat {node}"),
            LayoutError::UnknownEdgeEndpoint { missing, .. } => format!("stale {missing}"),
            LayoutError::InvalidEdgeWeight { edge, .. } => format!("weight of edge {edge}"),
            LayoutError::InvalidNodeForce { node, part, .. } => format!("{part} of {node}"),
            other => format!("{other:?}"),
        })
        .collect()
}

#[test]
fn step_lists_what_it_left_out_and_why() {
    let (scene, extras) = faulty();
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.extras = extras;
    host.frame(FRAME);
    let expected = [
        "position 3",
        "repeat 1",
        "stale 9",
        "weight of edge 4",
        "y of 2",
    ];
    assert_eq!(kinds(host.layout.skipped()), expected);
    // Each problem fixed in turn: the list shrinks to nothing.
    host.scene.nodes[3].position = Point2D::new(-300.0, 0.0);
    host.frame(FRAME);
    assert_eq!(kinds(host.layout.skipped()), &expected[1..]);
    host.scene.nodes.remove(4);
    host.scene.edges.truncate(3);
    host.extras.forces.clear();
    host.frame(FRAME);
    assert!(
        host.layout.skipped().is_empty(),
        "all fixed, yet skipped: {:?}",
        host.layout.skipped()
    );
}

#[test]
fn a_layout_can_rest_while_a_node_waits_and_says_which() {
    let mut scene = triangle();
    scene.nodes.push(node(3, f32::NAN, f32::NAN));
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.settle(1_200);
    assert_eq!(
        kinds(host.layout.skipped()),
        ["position 3"],
        "at rest, with node 3 left out"
    );
}

#[test]
fn problems_lists_every_problem_and_try_step_names_the_first() {
    let (scene, extras) = faulty();
    let all = RapierLayout::problems(&scene, &extras);
    assert_eq!(
        kinds(&all),
        [
            "position 3",
            "repeat 1",
            "stale 9",
            "weight of edge 4",
            "y of 2"
        ]
    );
    let mut layout = RapierLayout::new(RapierLayoutConfig::default());
    let mut state = RapierLayoutState::default();
    let first = layout
        .try_step(
            &scene,
            &mut state,
            FRAME,
            &CanvasViewport::default(),
            &extras,
        )
        .expect_err("a faulty scene");
    // (Compared by kind and id: the NaN it carries is not equal to itself.)
    assert_eq!(
        kinds(&[first]),
        kinds(&all[..1]),
        "try_step names the first of problems()"
    );
    assert!(RapierLayout::problems(&triangle(), &LayoutExtras::default()).is_empty());
}

#[test]
fn apply_deltas_moves_the_copy_that_step_lays_out() {
    // Node 1 twice: step models the first copy (its spring pulls it in) and ignores the
    // second; apply_deltas moves the first only, so the host's first copy stays on its
    // body and the repeat where the host put it.
    let mut scene = triangle();
    scene.nodes.push(node(1, 900.0, 900.0));
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frames(30);
    let body = host.layout.world().unwrap().get_position(&1).unwrap();
    assert!(
        dist(host.scene.nodes[1].position, body) < 1e-3,
        "first copy at {:?}, body at {body:?}",
        host.scene.nodes[1].position
    );
    assert_eq!(
        host.scene.nodes[3].position,
        Point2D::new(900.0, 900.0),
        "the repeat moved"
    );
}
