//! Input validation: what counts as bad input, and the error that names it.

use std::collections::HashMap;
use std::fmt;
use std::hash::Hash;

use euclid::default::Point2D;

use crate::input::clusters::{bad_parent, usable, usable_padding, walk_members, Membership};
use crate::input::constraints::usable_gap;
use crate::input::layout::{IdHasher, LayoutExtras};
use crate::input::node_forces::NodeForces;
use crate::input::scene::{CanvasNode, CanvasSceneInput};

/// The largest coordinate a node's position may have, in world units (either sign).
/// Beyond it an `f32` resolves positions to more than 64 units, rapier's contacts and
/// sleep thresholds mean nothing, and the differences and squares its solver takes
/// overflow towards infinity near `f32::MAX`: such a position is bad input, like a NaN.
/// The layout keeps its own positions within it too: a node pushed to the edge stops
/// there.
pub const MAX_COORDINATE: f32 = 1.0e9;

/// Bad input rejected by [`RapierLayout::try_step`](crate::RapierLayout::try_step). A
/// rejected call changes nothing: not the world, not the state, not the counters.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum LayoutError<N> {
    /// A node's position has a NaN or infinite coordinate.
    NonFinitePosition {
        /// The node.
        node: N,
        /// The position the host gave.
        position: Point2D<f32>,
    },
    /// A node's position has a coordinate beyond ±[`MAX_COORDINATE`].
    PositionOutOfRange {
        /// The node.
        node: N,
        /// The position the host gave.
        position: Point2D<f32>,
    },
    /// A node's radius is NaN, infinite, negative or beyond [`MAX_COORDINATE`].
    InvalidRadius {
        /// The node.
        node: N,
        /// The radius the host gave.
        radius: f32,
    },
    /// A node's box ([`NodeShape::Rect`](crate::NodeShape::Rect)) has a side or corner
    /// radius that is NaN, infinite, negative or beyond 2 × [`MAX_COORDINATE`].
    InvalidShape {
        /// The node.
        node: N,
        /// `"width"`, `"height"` or `"corner radius"`.
        part: &'static str,
        /// The value the host gave.
        value: f32,
    },
    /// Two scene nodes share an id.
    DuplicateNode {
        /// The id.
        node: N,
        /// Index of its first occurrence in `scene.nodes`.
        first: usize,
        /// Index of the repeat.
        second: usize,
    },
    /// An edge names a node that is not in the scene.
    UnknownEdgeEndpoint {
        /// Index of the edge in `scene.edges`.
        edge: usize,
        /// The edge's source.
        source: N,
        /// The edge's target.
        target: N,
        /// The endpoint that is missing.
        missing: N,
    },
    /// An edge's weight is negative, NaN or infinite.
    InvalidEdgeWeight {
        /// Index of the edge in `scene.edges`.
        edge: usize,
        /// The edge's source.
        source: N,
        /// The edge's target.
        target: N,
        /// The weight the host gave.
        weight: f32,
    },
    /// A node's entry in [`LayoutExtras::forces`](crate::LayoutExtras::forces) has a
    /// non-finite target or centre, or a negative or non-finite radius or strength.
    InvalidNodeForce {
        /// The node.
        node: N,
        /// The part with the bad value: `"x"`, `"y"`, `"x strength"`, `"y strength"`,
        /// `"ring centre"`, `"ring radius"` or `"ring strength"`.
        part: &'static str,
        /// The value the host gave.
        value: f32,
    },
    /// A constraint in [`LayoutExtras::constraints`](crate::LayoutExtras::constraints)
    /// names a node that is not in the scene.
    UnknownConstraintNode {
        /// Index of the constraint in `extras.constraints`.
        constraint: usize,
        /// The node that is missing.
        node: N,
    },
    /// A separation's gap is negative, NaN or infinite.
    InvalidConstraintGap {
        /// Index of the constraint in `extras.constraints`.
        constraint: usize,
        /// The gap the host gave.
        gap: f32,
    },
    /// A cluster in [`LayoutExtras::clusters`](crate::LayoutExtras::clusters) names a
    /// node that is not in the scene.
    UnknownClusterMember {
        /// Index of the cluster in `extras.clusters`.
        cluster: usize,
        /// The node that is missing.
        node: N,
    },
    /// A cluster's padding is negative, NaN, infinite or beyond [`MAX_COORDINATE`].
    InvalidClusterPadding {
        /// Index of the cluster in `extras.clusters`.
        cluster: usize,
        /// The padding the host gave.
        padding: f32,
    },
    /// A cluster is nested in an index beyond the list, in itself, or in a chain of
    /// parents that comes back to it.
    InvalidClusterParent {
        /// Index of the cluster in `extras.clusters`.
        cluster: usize,
        /// The parent index the host gave.
        parent: usize,
    },
    /// A node is listed by two clusters that do not nest one in the other (a node
    /// belongs to at most one cluster of each level).
    NodeInTwoClusters {
        /// The node.
        node: N,
        /// The cluster that listed it first.
        first: usize,
        /// The cluster that listed it again.
        second: usize,
    },
}

