//! A graph of [`WORKER_FROM`] nodes or more in a real `GraphView` is laid out on a
//! `LayoutWorker`: egui's frames go on while the worker steps, the positions come back,
//! the state says when it rests, and a node dragged and let go pulls its neighbours.

use std::time::{Duration, Instant};

use egui::{Context, Pos2, RawInput, Rect};
use egui_graphs::{get_layout_state, Graph, GraphView, SettingsInteraction, SettingsNavigation};
use graph_canvas_layout_egui_graphs::{RapierGraphLayout, RapierGraphState, WORKER_FROM};
use petgraph::stable_graph::{NodeIndex, StableGraph};
use petgraph::Undirected;

type G = Graph<(), (), Undirected>;

/// One headless frame of `graph`; returns whether the layout rests.
fn frame(ctx: &Context, graph: &mut G, time: f64) -> bool {
    let input = RawInput {
        screen_rect: Some(Rect::from_min_size(Pos2::ZERO, egui::vec2(800.0, 600.0))),
        time: Some(time),
        predicted_dt: 1.0 / 60.0,
        ..RawInput::default()
    };
    let mut converged = false;
    let output = ctx.run_ui(input, |ui| {
        GraphView::<RapierGraphState, RapierGraphLayout>::new()
            .with_interactions(&SettingsInteraction::new().with_dragging_enabled(false))
            .with_navigations(&SettingsNavigation::new().with_fit_to_screen_enabled(false))
            .show(ui, graph);
        converged = get_layout_state::<RapierGraphState>(ui, None).converged;
    });
    output.drop_without_applying_deltas();
    converged
}

/// Frames (5 ms apart: the worker follows real time) until the layout rests; panics
/// after 60 s.
fn settle(ctx: &Context, graph: &mut G, time: &mut f64) {
    let started = Instant::now();
    loop {
        *time += 1.0 / 60.0;
        if frame(ctx, graph, *time) {
            return;
        }
        assert!(
            started.elapsed() < Duration::from_secs(60),
            "not at rest in 60 s"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn a_large_graph_is_laid_out_on_the_worker_and_a_drag_pulls_its_neighbours() {
    // A ring of WORKER_FROM nodes, every node at the origin.
    let n = WORKER_FROM as u32;
    let edges: Vec<(u32, u32)> = (0..n).map(|i| (i, (i + 1) % n)).collect();
    let mut graph = G::from(&StableGraph::<(), (), Undirected>::from_edges(edges));
    let ctx = Context::default();
    let mut time = 0.0;
    settle(&ctx, &mut graph, &mut time);
    let at = |g: &G, i: u32| g.node(NodeIndex::new(i as usize)).unwrap().location();
    let spread = (at(&graph, n / 2) - at(&graph, 0)).length();
    assert!(
        spread > 1_000.0,
        "a ring of {n} laid out: opposite nodes {spread} apart"
    );
    // Node 0 dragged 300 units away for half a second of frames, then let go.
    let start = at(&graph, 0);
    let to = start + egui::vec2(300.0, 0.0);
    let before = (at(&graph, 1) - to).length();
    let far_before = at(&graph, n / 2);
    let node = NodeIndex::new(0);
    graph.node_mut(node).unwrap().set_dragged(true);
    for _ in 0..30 {
        graph.node_mut(node).unwrap().set_location(to);
        time += 1.0 / 60.0;
        frame(&ctx, &mut graph, time);
        assert_eq!(at(&graph, 0), to, "the dragged node left the pointer");
        std::thread::sleep(Duration::from_millis(16));
    }
    graph.node_mut(node).unwrap().set_dragged(false);
    settle(&ctx, &mut graph, &mut time);
    let after = (at(&graph, 1) - to).length();
    // Its neighbour is pulled after it (44 units of the 300 in one run); the far side
    // of the ring stays where it was.
    assert!(
        after < before - 20.0,
        "node 1 was {before} from where node 0 was dragged, now {after}"
    );
    let far = (at(&graph, n / 2) - far_before).length();
    assert!(far < 1.0, "the far side of the ring moved {far} units");
}
