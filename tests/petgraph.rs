//! petgraph graphs in (feature `petgraph`): any graph through the visit traits, its own
//! node ids as scene ids, a start spiral that suits default disks, and a `StableGraph`
//! whose reused index does not hand a removed node's body to a new one.
#![cfg(feature = "petgraph")]

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::petgraph::graphmap::UnGraphMap;
use graph_canvas_layout::petgraph::stable_graph::StableGraph;
use graph_canvas_layout::petgraph::Graph;
use graph_canvas_layout::scene::NodeStart;
use graph_canvas_layout::{spiral_position, CanvasSceneInput, RapierLayoutConfig, SPIRAL_SPACING};

#[test]
fn every_petgraph_graph_kind_becomes_a_scene_with_its_own_ids() {
    let mut directed = Graph::<(), ()>::new();
    let n: Vec<_> = (0..4).map(|_| directed.add_node(())).collect();
    directed.extend_with_edges([(n[0], n[1]), (n[1], n[2]), (n[2], n[0]), (n[3], n[0])]);
    let scene = CanvasSceneInput::from_petgraph(&directed);
    assert_eq!(scene.nodes.iter().map(|x| x.id).collect::<Vec<_>>(), n);
    assert_eq!(scene.edges.len(), 4);
    assert!(scene
        .edges
        .iter()
        .all(|e| e.weight.to_bits() == 1.0_f32.to_bits()));

    let mut stable = StableGraph::<&str, ()>::new();
    let a = stable.add_node("a");
    let b = stable.add_node("b");
    let c = stable.add_node("c");
    stable.remove_node(b);
    stable.add_edge(a, c, ());
    let scene = CanvasSceneInput::from_petgraph(&stable);
    assert_eq!(scene.nodes.iter().map(|x| x.id).collect::<Vec<_>>(), [a, c]);

    let map = UnGraphMap::<&str, f32>::from_edges([("x", "y", 2.0), ("y", "z", 0.5)]);
    let scene = CanvasSceneInput::from_petgraph_with(&map, |_, _| NodeStart::default(), |&w| w);
    let ids: Vec<&str> = scene.nodes.iter().map(|x| x.id).collect();
    assert_eq!(ids, ["x", "y", "z"]);
    let weights: Vec<f32> = scene.edges.iter().map(|e| e.weight).collect();
    assert_eq!(weights, [2.0, 0.5]);
}

#[test]
fn the_start_spiral_keeps_default_disks_apart() {
    // The nearest two of the first thousand start positions are over a default disk's
    // diameter (32) apart, so nothing starts overlapping.
    let points: Vec<Point2D<f32>> = (0..1000).map(spiral_position).collect();
    let mut nearest = f32::INFINITY;
    for (i, p) in points.iter().enumerate() {
        for q in &points[i + 1..] {
            nearest = nearest.min(dist(*p, *q));
        }
    }
    assert!(
        (32.0..2.0 * SPIRAL_SPACING).contains(&nearest),
        "nearest start positions {nearest} apart"
    );
}

#[test]
fn a_petgraph_graph_lays_out_to_rest() {
    let mut graph = StableGraph::<(), ()>::default();
    let ids: Vec<_> = (0..30).map(|_| graph.add_node(())).collect();
    for i in 0..30 {
        graph.add_edge(ids[i], ids[(i + 1) % 30], ());
    }
    let mut host = Host::new(
        CanvasSceneInput::from_petgraph(&graph),
        RapierLayoutConfig::force_directed(),
    );
    host.settle(600);
    let mean = graph_canvas_layout::quality::mean_edge_length(&host.scene).unwrap();
    assert!(
        (70.0..160.0).contains(&mean),
        "a ring of 30 at rest: mean edge {mean}"
    );
}

