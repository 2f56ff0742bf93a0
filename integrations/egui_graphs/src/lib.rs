//! [graph-canvas-layout](graph_canvas_layout) as an [egui_graphs] layout: one persistent
//! Rapier2D world behind a `GraphView`, so a thrown node keeps flying, pinned nodes hold,
//! an edit heats only its neighbourhood, and the layout says when it rests.
//!
//! # Quick start
//! ```no_run
//! use egui_graphs::{Graph, GraphView};
//! use graph_canvas_layout_egui_graphs::{RapierGraphLayout, RapierGraphState};
//!
//! fn show(ui: &mut egui::Ui, graph: &mut Graph) {
//!     GraphView::<RapierGraphState, RapierGraphLayout>::new().show(ui, graph);
//! }
//! ```
//! `examples/les_miserables.rs` shows Les Misérables in a window: `cargo run --release -p
//! graph-canvas-layout-egui-graphs --example les_miserables`.
//!
//! # How it fits egui_graphs
//! egui_graphs builds its layout from the state it keeps in egui's memory on every frame
//! ([`Layout::from_state`](egui_graphs::Layout::from_state), then
//! [`Layout::next`](egui_graphs::Layout::next), then the state is saved again). The world
//! cannot be rebuilt every frame, so [`RapierGraphState`] holds it behind a shared handle
//! that every copy of the state points to and that serde skips: the settings (running,
//! pins, the configuration) persist with egui's memory, the world lives as long as the
//! app does, and a restored app lays the graph out again from the saved positions.
//!
//! Every frame [`RapierGraphLayout`] passes the graph's nodes (their locations, by node
//! index, and their shapes as their displays draw them), its edges (weight 1), the nodes egui_graphs is dragging and the state's pins to
//! [`RapierLayout::step`](graph_canvas_layout::Layout::step) with egui's stable frame
//! time, and adds the deltas to the node locations. Releasing a dragged node throws it
//! with the pointer's speed. While the layout moves it asks egui for another frame.
//!
//! [`AnimatedState`] is implemented, so
//! [`GraphView::fast_forward_until_stable`](egui_graphs::GraphView::fast_forward_until_stable)
//! runs the layout ahead within one frame: at rest every delta is exactly zero, so an
//! `epsilon` of `f32::MIN_POSITIVE` runs it until the layout rests (a larger one may stop
//! in the cooling's tail, where nodes still creep).
//!
//! # Large graphs
//! A graph of [`WORKER_FROM`] nodes or more when the layout first sees it is laid out
//! on a [`LayoutWorker`](graph_canvas_layout::worker::LayoutWorker), on a thread of its own:
//! each frame sends what changed in the graph (nodes and edges added or removed, shapes,
//! drags, pins, the configuration, nodes the app moved) and takes the newest positions,
//! so egui's frame never waits for a step. The worker follows real time, so
//! [`GraphView::fast_forward_until_stable`](egui_graphs::GraphView::fast_forward_until_stable)
//! does not run such a layout ahead.
//!
//! # Node sizes and label boxes
//! Each node is laid out with the outline its display draws, read from
//! [`DisplayNode::closest_boundary_point`]: probed along the axes it gives a width and a
//! height, and along the diagonal it tells a disk from a box. egui_graphs' default node
//! is a disk of radius 5 with its label drawn outside it, where no layout can keep it
//! clear; [`LabelBox`] draws the label inside a box the layout keeps apart from the
//! others (`Graph<N, E, Ty, Ix, LabelBox>`). A display of your own works the same way,
//! as long as its boundary is a disk or a level box around its centre.
//!
//! # Groups and constraints
//! egui_graphs has no groups of its own: list them by node index in
//! [`RapierGraphState::clusters`] (and hard constraints in
//! [`RapierGraphState::constraints`]), set the state with `egui_graphs::set_layout_state`,
//! and draw [`RapierGraphState::cluster_bounds`] from the state `get_layout_state` returns
//! after the frame, through the view's graph-to-screen transform as nodes are drawn. Both
//! lists persist with the rest of the state; a changed list is an edit the layout takes
//! on the next frame, on the worker too.
//!
//! A `StableGraph` reuses a removed node's index for the next node added: when you
//! remove a node and add another in the same frame, call
//! [`RapierGraphState::forget_node`] so the new node does not take over the old body.

mod label_box;
mod outline;
mod worker;

pub use label_box::{label_size, LabelBox, BOX_HEIGHT, CHAR_WIDTH};
pub use worker::WORKER_FROM;

use std::collections::BTreeSet;
use std::sync::{Arc, Mutex, PoisonError};

use egui_graphs::{AnimatedState, DisplayEdge, DisplayNode, Graph, Layout, LayoutState};
use graph_canvas_layout::euclid::default::{Box2D, Point2D};
use graph_canvas_layout::{
    CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport, Cluster, Constraint, Layout as _,
    LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState,
};
use petgraph::stable_graph::{IndexType, NodeIndex};
use petgraph::EdgeType;
use serde::{Deserialize, Serialize};

