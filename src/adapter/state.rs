//! [`RapierLayoutState`]: what the host keeps (and may persist) between calls.

use serde::{Deserialize, Serialize};

/// State the host keeps for a [`RapierLayout`](crate::RapierLayout) between frames.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RapierLayoutState {
    /// Number of `step` calls made with this state.
    pub step_count: u64,
    /// The fixed physics timestep in seconds, the longest substep a call takes; `0.0`
    /// (or any unusable value) means 1/60. Not the frame time: that is `step`'s own `dt`
    /// argument, which a call covers in substeps of at most this length. A shorter
    /// timestep buys accuracy for substeps (cost).
    pub dt: f32,
    /// Gravity along x, in world units per second². Default: `0.0`.
    pub gravity_x: f32,
    /// Gravity along y, in world units per second² (canvas y grows downwards).
    /// Default: `0.0`.
    pub gravity_y: f32,
    /// Simulated time so far, in seconds.
    pub simulated_time: f64,
}
