//! What steps the demo's layout: a `RapierLayout` on the UI thread for small graphs, a
//! `LayoutWorker` (the layout on a thread of its own) for large ones, so a 10,000-node
//! graph never holds up a frame. The demo's scene stays the source of what the graph
//! is; with the worker, its edits go over as messages and the positions come back.

use std::sync::Arc;
use std::time::Instant;

use graph_canvas_layout::euclid::default::Box2D;
use graph_canvas_layout::worker::LayoutWorker;
use graph_canvas_layout::{
    CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport, Layout, LayoutExtras, RapierLayout,
    RapierLayoutConfig, RapierLayoutState,
};

/// Graphs of this many nodes or more are laid out on the worker.
pub const WORKER_FROM: usize = 5_000;

/// The layout behind the demo.
pub enum Engine {
    /// Stepped on the UI thread, once a frame.
    Direct {
        layout: Box<RapierLayout<u32>>,
        state: RapierLayoutState,
    },
    /// Stepped on its own thread; the UI reads its newest positions.
    Worker {
        worker: Box<LayoutWorker<u32>>,
        config: Box<RapierLayoutConfig>,
        /// The cluster boxes of the newest frame read.
        bounds: Arc<Vec<Box2D<f32>>>,
    },
}

impl Engine {
    /// The layout for `scene`: on the worker with `worker`.
    pub fn new(scene: &CanvasSceneInput<u32>, config: RapierLayoutConfig, worker: bool) -> Self {
        if worker {
            Engine::Worker {
                worker: Box::new(LayoutWorker::spawn(scene.clone(), config.clone())),
                config: Box::new(config),
                bounds: Arc::default(),
            }
        } else {
            Engine::Direct {
                layout: Box::new(RapierLayout::new(config)),
                state: RapierLayoutState::default(),
            }
        }
    }

    /// Each cluster's box after the last frame (the worker's newest frame).
    pub fn cluster_bounds(&self) -> &[Box2D<f32>] {
        match self {
            Engine::Direct { layout, .. } => layout.cluster_bounds(),
            Engine::Worker { bounds, .. } => bounds,
        }
    }

    /// Whether the layout runs on the worker.
    pub fn on_worker(&self) -> bool {
        matches!(self, Engine::Worker { .. })
    }

    pub fn config(&self) -> &RapierLayoutConfig {
        match self {
            Engine::Direct { layout, .. } => &layout.config,
            Engine::Worker { config, .. } => config,
        }
    }

    pub fn set_config(&mut self, new: RapierLayoutConfig) {
        match self {
            Engine::Direct { layout, .. } => layout.config = new,
            Engine::Worker { worker, config, .. } => {
                worker.set_config(new.clone());
                **config = new;
            }
        }
    }

    pub fn is_converged(&self) -> bool {
        match self {
            Engine::Direct { layout, state } => layout.is_converged(state),
            Engine::Worker { worker, .. } => worker.is_converged(),
        }
    }

    /// Rebuilds and patches of the world (not shown by the worker).
    pub fn counts(&self) -> Option<(u64, u64)> {
        match self {
            Engine::Direct { layout, .. } => Some((layout.rebuild_count(), layout.patch_count())),
            Engine::Worker { .. } => None,
        }
    }

    /// One frame of `dt` seconds: the scene's positions moved on (the dragged nodes
    /// stay where the demo put them). Returns the step's time in microseconds, when a
    /// step ran (the worker's steps since the last frame, on average).
    pub fn frame(
        &mut self,
        scene: &mut CanvasSceneInput<u32>,
        extras: &LayoutExtras<u32>,
        dt: f32,
    ) -> Option<f32> {
        match self {
            Engine::Direct { layout, state } => {
                let started = Instant::now();
                let deltas = layout.step(scene, state, dt, &CanvasViewport::default(), extras);
                let took = started.elapsed().as_secs_f32() * 1e6;
                scene.apply_deltas(&deltas);
                Some(took)
            }
            Engine::Worker { worker, bounds, .. } => {
                worker.hold(scene, extras);
                let frame = worker.frame();
                *bounds = Arc::clone(&frame.cluster_bounds);
                for node in &mut scene.nodes {
                    if extras.dragging.contains(&node.id) {
                        continue;
                    }
                    if let Some(&i) = frame.index.get(&node.id) {
                        node.position = frame.positions[i];
                    }
                }
                let times = &frame.step_times;
                (!times.is_empty()).then(|| {
                    times.iter().map(|t| t.as_secs_f32()).sum::<f32>() * 1e6 / times.len() as f32
                })
            }
        }
    }

