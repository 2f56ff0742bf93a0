//! What the world was built from: the configuration it was built with, the topology and
//! weights it models, how often it was rebuilt or patched, and the timestep its joints
//! are tuned for. The reconfigure and topology stages (`reconfigure.rs`, `edits.rs`)
//! write it; snapshots keep it.

use crate::config::RapierLayoutConfig;
use crate::timestep::DEFAULT_TIMESTEP;

/// The world's making, as the reconfigure and topology stages keep it.
#[derive(Clone, Debug)]
pub(super) struct Built {
    /// The configuration the world was built with.
    pub(super) applied: Option<RapierLayoutConfig>,
    /// The order-free hash of the topology the world models (0: none yet, or to be
    /// worked out again).
    pub(super) topology_hash: u64,
    /// The order-free hash of the edge weights the world's joints were built with.
    pub(super) weight_hash: u64,
    pub(super) rebuilds: u64,
    pub(super) patches: u64,
    /// The timestep new and re-tuned joints are tuned for: this call's fixed timestep.
    pub(super) joint_dt: f32,
    /// Built by [`RapierLayout::at_rest`](crate::RapierLayout::at_rest): the first world
    /// starts cold.
    pub(super) cold_start: bool,
    /// The next world starts anew, as the first one did (the layers turned off).
    pub(super) start_again: bool,
}

impl Default for Built {
    fn default() -> Self {
        Self {
            applied: None,
            topology_hash: 0,
            weight_hash: 0,
            rebuilds: 0,
            patches: 0,
            joint_dt: DEFAULT_TIMESTEP,
            cold_start: false,
            start_again: false,
        }
    }
}
