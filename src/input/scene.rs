//! Scene input: the read-only description of the graph that a host hands to a layout
//! every frame.

use euclid::default::{Point2D, Rect};
use serde::{Deserialize, Serialize};

use crate::input::shape::NodeShape;

/// One node of the host's graph, as the host sees it this frame.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode};
/// let node = CanvasNode::new(7_u32, Point2D::new(10.0, 20.0));
/// assert_eq!(node.radius, 0.0); // 0 means "use the layout's default radius"
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CanvasNode<N> {
    /// The host's identifier of the node. Needs `Clone + Eq + Hash`, never `Ord`.
    pub id: N,
    /// Where the host currently draws the node, in world units (canvas pixels).
    pub position: Point2D<f32>,
    /// Radius of the node's disk in world units; `0.0` means the layout's default radius.
    /// At most [`MAX_COORDINATE`](crate::MAX_COORDINATE).
    /// A box ([`shape`](Self::shape)) ignores it.
    pub radius: f32,
    /// Optional text the host shows; layouts ignore it.
    pub label: Option<String>,
    /// The node's outline, which the layout keeps apart from the others: the disk of
    /// [`radius`](Self::radius) (the default) or a box ([`NodeShape`]).
    #[serde(default)]
    pub shape: NodeShape,
}

impl<N> CanvasNode<N> {
    /// A node at `position` with radius `0.0` (use the layout's default) and no label.
    pub fn new(id: N, position: Point2D<f32>) -> Self {
        Self {
            id,
            position,
            radius: 0.0,
            label: None,
            shape: NodeShape::Disk,
        }
    }

    /// The same node with an explicit radius.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode};
    /// let node = CanvasNode::new("a", Point2D::origin()).with_radius(24.0);
    /// assert_eq!(node.radius, 24.0);
    /// ```
    #[must_use]
    pub fn with_radius(mut self, radius: f32) -> Self {
        self.radius = radius;
        self
    }

    /// This node as an axis-aligned box of `width` × `height` world units, centred on
    /// its position and level at all times (a label box). The layout's contacts keep it
    /// from overlapping other nodes by its outline; it weighs what a default disk
    /// weighs, whatever its size ([`NodeShape`] says what else a box changes).
    /// Non-finite or negative sides are bad input
    /// ([`LayoutError::InvalidShape`](crate::LayoutError::InvalidShape)).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode};
    /// let label = "node 17";
    /// // 7 units a character, 20 high: the box the host draws the label in.
    /// let node = CanvasNode::new(17_u32, Point2D::origin())
    ///     .with_rect(7.0 * label.len() as f32, 20.0)
    ///     .with_label(label);
    /// assert_eq!(node.radius, 0.0); // a box ignores its radius
    /// ```
    #[must_use]
    pub fn with_rect(mut self, width: f32, height: f32) -> Self {
        self.shape = NodeShape::Rect {
            width,
            height,
            corner_radius: 0.0,
        };
        self
    }

    /// This node as a box of `width` × `height` with corners rounded to
    /// `corner_radius` (at most half the shorter side), as
    /// [`with_rect`](Self::with_rect) otherwise.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode, NodeShape};
    /// let node = CanvasNode::new(1_u32, Point2D::origin()).with_rounded_rect(80.0, 24.0, 6.0);
    /// assert!(matches!(node.shape, NodeShape::Rect { corner_radius, .. } if corner_radius == 6.0));
    /// ```
    #[must_use]
    pub fn with_rounded_rect(mut self, width: f32, height: f32, corner_radius: f32) -> Self {
        self.shape = NodeShape::Rect {
            width,
            height,
            corner_radius,
        };
        self
    }

    /// This node as the disk of its radius again (the default shape).
    #[must_use]
    pub fn with_disk(mut self) -> Self {
        self.shape = NodeShape::Disk;
        self
    }

    /// This node with a label (the layout does not read it; a host draws it).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode};
    /// let node = CanvasNode::new(3_u32, Point2D::origin()).with_label("Valjean");
    /// assert_eq!(node.label.as_deref(), Some("Valjean"));
    /// ```
    #[must_use]
    pub fn with_label(mut self, label: impl Into<String>) -> Self {
        self.label = Some(label.into());
        self
    }
}

