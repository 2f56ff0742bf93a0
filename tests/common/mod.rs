//! Shared helpers for the integration tests: a minimal host loop and scene loading.
#![allow(dead_code)]

use std::collections::HashMap;
use std::hash::Hash;

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::scene::{Cluster, SceneFile};
use graph_canvas_layout::{
    CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport, DeltaMap, Layout, LayoutError,
    LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState,
};

pub const FRAME: f32 = 1.0 / 60.0;

/// A host canvas: owns positions, calls `step` once per frame, adds the deltas.
pub struct Host<N: Clone + Eq + Hash> {
    pub scene: CanvasSceneInput<N>,
    pub layout: RapierLayout<N>,
    pub state: RapierLayoutState,
    pub extras: LayoutExtras<N>,
}

impl<N: Clone + Eq + Hash + std::fmt::Debug> Host<N> {
    pub fn new(scene: CanvasSceneInput<N>, config: RapierLayoutConfig) -> Self {
        Self {
            scene,
            layout: RapierLayout::new(config),
            state: RapierLayoutState::default(),
            extras: LayoutExtras::default(),
        }
    }

    /// One frame of `dt` seconds; returns the deltas after applying them.
    pub fn frame(&mut self, dt: f32) -> DeltaMap<N> {
        let deltas = self.layout.step(
            &self.scene,
            &mut self.state,
            dt,
            &CanvasViewport::default(),
            &self.extras,
        );
        self.scene.apply_deltas(&deltas);
        deltas
    }

    /// One frame of `dt` seconds through `try_step`: the deltas, applied, or the error
    /// that names the bad input (nothing applied).
    pub fn try_frame(&mut self, dt: f32) -> Result<DeltaMap<N>, LayoutError<N>> {
        let deltas = self.layout.try_step(
            &self.scene,
            &mut self.state,
            dt,
            &CanvasViewport::default(),
            &self.extras,
        )?;
        self.scene.apply_deltas(&deltas);
        Ok(deltas)
    }

    /// Runs frames until `is_converged`; returns how many it took. Panics, with the
    /// heat, when `budget` frames are not enough.
    pub fn settle(&mut self, budget: usize) -> usize {
        for frame in 1..=budget {
            self.frame(FRAME);
            if self.layout.is_converged(&self.state) {
                return frame;
            }
        }
        panic!(
            "not at rest after {budget} frames (heat {:?})",
            self.layout.heat()
        );
    }

    pub fn frames(&mut self, n: usize) {
        for _ in 0..n {
            self.frame(FRAME);
        }
    }

    pub fn pos(&self, id: &N) -> Point2D<f32> {
        self.scene
            .nodes
            .iter()
            .find(|n| &n.id == id)
            .unwrap_or_else(|| panic!("node {id:?} not in scene"))
            .position
    }

    pub fn set_pos(&mut self, id: &N, p: Point2D<f32>) {
        let node = self
            .scene
            .nodes
            .iter_mut()
            .find(|n| &n.id == id)
            .expect("node in scene");
        node.position = p;
    }

    pub fn world_pos(&self, id: &N) -> Point2D<f32> {
        self.layout
            .world()
            .and_then(|w| w.get_position(id))
            .unwrap_or_else(|| panic!("node {id:?} has no body"))
    }
}

pub fn node<N>(id: N, x: f32, y: f32) -> CanvasNode<N> {
    CanvasNode::new(id, Point2D::new(x, y))
}

pub fn edge<N>(a: N, b: N) -> CanvasEdge<N> {
    CanvasEdge::new(a, b)
}

/// Two clusters that cannot both hold, under `stress()`, not yet stepped: nodes 0 and 1
/// (cluster 0) pinned 200 apart hold its box across x 0..200, and node 2 of cluster 1
/// (nodes 2 and 3) is pinned inside that box.
pub fn clusters_held_overlapping() -> Host<u32> {
    let scene = CanvasSceneInput::new(
        vec![
            node(0, 0.0, 0.0),
            node(1, 200.0, 0.0),
            node(2, 100.0, 20.0),
            node(3, 100.0, 200.0),
        ],
        vec![edge(0, 1), edge(2, 3), edge(1, 2)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    host.extras.clusters = vec![Cluster::new(vec![0, 1]), Cluster::new(vec![2, 3])];
    host.extras.pinned.extend([0, 1, 2]);
    host
}

pub fn dist(a: Point2D<f32>, b: Point2D<f32>) -> f32 {
    (a - b).length()
}

pub fn speed(v: Vector2D<f32>) -> f32 {
    v.length()
}

/// Loads a scene from `scenes/<name>.json`.
pub fn load_scene(name: &str) -> CanvasSceneInput<u32> {
    let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let file: SceneFile = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    file.into_scene()
}

/// The farthest any node of `scene` is from where `before` (a [`positions`] snapshot)
/// had it.
pub fn farthest_moved<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    before: &HashMap<N, Point2D<f32>>,
) -> f32 {
    scene
        .nodes
        .iter()
        .map(|n| dist(n.position, before[&n.id]))
        .fold(0.0, f32::max)
}

pub fn positions<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> HashMap<N, Point2D<f32>> {
    scene
        .nodes
        .iter()
        .map(|n| (n.id.clone(), n.position))
        .collect()
}
/// The nodes of `scene` nearest to the centroid of its positions and farthest from it.
pub fn nearest_and_farthest_from_centroid(scene: &CanvasSceneInput<u32>) -> (u32, u32) {
    let n = scene.nodes.len() as f32;
    let centroid = scene.nodes.iter().fold(Point2D::origin(), |c, node| {
        c + node.position.to_vector() / n
    });
    let by_distance = |a: &&CanvasNode<u32>, b: &&CanvasNode<u32>| {
        dist(a.position, centroid).total_cmp(&dist(b.position, centroid))
    };
    let nearest = scene.nodes.iter().min_by(by_distance).expect("nodes");
    let farthest = scene.nodes.iter().max_by(by_distance).expect("nodes");
    (nearest.id, farthest.id)
}

pub mod damage;
pub mod session;
