//! The scene file format used by the shipped graphs:
//! `{"nodes":[{"id","x","y","radius"}],"edges":[[a,b],...]}`.
//!
//! The crate only derives `Deserialize`; read the text with the JSON crate of your
//! choice (the examples use `serde_json`).

use euclid::default::Point2D;
use serde::{Deserialize, Serialize};

use crate::input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput};

/// One node of a scene file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneFileNode {
    /// The node's id.
    pub id: u32,
    /// x in world units.
    pub x: f32,
    /// y in world units.
    pub y: f32,
    /// Radius in world units (0 for the layout's default).
    #[serde(default)]
    pub radius: f32,
}

/// A graph as stored in `scenes/*.json`. Extra fields (name, source, counts) are ignored.
///
/// # Example
/// ```
/// use graph_canvas_layout::SceneFile;
/// let file = SceneFile {
///     nodes: vec![graph_canvas_layout::SceneFileNode { id: 1, x: 0.0, y: 0.0, radius: 16.0 }],
///     edges: vec![],
/// };
/// let scene = file.into_scene();
/// assert_eq!(scene.nodes[0].id, 1);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneFile {
    /// The nodes.
    pub nodes: Vec<SceneFileNode>,
    /// The edges as `[source, target]` pairs.
    pub edges: Vec<(u32, u32)>,
}

impl SceneFile {
    /// The scene a host would pass to a layout.
    pub fn into_scene(self) -> CanvasSceneInput<u32> {
        CanvasSceneInput::new(
            self.nodes
                .into_iter()
                .map(|n| CanvasNode::new(n.id, Point2D::new(n.x, n.y)).with_radius(n.radius))
                .collect(),
            self.edges
                .into_iter()
                .map(|(a, b)| CanvasEdge::new(a, b))
                .collect(),
        )
    }
}