/// The world and the buffers it is fed from, shared by every copy of the state.
struct World {
    layout: RapierLayout<usize>,
    state: RapierLayoutState,
    scene: CanvasSceneInput<usize>,
    extras: LayoutExtras<usize>,
    /// For graphs of [`WORKER_FROM`] nodes or more: the layout on a thread of its own.
    synced: Option<worker::Synced>,
}

/// A handle to the world: clones share it; serde skips it.
#[derive(Clone, Default)]
struct Handle(Arc<Mutex<Option<World>>>);

impl std::fmt::Debug for Handle {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let world = self.0.lock().unwrap_or_else(PoisonError::into_inner);
        f.debug_struct("Handle")
            .field("has_world", &world.is_some())
            .finish()
    }
}

/// The layout's state in egui's memory: what persists (whether it runs, the pins, the
/// configuration) and, behind a shared handle, the world.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(default)]
pub struct RapierGraphState {
    /// Whether frames step the layout. Default: `true`.
    pub is_running: bool,
    /// The layout's configuration; changes take effect on the next frame as
    /// [`RapierLayout::config`] changes do. Default: [`RapierLayoutConfig::stress`].
    pub config: RapierLayoutConfig,
    /// Pinned nodes, by node index: they hold where they are (and where the host or a
    /// drag puts them).
    pub pinned: BTreeSet<usize>,
    /// Groups of nodes, by node index, each kept in a box no other node enters
    /// ([`LayoutExtras::clusters`]): egui_graphs has no groups of its own, so the app
    /// lists them here and draws [`cluster_bounds`](Self::cluster_bounds). Default:
    /// none.
    pub clusters: Vec<Cluster<usize>>,
    /// Hard constraints on the nodes, by node index ([`LayoutExtras::constraints`]).
    /// Default: none.
    pub constraints: Vec<Constraint<usize>>,
    /// Each cluster's box after the last frame, in [`clusters`](Self::clusters)' order
    /// and in the graph's coordinates (those of the node locations).
    #[serde(skip)]
    pub cluster_bounds: Vec<Box2D<f32>>,
    /// Whether the layout was at rest after the last frame.
    pub converged: bool,
    /// The mean distance the graph's nodes moved in the last frame (0 at rest).
    #[serde(skip)]
    pub last_avg_displacement: Option<f32>,
    /// Frames stepped.
    pub step_count: u64,
    #[serde(skip)]
    world: Handle,
}

impl Default for RapierGraphState {
    fn default() -> Self {
        Self {
            is_running: true,
            config: RapierLayoutConfig::stress(),
            pinned: BTreeSet::new(),
            clusters: Vec::new(),
            constraints: Vec::new(),
            cluster_bounds: Vec::new(),
            converged: false,
            last_avg_displacement: None,
            step_count: 0,
            world: Handle::default(),
        }
    }
}

impl LayoutState for RapierGraphState {}

impl AnimatedState for RapierGraphState {
    fn is_running(&self) -> bool {
        self.is_running
    }
    fn set_running(&mut self, v: bool) {
        self.is_running = v;
    }
    fn last_avg_displacement(&self) -> Option<f32> {
        self.last_avg_displacement
    }
    fn set_last_avg_displacement(&mut self, v: Option<f32>) {
        self.last_avg_displacement = v;
    }
    fn step_count(&self) -> u64 {
        self.step_count
    }
    fn set_step_count(&mut self, v: u64) {
        self.step_count = v;
    }
}

impl RapierGraphState {
    /// A state with `config` instead of [`RapierLayoutConfig::stress`].
    pub fn with_config(config: RapierLayoutConfig) -> Self {
        Self {
            config,
            ..Self::default()
        }
    }

    /// Drops the body of the node at `index`, so a node added later under the same
    /// index starts afresh ([`RapierLayout::forget_node`]). Returns whether it had one.
    pub fn forget_node(&self, index: usize) -> bool {
        let mut world = self.world.0.lock().unwrap_or_else(PoisonError::into_inner);
        world
            .as_mut()
            .is_some_and(|world| match world.synced.as_mut() {
                Some(synced) => synced.forget(index),
                None => world.layout.forget_node(&index),
            })
    }

    /// Runs `f` on the layout, once it exists (after the first frame), for what the
    /// state does not show: [`RapierLayout::world`], [`RapierLayout::heat`],
    /// [`RapierLayout::reheat`].
    pub fn with_layout<T>(&self, f: impl FnOnce(&mut RapierLayout<usize>) -> T) -> Option<T> {
        let mut world = self.world.0.lock().unwrap_or_else(PoisonError::into_inner);
        world.as_mut().map(|world| f(&mut world.layout))
    }
}

/// The egui_graphs [`Layout`] that steps a [`RapierLayout`]; built from its
/// [`RapierGraphState`] every frame.
#[derive(Debug, Default)]
pub struct RapierGraphLayout {
    state: RapierGraphState,
}

impl Layout<RapierGraphState> for RapierGraphLayout {
    fn from_state(state: RapierGraphState) -> impl Layout<RapierGraphState> {
        Self { state }
    }

