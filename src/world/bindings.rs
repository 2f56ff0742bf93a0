//! What the world wrapper builds from: per-node bindings (shape, material, body kind),
//! node snapshots, and edge joint specifications.

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::RigidBodyType;
use serde::{Deserialize, Serialize};

use crate::input::shape::NodeShape;
use crate::input::validation::MAX_COORDINATE;
use crate::sanitize::finite_or;

/// The physical material of a node's body and collider.
///
/// Units are the world's: lengths in canvas pixels, time in seconds, mass in
/// `density × area`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PhysicsMaterial {
    /// Mass per unit of area. A disk of radius `r` weighs `density × π r²`.
    ///
    /// Heavier nodes respond more slowly to springs of the same stiffness: the
    /// period of two equal disks of mass `m` on a spring `k` is `2π √(m / 2k)`.
    /// Default: `0.005` (a radius-16 disk weighs about 4, so the default spring of
    /// stiffness 50 swings a pair with a period of about 1.3 s).
    pub density: f32,
    /// Coulomb friction between touching disks. Rotations are locked, so friction only
    /// slows disks sliding past each other. Default: `0.0`.
    pub friction: f32,
    /// Bounciness of contacts, from 0 (none) to 1 (elastic). Default: `0.0`.
    pub restitution: f32,
    /// Velocity damping per second: each step scales the velocity by
    /// `1 / (1 + dt × linear_damping)`. Higher values settle faster and feel heavier;
    /// zero keeps a thrown node flying until a joint or a contact stops it.
    /// Default: `1.0`.
    pub linear_damping: f32,
    /// Angular velocity damping. Rotations are locked for disks, so it only matters to
    /// hosts that build their own bindings. Default: `0.0`.
    pub angular_damping: f32,
    /// Multiplier of the state's gravity on this body. Default: `1.0`.
    pub gravity_scale: f32,
}

impl Default for PhysicsMaterial {
    fn default() -> Self {
        Self {
            density: 0.005,
            friction: 0.0,
            restitution: 0.0,
            linear_damping: 1.0,
            angular_damping: 0.0,
            gravity_scale: 1.0,
        }
    }
}

/// The collision shape of a node.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[non_exhaustive]
pub enum ColliderSpec {
    /// A disk.
    Circle {
        /// Radius in world units.
        radius: f32,
    },
    /// An axis-aligned rectangle (rotations are locked, so it stays aligned).
    Rect {
        /// Half width and half height in world units.
        half_extents: Vector2D<f32>,
    },
    /// An axis-aligned rectangle with rounded corners.
    RoundRect {
        /// Half width and half height in world units, corners included.
        half_extents: Vector2D<f32>,
        /// The corners' radius in world units; at most the smaller half extent (larger
        /// values count as that).
        corner_radius: f32,
    },
}

impl ColliderSpec {
    /// The shape's area, which with the material's density gives the body's mass.
    pub fn area(&self) -> f32 {
        match *self {
            ColliderSpec::Circle { radius } => std::f32::consts::PI * radius * radius,
            ColliderSpec::Rect { half_extents } => 4.0 * half_extents.x * half_extents.y,
            ColliderSpec::RoundRect { .. } => {
                let (inner, c) = self.inner_and_round();
                4.0 * (inner.x + c) * (inner.y + c) - (4.0 - std::f32::consts::PI) * c * c
            }
        }
    }

    /// Half the width and half the height of the smallest axis-aligned box around the
    /// shape (a disk's radius on both axes).
    pub fn half_extents(&self) -> Vector2D<f32> {
        match *self {
            ColliderSpec::Circle { radius } => Vector2D::new(radius, radius),
            ColliderSpec::Rect { half_extents } | ColliderSpec::RoundRect { half_extents, .. } => {
                half_extents
            }
        }
    }

    /// The radius of the smallest disk around the shape's centre that holds it.
    pub fn bounding_radius(&self) -> f32 {
        match *self {
            ColliderSpec::Circle { radius } => radius,
            ColliderSpec::Rect { half_extents } => half_extents.length(),
            ColliderSpec::RoundRect { .. } => {
                let (inner, c) = self.inner_and_round();
                inner.length() + c
            }
        }
    }

    /// The shape as a box swept by a disk: the box's half extents and the disk's radius
    /// (a disk is a point swept by itself, a rectangle a box swept by nothing). Two such
    /// shapes touch where their centres' offset is the radii's sum from the box of both
    /// half extents, which is what the layout's own contacts test.
    pub(crate) fn inner_and_round(&self) -> (Vector2D<f32>, f32) {
        match *self {
            ColliderSpec::Circle { radius } => (Vector2D::zero(), radius),
            ColliderSpec::Rect { half_extents } => (half_extents, 0.0),
            ColliderSpec::RoundRect {
                half_extents,
                corner_radius,
            } => {
                let c = corner_radius
                    .min(half_extents.x)
                    .min(half_extents.y)
                    .max(0.0);
                (half_extents - Vector2D::new(c, c), c)
            }
        }
    }
}

