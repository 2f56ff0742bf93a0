//! Which body kind a node gets ([`BodyKindPolicy`]). What an edge becomes
//! ([`EdgeJoint`](crate::EdgeJoint)) is the world's vocabulary (`world/edge_joint.rs`),
//! and how springs are solved and tuned is the springs group (`springs.rs`).

use serde::{Deserialize, Serialize};

/// Which body kind pinned (and all) nodes get. Dragged nodes are always driven
/// kinematically to the host's position, except pinned nodes under
/// [`PinnedStatic`](BodyKindPolicy::PinnedStatic), which stay anchors while the host
/// moves them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum BodyKindPolicy {
    /// Pinned nodes are static bodies: anchors that other bodies rest against and that
    /// joints pull on without moving them. Free nodes are dynamic.
    #[default]
    PinnedStatic,
    /// Pinned nodes are kinematic bodies that follow the host's position and push what
    /// they meet with the speed of that motion. Free nodes are dynamic.
    PinnedKinematic,
    /// Every node is kinematic: the layout only follows the host (no physics motion,
    /// no deltas). Useful to keep a world for contact queries without simulating.
    AllKinematic,
}
