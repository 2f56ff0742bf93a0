//! Layout quality measures: normalised stress, edge-length spread, overlapping nodes, edge crossings, and
//! how far a disturbance reached (displacement by hop distance). Used by the quality and
//! feel examples and the tests; handy for hosts comparing layouts.

mod clusters;

use std::collections::HashMap;
use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use crate::contacts::shapes::gap;
use crate::graph::Graph;
use crate::input::layout::IdHasher;
use crate::input::scene::{CanvasNode, CanvasSceneInput};
use crate::world::bindings::ColliderSpec;

pub use clusters::{cluster_violations, ClusterViolations};

/// The shape `node` is laid out with: its own radius, or `default_radius` for 0.
fn outline<N>(node: &CanvasNode<N>, default_radius: f32) -> ColliderSpec {
    let radius = if node.radius > 0.0 {
        node.radius
    } else {
        default_radius
    };
    node.shape.collider(radius)
}

/// Each node's index in the scene's node list, by id.
fn index_of<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> HashMap<&N, usize, IdHasher> {
    scene
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| (&n.id, i))
        .collect()
}

/// The scene's edges as a graph of its nodes, in the scene's order.
fn graph_of<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> Graph {
    let segments = segments(scene);
    Graph::new(
        scene.nodes.len(),
        segments.iter().map(|&(a, b, _, _)| (a, b)),
    )
}

/// The edges as segments (self-loops and edges naming missing nodes left out).
fn segments<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
) -> Vec<(usize, usize, Point2D<f32>, Point2D<f32>)> {
    let index = index_of(scene);
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

/// Pairs of nodes whose outlines overlap by more than `tolerance` world units: disks
/// by their radius (0 counts as `default_radius`), boxes
/// ([`NodeShape::Rect`](crate::NodeShape::Rect)) by their sides, so two boxes overlap
/// when each is more than `tolerance` inside the other on both axes. Grid-bucketed:
/// about O(n) for spread-out layouts.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, quality, CanvasNode, CanvasSceneInput};
/// // Two label boxes of 60 × 20, side by side with 2 units of overlap, and a disk apart.
/// let scene = CanvasSceneInput::<u32>::new(
///     vec![
///         CanvasNode::new(0, Point2D::new(0.0, 0.0)).with_rect(60.0, 20.0),
///         CanvasNode::new(1, Point2D::new(58.0, 5.0)).with_rect(60.0, 20.0),
///         CanvasNode::new(2, Point2D::new(0.0, 60.0)),
///     ],
///     vec![],
/// );
/// assert_eq!(quality::overlapping_pairs(&scene, 16.0, 1.0), 1);
/// assert_eq!(quality::overlapping_pairs(&scene, 16.0, 3.0), 0);
/// ```
pub fn overlapping_pairs<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    default_radius: f32,
    tolerance: f32,
) -> usize {
    let shapes: Vec<ColliderSpec> = scene
        .nodes
        .iter()
        .map(|n| outline(n, default_radius))
        .collect();
    let max_r = shapes
        .iter()
        .map(ColliderSpec::bounding_radius)
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
        let (inner_a, round_a) = shapes[i].inner_and_round();
        for dx in -1..=1 {
            for dy in -1..=1 {
                let Some(bucket) = grid.get(&(kx + dx, ky + dy)) else {
                    continue;
                };
                for &j in bucket.iter().filter(|&&j| j > i) {
                    let (inner_b, round_b) = shapes[j].inner_and_round();
                    let m = &scene.nodes[j];
                    let apart = if inner_a == Vector2D::zero() && inner_b == Vector2D::zero() {
                        // Two disks.
                        (n.position - m.position).length() - round_a - round_b
                    } else {
                        gap(
                            m.position - n.position,
                            inner_a + inner_b,
                            round_a + round_b,
                        )
                    };
                    if apart < -tolerance {
                        count += 1;
                    }
                }
            }
        }
    }
    count
}