#[test]
fn a_reused_stable_graph_index_does_not_inherit_the_removed_nodes_body() {
    let mut graph = StableGraph::<(), ()>::default();
    let a = graph.add_node(());
    let b = graph.add_node(());
    graph.add_edge(a, b, ());
    let mut host = Host::new(
        CanvasSceneInput::from_petgraph(&graph),
        RapierLayoutConfig::default(),
    );
    host.frames(5);
    // b is thrown hard, then removed, and a new node added in the same frame takes its
    // index.
    host.extras.dragging.insert(b);
    for k in 1..=3 {
        let p = host.pos(&b);
        host.set_pos(&b, p + Point2D::new(40.0 * k as f32, 0.0).to_vector());
        host.frame(FRAME);
    }
    host.extras.dragging.remove(&b);
    host.frame(FRAME);
    let thrown = host.layout.world().unwrap().linear_velocity(&b).unwrap();
    assert!(thrown.length() > 1_000.0, "the throw: {thrown:?}");
    graph.remove_node(b);
    let d = graph.add_node(());
    assert_eq!(d, b, "StableGraph reuses the index");
    let start = Point2D::new(-600.0, 300.0);
    host.scene = CanvasSceneInput::from_petgraph_with(
        &graph,
        |id, _| NodeStart {
            position: Some(if id == d { start } else { host.pos(&id) }),
            radius: 0.0,
        },
        |_| 1.0,
    );
    assert!(host.layout.forget_node(&b));
    host.frame(FRAME);
    let world = host.layout.world().unwrap();
    let v = world.linear_velocity(&d).unwrap();
    // A new node: where the host put it, at rest but for one frame of nothing pulling
    // it (its only edge went with b).
    assert!(
        v.length() < 1e-3,
        "the new node inherited a velocity: {v:?}"
    );
    assert_eq!(host.pos(&d), start);
    assert_eq!(world.joint_count(), 0, "b's spring went with it");
}

#[test]
fn a_node_added_without_a_position_is_seated_beside_its_neighbour() {
    // A host's graph laid out to rest, its positions kept in the host's own store.
    let file = load_scene("karate");
    let mut graph = StableGraph::<(), ()>::default();
    let ids: Vec<_> = file.nodes.iter().map(|_| graph.add_node(())).collect();
    for e in &file.edges {
        graph.add_edge(ids[e.source as usize], ids[e.target as usize], ());
    }
    let mut host = Host::new(
        CanvasSceneInput::from_petgraph(&graph),
        RapierLayoutConfig::force_directed(),
    );
    host.settle(600);
    let store: std::collections::HashMap<_, _> = host
        .scene
        .nodes
        .iter()
        .map(|n| (n.id, n.position))
        .collect();
    // Five nodes added to node 0 (the club's instructor, 16 neighbours) without a
    // position: they start at its position and the layout seats them around it.
    let anchor = ids[0];
    let added: Vec<_> = (0..5).map(|_| graph.add_node(())).collect();
    for &d in &added {
        graph.add_edge(anchor, d, ());
    }
    host.scene = CanvasSceneInput::from_petgraph_with(
        &graph,
        |id, _| NodeStart {
            position: store.get(&id).copied(),
            radius: 0.0,
        },
        |_| 1.0,
    );
    for &d in &added {
        assert_eq!(host.pos(&d), store[&anchor], "starts at its neighbour");
    }
    host.settle(600);
    let moved = dist(host.pos(&anchor), store[&anchor]);
    assert!(moved < 40.0, "the anchor moved {moved} units");
    for &d in &added {
        let away = dist(host.pos(&d), host.pos(&anchor));
        assert!(
            (32.0..250.0).contains(&away),
            "an added node rests {away} units from its neighbour"
        );
    }
    assert_eq!(
        graph_canvas_layout::quality::overlapping_pairs(&host.scene, 16.0, 0.5),
        0,
        "disks overlap at rest"
    );
}

#[test]
fn a_scene_keyed_by_petgraph_ids_serialises() {
    let mut graph = StableGraph::<(), ()>::default();
    let a = graph.add_node(());
    let b = graph.add_node(());
    graph.add_edge(a, b, ());
    let scene = CanvasSceneInput::from_petgraph(&graph);
    let json = serde_json::to_string(&scene).expect("serialise");
    let back: CanvasSceneInput<_> = serde_json::from_str(&json).expect("deserialise");
    assert_eq!(back, scene, "{json}");
}