/// One edge of the host's graph. Edges are undirected for the physics: `(a, b)`,
/// `(b, a)` and repeats make one joint; self-loops are ignored.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CanvasEdge<N> {
    /// One end of the edge.
    pub source: N,
    /// The other end of the edge.
    pub target: N,
    /// The edge's weight; `1.0` by default. The layout scales the edge's joint by it,
    /// its strength or its length as
    /// [`RapierLayoutConfig::springs.weight`](crate::config::Springs::weight) says;
    /// 0 keeps the edge as topology only. Negative or non-finite weights are bad input.
    pub weight: f32,
}

impl<N> CanvasEdge<N> {
    /// An edge between `source` and `target` with weight `1.0`.
    pub fn new(source: N, target: N) -> Self {
        Self {
            source,
            target,
            weight: 1.0,
        }
    }

    /// This edge with weight `weight`
    /// ([`RapierLayoutConfig::springs.weight`](crate::config::Springs::weight) says
    /// what it scales).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::CanvasEdge;
    /// let edge = CanvasEdge::new(1_u32, 2).with_weight(2.5);
    /// assert_eq!(edge.weight, 2.5);
    /// ```
    pub fn with_weight(mut self, weight: f32) -> Self {
        self.weight = weight;
        self
    }
}

/// Everything a layout reads about the graph this frame.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput};
/// let scene = CanvasSceneInput::new(
///     vec![CanvasNode::new(0, Point2D::new(0.0, 0.0)), CanvasNode::new(1, Point2D::new(90.0, 0.0))],
///     vec![CanvasEdge::new(0, 1)],
/// );
/// assert_eq!(scene.nodes.len(), 2);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CanvasSceneInput<N> {
    /// The nodes, in the host's order. The order reaches rapier (insertion order), so
    /// keep it stable for reproducible runs; it never changes the topology hash.
    pub nodes: Vec<CanvasNode<N>>,
    /// The edges, in any order.
    pub edges: Vec<CanvasEdge<N>>,
}

impl<N> CanvasSceneInput<N> {
    /// A scene from its nodes and edges.
    pub fn new(nodes: Vec<CanvasNode<N>>, edges: Vec<CanvasEdge<N>>) -> Self {
        Self { nodes, edges }
    }
}

impl<N: Eq + std::hash::Hash> CanvasSceneInput<N> {
    /// Adds each node's delta to its position: what a host that keeps its positions in
    /// the scene does with the map [`Layout::step`](crate::Layout::step) returns. A
    /// repeated id moves at its first occurrence only, the one `step` lays out (it
    /// ignores the repeats).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::{Point2D, Vector2D}, CanvasNode, CanvasSceneInput, DeltaMap};
    /// let mut scene = CanvasSceneInput::new(
    ///     vec![CanvasNode::new(1_u32, Point2D::new(1.0, 1.0)), CanvasNode::new(1, Point2D::new(5.0, 5.0))],
    ///     vec![],
    /// );
    /// let mut deltas = DeltaMap::default();
    /// deltas.insert(1, Vector2D::new(2.0, 0.0));
    /// scene.apply_deltas(&deltas);
    /// assert_eq!(scene.nodes[0].position, Point2D::new(3.0, 1.0));
    /// assert_eq!(scene.nodes[1].position, Point2D::new(5.0, 5.0), "the repeat stays");
    /// ```
    pub fn apply_deltas(&mut self, deltas: &crate::DeltaMap<N>) {
        if deltas.is_empty() {
            return;
        }
        // The ids moved so far, borrowed from the map's keys.
        let mut moved: std::collections::HashSet<&N, crate::IdHasher> =
            std::collections::HashSet::with_capacity_and_hasher(
                deltas.len(),
                crate::IdHasher::default(),
            );
        for node in &mut self.nodes {
            if let Some((id, delta)) = deltas.get_key_value(&node.id) {
                if moved.insert(id) {
                    node.position += *delta;
                }
            }
        }
    }
}

impl<N> Default for CanvasSceneInput<N> {
    fn default() -> Self {
        Self::new(Vec::new(), Vec::new())
    }
}

/// The part of the world the host shows. The Rapier layout does not read it; it is part
/// of the [`Layout`](crate::Layout) contract for layouts that do.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CanvasViewport {
    /// The visible rectangle, in world units.
    pub rect: Rect<f32>,
    /// Device pixels per world unit.
    pub scale_factor: f32,
}

impl Default for CanvasViewport {
    /// An 800 × 600 rectangle at the origin with scale factor 1.
    fn default() -> Self {
        Self {
            rect: Rect::new(
                Point2D::origin(),
                euclid::default::Size2D::new(800.0, 600.0),
            ),
            scale_factor: 1.0,
        }
    }
}