/// Pairs of edges that cross (edges sharing an endpoint never count; edges that only
/// touch or overlap along a line do not count). A sweep along x compares only edges
/// whose x ranges overlap: O(e log e) plus the pairs compared, at worst O(e²).
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, quality, CanvasEdge, CanvasNode, CanvasSceneInput};
/// // The two diagonals of a square cross; its sides share corners with them.
/// let corners = [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)];
/// let scene = CanvasSceneInput::new(
///     (0..4).map(|i| CanvasNode::new(i, Point2D::new(corners[i as usize].0, corners[i as usize].1))).collect(),
///     vec![CanvasEdge::new(0, 2), CanvasEdge::new(1, 3), CanvasEdge::new(0, 1), CanvasEdge::new(2, 3)],
/// );
/// assert_eq!(quality::edge_crossings(&scene), 1);
/// ```
pub fn edge_crossings<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> usize {
    fn orient(a: Point2D<f32>, b: Point2D<f32>, c: Point2D<f32>) -> f64 {
        (f64::from(b.x) - f64::from(a.x)) * (f64::from(c.y) - f64::from(a.y))
            - (f64::from(b.y) - f64::from(a.y)) * (f64::from(c.x) - f64::from(a.x))
    }
    let mut segs = segments(scene);
    let low = |p: Point2D<f32>, q: Point2D<f32>| p.x.min(q.x);
    segs.sort_by(|s, t| low(s.2, s.3).total_cmp(&low(t.2, t.3)));
    let mut count = 0;
    for (k, &(a1, b1, p1, q1)) in segs.iter().enumerate() {
        let right = p1.x.max(q1.x);
        for &(a2, b2, p2, q2) in &segs[k + 1..] {
            if low(p2, q2) > right {
                // Sorted by their left ends: no later edge reaches back to this one.
                break;
            }
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

/// Hop distance (edges on a shortest path) from `origin` to every node it reaches, over
/// the scene's edges taken as undirected; `origin` itself is at 0. Empty when `origin`
/// is not in the scene. O(n + e).
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, quality, CanvasEdge, CanvasNode, CanvasSceneInput};
/// let scene = CanvasSceneInput::new(
///     (0..4).map(|i| CanvasNode::new(i, Point2D::new(i as f32, 0.0))).collect(),
///     vec![CanvasEdge::new(0, 1), CanvasEdge::new(2, 1)],
/// );
/// let hops = quality::hop_distances(&scene, &0);
/// assert_eq!((hops[&0], hops[&1], hops[&2]), (0, 1, 2));
/// assert!(!hops.contains_key(&3), "not connected");
/// ```
pub fn hop_distances<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    origin: &N,
) -> HashMap<N, usize> {
    let Some(&start) = index_of(scene).get(origin) else {
        return HashMap::new();
    };
    let mut hops = vec![u32::MAX; scene.nodes.len()];
    graph_of(scene).search([start], &mut hops, &mut Vec::new(), |_, _| true);
    scene
        .nodes
        .iter()
        .zip(hops)
        .filter(|&(_, h)| h != u32::MAX)
        .map(|(n, h)| (n.id.clone(), h as usize))
        .collect()
}

/// How far the nodes at one hop distance moved ([`displacement_by_hops`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Displacement {
    /// Mean distance moved, in world units (0 without nodes).
    pub mean: f32,
    /// The farthest any of them moved.
    pub max: f32,
    /// How many nodes are at this distance.
    pub nodes: usize,
}