impl<N: fmt::Debug> fmt::Display for LayoutError<N> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LayoutError::NonFinitePosition { node, position } => write!(
                f,
                "node {node:?} has a non-finite position ({}, {})",
                position.x, position.y
            ),
            LayoutError::PositionOutOfRange { node, position } => write!(
                f,
                "node {node:?} has a position ({}, {}) beyond ±{MAX_COORDINATE:e}",
                position.x, position.y
            ),
            LayoutError::InvalidRadius { node, radius } => write!(
                f,
                "node {node:?} has an invalid radius {radius} (must be from 0 to {MAX_COORDINATE:e})"
            ),
            LayoutError::InvalidShape { node, part, value } => write!(
                f,
                "node {node:?} has an invalid box {part} {value} (must be finite, >= 0 and <= {:e})",
                2.0 * MAX_COORDINATE
            ),
            LayoutError::DuplicateNode {
                node,
                first,
                second,
            } => write!(
                f,
                "node id {node:?} appears twice in the scene (nodes[{first}] and nodes[{second}])"
            ),
            LayoutError::UnknownEdgeEndpoint {
                edge,
                source,
                target,
                missing,
            } => write!(
                f,
                "edge {edge} ({source:?} -> {target:?}) names node {missing:?}, which is not in the scene"
            ),
            LayoutError::InvalidEdgeWeight {
                edge,
                source,
                target,
                weight,
            } => write!(
                f,
                "edge {edge} ({source:?} -> {target:?}) has an invalid weight {weight} (must be finite and >= 0)"
            ),
            LayoutError::InvalidNodeForce { node, part, value } => write!(
                f,
                "node {node:?} has an invalid {part} {value} in its forces (targets must be finite, radii and strengths finite and >= 0)"
            ),
            LayoutError::UnknownConstraintNode { constraint, node } => write!(
                f,
                "constraint {constraint} names node {node:?}, which is not in the scene"
            ),
            LayoutError::InvalidConstraintGap { constraint, gap } => write!(
                f,
                "constraint {constraint} has an invalid gap {gap} (must be finite and >= 0)"
            ),
            LayoutError::UnknownClusterMember { cluster, node } => write!(
                f,
                "cluster {cluster} names node {node:?}, which is not in the scene"
            ),
            LayoutError::InvalidClusterPadding { cluster, padding } => write!(
                f,
                "cluster {cluster} has an invalid padding {padding} (must be from 0 to {MAX_COORDINATE:e})"
            ),
            LayoutError::InvalidClusterParent { cluster, parent } => write!(
                f,
                "cluster {cluster} is nested in cluster {parent}, which is beyond the list or nested in it"
            ),
            LayoutError::NodeInTwoClusters {
                node,
                first,
                second,
            } => write!(
                f,
                "node {node:?} is in clusters {first} and {second}, which do not nest one in the other"
            ),
        }
    }
}

impl<N: fmt::Debug> std::error::Error for LayoutError<N> {}

/// Whether the layout can use this node's values: a position within ±[`MAX_COORDINATE`],
/// a radius from 0 (the default radius) to [`MAX_COORDINATE`] and a usable shape.
pub(crate) fn node_is_valid<N>(node: &CanvasNode<N>) -> bool {
    position_in_range(node.position) && radius_ok(node.radius) && node.shape.is_valid()
}

/// A radius from 0 (the default radius) to [`MAX_COORDINATE`]: a disk wider than the
/// range would push its neighbours out of it.
fn radius_ok(radius: f32) -> bool {
    (0.0..=MAX_COORDINATE).contains(&radius)
}

/// Whether both coordinates are within ±[`MAX_COORDINATE`] (and so finite).
pub(crate) fn position_in_range(p: Point2D<f32>) -> bool {
    p.x.abs() <= MAX_COORDINATE && p.y.abs() <= MAX_COORDINATE
}

/// The first problem in `scene`, in scene order: nodes first, then edges, then the
/// forces of the scene's nodes in `extras`.
pub(crate) fn validate<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    extras: &LayoutExtras<N>,
) -> Result<(), LayoutError<N>> {
    match collect(scene, extras, true).pop() {
        Some(problem) => Err(problem),
        None => Ok(()),
    }
}

