//! Wide labels in a real `GraphView`: karate's members drawn as [`LabelBox`]es ("member
//! 12", 64 to 71 × 20 units), laid out from the origin to rest by the layout reading each
//! box from its display: no two boxes overlap.

use egui::{Context, Pos2, RawInput, Rect};
use egui_graphs::{get_layout_state, Graph, GraphView, SettingsNavigation};
use graph_canvas_layout_egui_graphs::{label_size, LabelBox, RapierGraphLayout, RapierGraphState};
use petgraph::stable_graph::{DefaultIx, NodeIndex, StableGraph};
use petgraph::Undirected;

/// Zachary's karate club, 34 members and 78 ties.
#[rustfmt::skip]
const KARATE: &[(u32, u32)] = &[
    (0, 1), (0, 2), (0, 3), (0, 4), (0, 5), (0, 6), (0, 7), (0, 8), (0, 10), (0, 11),
    (0, 12), (0, 13), (0, 17), (0, 19), (0, 21), (0, 31), (1, 2), (1, 3), (1, 7), (1, 13),
    (1, 17), (1, 19), (1, 21), (1, 30), (2, 3), (2, 7), (2, 8), (2, 9), (2, 13), (2, 27),
    (2, 28), (2, 32), (3, 7), (3, 12), (3, 13), (4, 6), (4, 10), (5, 6), (5, 10), (5, 16),
    (6, 16), (8, 30), (8, 32), (8, 33), (9, 33), (13, 33), (14, 32), (14, 33), (15, 32),
    (15, 33), (18, 32), (18, 33), (19, 33), (20, 32), (20, 33), (22, 32), (22, 33),
    (23, 25), (23, 27), (23, 29), (23, 32), (23, 33), (24, 25), (24, 27), (24, 31),
    (25, 31), (26, 29), (26, 33), (27, 33), (28, 31), (28, 33), (29, 32), (29, 33),
    (30, 32), (30, 33), (31, 32), (31, 33), (32, 33),
];

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
