//! What the flow example measures on a layout: how many edges point the flow's way and
//! by how much, how far the worst falls short, overlaps, crossings and stress.

use graph_canvas_layout::{quality, CanvasSceneInput};

/// One layout's figures.
pub struct Figures {
    /// Share of edges (exempt ones aside) whose target is at least `gap - 1` below its
    /// source.
    pub down: f64,
    /// The least `target.y - source.y`, exempt edges aside.
    pub least_drop: f32,
    /// Pairs of disks overlapping by more than half a unit.
    pub overlaps: usize,
    pub crossings: usize,
    pub stress: f64,
}

impl Figures {
    pub fn of(scene: &CanvasSceneInput<u32>, gap: f32, exempt: &[usize]) -> Self {
        let drops: Vec<f32> = drops(scene, exempt).collect();
        let down = drops.iter().filter(|&&d| d >= gap - 1.0).count();
        Self {
            down: down as f64 / drops.len().max(1) as f64,
            least_drop: drops.iter().copied().fold(f32::INFINITY, f32::min),
            overlaps: quality::overlapping_pairs(scene, 16.0, 0.5),
            crossings: quality::edge_crossings(scene),
            stress: quality::normalized_stress(scene).unwrap_or(f64::NAN),
        }
    }
}

/// `target.y - source.y` of each edge, exempt ones (ascending indices) left out. Node
/// ids are their indices in the scene (as in the shipped scene files).
pub fn drops<'a>(
    scene: &'a CanvasSceneInput<u32>,
    exempt: &'a [usize],
) -> impl Iterator<Item = f32> + 'a {
    let y = |id: u32| scene.nodes[id as usize].position.y;
    scene
        .edges
        .iter()
        .enumerate()
        .filter(|(i, _)| exempt.binary_search(i).is_err())
        .map(move |(_, e)| y(e.target) - y(e.source))
}

/// How far the worst edge falls short of `gap` (0 when every edge holds).
pub fn worst_shortfall(scene: &CanvasSceneInput<u32>, gap: f32, exempt: &[usize]) -> f32 {
    drops(scene, exempt).fold(0.0_f32, |worst, d| worst.max(gap - d))
}