/// Every problem in `scene` and `extras`, in the order [`validate`] finds the first.
pub(crate) fn problems<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    extras: &LayoutExtras<N>,
) -> Vec<LayoutError<N>> {
    collect(scene, extras, false)
}

/// The problems of `scene` and `extras` in scene order, only the first when `first`.
fn collect<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    extras: &LayoutExtras<N>,
    first_only: bool,
) -> Vec<LayoutError<N>> {
    let mut found = Vec::new();
    macro_rules! report {
        ($problem:expr) => {{
            found.push($problem);
            if first_only {
                return found;
            }
        }};
    }
    let mut first: HashMap<&N, usize, IdHasher> =
        HashMap::with_capacity_and_hasher(scene.nodes.len(), IdHasher::default());
    for (i, node) in scene.nodes.iter().enumerate() {
        if !(node.position.x.is_finite() && node.position.y.is_finite()) {
            report!(LayoutError::NonFinitePosition {
                node: node.id.clone(),
                position: node.position,
            });
        } else if !position_in_range(node.position) {
            report!(LayoutError::PositionOutOfRange {
                node: node.id.clone(),
                position: node.position,
            });
        }
        if !radius_ok(node.radius) {
            report!(LayoutError::InvalidRadius {
                node: node.id.clone(),
                radius: node.radius,
            });
        }
        if let Some((part, value)) = node.shape.problem() {
            report!(LayoutError::InvalidShape {
                node: node.id.clone(),
                part,
                value,
            });
        }
        if let Some(&j) = first.get(&node.id) {
            report!(LayoutError::DuplicateNode {
                node: node.id.clone(),
                first: j,
                second: i,
            });
        } else {
            first.insert(&node.id, i);
        }
    }
    for (i, edge) in scene.edges.iter().enumerate() {
        for end in [&edge.source, &edge.target] {
            if !first.contains_key(end) {
                report!(LayoutError::UnknownEdgeEndpoint {
                    edge: i,
                    source: edge.source.clone(),
                    target: edge.target.clone(),
                    missing: end.clone(),
                });
                // One error per edge: its other end adds nothing a host can act on.
                break;
            }
        }
        if !(edge.weight.is_finite() && edge.weight >= 0.0) {
            report!(LayoutError::InvalidEdgeWeight {
                edge: i,
                source: edge.source.clone(),
                target: edge.target.clone(),
                weight: edge.weight,
            });
        }
    }
    if !extras.forces.is_empty() {
        for (i, node) in scene.nodes.iter().enumerate() {
            if first.get(&node.id) != Some(&i) {
                continue; // a repeat, reported above
            }
            let problem = extras.forces.get(&node.id).and_then(NodeForces::problem);
            if let Some((part, value)) = problem {
                report!(LayoutError::InvalidNodeForce {
                    node: node.id.clone(),
                    part,
                    value,
                });
            }
        }
    }
    for (i, constraint) in extras.constraints.iter().enumerate() {
        if let Some(node) = constraint.nodes().iter().find(|n| !first.contains_key(n)) {
            report!(LayoutError::UnknownConstraintNode {
                constraint: i,
                node: node.clone(),
            });
        }
        if let Some(gap) = constraint.gap().filter(|&g| !usable_gap(g)) {
            report!(LayoutError::InvalidConstraintGap { constraint: i, gap });
        }
    }
    for (i, cluster) in extras.clusters.iter().enumerate() {
        if !usable_padding(cluster.padding()) {
            report!(LayoutError::InvalidClusterPadding {
                cluster: i,
                padding: cluster.padding(),
            });
        }
        if let Some(parent) = bad_parent(&extras.clusters, i) {
            report!(LayoutError::InvalidClusterParent { cluster: i, parent });
        }
    }
    if !extras.clusters.is_empty() {
        let held = usable(&extras.clusters);
        let mut clusters_found = Vec::new();
        let index_of = |n: &N| first.get(n).copied();
        walk_members(
            &extras.clusters,
            &held,
            scene.nodes.len(),
            index_of,
            |c, node, m| {
                clusters_found.push(match m {
                    Membership::Kept(_) => return,
                    Membership::Unknown => LayoutError::UnknownClusterMember {
                        cluster: c,
                        node: node.clone(),
                    },
                    Membership::Clash { other, .. } => LayoutError::NodeInTwoClusters {
                        node: node.clone(),
                        first: other,
                        second: c,
                    },
                })
            },
        );
        for problem in clusters_found {
            report!(problem);
        }
    }
    found
}
