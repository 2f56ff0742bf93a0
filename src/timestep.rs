//! Frame time to substeps: how one call's `dt` becomes equal rapier steps.

use crate::sanitize::positive_or;

/// The fixed timestep used when the state's is unset (`0.0`) or unusable.
pub const DEFAULT_TIMESTEP: f32 = 1.0 / 60.0;

/// Shortest substep and frame time used, in seconds: shorter (subnormal) values would
/// make rapier's `1 / dt` infinite.
pub const MIN_TIMESTEP: f32 = 1.0e-9;

/// The fixed timestep a state's `dt` stands for: itself when finite and positive, else
/// [`DEFAULT_TIMESTEP`].
pub(crate) fn fixed_timestep(dt: f32) -> f32 {
    positive_or(dt, DEFAULT_TIMESTEP)
}

/// How one call advances simulated time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepPlan {
    /// Number of rapier steps this call runs (at least 1).
    pub substeps: u32,
    /// Length of each of them, in seconds; never longer than the fixed timestep.
    pub substep_dt: f32,
    /// The frame's elapsed time used to measure drag speeds, in seconds: `dt` when it is
    /// a positive finite number, else the fixed timestep.
    pub frame_dt: f32,
}

/// The most substeps one call takes, whatever `max_substeps` says: a bound on a call's
/// cost (17 s of simulated time at 60 Hz).
const MAX_FRAME_SUBSTEPS: u32 = 1024;

impl StepPlan {
    /// Simulated time this call advances: `substeps × substep_dt`.
    pub fn simulated(&self) -> f32 {
        self.substeps as f32 * self.substep_dt
    }

    /// The plan for a call with frame time `dt`, fixed timestep `fixed_dt`, at most
    /// `max_frame_time` seconds and `max_substeps` steps per call.
    ///
    /// `dt > 0` (finite): `min(dt, max_frame_time)` in `ceil(time / fixed_dt)` equal
    /// substeps, at most `max_substeps` of them (time beyond is dropped, never
    /// integrated in one longer step). `dt` zero, negative or non-finite: one fixed step.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::StepPlan;
    /// let plan = StepPlan::new(0.05, 1.0 / 60.0, 0.25, 16);
    /// assert_eq!(plan.substeps, 3);
    /// assert!((plan.substep_dt - 0.05 / 3.0).abs() < 1e-7);
    /// let idle = StepPlan::new(f32::NAN, 1.0 / 60.0, 0.25, 16);
    /// assert_eq!((idle.substeps, idle.substep_dt), (1, 1.0 / 60.0));
    /// ```
    pub fn new(dt: f32, fixed_dt: f32, max_frame_time: f32, max_substeps: u32) -> Self {
        let fixed = fixed_timestep(fixed_dt);
        if !(dt.is_finite() && dt > 0.0) {
            return Self {
                substeps: 1,
                substep_dt: fixed,
                frame_dt: fixed,
            };
        }
        let cap = positive_or(max_frame_time, 0.25);
        let max_substeps = max_substeps.clamp(1, MAX_FRAME_SUBSTEPS);
        let time = dt.min(cap).max(MIN_TIMESTEP);
        let dt = dt.max(MIN_TIMESTEP);
        // A hair of tolerance so 0.05 s at 1/60 s is 3 substeps, not 4.
        let wanted = ((time / fixed) * (1.0 - 1e-5)).ceil().max(1.0);
        if wanted > max_substeps as f32 {
            Self {
                substeps: max_substeps,
                substep_dt: fixed,
                frame_dt: dt,
            }
        } else {
            let substeps = wanted as u32;
            Self {
                substeps,
                substep_dt: (time / substeps as f32).min(fixed),
                frame_dt: dt,
            }
        }
    }
}