    /// A node added to the scene (the direct layout reads it from the scene).
    pub fn add_node(&mut self, node: &CanvasNode<u32>) {
        if let Engine::Worker { worker, .. } = self {
            worker.add_node(node.clone());
        }
    }

    pub fn remove_node(&mut self, id: u32) {
        if let Engine::Worker { worker, .. } = self {
            worker.remove_node(id);
        }
    }

    pub fn add_edge(&mut self, a: u32, b: u32) {
        if let Engine::Worker { worker, .. } = self {
            worker.add_edge(CanvasEdge::new(a, b));
        }
    }

    pub fn remove_edge(&mut self, a: u32, b: u32) {
        if let Engine::Worker { worker, .. } = self {
            worker.remove_edge(a, b);
        }
    }

    /// A node's radius or shape changed in the scene.
    pub fn reshape(&mut self, node: &CanvasNode<u32>) {
        if let Engine::Worker { worker, .. } = self {
            worker.reshape(node.id, node.radius, node.shape);
        }
    }
}

#[cfg(test)]
mod tests {
    use std::time::{Duration, Instant};

    use graph_canvas_layout::euclid::default::Point2D;

    use super::*;

    /// Frames until the layout rests; panics after 60 s (the worker follows real time).
    fn rest(engine: &mut Engine, scene: &mut CanvasSceneInput<u32>, extras: &LayoutExtras<u32>) {
        let started = Instant::now();
        while !engine.is_converged() {
            engine.frame(scene, extras, 1.0 / 60.0);
            assert!(
                started.elapsed() < Duration::from_secs(60),
                "not at rest in 60 s"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        engine.frame(scene, extras, 1.0 / 60.0);
    }

    /// A ring laid out on the worker: the demo's scene gets the positions, a node it
    /// drags stays under the pointer, and its neighbour follows it.
    #[test]
    fn the_worker_lays_out_the_scene_and_a_drag_pulls_the_neighbours() {
        let n = 30;
        let mut scene = CanvasSceneInput::new(
            (0..n)
                .map(|i| CanvasNode::new(i, Point2D::origin()))
                .collect(),
            (0..n).map(|i| CanvasEdge::new(i, (i + 1) % n)).collect(),
        );
        let mut extras = LayoutExtras::default();
        let mut engine = Engine::new(&scene, RapierLayoutConfig::stress(), true);
        rest(&mut engine, &mut scene, &extras);
        assert!(
            scene.nodes.iter().all(|a| a.position.is_finite())
                && scene.nodes[1].position != scene.nodes[2].position,
            "laid out: {:?}",
            &scene.nodes[..3]
        );
        let far = Point2D::new(2_000.0, 0.0);
        let before = (scene.nodes[1].position - far).length();
        extras.dragging.insert(0);
        for _ in 0..60 {
            scene.nodes[0].position = far;
            engine.frame(&mut scene, &extras, 1.0 / 60.0);
            assert_eq!(
                scene.nodes[0].position, far,
                "the dragged node left the pointer"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        extras.dragging.clear();
        rest(&mut engine, &mut scene, &extras);
        let after = (scene.nodes[1].position - far).length();
        assert!(
            after < before - 500.0,
            "node 1 was {before} from where node 0 was dragged, now {after}"
        );
    }
}
