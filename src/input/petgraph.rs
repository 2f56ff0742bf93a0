//! petgraph graphs in (feature `petgraph`): a scene from any graph petgraph's visit
//! traits describe (`&Graph`, `&StableGraph`, `&GraphMap`, directed or not), with the
//! graph's own node ids as scene ids. Keeping a layout alive across a host's edits is
//! [`RapierLayout::forget_node`](crate::RapierLayout::forget_node)'s part.

use std::collections::HashMap;
use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use petgraph::visit::{EdgeRef, IntoEdgeReferences, IntoNodeReferences, NodeRef};

use crate::input::layout::IdHasher;
use crate::input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput};

/// The spacing of the start spiral: node `i` starts `SPIRAL_SPACING · √(0.5 + i)` units
/// from the origin at angle `i · π (3 − √5)`, d3-force's phyllotaxis at 2.2 times its
/// radius, so default disks (radius 16) start at least 34 units apart instead of
/// overlapping.
pub const SPIRAL_SPACING: f32 = 22.0;

/// Where the `i`-th node of a graph without positions starts ([`SPIRAL_SPACING`]).
///
/// # Example
/// ```
/// use graph_canvas_layout::spiral_position;
/// assert!((spiral_position(0).to_vector().length() - 22.0 * 0.5_f32.sqrt()).abs() < 1e-4);
/// assert_ne!(spiral_position(1), spiral_position(2));
/// ```
pub fn spiral_position(i: usize) -> Point2D<f32> {
    let radius = f64::from(SPIRAL_SPACING) * (0.5 + i as f64).sqrt();
    let angle = i as f64 * std::f64::consts::PI * (3.0 - 5.0_f64.sqrt());
    Point2D::new((radius * angle.cos()) as f32, (radius * angle.sin()) as f32)
}

/// How a node of a petgraph graph starts in the scene
/// ([`CanvasSceneInput::from_petgraph_with`]).
///
/// A host that keeps positions for the nodes it has laid out and adds a node later gives
/// the new node `position: None`: it starts at the centre of its neighbours that have a
/// position, and a [`RapierLayout`](crate::RapierLayout) seats it beside them (an edge
/// length from a single neighbour, in the freest direction) without moving the rest.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NodeStart {
    /// Its position, or `None`: at the centre of its neighbours that have one, or on the
    /// start spiral when none has.
    pub position: Option<Point2D<f32>>,
    /// Its radius (0: the layout's default).
    pub radius: f32,
}

impl<N: Clone + Eq + Hash> CanvasSceneInput<N> {
    /// The scene of a petgraph graph: one node per graph node with the graph's node id
    /// as its id, in the graph's node order, on the start spiral ([`spiral_position`]),
    /// radius 0 (the layout's default); one edge per graph edge, weight 1. Directed
    /// edges count as undirected, parallel edges as one.
    ///
    /// # Example
    /// Lay a `StableGraph` out to rest and write the positions back to the host's store:
    /// ```
    /// use graph_canvas_layout::petgraph::stable_graph::StableUnGraph;
    /// use graph_canvas_layout::{CanvasSceneInput, Layout, LayoutExtras, RapierLayout,
    ///     RapierLayoutConfig, RapierLayoutState};
    /// let mut graph = StableUnGraph::<&str, ()>::default();
    /// let (a, b, c) = (graph.add_node("a"), graph.add_node("b"), graph.add_node("c"));
    /// graph.extend_with_edges([(a, b), (b, c)]);
    ///
    /// let mut scene = CanvasSceneInput::from_petgraph(&graph);
    /// let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
    /// let (mut state, extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// loop {
    ///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    ///     scene.apply_deltas(&deltas);
    ///     if layout.is_converged(&state) {
    ///         break;
    ///     }
    /// }
    /// // The host's own store, keyed by the graph's node index.
    /// let positions: std::collections::HashMap<_, _> =
    ///     scene.nodes.iter().map(|n| (n.id, n.position)).collect();
    /// let ab = (positions[&a] - positions[&b]).length();
    /// assert!((60.0..140.0).contains(&ab), "edge a-b at rest: {ab}");
    ///
    /// // An edit: remove c and add d, which takes c's index. Forget the old node so the
    /// // new one starts afresh instead of taking over c's body and motion.
    /// graph.remove_node(c);
    /// let d = graph.add_node("d");
    /// assert_eq!(d, c, "StableGraph reuses the index");
    /// graph.add_edge(a, d, ());
    /// layout.forget_node(&c);
    /// scene = CanvasSceneInput::from_petgraph_with(&graph, |id, _| graph_canvas_layout::scene::NodeStart {
    ///     position: positions.get(&id).copied().filter(|_| id != d),
    ///     radius: 0.0,
    /// }, |_| 1.0);
    /// layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    /// ```
    pub fn from_petgraph<G>(graph: G) -> Self
    where
        G: IntoNodeReferences<NodeId = N> + IntoEdgeReferences,
    {
        Self::from_petgraph_with(graph, |_, _| NodeStart::default(), |_| 1.0)
    }

