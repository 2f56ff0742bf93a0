//! The layout inside a real `GraphView`, frame by frame on a headless egui context: a
//! graph straight from a `StableGraph` (every node at the origin) lays out to rest, a
//! pinned node holds, and a node dragged and let go flies on.

use egui::{Context, Pos2, RawInput, Rect};
use egui_graphs::{
    get_layout_state, set_layout_state, DefaultNodeShape, DisplayNode, Graph, GraphView,
    SettingsInteraction, SettingsNavigation,
};
use graph_canvas_layout_egui_graphs::{RapierGraphLayout, RapierGraphState};
use petgraph::stable_graph::{DefaultIx, NodeIndex, StableGraph};
use petgraph::Undirected;

mod common;

use common::KARATE;

/// A graph whose nodes `D` draws.
type G<D = DefaultNodeShape> = Graph<(), (), Undirected, DefaultIx, D>;

fn karate<D: DisplayNode<(), (), Undirected, DefaultIx>>() -> G<D> {
    let edges: Vec<(u32, u32)> = KARATE.to_vec();
    G::from(&StableGraph::<(), (), Undirected>::from_edges(edges))
}

/// One egui context showing one graph view; the host's hand on the graph goes through
/// `hand` between frames, as egui_graphs' own drag handling would.
struct Window<D: DisplayNode<(), (), Undirected, DefaultIx> = DefaultNodeShape> {
    ctx: Context,
    graph: G<D>,
    time: f64,
}

const FRAME: f32 = 1.0 / 60.0;

impl<D: DisplayNode<(), (), Undirected, DefaultIx>> Window<D> {
    fn new(graph: G<D>) -> Self {
        Self {
            ctx: Context::default(),
            graph,
            time: 0.0,
        }
    }

    fn frame(&mut self, before: impl FnOnce(&mut egui::Ui)) -> RapierGraphState {
        self.time += f64::from(FRAME);
        let input = RawInput {
            screen_rect: Some(Rect::from_min_size(Pos2::ZERO, egui::vec2(800.0, 600.0))),
            time: Some(self.time),
            predicted_dt: FRAME,
            ..RawInput::default()
        };
        let graph = &mut self.graph;
        let mut before = Some(before);
        let mut state = None;
        let output = self.ctx.run_ui(input, |ui| {
            if let Some(before) = before.take() {
                before(ui);
            }
            // egui_graphs' own drag handling is off: the test moves the node as the
            // pointer would.
            GraphView::<RapierGraphState, RapierGraphLayout>::new()
                .with_interactions(&SettingsInteraction::new().with_dragging_enabled(false))
                .with_navigations(&SettingsNavigation::new().with_fit_to_screen_enabled(false))
                .show(ui, graph);
            state = Some(get_layout_state::<RapierGraphState>(ui, None));
        });
        // Nothing is painted: the font atlas egui uploads on its first frame is dropped.
        output.drop_without_applying_deltas();
        state.expect("the frame ran")
    }

    /// Frames until the layout rests (at most `max`); returns how many it took.
    fn settle(&mut self, max: u32) -> Option<u32> {
        (1..=max).find(|_| self.frame(|_| ()).converged)
    }

    fn location(&self, i: u32) -> Pos2 {
        self.graph
            .node(NodeIndex::new(i as usize))
            .unwrap()
            .location()
    }
}

#[test]
fn a_graph_with_every_node_at_the_origin_lays_out_to_rest() {
    let mut window = Window::<DefaultNodeShape>::new(karate());
    assert!(window
        .graph
        .nodes_iter()
        .all(|(_, n)| n.location() == Pos2::ZERO));
    // stress() rests within its 2 s schedule (86 frames in one run); 300 frames is
    // d3-force's whole schedule.
    let frames = window.settle(300);
    assert!(frames.is_some(), "karate did not rest within 300 frames");
    let positions: Vec<Pos2> = (0..34).map(|i| window.location(i)).collect();
    assert!(positions.iter().all(|p| p.x.is_finite() && p.y.is_finite()));
    // egui_graphs' default disks (radius 5, read from their display) end apart; the
    // layout's last projection leaves overlaps under a unit, so 9 units between centres
    // is a generous floor.
    let mut closest = f32::INFINITY;
    for (i, a) in positions.iter().enumerate() {
        for b in &positions[i + 1..] {
            closest = closest.min(a.distance(*b));
        }
    }
    assert!(
        closest > 9.0,
        "after {frames:?} frames two nodes are {closest} units apart"
    );
    let spread = positions
        .iter()
        .map(|p| p.to_vec2().length())
        .fold(0.0, f32::max);
    assert!(
        spread > 100.0,
        "the graph stayed in a blob: farthest node {spread} units from the origin"
    );
}

