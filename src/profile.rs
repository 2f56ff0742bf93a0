//! Where a layout's calls spend their time ([`StepProfile`]), measured only while a
//! host asks for it ([`RapierLayout::set_profiling`](crate::RapierLayout::set_profiling)).

use std::time::{Duration, Instant};

/// The time a [`RapierLayout`](crate::RapierLayout)'s calls took, by stage, summed over
/// the calls since profiling was switched on
/// ([`RapierLayout::set_profiling`](crate::RapierLayout::set_profiling)).
///
/// Wall-clock time on the calling thread (the stages that run on rayon's pool under
/// the `parallel` feature count the time until the pool is done). Compare two
/// configurations, or one and two threads, in the same session: a shared machine's
/// load moves the figures from one session to the next (`docs/performance.md` says by
/// how much).
///
/// # Example
/// ```
/// use graph_canvas_layout::{
///     CanvasNode, CanvasSceneInput, CanvasViewport, Layout, LayoutExtras, RapierLayout,
///     RapierLayoutConfig, RapierLayoutState,
/// };
/// use graph_canvas_layout::euclid::default::Point2D;
///
/// let nodes = (0..20_u32).map(|i| CanvasNode::new(i, Point2D::new(i as f32 * 3.0, 0.0)));
/// let scene = CanvasSceneInput::new(nodes.collect(), vec![]);
/// let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
/// let mut state = RapierLayoutState::default();
/// layout.set_profiling(true);
/// for _ in 0..10 {
///     let viewport = CanvasViewport::default();
///     layout.step(&scene, &mut state, 1.0 / 60.0, &viewport, &LayoutExtras::default());
/// }
/// let profile = layout.profile().expect("profiling is on");
/// assert_eq!(profile.calls, 10);
/// let stages = profile.forces + profile.contacts + profile.rapier + profile.constraints;
/// assert!(stages <= profile.total);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct StepProfile {
    /// Calls measured.
    pub calls: u64,
    /// Substeps simulated (a call simulates none while the layout rests).
    pub substeps: u64,
    /// The whole of every call: the stages below, the host's scene matched and read in,
    /// the deltas written out and the rest bookkeeping.
    pub total: Duration,
    /// The layout's own forces: repulsion (Barnes–Hut), springs applied as forces, the
    /// stress model's terms, the host's per-node forces, centring and groups.
    pub forces: Duration,
    /// The layout's own contacts ([`ContactModel::Disks`](crate::config::ContactModel)): the
    /// pairs found and solved before rapier's step, and relaxed after it.
    pub contacts: Duration,
    /// rapier's own steps (integration, and its contacts and joints where the
    /// configuration leaves them to rapier).
    pub rapier: Duration,
    /// The hard constraints (a [`Flow`](crate::config::Flow)'s edges and
    /// [`LayoutExtras::constraints`](crate::LayoutExtras::constraints)): the projection
    /// after each substep, and the halt's last settling.
    pub constraints: Duration,
}

/// A stage's start, when profiling is on.
pub(crate) struct Stopwatch(Option<Instant>);

impl Stopwatch {
    /// Starts a stage; reads the clock only when `profile` is on.
    pub(crate) fn start(profile: &Option<StepProfile>) -> Self {
        Self(profile.is_some().then(Instant::now))
    }

    /// Adds the time since [`start`](Self::start) to the stage `stage` picks.
    pub(crate) fn stop(
        self,
        profile: &mut Option<StepProfile>,
        stage: impl FnOnce(&mut StepProfile) -> &mut Duration,
    ) {
        if let (Some(started), Some(profile)) = (self.0, profile.as_mut()) {
            *stage(profile) += started.elapsed();
        }
    }
}
