//! The frame group ([`FrameLimits`]): how much simulated time one call may run, read by
//! the frame plan (`timestep.rs`, `adapter/substeps.rs`).

use serde::{Deserialize, Serialize};

/// How much one call may simulate. Both take effect at the next call.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::FrameLimits;
/// use graph_canvas_layout::RapierLayoutConfig;
/// // A call never runs more than 4 substeps: after a stall, the layout resumes.
/// let config = RapierLayoutConfig {
///     frame: FrameLimits { max_substeps: 4, ..FrameLimits::default() },
///     ..RapierLayoutConfig::default()
/// };
/// assert_eq!(config.frame.max_frame_time, 0.25);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FrameLimits {
    /// Longest frame time simulated in one call, in seconds; time beyond it is dropped
    /// (after a stall the layout resumes instead of fast-forwarding). Default: `0.25`.
    pub max_frame_time: f32,
    /// Most substeps one call runs. With the default 1/60 s timestep, 16 substeps cover
    /// the default `max_frame_time`. Lower it to bound the worst-case cost of a call;
    /// simulated time beyond `max_substeps × timestep` is dropped. At most 1,024 (a
    /// larger count is taken as 1,024). Default: `16`.
    pub max_substeps: u32,
}

impl Default for FrameLimits {
    fn default() -> Self {
        Self {
            max_frame_time: 0.25,
            max_substeps: 16,
        }
    }
}
