//! How groups of nodes ([`NodeForces::group`](crate::NodeForces::group)) hold together
//! and keep apart; the force itself is `forces/group.rs`.

use serde::{Deserialize, Serialize};

/// The group force: every node with a group key is pulled toward its group's centre of
/// mass, and groups may push each other apart, so a categorical attribute lays out as
/// clusters (cosmos' `setPointClusters`, d3's cluster forces).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct GroupForce {
    /// The pull toward the group's centre, in d3-force's strength units as
    /// [`AxisTarget::strength`](crate::scene::AxisTarget::strength): the share of the distance
    /// closed per 1/60 s, critically damped and implicit. Stronger packs a group
    /// tighter against its own springs and the repulsion, until its disks touch; weaker
    /// lets the edges between groups mix them. Costs one pass over the grouped nodes per
    /// substep. Default: `0.05`.
    pub pull: f32,
    /// How hard groups push each other apart: each grouped node is pushed from the
    /// centre of every other group with `separation × (that group's size) / distance`
    /// per 1/60 s tick in d3-force's many-body units (its default strength is 30 per
    /// node), scaled by the heat like the repulsion. Costs `groups²` per substep; `0`
    /// turns it off. Default: `0.0`.
    pub separation: f32,
}

impl Default for GroupForce {
    fn default() -> Self {
        Self {
            pull: 0.05,
            separation: 0.0,
        }
    }
}