#[test]
fn a_pinned_node_holds_where_it_is() {
    let mut window = Window::<DefaultNodeShape>::new(karate());
    window
        .graph
        .node_mut(NodeIndex::new(0))
        .unwrap()
        .set_location(Pos2::new(-250.0, 40.0));
    window.frame(|ui| {
        let mut state = RapierGraphState::default();
        state.pinned.insert(0);
        set_layout_state(ui, state, None);
    });
    window
        .settle(1_200)
        .expect("karate rests with node 0 pinned");
    assert_eq!(
        window.location(0),
        Pos2::new(-250.0, 40.0),
        "the pinned node moved"
    );
    let far = (1..34).map(|i| window.location(i).distance(Pos2::new(-250.0, 40.0)));
    assert!(
        far.fold(0.0, f32::max) > 100.0,
        "the others piled onto the pin"
    );
}

#[test]
fn a_node_let_go_mid_drag_flies_on() {
    let mut window = Window::<DefaultNodeShape>::new(karate());
    window.settle(1_200).expect("karate rests");
    // Node 16 is a leaf of the club's edge; drag it away from the centre at 600 units/s.
    let centre = (0..34).fold(egui::Vec2::ZERO, |s, i| s + window.location(i).to_vec2()) / 34.0;
    let start = window.location(16);
    let out = (start.to_vec2() - centre).normalized();
    let node = NodeIndex::new(16);
    window.graph.node_mut(node).unwrap().set_dragged(true);
    for k in 1..=10 {
        let at = start + out * (10.0 * k as f32);
        window.graph.node_mut(node).unwrap().set_location(at);
        let state = window.frame(|_| ());
        assert!(!state.converged, "a drag in progress counts as motion");
    }
    let released = window.location(16);
    window.graph.node_mut(node).unwrap().set_dragged(false);
    for _ in 0..15 {
        window.frame(|_| ());
    }
    let beyond = (window.location(16) - released).dot(out);
    assert!(
        beyond > 20.0,
        "let go at 600 units/s, it went {beyond} units on in 0.25 s"
    );
    assert!(
        window.settle(1_200).is_some(),
        "the layout did not rest again after the throw"
    );
}

#[test]
fn fast_forward_until_stable_lays_the_graph_out_in_one_frame() {
    // At rest every delta is exactly zero, so the smallest positive epsilon runs the
    // layout until nothing moves (a larger one may stop in the cooling's tail).
    let mut window = Window::<DefaultNodeShape>::new(karate());
    let mut result = None;
    let state = window.frame(|_| ());
    assert!(!state.converged, "one frame does not lay karate out");
    let graph = &mut window.graph;
    let output = window.ctx.run_ui(RawInput::default(), |ui| {
        result = Some(
            GraphView::<RapierGraphState, RapierGraphLayout>::fast_forward_until_stable(
                ui,
                graph,
                f32::MIN_POSITIVE,
                2_000,
                None,
            ),
        );
    });
    output.drop_without_applying_deltas();
    let (steps, displacement) = result.expect("the frame ran");
    assert!(
        steps < 2_000 && displacement == 0.0,
        "fast forward ran {steps} steps, last mean displacement {displacement}"
    );
    // Laid out: every body asleep, nothing moves again, and within the rest time (half a
    // second) the layout says so.
    let before = window.location(0);
    let frames = window.settle(30).expect("at rest within half a second");
    assert_eq!(
        window.location(0),
        before,
        "a node moved after {frames} frames"
    );
}

/// Groups through the state: karate's two factions listed as clusters rest in boxes
/// that hold their members and keep the other faction out, and the state hands the
/// boxes back for the app to draw.
#[test]
fn clusters_in_the_state_keep_the_factions_in_boxes_of_their_own() {
    use graph_canvas_layout::quality::cluster_violations;
    use graph_canvas_layout::{CanvasNode, CanvasSceneInput, Cluster};
    // Zachary's split: the members who followed the instructor (node 0).
    const INSTRUCTOR: [usize; 17] = [0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 16, 17, 19, 21];
    let clusters = vec![
        Cluster::new(INSTRUCTOR.to_vec()),
        Cluster::new((0..34).filter(|i| !INSTRUCTOR.contains(i)).collect()),
    ];
    let mut window = Window::<DefaultNodeShape>::new(karate());
    let listed = clusters.clone();
    window.frame(move |ui| {
        let mut state = RapierGraphState::default();
        state.clusters = listed;
        set_layout_state(ui, state, None);
    });
    let frames = window
        .settle(1_200)
        .expect("karate rests with its clusters");
    let state = window.frame(|_| ());
    assert_eq!(state.cluster_bounds.len(), 2, "one box per cluster");
    let scene = CanvasSceneInput::new(
        (0..34)
            .map(|i| {
                let p = window.location(i);
                CanvasNode::new(
                    i as usize,
                    graph_canvas_layout::euclid::default::Point2D::new(p.x, p.y),
                )
                .with_radius(5.0)
            })
            .collect(),
        Vec::new(),
    );
    let v = cluster_violations(&scene, &clusters, &state.cluster_bounds, 5.0, 1.0);
    assert!(v.is_empty(), "at rest after {frames} frames: {v:?}");
}
