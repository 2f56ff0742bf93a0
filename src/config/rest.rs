//! The rest group ([`RestDetection`]): when the layout counts as at rest and which
//! displacements it reports, read by the report stage (`adapter/sync_out.rs`,
//! `adapter/heat/rest.rs`).

use serde::{Deserialize, Serialize};

/// How long (simulated seconds) every dynamic body must stay under
/// [`RestDetection::speed`] before
/// [`Layout::is_converged`](crate::Layout::is_converged) says so; the same time rapier
/// waits before putting a body to sleep.
pub const REST_TIME: f32 = 0.5;

/// When the layout reports rest, and the smallest displacement it reports. Both take
/// effect at the next call.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::RestDetection;
/// use graph_canvas_layout::RapierLayoutConfig;
/// // Report rest sooner: anything slower than 20 units/s counts as calm.
/// let config = RapierLayoutConfig {
///     rest: RestDetection { speed: 20.0, ..RestDetection::default() },
///     ..RapierLayoutConfig::default()
/// };
/// assert_eq!(config.rest.delta_epsilon, 1e-4);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RestDetection {
    /// Speed, in world units per second, under which a body counts as calm:
    /// [`Layout::is_converged`](crate::Layout::is_converged) reports rest once no
    /// dynamic body was faster for [`REST_TIME`] and rapier
    /// has put every body to sleep (rapier sleeps bodies slower than
    /// `0.05 × length_unit`, 5 units/s at the default, for 0.5 s). Higher reports rest
    /// sooner, with more motion left. Default: `5.0`.
    pub speed: f32,
    /// Displacements shorter than this (world units) are left out of the returned map;
    /// they stay owed to the host and are reported once they add up. Default: `1e-4`.
    pub delta_epsilon: f32,
}

impl Default for RestDetection {
    fn default() -> Self {
        Self {
            speed: 5.0,
            delta_epsilon: 1e-4,
        }
    }
}
