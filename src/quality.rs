//! Layout quality measures: edge-length spread, overlapping nodes, edge crossings.
//! Used by the quality example and tests; handy for hosts comparing layouts.

use std::collections::HashMap;
use std::hash::Hash;

use euclid::default::Point2D;

use crate::input::scene::CanvasSceneInput;
use crate::layout::IdHasher;

/// The edges as segments (self-loops and edges naming missing nodes left out).
fn segments<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
) -> Vec<(usize, usize, Point2D<f32>, Point2D<f32>)> {
    let index: HashMap<&N, usize, IdHasher> = scene
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| (&n.id, i))
        .collect();
    scene
        .edges
        .iter()
        .filter_map(|e| {
            let (a, b) = (*index.get(&e.source)?, *index.get(&e.target)?);
            (a != b).then(|| (a, b, scene.nodes[a].position, scene.nodes[b].position))
        })
        .collect()
}

/// Coefficient of variation (standard deviation / mean) of the edge lengths; 0 when
/// every edge has the same length. `None` without edges.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, quality, CanvasEdge, CanvasNode, CanvasSceneInput};
/// let scene = CanvasSceneInput::new(
///     vec![CanvasNode::new(0, Point2D::new(0.0, 0.0)), CanvasNode::new(1, Point2D::new(100.0, 0.0)),
///          CanvasNode::new(2, Point2D::new(100.0, 100.0))],
///     vec![CanvasEdge::new(0, 1), CanvasEdge::new(1, 2)],
/// );
/// assert_eq!(quality::edge_length_cv(&scene), Some(0.0));
/// ```
pub fn edge_length_cv<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> Option<f32> {
    let lengths: Vec<f64> = segments(scene)
        .iter()
        .map(|(_, _, a, b)| f64::from((*a - *b).length()))
        .collect();
    if lengths.is_empty() {
        return None;
    }
    let n = lengths.len() as f64;
    let mean = lengths.iter().sum::<f64>() / n;
    let var = lengths.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / n;
    Some(if mean > 0.0 {
        (var.sqrt() / mean) as f32
    } else {
        0.0
    })
}

/// Mean edge length; `None` without edges.
pub fn mean_edge_length<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> Option<f32> {
    let segs = segments(scene);
    (!segs.is_empty()).then(|| {
        segs.iter()
            .map(|(_, _, a, b)| (*a - *b).length())
            .sum::<f32>()
            / segs.len() as f32
    })
}

/// Pairs of nodes whose disks overlap by more than `tolerance` world units (radius 0
/// counts as `default_radius`). Grid-bucketed: about O(n) for spread-out layouts.
pub fn overlapping_pairs<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    default_radius: f32,
    tolerance: f32,
) -> usize {
    let radius = |r: f32| if r > 0.0 { r } else { default_radius };
    let max_r = scene
        .nodes
        .iter()
        .map(|n| radius(n.radius))
        .fold(0.0_f32, f32::max);
    let cell = (2.0 * max_r).max(1.0);
    let key = |p: Point2D<f32>| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<usize>, IdHasher> = HashMap::default();
    for (i, n) in scene.nodes.iter().enumerate() {
        grid.entry(key(n.position)).or_default().push(i);
    }
    let mut count = 0;
    for (i, n) in scene.nodes.iter().enumerate() {
        let (kx, ky) = key(n.position);
        for dx in -1..=1 {
            for dy in -1..=1 {
                let Some(bucket) = grid.get(&(kx + dx, ky + dy)) else {
                    continue;
                };
                for &j in bucket.iter().filter(|&&j| j > i) {
                    let m = &scene.nodes[j];
                    let gap =
                        (n.position - m.position).length() - radius(n.radius) - radius(m.radius);
                    if gap < -tolerance {
                        count += 1;
                    }
                }
            }
        }
    }
    count
}

/// Pairs of edges that cross (edges sharing an endpoint never count). O(e²).
pub fn edge_crossings<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> usize {
    fn orient(a: Point2D<f32>, b: Point2D<f32>, c: Point2D<f32>) -> f64 {
        (f64::from(b.x) - f64::from(a.x)) * (f64::from(c.y) - f64::from(a.y))
            - (f64::from(b.y) - f64::from(a.y)) * (f64::from(c.x) - f64::from(a.x))
    }
    let segs = segments(scene);
    let mut count = 0;
    for (k, &(a1, b1, p1, q1)) in segs.iter().enumerate() {
        for &(a2, b2, p2, q2) in &segs[k + 1..] {
            if a1 == a2 || a1 == b2 || b1 == a2 || b1 == b2 {
                continue;
            }
            let (d1, d2) = (orient(p1, q1, p2), orient(p1, q1, q2));
            let (d3, d4) = (orient(p2, q2, p1), orient(p2, q2, q1));
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                count += 1;
            }
        }
    }
    count
}
