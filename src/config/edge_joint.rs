//! What an edge becomes in the physics world ([`EdgeJoint`]) and which body kind a node
//! gets ([`BodyKindPolicy`]). How springs are solved and tuned is the springs group
//! (`springs.rs`); the rapier joints themselves are built in `world::rapier_joint`,
//! springs applied as forces in `forces/springs.rs`.

use serde::{Deserialize, Serialize};

use crate::config::EdgeWeight;
use crate::world::bindings::EdgeJointSpec;

/// What each edge becomes in the physics world.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum EdgeJoint {
    /// A spring that pulls toward `rest_length` from both sides: stretched, it pulls
    /// the ends together; compressed, it pushes them apart.
    ///
    /// `stiffness` is force per unit of stretch and `damping` force per unit of
    /// relative speed, with mass from density × disk area. The spring is solved
    /// implicitly. A stiffness above what the timestep resolves,
    /// [`max_resolved_stiffness`](crate::world::max_resolved_stiffness) `= m / dt²` (about 7,200
    /// for two default nodes at 1/60 s), acts as that limit: stiffer springs would
    /// correct their whole stretch within one step and fight each other in any graph
    /// whose edges cannot all have their rest length. The limit is taken when the joint
    /// is built, from the masses and the timestep of that call.
    Spring {
        /// Length at which the spring exerts no force.
        rest_length: f32,
        /// Force per unit of stretch.
        stiffness: f32,
        /// Force per unit of relative speed along the edge.
        damping: f32,
    },
    /// A rope: no force at all while the ends are closer than `max_length`; past it, a
    /// limit resists further stretching with `stiffness` (force per unit of stretch,
    /// critically damped, so the stretch is dissipated, not bounced). A very large
    /// stiffness makes it inextensible.
    Rope {
        /// Length at which the rope becomes taut.
        max_length: f32,
        /// Force per unit of stretch past `max_length`.
        stiffness: f32,
    },
    /// A rod: holds the ends at `length` both ways (a stiff, critically damped
    /// constraint).
    Distance {
        /// The held distance.
        length: f32,
    },
    /// No joint at all: the edge is topology only (it still counts in the topology
    /// hash), and the world models nothing for it.
    None,
}

impl Default for EdgeJoint {
    /// `Spring { rest_length: 100, stiffness: 50, damping: 1 }`.
    fn default() -> Self {
        EdgeJoint::Spring {
            rest_length: 100.0,
            stiffness: 50.0,
            damping: 1.0,
        }
    }
}

impl EdgeJoint {
    /// This joint for an edge of weight `weight` under `mapping` ([`EdgeWeight`]): a
    /// weight that is not positive (0, negative, NaN) gives no joint. Weight 1 gives
    /// the joint itself, bit for bit.
    pub(crate) fn weighted(self, weight: f32, mapping: EdgeWeight) -> EdgeJoint {
        if !(weight > 0.0 && weight.is_finite()) {
            return EdgeJoint::None;
        }
        match (mapping, self) {
            (
                EdgeWeight::Strength,
                EdgeJoint::Spring {
                    rest_length,
                    stiffness,
                    damping,
                },
            ) => EdgeJoint::Spring {
                rest_length,
                stiffness: stiffness * weight,
                damping: damping * weight,
            },
            (
                EdgeWeight::Strength,
                EdgeJoint::Rope {
                    max_length,
                    stiffness,
                },
            ) => EdgeJoint::Rope {
                max_length,
                stiffness: stiffness * weight,
            },
            (
                EdgeWeight::Length,
                EdgeJoint::Spring {
                    rest_length,
                    stiffness,
                    damping,
                },
            ) => EdgeJoint::Spring {
                rest_length: rest_length * weight,
                stiffness,
                damping,
            },
            (
                EdgeWeight::Length,
                EdgeJoint::Rope {
                    max_length,
                    stiffness,
                },
            ) => EdgeJoint::Rope {
                max_length: max_length * weight,
                stiffness,
            },
            (EdgeWeight::Length, EdgeJoint::Distance { length }) => EdgeJoint::Distance {
                length: length * weight,
            },
            (_, kind) => kind,
        }
    }
}

impl From<EdgeJointSpec> for EdgeJoint {
    fn from(spec: EdgeJointSpec) -> Self {
        EdgeJoint::Spring {
            rest_length: spec.rest_length,
            stiffness: spec.stiffness,
            damping: spec.damping,
        }
    }
}

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