/// How rapier treats a node's body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum SceneBodyKind {
    /// Moved by forces, joints and contacts.
    Dynamic,
    /// Never moves by itself: an anchor.
    Static,
    /// Moved only by setting its next position; pushes dynamic bodies it meets.
    KinematicPositionBased,
    /// Moved only by setting its velocity; pushes dynamic bodies it meets.
    KinematicVelocityBased,
}

impl SceneBodyKind {
    /// The matching rapier body type.
    pub fn rigid_body_type(self) -> RigidBodyType {
        match self {
            SceneBodyKind::Dynamic => RigidBodyType::Dynamic,
            SceneBodyKind::Static => RigidBodyType::Fixed,
            SceneBodyKind::KinematicPositionBased => RigidBodyType::KinematicPositionBased,
            SceneBodyKind::KinematicVelocityBased => RigidBodyType::KinematicVelocityBased,
        }
    }
}

/// How to build a node's body: its shape, its material and its kind.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NodeAvatarBinding<N> {
    /// The node this binding belongs to.
    pub node_id: N,
    /// The collision shape.
    pub collider: ColliderSpec,
    /// The physical material.
    pub material: PhysicsMaterial,
    /// The body kind.
    pub body_kind: SceneBodyKind,
}

impl<N> NodeAvatarBinding<N> {
    /// A dynamic disk of `radius` with the default material.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{NodeAvatarBinding, SceneBodyKind};
    /// let binding = NodeAvatarBinding::circle(1_u32, 16.0);
    /// assert_eq!(binding.body_kind, SceneBodyKind::Dynamic);
    /// ```
    pub fn circle(id: N, radius: f32) -> Self {
        Self {
            node_id: id,
            collider: ColliderSpec::Circle { radius },
            material: PhysicsMaterial::default(),
            body_kind: SceneBodyKind::Dynamic,
        }
    }

    /// A static (anchored) disk of `radius` with the default material.
    pub fn pinned_circle(id: N, radius: f32) -> Self {
        Self {
            body_kind: SceneBodyKind::Static,
            ..Self::circle(id, radius)
        }
    }
}

/// Where a node is when its body is built.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NodeSnapshot<N> {
    /// The node.
    pub id: N,
    /// Its position in world units.
    pub position: Point2D<f32>,
    /// Its radius in world units.
    pub radius: f32,
    /// Whether the host pins it.
    pub pinned: bool,
}

/// A spring between two nodes, as the world wrapper's
/// [`build_edge_joints`](crate::RapierSceneWorld::build_edge_joints) takes it. Other joint
/// kinds go through [`EdgeJoint`](crate::EdgeJoint).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct EdgeJointSpec {
    /// Length at which the spring exerts no force, in world units.
    pub rest_length: f32,
    /// Force per unit of stretch.
    pub stiffness: f32,
    /// Force per unit of relative speed along the edge.
    pub damping: f32,
}

/// What the world makes of a host's node shape (the scene's vocabulary, read here so
/// that the scene needs nothing of the world).
impl NodeShape {
    /// The collider the layout gives a node of this shape: the disk of `radius` (the
    /// node's radius with the default already put in for 0), or the box, rounded where
    /// its corners are, with finite extents from 0 to [`MAX_COORDINATE`] (unusable
    /// values count as 0, a corner radius as at most half the shorter side).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Vector2D, ColliderSpec, NodeShape};
    /// let label = NodeShape::Rect { width: 63.0, height: 20.0, corner_radius: 0.0 };
    /// assert_eq!(label.collider(16.0), ColliderSpec::Rect { half_extents: Vector2D::new(31.5, 10.0) });
    /// assert_eq!(NodeShape::Disk.collider(16.0), ColliderSpec::Circle { radius: 16.0 });
    /// ```
    pub fn collider(&self, radius: f32) -> ColliderSpec {
        match *self {
            NodeShape::Disk => ColliderSpec::Circle { radius },
            NodeShape::Rect {
                width,
                height,
                corner_radius,
            } => {
                let half = |v: f32| (0.5 * finite_or(v, 0.0)).clamp(0.0, MAX_COORDINATE);
                let half_extents = Vector2D::new(half(width), half(height));
                let corner_radius =
                    finite_or(corner_radius, 0.0).clamp(0.0, half_extents.x.min(half_extents.y));
                if corner_radius > 0.0 {
                    ColliderSpec::RoundRect {
                        half_extents,
                        corner_radius,
                    }
                } else {
                    ColliderSpec::Rect { half_extents }
                }
            }
        }
    }
}
