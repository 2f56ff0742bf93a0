//! Large graphs on a [`LayoutWorker`]: the layout steps on a thread of its own, and each
//! frame the egui_graphs layout sends what changed in the graph (nodes and edges added
//! or removed, shapes, drags, pins, the configuration, nodes the app moved) and reads
//! the newest positions back, so a 10,000-node graph never holds up egui's frame.

use std::collections::{BTreeSet, HashMap};

use egui::Pos2;
use graph_canvas_layout::euclid::default::{Box2D, Point2D};
use graph_canvas_layout::scene::topology_hash;
use graph_canvas_layout::worker::LayoutWorker;
use graph_canvas_layout::{
    CanvasEdge, CanvasSceneInput, LayoutExtras, NodeShape, RapierLayoutConfig,
};

/// Graphs of this many nodes or more, when the layout first sees them, are laid out on a
/// [`LayoutWorker`].
pub const WORKER_FROM: usize = 5_000;

/// The worker and what it was last told.
pub(crate) struct Synced {
    worker: LayoutWorker<usize>,
    /// Each node's radius and shape as sent.
    nodes: HashMap<usize, (f32, NodeShape)>,
    /// The edges as sent, and their hash.
    edges: Vec<(usize, usize)>,
    edges_hash: u64,
    config: RapierLayoutConfig,
    /// Where each node was put last frame, to tell a node the app moved.
    told: HashMap<usize, Pos2>,
}

impl Synced {
    pub(crate) fn spawn(
        scene: &CanvasSceneInput<usize>,
        extras: &LayoutExtras<usize>,
        config: RapierLayoutConfig,
    ) -> Self {
        let worker_extras = LayoutExtras {
            pinned: extras.pinned.clone(),
            constraints: extras.constraints.clone(),
            clusters: extras.clusters.clone(),
            ..LayoutExtras::default()
        };
        let worker = LayoutWorker::spawn_with(
            scene.clone(),
            config.clone(),
            worker_extras,
            std::time::Duration::from_secs_f64(1.0 / 60.0),
        );
        Self {
            worker,
            nodes: scene
                .nodes
                .iter()
                .map(|n| (n.id, (n.radius, n.shape)))
                .collect(),
            edges: scene
                .edges
                .iter()
                .map(ends)
                .collect::<BTreeSet<_>>()
                .into_iter()
                .collect(),
            edges_hash: edges_hash(scene),
            config,
            told: HashMap::new(),
        }
    }

    /// Sends what changed since the last frame: `scene` is the graph as read this frame
    /// (`location` of each node included), `extras` its drags, pins, constraints and
    /// clusters.
    pub(crate) fn send(
        &mut self,
        scene: &CanvasSceneInput<usize>,
        extras: &LayoutExtras<usize>,
        config: &RapierLayoutConfig,
    ) {
        if *config != self.config {
            self.worker.set_config(config.clone());
            self.config = config.clone();
        }
        self.send_nodes(scene);
        let hash = edges_hash(scene);
        if hash != self.edges_hash {
            self.send_edges(scene);
            self.edges_hash = hash;
        }
        self.worker.hold(scene, extras);
        for node in &scene.nodes {
            let at = Pos2::new(node.position.x, node.position.y);
            if extras.dragging.contains(&node.id) {
                // Where the pointer left it: no host move when it is let go.
                self.told.insert(node.id, at);
            } else if self.told.get(&node.id).is_some_and(|&told| told != at) {
                // Moved by the app since the layout put it there.
                self.worker.move_node(node.id, node.position);
            }
        }
    }

    /// The newest positions, by node index, and whether the layout rests; the clusters'
    /// boxes into `bounds`.
    pub(crate) fn receive(
        &mut self,
        bounds: &mut Vec<Box2D<f32>>,
    ) -> (Vec<(usize, Point2D<f32>)>, bool) {
        let frame = self.worker.frame();
        bounds.clear();
        bounds.extend_from_slice(&frame.cluster_bounds);
        let positions = frame
            .ids
            .iter()
            .zip(&frame.positions)
            .map(|(&id, &p)| (id, p))
            .collect();
        (positions, self.worker.is_converged())
    }

    /// Drops node `id` from the worker; the next frame adds whatever node then has the
    /// index, afresh.
    pub(crate) fn forget(&mut self, id: usize) -> bool {
        let known = self.nodes.remove(&id).is_some();
        if known {
            self.worker.remove_node(id);
            self.told.remove(&id);
        }
        known
    }

    /// Records where a node was put this frame.
    pub(crate) fn told(&mut self, id: usize, at: Pos2) {
        self.told.insert(id, at);
    }

    /// Nodes added, removed or reshaped.
    fn send_nodes(&mut self, scene: &CanvasSceneInput<usize>) {
        let mut seen = 0;
        for node in &scene.nodes {
            match self.nodes.get(&node.id) {
                None => {
                    self.worker.add_node(node.clone());
                    self.nodes.insert(node.id, (node.radius, node.shape));
                }
                Some(&(radius, shape)) => {
                    if radius.to_bits() != node.radius.to_bits() || shape != node.shape {
                        self.worker.reshape(node.id, node.radius, node.shape);
                        self.nodes.insert(node.id, (node.radius, node.shape));
                    }
                }
            }
            seen += 1;
        }
        if seen < self.nodes.len() {
            let now: BTreeSet<usize> = scene.nodes.iter().map(|n| n.id).collect();
            let gone: Vec<usize> = self
                .nodes
                .keys()
                .copied()
                .filter(|id| !now.contains(id))
                .collect();
            for id in gone {
                self.worker.remove_node(id);
                self.nodes.remove(&id);
                self.told.remove(&id);
            }
        }
    }

    /// Edges added or removed.
    fn send_edges(&mut self, scene: &CanvasSceneInput<usize>) {
        let now: BTreeSet<(usize, usize)> = scene.edges.iter().map(ends).collect();
        let before: BTreeSet<(usize, usize)> = self.edges.iter().copied().collect();
        for &(a, b) in before.difference(&now) {
            self.worker.remove_edge(a, b);
        }
        for &(a, b) in now.difference(&before) {
            self.worker.add_edge(CanvasEdge::new(a, b));
        }
        self.edges = now.into_iter().collect();
    }
}

/// An edge's ends, the smaller first.
fn ends(edge: &CanvasEdge<usize>) -> (usize, usize) {
    (edge.source.min(edge.target), edge.source.max(edge.target))
}

/// An order-free hash of the scene's node set and edge set.
fn edges_hash(scene: &CanvasSceneInput<usize>) -> u64 {
    topology_hash(scene, &LayoutExtras::default())
}
