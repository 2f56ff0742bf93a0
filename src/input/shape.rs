//! The shape a host draws a node as ([`NodeShape`]): the disk of its radius, or an
//! axis-aligned box (a label box), which the layout keeps level and apart.

use serde::{Deserialize, Serialize};

use crate::input::validation::MAX_COORDINATE;

/// The shape of a node, as the host draws it: what the layout's contacts keep apart.
///
/// Set with [`CanvasNode::with_rect`](crate::CanvasNode::with_rect) or
/// [`CanvasNode::with_rounded_rect`](crate::CanvasNode::with_rounded_rect); a node is a
/// disk of its [`radius`](crate::CanvasNode::radius) unless it says otherwise.
///
/// What a box changes, and what it does not:
/// - **Contacts.** The layout's own contacts
///   ([`ContactModel::Disks`](crate::config::ContactModel::Disks)) part boxes from boxes and
///   from disks by their outlines, not their bounding circles; rapier's contacts
///   ([`ContactModel::Rapier`](crate::config::ContactModel::Rapier)) get a cuboid (rounded
///   where the corners are). Rotation stays locked: a label stays level.
/// - **Mass.** A box weighs what a node of the layout's
///   [`default_radius`](crate::RapierLayoutConfig::default_radius) weighs, whatever its
///   size, so a long label throws, springs and settles like a short one. A disk weighs
///   `density × π r²`.
/// - **Radius.** A box ignores [`radius`](crate::CanvasNode::radius) (it must still be
///   finite and non-negative); its corners are set by `corner_radius`.
/// - **Edges.** An edge's rest length runs centre to centre, as for disks; the contacts
///   keep two boxes joined by an edge from sitting on each other's text, and the
///   stress model's hop is fitted to the boxes' size (`docs/shapes.md`).
/// - **Repulsion** (Barnes–Hut) treats every node as a point, as d3-force does.
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode, NodeShape};
/// let node = CanvasNode::new(1_u32, Point2D::origin()).with_rect(63.0, 20.0);
/// assert_eq!(node.shape, NodeShape::Rect { width: 63.0, height: 20.0, corner_radius: 0.0 });
/// assert_eq!(CanvasNode::new(2_u32, Point2D::origin()).shape, NodeShape::Disk);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum NodeShape {
    /// The disk of the node's [`radius`](crate::CanvasNode::radius) (0: the layout's
    /// default radius).
    #[default]
    Disk,
    /// An axis-aligned box centred on the node's position.
    Rect {
        /// Width in world units, finite and non-negative.
        width: f32,
        /// Height in world units, finite and non-negative.
        height: f32,
        /// The radius of its rounded corners in world units (0: square corners), at
        /// most half the shorter side (larger values count as that).
        corner_radius: f32,
    },
}

impl NodeShape {
    /// Whether the layout can use the shape: a disk, or a box whose sides and corner
    /// radius are finite, non-negative and no larger than 2 × [`MAX_COORDINATE`].
    pub fn is_valid(&self) -> bool {
        self.problem().is_none()
    }

    /// The first unusable part of the shape as `(part, value)`: `"width"`, `"height"`
    /// or `"corner radius"`.
    pub(crate) fn problem(&self) -> Option<(&'static str, f32)> {
        let ok = |v: f32| v.is_finite() && (0.0..=2.0 * MAX_COORDINATE).contains(&v);
        match *self {
            NodeShape::Disk => None,
            NodeShape::Rect {
                width,
                height,
                corner_radius,
            } => [
                ("width", width),
                ("height", height),
                ("corner radius", corner_radius),
            ]
            .into_iter()
            .find(|&(_, v)| !ok(v)),
        }
    }
}
