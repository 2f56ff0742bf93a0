//! How far a layout keeps its clusters: members outside their box, other nodes inside
//! it, sibling boxes overlapping.

use std::hash::Hash;

use euclid::default::Box2D;

use super::{index_of, outline};
use crate::input::clusters::{held_parent, usable, walk_members, Cluster, NO_CLUSTER};
use crate::input::scene::{CanvasNode, CanvasSceneInput};

/// What [`cluster_violations`] counts, each beyond its tolerance.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ClusterViolations {
    /// Members whose outline reaches out of their cluster's box (or a box it is nested
    /// in).
    pub members_outside: usize,
    /// Pairs of a node and a cluster it is not in whose box its outline enters.
    pub intruders: usize,
    /// Pairs of sibling boxes (the same parent, or both at the top level) that overlap.
    pub overlapping_siblings: usize,
    /// The deepest of them (world units): how far out, or in.
    pub worst: f32,
}

impl ClusterViolations {
    /// Whether nothing is violated.
    pub fn is_empty(&self) -> bool {
        self.members_outside + self.intruders + self.overlapping_siblings == 0
    }
}

/// Checks `scene` against `clusters` and their boxes (`bounds`, index-aligned, as
/// [`RapierLayout::cluster_bounds`](crate::RapierLayout::cluster_bounds) gives them),
/// counting what is more than `tolerance` (world units) from holding. A node's outline
/// is its box ([`NodeShape::Rect`](crate::NodeShape::Rect)) or the square around its
/// disk (`default_radius` for a radius of 0). Clusters the layout leaves out as bad
/// input, and members not in the scene, are not checked. O(n × clusters).
///
/// # Example
/// ```
/// use graph_canvas_layout::euclid::default::{Box2D, Point2D};
/// use graph_canvas_layout::{quality, scene::Cluster, CanvasNode, CanvasSceneInput};
/// let scene = CanvasSceneInput::<u32>::new(
///     vec![
///         CanvasNode::new(0, Point2D::new(0.0, 0.0)).with_radius(10.0),
///         CanvasNode::new(1, Point2D::new(15.0, 0.0)).with_radius(10.0), // inside 0's box
///     ],
///     vec![],
/// );
/// let clusters = vec![Cluster::new(vec![0]).with_padding(5.0)];
/// let bounds = [Box2D::new(Point2D::new(-15.0, -15.0), Point2D::new(15.0, 15.0))];
/// let v = quality::cluster_violations(&scene, &clusters, &bounds, 16.0, 1.0);
/// assert_eq!((v.members_outside, v.intruders, v.overlapping_siblings), (0, 1, 0));
/// assert_eq!(v.worst, 10.0, "node 1 reaches 10 units into the box");
/// ```
pub fn cluster_violations<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    clusters: &[Cluster<N>],
    bounds: &[Box2D<f32>],
    default_radius: f32,
    tolerance: f32,
) -> ClusterViolations {
    let mut v = ClusterViolations::default();
    let held = usable(clusters);
    let index = index_of(scene);
    let count = scene.nodes.len();
    let innermost = walk_members(
        clusters,
        &held,
        count,
        |n| index.get(n).copied(),
        |_, _, _| {},
    );
    let parent = |c: usize| held_parent(clusters, &held, c);
    let box_of = |c: usize| bounds.get(c).copied().unwrap_or_else(Box2D::zero);
    let mut note = |counter: &mut usize, depth: f32| {
        if depth > tolerance {
            *counter += 1;
            v.worst = v.worst.max(depth);
        }
    };
    let (mut outside, mut inside, mut siblings) = (0, 0, 0);
    for (i, node) in scene.nodes.iter().enumerate() {
        let outline = outline_box(node, default_radius);
        let mut chain = Vec::new();
        let mut at = (innermost[i] != NO_CLUSTER).then_some(innermost[i] as usize);
        while let Some(c) = at {
            chain.push(c);
            at = parent(c);
        }
        for &c in &chain {
            let b = box_of(c);
            let out = [
                b.min.x - outline.min.x,
                b.min.y - outline.min.y,
                outline.max.x - b.max.x,
                outline.max.y - b.max.y,
            ];
            note(&mut outside, out.into_iter().fold(0.0, f32::max));
        }
        for c in (0..clusters.len()).filter(|&c| held[c] && !chain.contains(&c)) {
            note(&mut inside, depth_in(outline, box_of(c)));
        }
    }
    for a in (0..clusters.len()).filter(|&c| held[c]) {
        for b in (a + 1..clusters.len()).filter(|&c| held[c] && parent(c) == parent(a)) {
            note(&mut siblings, depth_in(box_of(a), box_of(b)));
        }
    }
    (v.members_outside, v.intruders, v.overlapping_siblings) = (outside, inside, siblings);
    v
}

/// The box around `node`'s outline.
fn outline_box<N>(node: &CanvasNode<N>, default_radius: f32) -> Box2D<f32> {
    let r = outline(node, default_radius).half_extents();
    Box2D::new(node.position - r, node.position + r)
}

/// How far `a` and `b` overlap: the lesser of the two axes' overlaps (0 when apart).
fn depth_in(a: Box2D<f32>, b: Box2D<f32>) -> f32 {
    let x = a.max.x.min(b.max.x) - a.min.x.max(b.min.x);
    let y = a.max.y.min(b.max.y) - a.min.y.max(b.min.y);
    x.min(y).max(0.0)
}
