//! The scene file format used by the shipped graphs:
//! `{"nodes":[{"id","x","y","radius"}],"edges":[[a,b],...]}`.
//!
//! The crate only derives `Deserialize`; read the text with the JSON crate of your
//! choice (the examples use `serde_json`), whose error names what did not parse, then
//! [`SceneFile::try_into_scene`] names what parsed but no layout can use. No bytes make
//! either panic.

use euclid::default::Point2D;
use serde::{Deserialize, Serialize};

use crate::input::layout::LayoutExtras;
use crate::input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput};
use crate::input::validation::{validate, LayoutError};

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
/// use graph_canvas_layout::scene::SceneFile;
/// let file = SceneFile {
///     nodes: vec![graph_canvas_layout::scene::SceneFileNode { id: 1, x: 0.0, y: 0.0, radius: 16.0 }],
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
    /// The scene a host would pass to a layout, as the file gives it, unchecked: a
    /// layout's [`step`](crate::Layout::step) leaves out what it cannot use and lists it
    /// in [`skipped`](crate::RapierLayout::skipped). A file from outside is better read
    /// with [`try_into_scene`](Self::try_into_scene).
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

    /// The scene, once every node and edge is one a layout can use: the first that is
    /// not, as [`try_step`](crate::RapierLayout::try_step) would name it.
    ///
    /// # Errors
    /// [`LayoutError`] for the first node with a non-finite position, one beyond
    /// ±[`MAX_COORDINATE`](crate::MAX_COORDINATE), a radius outside 0 to
    /// [`MAX_COORDINATE`](crate::MAX_COORDINATE) or a repeated id, or the first edge
    /// naming a node the file lacks.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::LayoutError;
    /// use graph_canvas_layout::scene::SceneFile;
    /// let text = r#"{"nodes":[{"id":1,"x":0,"y":0},{"id":2,"x":40,"y":0}],"edges":[[1,3]]}"#;
    /// let file: SceneFile = serde_json::from_str(text).unwrap();
    /// assert!(matches!(
    ///     file.try_into_scene(),
    ///     Err(LayoutError::UnknownEdgeEndpoint { missing: 3, .. })
    /// ));
    /// ```
    pub fn try_into_scene(self) -> Result<CanvasSceneInput<u32>, LayoutError<u32>> {
        let scene = self.into_scene();
        validate(&scene, &LayoutExtras::default())?;
        Ok(scene)
    }
}
