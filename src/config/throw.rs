//! The throw group ([`Throw`]): what a released drag throws and how a thrown node
//! flies, read by the host sync (`adapter/sync_in.rs`, `adapter/drag.rs`).

use serde::{Deserialize, Serialize};

#[cfg(doc)]
use crate::config::RestDetection;

/// What a release throws, and how the thrown node is damped in flight. Both take effect
/// at the next call.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::Throw;
/// use graph_canvas_layout::RapierLayoutConfig;
/// // Throws fly until their springs turn them, damped at 1 per second.
/// let config = RapierLayoutConfig {
///     throw: Throw { flight_damping: Some(1.0), ..Throw::default() },
///     ..RapierLayoutConfig::default()
/// };
/// assert_eq!(config.throw.window, 0.05);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Throw {
    /// How long, in seconds, a dragged node's pointer may go without reporting motion
    /// and still count as moving. A release throws the node with the pointer's velocity
    /// over its last reported move: the move's length over the time since the report
    /// before it, which takes in the frames without motion that pointers leave when they
    /// report at their own rate (a 60 Hz mouse on a 120 Hz display moves a drag every
    /// other frame), or over the move's own frame after a pause longer than the window
    /// (a flick from rest). A release after the pointer stood still for longer than the
    /// window throws nothing. Frame times are the real `dt` passed to
    /// [`step`](crate::Layout::step) (the fixed timestep when it is unusable). Longer
    /// windows bridge longer gaps between reports and still throw a node the hand paused
    /// on briefly before letting go; `0` counts only a move in the frame just before the
    /// release. Default: `0.05` (three frames at 60 Hz).
    pub window: f32,
    /// Linear damping, per second, of a thrown node from its release until it turns
    /// back toward where it was let go (or slows below [`RestDetection::speed`]),
    /// instead of the material's; `None` keeps the material's throughout. A layout
    /// damped as heavily as d3-force (20 per second in
    /// [`force_directed`](crate::RapierLayoutConfig::force_directed)) stops a throw of
    /// 1,800 units/s within 90 units; with little damping in flight the node flies until
    /// its springs turn it, and the material's damping then brings it back without
    /// overshoot. Lower flies further; the material's own value turns the feature off.
    /// Costs nothing but a check per thrown node per call. Default: `None`
    /// ([`force_directed`](crate::RapierLayoutConfig::force_directed) uses `1.0`).
    pub flight_damping: Option<f32>,
}

impl Default for Throw {
    fn default() -> Self {
        Self {
            window: 0.05,
            flight_damping: None,
        }
    }
}