    /// [`from_petgraph`](Self::from_petgraph) with each node's start (`node(id, weight)`:
    /// position and radius) and each edge's weight (`weight(edge weight)`) taken from
    /// the graph's own data. A node without a position starts at the centre of its
    /// neighbours that have one (the layout seats it beside them on its first call), or
    /// on the spiral when none has.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::euclid::default::Point2D;
    /// use graph_canvas_layout::petgraph::Graph;
    /// use graph_canvas_layout::CanvasSceneInput;
    /// use graph_canvas_layout::scene::NodeStart;
    /// let mut graph = Graph::<(f32, f32), f32>::new();
    /// let a = graph.add_node((0.0, 0.0));
    /// let b = graph.add_node((120.0, 0.0));
    /// graph.add_edge(a, b, 2.5);
    /// let scene = CanvasSceneInput::from_petgraph_with(
    ///     &graph,
    ///     |_, &(x, y)| NodeStart { position: Some(Point2D::new(x, y)), radius: 10.0 },
    ///     |&w| w,
    /// );
    /// assert_eq!(scene.nodes[1].position, Point2D::new(120.0, 0.0));
    /// assert_eq!((scene.nodes[1].radius, scene.edges[0].weight), (10.0, 2.5));
    /// ```
    pub fn from_petgraph_with<G>(
        graph: G,
        mut node: impl FnMut(N, &G::NodeWeight) -> NodeStart,
        mut weight: impl FnMut(&G::EdgeWeight) -> f32,
    ) -> Self
    where
        G: IntoNodeReferences<NodeId = N> + IntoEdgeReferences,
    {
        let mut nodes: Vec<CanvasNode<N>> = Vec::new();
        let mut given: Vec<bool> = Vec::new();
        for r in graph.node_references() {
            let start = node(r.id(), r.weight());
            let position = start.position.unwrap_or_else(Point2D::origin);
            nodes.push(CanvasNode::new(r.id(), position).with_radius(start.radius));
            given.push(start.position.is_some());
        }
        let edges: Vec<CanvasEdge<N>> = graph
            .edge_references()
            .map(|e| CanvasEdge::new(e.source(), e.target()).with_weight(weight(e.weight())))
            .collect();
        place_beside_neighbours(&mut nodes, &given, &edges);
        CanvasSceneInput::new(nodes, edges)
    }
}

/// Gives every node without a position (`given` false) the centre of its neighbours
/// that have one, in edge order, or its place on the start spiral when none has.
fn place_beside_neighbours<N: Clone + Eq + Hash>(
    nodes: &mut [CanvasNode<N>],
    given: &[bool],
    edges: &[CanvasEdge<N>],
) {
    if given.iter().all(|&g| g) {
        return;
    }
    let index: HashMap<&N, usize, IdHasher> =
        nodes.iter().enumerate().map(|(i, n)| (&n.id, i)).collect();
    let mut sums = vec![(Vector2D::zero(), 0_u32); nodes.len()];
    for edge in edges {
        let (Some(&a), Some(&b)) = (index.get(&edge.source), index.get(&edge.target)) else {
            continue;
        };
        for (end, other) in [(a, b), (b, a)] {
            if !given[end] && given[other] {
                let sum = &mut sums[end];
                *sum = (sum.0 + nodes[other].position.to_vector(), sum.1 + 1);
            }
        }
    }
    for (i, node) in nodes.iter_mut().enumerate() {
        if !given[i] {
            let (sum, count) = sums[i];
            node.position = if count > 0 {
                (sum / count as f32).to_point()
            } else {
                spiral_position(i)
            };
        }
    }
}
