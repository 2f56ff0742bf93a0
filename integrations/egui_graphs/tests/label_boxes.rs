//! Wide labels in a real `GraphView`: karate's members drawn as [`LabelBox`]es ("member
//! 12", 64 to 71 × 20 units), laid out from the origin to rest by the layout reading each
//! box from its display: no two boxes overlap.

use egui::{Context, Pos2, RawInput, Rect};
use egui_graphs::{get_layout_state, Graph, GraphView, SettingsNavigation};
use graph_canvas_layout_egui_graphs::{label_size, LabelBox, RapierGraphLayout, RapierGraphState};
use petgraph::stable_graph::{DefaultIx, NodeIndex, StableGraph};
use petgraph::Undirected;

mod common;

use common::KARATE;

type Boxes = Graph<(), (), Undirected, DefaultIx, LabelBox>;

/// Frames of a headless egui context showing `graph` until the layout rests (at most
/// `max`); returns how many it took.
fn settle(graph: &mut Boxes, max: u32) -> Option<u32> {
    let ctx = Context::default();
    (1..=max).find(|&frame| {
        let input = RawInput {
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, egui::vec2(800.0, 600.0))),
            time: Some(f64::from(frame) / 60.0),
            predicted_dt: 1.0 / 60.0,
            ..RawInput::default()
        };
        let mut converged = false;
        let output = ctx.run_ui(input, |ui| {
            GraphView::<RapierGraphState, RapierGraphLayout>::new()
                .with_navigations(&SettingsNavigation::new().with_fit_to_screen_enabled(false))
                .show(ui, graph);
            converged = get_layout_state::<RapierGraphState>(ui, None).converged;
        });
        output.drop_without_applying_deltas();
        converged
    })
}

#[test]
fn wide_label_boxes_rest_without_overlapping() {
    let edges: Vec<(u32, u32)> = KARATE.to_vec();
    let mut graph = Boxes::from(&StableGraph::<(), (), Undirected>::from_edges(edges));
    for i in 0..34 {
        let node = graph.node_mut(NodeIndex::new(i)).expect("a member");
        node.set_label(format!("member {i}"));
    }
    let frames = settle(&mut graph, 600).expect("karate's label boxes rest within 600 frames");
    let boxes: Vec<(usize, Rect)> = graph
        .nodes_iter()
        .map(|(i, n)| {
            (
                i.index(),
                Rect::from_center_size(n.location(), label_size(&n.label())),
            )
        })
        .collect();
    // A pair overlaps when each is more than 1 unit inside the other on both axes (the
    // soft contacts hold a pressed pair a fraction of a unit inside).
    let mut overlapping = Vec::new();
    for (k, &(a, ra)) in boxes.iter().enumerate() {
        for &(b, rb) in &boxes[k + 1..] {
            let inside = ra.intersect(rb);
            if inside.width() > 1.0 && inside.height() > 1.0 {
                overlapping.push((a, b, inside.width(), inside.height()));
            }
        }
    }
    assert!(
        overlapping.is_empty(),
        "at rest after {frames} frames, {} pairs of label boxes overlap, first {:?} (width x height inside each other)",
        overlapping.len(),
        overlapping.first()
    );
}
