//! What the examples share: the shipped scenes, a host that owns its positions and
//! calls `step` once per frame, and SVG pictures (`svg.rs`).
#![allow(dead_code)]

pub mod communities;
pub mod svg;

use std::hash::Hasher;

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, DeltaMap, Layout, LayoutExtras, RapierLayout,
    RapierLayoutConfig, RapierLayoutState,
};

#[path = "../../benches/common/generate.rs"]
pub mod generate;

/// Loads `scenes/<name>.json`, or generates the scene a generator's name stands for
/// (`ba_n10000_m2`, `random_n100000_e250000`: `generate::by_name`).
pub fn load(name: &str) -> CanvasSceneInput<u32> {
    if let Some(scene) = generate::by_name(name) {
        return scene;
    }
    let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str::<SceneFile>(&text)
        .unwrap_or_else(|e| panic!("{path}: {e}"))
        .into_scene()
}

/// Each edge's ends as indices into `scene.nodes` (the first node of an id), in edge
/// order; an edge naming a node the scene lacks is left out.
pub fn edge_ends(scene: &CanvasSceneInput<u32>) -> Vec<(usize, usize)> {
    let mut index = std::collections::HashMap::new();
    for (i, n) in scene.nodes.iter().enumerate() {
        index.entry(n.id).or_insert(i);
    }
    let at = |id: &u32| index.get(id).copied();
    let ends = scene.edges.iter().map(|e| at(&e.source).zip(at(&e.target)));
    ends.flatten().collect()
}

/// FNV-1a over 64 bits: stable across builds and platforms.
pub struct Fnv(pub u64);

impl Hasher for Fnv {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 ^= u64::from(*b);
            self.0 = self.0.wrapping_mul(0x100_0000_01b3);
        }
    }
}

impl Fnv {
    pub fn new() -> Self {
        Self(0xcbf2_9ce4_8422_2325)
    }
    pub fn f32(&mut self, x: f32) {
        self.write_u32(x.to_bits());
    }
}

/// The `q` quantile (0 to 1) of `sorted`, the nearest rank; 0 for no values.
pub fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

/// A run to rest ([`Host::settle_timed`]): frames, wall time and the step's p95 (ms).
pub struct Timed {
    pub frames: usize,
    pub wall_ms: f64,
    pub p95_ms: f64,
}

/// A host canvas: its scene (positions included), the layout and what it passes in.
pub struct Host {
    pub scene: CanvasSceneInput<u32>,
    pub layout: RapierLayout<u32>,
    pub state: RapierLayoutState,
    pub extras: LayoutExtras<u32>,
}

impl Host {
    pub fn new(scene: CanvasSceneInput<u32>, config: RapierLayoutConfig) -> Self {
        Self {
            scene,
            layout: RapierLayout::new(config),
            state: RapierLayoutState::default(),
            extras: LayoutExtras::default(),
        }
    }

    /// One frame of `dt` seconds, its deltas applied; returns them.
    pub fn frame(&mut self, dt: f32) -> DeltaMap<u32> {
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

    /// Frames of `dt` until `is_converged`, at most `budget`; returns how many ran.
    pub fn settle(&mut self, dt: f32, budget: usize) -> usize {
        for frame in 1..=budget {
            self.frame(dt);
            if self.layout.is_converged(&self.state) {
                return frame;
            }
        }
        budget
    }

    /// Frames of `dt` until `is_converged`, at most `budget`, each timed; `after` sees
    /// the host after every frame. Returns the frames, the wall time and the step's p95.
    pub fn settle_timed(&mut self, dt: f32, budget: usize, mut after: impl FnMut(&Host)) -> Timed {
        let started = std::time::Instant::now();
        let mut steps = Vec::new();
        while steps.len() < budget {
            let step = std::time::Instant::now();
            self.frame(dt);
            steps.push(step.elapsed().as_secs_f64() * 1e3);
            after(self);
            if self.layout.is_converged(&self.state) {
                break;
            }
        }
        let wall_ms = started.elapsed().as_secs_f64() * 1e3;
        steps.sort_by(f64::total_cmp);
        Timed {
            frames: steps.len(),
            wall_ms,
            p95_ms: percentile(&steps, 0.95),
        }
    }

    /// Where the scene has node `id`.
    pub fn pos(&self, id: u32) -> Point2D<f32> {
        self.scene
            .nodes
            .iter()
            .find(|n| n.id == id)
            .unwrap_or_else(|| panic!("node {id} not in the scene"))
            .position
    }

    /// Moves node `id` in the scene (a host edit).
    pub fn set_pos(&mut self, id: u32, p: Point2D<f32>) {
        if let Some(n) = self.scene.nodes.iter_mut().find(|n| n.id == id) {
            n.position = p;
        }
    }

    /// The mean of the scene's positions.
    pub fn centre(&self) -> Point2D<f32> {
        let nodes = &self.scene.nodes;
        let sum = nodes
            .iter()
            .fold(Vector2D::zero(), |s, n| s + n.position.to_vector());
        (sum / nodes.len().max(1) as f32).to_point()
    }

    /// The leaf (a node of one edge) farthest from [`centre`](Self::centre), if any.
    pub fn outermost_leaf(&self) -> Option<u32> {
        let centre = self.centre();
        let edges = &self.scene.edges;
        let degree = |id: u32| {
            edges
                .iter()
                .filter(|e| e.source == id || e.target == id)
                .count()
        };
        self.scene
            .nodes
            .iter()
            .filter(|n| degree(n.id) == 1)
            .max_by(|a, b| {
                (a.position - centre)
                    .length()
                    .total_cmp(&(b.position - centre).length())
            })
            .map(|n| n.id)
    }
}