/// How far each node moved between `before` and `after`, grouped by its hop distance in
/// `after` from `origin`: entry `h` for nodes `h` hops away, the last entry (of
/// `groups`, at least 1) for those as far or farther, or not connected to `origin`.
/// Nodes missing from either scene are left out. What a user sees of an edit or a drag:
/// a local one moves its neighbourhood and leaves the far side where it was.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, quality, CanvasEdge, CanvasNode, CanvasSceneInput};
/// let before = CanvasSceneInput::new(
///     (0..3).map(|i| CanvasNode::new(i, Point2D::new(100.0 * i as f32, 0.0))).collect(),
///     vec![CanvasEdge::new(0, 1), CanvasEdge::new(1, 2)],
/// );
/// let mut after = before.clone();
/// after.nodes[0].position.x -= 30.0;
/// after.nodes[1].position.x -= 10.0;
/// let rows = quality::displacement_by_hops(&before, &after, &0, 2);
/// assert_eq!((rows[0].mean, rows[0].nodes), (30.0, 1));
/// assert_eq!((rows[1].mean, rows[1].max, rows[1].nodes), (5.0, 10.0, 2), "hops 1 and 2");
/// ```
pub fn displacement_by_hops<N: Clone + Eq + Hash>(
    before: &CanvasSceneInput<N>,
    after: &CanvasSceneInput<N>,
    origin: &N,
    groups: usize,
) -> Vec<Displacement> {
    let groups = groups.max(1);
    let hops = hop_distances(after, origin);
    let was: HashMap<&N, Point2D<f32>, IdHasher> =
        before.nodes.iter().map(|n| (&n.id, n.position)).collect();
    let mut rows = vec![Displacement::default(); groups];
    for node in &after.nodes {
        let Some(&from) = was.get(&node.id) else {
            continue;
        };
        let group = hops
            .get(&node.id)
            .map_or(groups - 1, |&h| h.min(groups - 1));
        let moved = (node.position - from).length();
        let row = &mut rows[group];
        row.mean += moved;
        row.max = row.max.max(moved);
        row.nodes += 1;
    }
    for row in &mut rows {
        if row.nodes > 0 {
            row.mean /= row.nodes as f32;
        }
    }
    rows
}

/// Normalised stress: how faithfully the layout keeps graph distances. The mean over
/// node pairs joined by a path of `(‖p_i − p_j‖ − s·d_ij)² / (s·d_ij)²`, with `d_ij` the
/// hop distance and `s` the scale that suits the layout best, so a layout is not
/// penalised for its unit; lower is better, 0 is a drawing that keeps every distance.
/// All pairs up to 2,000 nodes; above, 100 sources to up to 4,000 targets each, chosen
/// by a fixed sequence (the measure of the shared `stress.py`, which samples its own).
/// `None` without a pair.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, quality, CanvasEdge, CanvasNode, CanvasSceneInput};
/// // A path drawn straight keeps every distance.
/// let scene = CanvasSceneInput::new(
///     (0..4).map(|i| CanvasNode::new(i, Point2D::new(50.0 * i as f32, 0.0))).collect(),
///     (0..3).map(|i| CanvasEdge::new(i, i + 1)).collect(),
/// );
/// assert!(quality::normalized_stress(&scene).unwrap() < 1e-6);
/// ```
pub fn normalized_stress<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> Option<f64> {
    let n = scene.nodes.len();
    let graph = graph_of(scene);
    let mut queue = Vec::new();
    let mut bfs = |s: usize, hops: &mut Vec<u32>| {
        hops.clear();
        hops.resize(n, u32::MAX);
        graph.search([s], hops, &mut queue, |_, _| true);
    };
    let mut pairs: Vec<(usize, usize, f64)> = Vec::new();
    let mut hops = Vec::new();
    if n <= 2_000 {
        for i in 0..n {
            bfs(i, &mut hops);
            pairs.extend(
                (i + 1..n)
                    .filter(|&j| hops[j] != u32::MAX)
                    .map(|j| (i, j, f64::from(hops[j]))),
            );
        }
    } else {
        let mut state = 7_u64;
        let mut next = |bound: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % bound as u64) as usize
        };
        for _ in 0..100 {
            let s = next(n);
            bfs(s, &mut hops);
            for _ in 0..4_000.min(n) {
                let j = next(n);
                if j != s && hops[j] != u32::MAX {
                    pairs.push((s, j, f64::from(hops[j])));
                }
            }
        }
    }
    if pairs.is_empty() {
        return None;
    }
    let p = |i: usize| scene.nodes[i].position;
    let e = |i: usize, j: usize| f64::from((p(i) - p(j)).length());
    let (mut a, mut b) = (0.0, 0.0);
    for &(i, j, d) in &pairs {
        let e = e(i, j);
        a += e * e / (d * d);
        b += e / d;
    }
    if b == 0.0 {
        // Every pair drawn at one point: no scale fits, each term is 1.
        return Some(1.0);
    }
    let s = a / b;
    let total: f64 = pairs
        .iter()
        .map(|&(i, j, d)| ((e(i, j) - s * d) / (s * d)).powi(2))
        .sum();
    Some(total / pairs.len() as f64)
}
