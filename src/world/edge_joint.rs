//! What each edge becomes in the physics world ([`EdgeJoint`]): the world's own
//! vocabulary, which the configuration names
//! ([`RapierLayoutConfig::edge_joint`](crate::RapierLayoutConfig::edge_joint)) and the
//! world's edge API takes. The rapier joints themselves are built in `rapier_joint.rs`;
//! springs applied as forces in `forces/springs.rs`.

use serde::{Deserialize, Serialize};

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

impl From<EdgeJointSpec> for EdgeJoint {
    fn from(spec: EdgeJointSpec) -> Self {
        EdgeJoint::Spring {
            rest_length: spec.rest_length,
            stiffness: spec.stiffness,
            damping: spec.damping,
        }
    }
}