    fn next<N, E, Ty, Ix, Dn, De>(&mut self, g: &mut Graph<N, E, Ty, Ix, Dn, De>, ui: &egui::Ui)
    where
        N: Clone,
        E: Clone,
        Ty: EdgeType,
        Ix: IndexType,
        Dn: DisplayNode<N, E, Ty, Ix>,
        De: DisplayEdge<N, E, Ty, Ix, Dn>,
    {
        if !self.state.is_running || g.node_count() == 0 {
            return;
        }
        let dt = ui.input(|i| i.stable_dt);
        let state = &mut self.state;
        let mut guard = state.world.0.lock().unwrap_or_else(PoisonError::into_inner);
        let world = guard.get_or_insert_with(|| World {
            layout: RapierLayout::new(state.config.clone()),
            state: RapierLayoutState::default(),
            scene: CanvasSceneInput::default(),
            extras: LayoutExtras::default(),
            synced: None,
        });
        if world.layout.config != state.config {
            world.layout.config = state.config.clone();
        }
        read_graph(g, &mut world.scene, &mut world.extras);
        world.extras.pinned.clear();
        world.extras.pinned.extend(state.pinned.iter().copied());
        if world.extras.clusters != state.clusters {
            world.extras.clusters.clone_from(&state.clusters);
        }
        if world.extras.constraints != state.constraints {
            world.extras.constraints.clone_from(&state.constraints);
        }
        if world.synced.is_none()
            && !world.layout.has_world()
            && world.scene.nodes.len() >= WORKER_FROM
        {
            world.synced = Some(worker::Synced::spawn(
                &world.scene,
                &world.extras,
                state.config.clone(),
            ));
        }
        if let Some(synced) = world.synced.as_mut() {
            synced.send(&world.scene, &world.extras, &state.config);
            let (positions, converged) = synced.receive(&mut state.cluster_bounds);
            // A list changed since reaches the worker's frames a step later: one box per
            // listed cluster meanwhile (an added one empty, at the origin).
            let listed = state.clusters.len();
            state.cluster_bounds.resize(listed, Box2D::zero());
            let mut moved = 0.0_f32;
            for (index, p) in positions {
                if world.extras.dragging.contains(&index) {
                    continue;
                }
                if let Some(node) = g.g_mut().node_weight_mut(NodeIndex::new(index)) {
                    let at = egui::pos2(p.x, p.y);
                    moved += (at - node.location()).length();
                    node.set_location(at);
                    synced.told(index, at);
                }
            }
            state.converged = converged;
            state.last_avg_displacement = Some(moved / g.node_count() as f32);
            state.step_count += 1;
            if !converged {
                ui.ctx().request_repaint();
            }
            return;
        }
        let deltas = world.layout.step(
            &world.scene,
            &mut world.state,
            dt,
            &CanvasViewport::default(),
            &world.extras,
        );
        let mut moved = 0.0_f32;
        for (&index, delta) in &deltas {
            if let Some(node) = g.g_mut().node_weight_mut(NodeIndex::new(index)) {
                node.set_location(node.location() + egui::vec2(delta.x, delta.y));
                moved += delta.length();
            }
        }
        state.cluster_bounds.clear();
        state
            .cluster_bounds
            .extend_from_slice(world.layout.cluster_bounds());
        state.converged = world.layout.is_converged(&world.state);
        state.last_avg_displacement = Some(moved / g.node_count() as f32);
        state.step_count += 1;
        if !state.converged {
            ui.ctx().request_repaint();
        }
    }

    fn state(&self) -> RapierGraphState {
        self.state.clone()
    }
}

/// The graph as the layout reads it: nodes by index at their locations, shaped as their
/// displays draw them (`outline.rs`), edges between
/// node indices, and the nodes being dragged (by their own flag, which egui_graphs sets
/// as the pointer takes and drops a node).
fn read_graph<N, E, Ty, Ix, Dn, De>(
    g: &Graph<N, E, Ty, Ix, Dn, De>,
    scene: &mut CanvasSceneInput<usize>,
    extras: &mut LayoutExtras<usize>,
) where
    N: Clone,
    E: Clone,
    Ty: EdgeType,
    Ix: IndexType,
    Dn: DisplayNode<N, E, Ty, Ix>,
    De: DisplayEdge<N, E, Ty, Ix, Dn>,
{
    scene.nodes.clear();
    extras.dragging.clear();
    for (index, node) in g.nodes_iter() {
        let p = node.location();
        let canvas = CanvasNode::new(index.index(), Point2D::new(p.x, p.y));
        scene
            .nodes
            .push(outline::shaped::<N, E, Ty, Ix, Dn>(canvas, node.display()));
        if node.dragged() {
            extras.dragging.insert(index.index());
        }
    }
    scene.edges.clear();
    scene.edges.extend(g.edges_iter().filter_map(|(index, _)| {
        let (a, b) = g.g().edge_endpoints(index)?;
        Some(CanvasEdge::new(a.index(), b.index()))
    }));
}
