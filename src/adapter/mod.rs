//! The adapter: [`RapierLayout`], which keeps one [`RapierSceneWorld`] alive across
//! frames and syncs the host's scene into it and the motion out of it.
//!
//! The layout's state is split by stage, and each stage borrows only what it touches
//! (the way rapier's pipeline passes its sets): [`Built`](built::Built) (what the world
//! was built from), `Matching` (scene nodes to bodies), `Host` (drives, throws,
//! gravity), [`HeatStage`](heat::HeatStage) (heat, local spread, rest), `Forces`
//! (`simulate/`: the force registry, the disk separation, the rest balance) and
//! `Report` (recovered and skipped). One call, `advance`, runs these stages in order,
//! each in a file or folder of its own:
//! 1. **Plan** (`substeps.rs`): the frame time becomes equal substeps.
//! 2. **Reconfigure** (`reconfigure.rs`): a changed configuration drops the world or
//!    replaces its joints.
//! 3. **Match and edit** (`matching.rs`, `known.rs`, `edits.rs`, `seating.rs`): scene
//!    nodes are matched to bodies; when nodes, edges or pins changed, the world is
//!    patched (or rebuilt, under `stress()` from the stress model's start:
//!    `stress/placement.rs`).
//! 4. **Sync in** (`sync_in.rs`, `drag.rs`): body kinds follow pins, drags and unusable
//!    input, flipped in place; pinned and dragged bodies are driven to the host's
//!    positions; a release throws the node with the pointer's speed; free bodies the
//!    host moved are put where the host put them.
//!    Then the host's per-node forces (`node_forces.rs`): the table the pulls read,
//!    wakes for changed ones, axis locks; and gravity.
//! 5. **Heat** (`heat/`): a disturbance reheats a cooling layout, all of it or near the
//!    disturbance only (`heat/spread.rs`); a halted one stays halted until disturbed.
//! 6. **Simulate** (`substeps.rs`, then `simulate/`): per substep, kinematic drives,
//!    the forces of the registry, one rapier step, the disk separation, the locked axes
//!    held. Then the heat cools and may stop the layout (`heat/rest.rs`).
//! 7. **Sync out** (`sync_out.rs`): each free node's displacement during this call.
//! 8. **Rest** (`heat/rest.rs`): the convergence signal.
//!
//! Snapshots are `resume.rs`; what a call left out, `skipped.rs`.

use std::hash::Hash;

use euclid::default::Vector2D;

use crate::clusters::Clusters;
use crate::config::RapierLayoutConfig;
use crate::constraints::Compiled;
use crate::input::layout::{DeltaMap, Layout, LayoutExtras};
use crate::input::scene::{CanvasSceneInput, CanvasViewport};
use crate::input::validation::{validate, LayoutError};
use crate::profile::{StepProfile, Stopwatch};
use crate::sanitize::finite_or;
use crate::simulate::Forces;
use crate::world::events::SceneEvent;
use crate::world::RapierSceneWorld;

mod built;
mod constraints;
mod drag;
mod edits;
mod heat;
mod known;
mod matching;
mod node_forces;
mod reconfigure;
mod resume;
mod seating;
mod skipped;
mod state;
mod substeps;
mod sync_in;
mod sync_out;

use built::Built;
use drag::Host;
use heat::HeatStage;
use matching::Matching;
pub use resume::LayoutSnapshot;
use skipped::Report;
pub use state::RapierLayoutState;
use substeps::{plan_frame, Substeps};
use sync_out::sync_out;

/// A graph layout on a persistent Rapier2D world.
///
/// Nodes are disks (rotations locked), edges are joints ([`EdgeJoint`](crate::EdgeJoint)),
/// and the world lives from call to call, so momentum carries across frames: a thrown
/// node keeps flying, a pinned node holds, and a topology edit patches the world without
/// stopping everybody else.
///
/// # Example
/// ```
/// use graph_canvas_layout::{
///     euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport,
///     Layout, LayoutExtras, RapierLayout, RapierLayoutState,
/// };
/// let mut scene = CanvasSceneInput::new(
///     vec![CanvasNode::new(1_u32, Point2D::new(0.0, 0.0)), CanvasNode::new(2, Point2D::new(300.0, 0.0))],
///     vec![CanvasEdge::new(1, 2)],
/// );
/// let mut layout = RapierLayout::default();
/// let mut state = RapierLayoutState::default();
/// for _ in 0..120 {
///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &CanvasViewport::default(), &LayoutExtras::default());
///     for node in &mut scene.nodes {
///         if let Some(d) = deltas.get(&node.id) {
///             node.position += *d;
///         }
///     }
/// }
/// let gap = scene.nodes[1].position.x - scene.nodes[0].position.x;
/// assert!(gap < 300.0, "the spring (rest 100) pulled the pair together: gap {gap}");
/// ```
pub struct RapierLayout<N> {
    /// The configuration; changes take effect on the next call (material, shape and
    /// collision changes rebuild the world, joint changes replace the joints).
    pub config: RapierLayoutConfig,
    world: Option<RapierSceneWorld<N>>,
    /// What the world was built from and how often: stages 2 and 3 write it.
    built: Built,
    /// Scene nodes matched to bodies this call: stage 3 writes it, 4 and 7 read it.
    matching: Matching<N>,
    /// Drives, throws and gravity: stage 4 writes it, 6 reads and lands the throws.
    host: Host<N>,
    /// The heat, what this call disturbed, and the rest signal: stages 4 (what was
    /// touched), 5, 6 (cooling) and 8.
    heat: HeatStage,
    /// The forces, their registry and the disk separation: stage 6 (and the host's
    /// per-node table, stage 4).
    forces: Forces<N>,
    /// What the call left out (stage 4) and recovered (stage 6).
    report: Report<N>,
    /// The hard constraints and a flow's edges by slot: stage 4 compiles them, 6 holds
    /// them.
    constraints: Compiled<N>,
    /// The clusters by slot and their boxes: stage 4 compiles them, 6 holds them, the
    /// end of the call notes the boxes.
    clusters: Clusters<N>,
    /// [`RapierLayout::set_pool_awake`].
    pool_awake: bool,
}

impl<N> std::fmt::Debug for RapierLayout<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RapierLayout")
            .field("config", &self.config)
            .field("world", &self.world)
            .field("topology_hash", &self.built.topology_hash)
            .field("rebuilds", &self.built.rebuilds)
            .field("patches", &self.built.patches)
            .field("converged", &self.heat.rest.converged)
            .finish_non_exhaustive()
    }
}

impl<N: Clone + Eq + Hash> Default for RapierLayout<N> {
    fn default() -> Self {
        Self::new(RapierLayoutConfig::default())
    }
}

// ── public API ────────────────────────────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// A layout with `config` and no world yet (it is built on the first non-empty step).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{RapierLayout, RapierLayoutConfig};
    /// let layout = RapierLayout::<u32>::new(RapierLayoutConfig { default_radius: 10.0, ..Default::default() });
    /// assert!(!layout.has_world());
    /// ```
    pub fn new(config: RapierLayoutConfig) -> Self {
        Self {
            config,
            world: None,
            built: Built::default(),
            matching: Matching::default(),
            host: Host::default(),
            heat: HeatStage::default(),
            forces: Forces::default(),
            report: Report::default(),
            constraints: Compiled::default(),
            clusters: Clusters::default(),
            pool_awake: true,
        }
    }

    /// Whether a persistent world exists.
    pub fn has_world(&self) -> bool {
        self.world.is_some()
    }

    /// The hash of the topology (node ids, undirected edges, pins) the world models; 0
    /// before the first build and after an empty scene. Independent of input order.
    pub fn current_topology_hash(&self) -> u64 {
        self.built.topology_hash
    }

    /// The persistent world, if any.
    pub fn world(&self) -> Option<&RapierSceneWorld<N>> {
        self.world.as_ref()
    }

    /// How many times a world was built from scratch.
    pub fn rebuild_count(&self) -> u64 {
        self.built.rebuilds
    }

    /// How many topology changes were applied to the existing world in place.
    pub fn patch_count(&self) -> u64 {
        self.built.patches
    }

    /// Starts measuring where the calls' time goes ([`StepProfile`], from zero), or
    /// stops. Off by default: a call then reads no clock.
    pub fn set_profiling(&mut self, on: bool) {
        self.forces.profile = on.then(StepProfile::default);
    }

    /// The time the calls took, by stage, since [`set_profiling`](Self::set_profiling)
    /// switched profiling on; `None` while it is off.
    pub fn profile(&self) -> Option<StepProfile> {
        self.forces.profile
    }

    /// Under the `parallel` feature, whether another thread of the pool stays awake
    /// through each substep of a call when 2,048 bodies or more are awake: it takes the
    /// parallel parts as they come and yields its core between looks, where otherwise
    /// it falls asleep between parts and takes time to wake for the next. A large
    /// layout's frame on two threads takes less time with it awake
    /// (`docs/performance.md` gives the figures); the cost is that thread's core, busy
    /// through the serial parts of the substeps too (rapier's step among them; it lets
    /// go after 2 ms without work). The results are the same bits either way. Without
    /// the feature it does nothing.
    /// [`LayoutWorker::set_pool_awake`](crate::worker::LayoutWorker) passes it on to a
    /// worker's layout.
    ///
    /// Default: on.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::RapierLayout;
    /// let mut layout = RapierLayout::<u32>::default();
    /// assert!(layout.pool_awake());
    /// layout.set_pool_awake(false); // idle cores between the parallel parts
    /// assert!(!layout.pool_awake());
    /// ```
    pub fn set_pool_awake(&mut self, on: bool) {
        self.pool_awake = on;
    }

    /// Whether the pool stays awake through the substeps ([`set_pool_awake`](Self::set_pool_awake)).
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn pool_awake(&self) -> bool {
        self.pool_awake
    }

    /// Whether `scene` and `extras` differ in topology (node set, edge set, pins) from
    /// what the world models: the check every `step` starts with. While the host passes
    /// the same nodes and edges in the same order it costs one id lookup per node and
    /// one comparison per edge; otherwise it computes the order-free hash (O(n + e)).
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode, CanvasSceneInput, Layout,
    ///     LayoutExtras, RapierLayout, RapierLayoutState};
    /// let mut scene = CanvasSceneInput::new(vec![CanvasNode::new(1_u32, Point2D::origin())], vec![]);
    /// let mut layout = RapierLayout::default();
    /// let extras = LayoutExtras::default();
    /// layout.step(&scene, &mut RapierLayoutState::default(), 0.016, &Default::default(), &extras);
    /// assert!(!layout.topology_changed(&scene, &extras));
    /// scene.nodes.push(CanvasNode::new(2, Point2D::new(50.0, 0.0)));
    /// assert!(layout.topology_changed(&scene, &extras));
    /// ```
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn topology_changed(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> bool {
        self.candidate_topology(scene, extras)
            .is_some_and(|topology| topology.hash != self.built.topology_hash)
    }

    /// The layout's heat under [`RapierLayoutConfig::cooling`] after the last call: 1
    /// at the first build, at least [`Cooling::reheat`](crate::config::Cooling::reheat) after a
    /// disturbance, falling to [`Cooling::min_alpha`](crate::config::Cooling::min_alpha)
    /// over [`Cooling::duration`](crate::config::Cooling::duration). `None` without a schedule.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode, CanvasSceneInput, Layout,
    ///     LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState};
    /// let scene = CanvasSceneInput::new(vec![CanvasNode::new(1_u32, Point2D::origin())], vec![]);
    /// let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
    /// let mut state = RapierLayoutState::default();
    /// for _ in 0..60 {
    ///     layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &LayoutExtras::default());
    /// }
    /// let alpha = layout.heat().unwrap();
    /// assert!(alpha < 0.5 && alpha > 0.1, "one second of a 4.5 s schedule: {alpha}");
    /// ```
    pub fn heat(&self) -> Option<f32> {
        self.config.cooling.map(|_| self.heat.state.alpha)
    }

    /// The heat the forces on `node` act with after the last call: its own after a local
    /// disturbance ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)) while that is
    /// hotter than the layout, else the layout's ([`heat`](Self::heat)). `None` without
    /// a schedule or a body for the node.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode,
    ///     CanvasSceneInput, Layout, LayoutExtras, RapierLayout, RapierLayoutConfig,
    ///     RapierLayoutState};
    /// let mut scene = CanvasSceneInput::new(
    ///     vec![CanvasNode::new(1_u32, Point2D::origin()), CanvasNode::new(2, Point2D::new(100.0, 0.0))],
    ///     vec![CanvasEdge::new(1, 2)],
    /// );
    /// let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
    /// let (mut state, mut extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// for _ in 0..600 {
    ///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    ///     scene.apply_deltas(&deltas);
    /// }
    /// assert!(layout.is_converged(&state));
    /// // Drag node 1: its neighbour heats, the layout does not.
    /// extras.dragging.insert(1);
    /// scene.nodes[0].position.x -= 30.0;
    /// layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    /// assert!(layout.node_heat(&2).unwrap() > 10.0 * layout.heat().unwrap());
    /// ```
    ///
    /// Test and debug introspection, not part of the API: it may change in any release.
    #[doc(hidden)]
    pub fn node_heat(&self, node: &N) -> Option<f32> {
        let alpha = self.heat()?;
        let world = self.world.as_ref()?;
        let own = world.host_at(world.slot_of(node)?).heat;
        Some(own.max(alpha))
    }

    /// Drops `node`'s body (and its joints), so the next call that names the id meets it
    /// as a new node: placed where the host has it, at rest. Call it when an id comes
    /// to mean another node, as a petgraph `StableGraph` reuses a removed node's index
    /// for the next one added: removed and re-added between two calls, the id would
    /// otherwise keep the old body, its position and its velocity. Returns whether there
    /// was a body. Untouched bodies keep their motion.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasNode, CanvasSceneInput, Layout,
    ///     LayoutExtras, RapierLayout, RapierLayoutState};
    /// let mut scene = CanvasSceneInput::new(vec![CanvasNode::new(7_u32, Point2D::origin())], vec![]);
    /// let mut layout = RapierLayout::default();
    /// let (mut state, extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    /// assert!(layout.forget_node(&7));
    /// assert!(!layout.world().unwrap().contains_node(&7));
    /// // Id 7 is another node now: a new body where the host puts it.
    /// scene.nodes[0].position = Point2D::new(500.0, 0.0);
    /// layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    /// assert_eq!(layout.world().unwrap().get_position(&7), Some(Point2D::new(500.0, 0.0)));
    /// ```
    pub fn forget_node(&mut self, node: &N) -> bool {
        let Some(world) = self.world.as_mut() else {
            return false;
        };
        if !world.remove_node(node) {
            return false;
        }
        // The next call works the topology out again and inserts the id anew.
        self.built.topology_hash = 0;
        self.matching.forget_edges();
        self.host.flights.retain(|flight| &flight.id != node);
        true
    }

    /// Nodes whose bodies went non-finite during the last call (rapier quarantined
    /// them) and were put back, at rest, where they last were valid.
    pub fn recovered_nodes(&self) -> &[N] {
        &self.report.recovered
    }

    /// Drains the contact events recorded since the last call (empty unless
    /// [`Contacts::events`](crate::config::Contacts::events) is on).
    pub fn drain_events(&mut self) -> Vec<SceneEvent<N>> {
        self.world
            .as_mut()
            .map(RapierSceneWorld::read_events)
            .unwrap_or_default()
    }

    /// `step` with validation: bad input is rejected with an error that names the node
    /// or edge, and the call changes nothing.
    ///
    /// # Errors
    /// The first [`LayoutError`] in scene order for a non-finite position or one beyond
    /// ±[`MAX_COORDINATE`](crate::MAX_COORDINATE), a NaN, infinite or negative radius, a
    /// repeated node id, an edge naming a node that is not in the scene, a negative or
    /// non-finite edge weight, or a bad value in [`LayoutExtras::forces`].
    /// [`RapierLayout::problems`] lists them all.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput,
    ///     CanvasViewport, LayoutError, LayoutExtras, RapierLayout, RapierLayoutState};
    /// let scene = CanvasSceneInput::new(vec![CanvasNode::new(1_u32, Point2D::origin())], vec![CanvasEdge::new(1, 9)]);
    /// let mut layout = RapierLayout::default();
    /// let mut state = RapierLayoutState::default();
    /// let err = layout.try_step(&scene, &mut state, 1.0 / 60.0, &CanvasViewport::default(), &LayoutExtras::default());
    /// assert!(matches!(err, Err(LayoutError::UnknownEdgeEndpoint { missing: 9, .. })));
    /// assert_eq!(state.step_count, 0);
    /// assert!(!layout.has_world());
    /// ```
    pub fn try_step(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        _viewport: &CanvasViewport,
        extras: &LayoutExtras<N>,
    ) -> Result<DeltaMap<N>, LayoutError<N>> {
        validate(scene, extras)?;
        Ok(self.advance(scene, state, dt, extras, None))
    }
}

impl<N: Clone + Eq + Hash> Layout<N> for RapierLayout<N> {
    type State = RapierLayoutState;

    /// Advances the layout by `dt` seconds of frame time and returns each free node's
    /// displacement.
    ///
    /// `dt` is the frame's real elapsed time (what drag speeds are measured against);
    /// the physics advances in fixed substeps of at most [`RapierLayoutState::dt`]
    /// (default 1/60 s) that cover it, up to
    /// [`max_frame_time`](crate::config::FrameLimits::max_frame_time). `viewport` is not read by
    /// this layout (it is part of the [`Layout`] contract for layouts that lay out only
    /// what is visible): pass `&CanvasViewport::default()`.
    ///
    /// Never panics on bad input: a node with a non-finite position or an invalid
    /// radius is left out for this call (a node that already has a body stays where it
    /// is, with no delta, until the host gives it usable values), repeated ids after the
    /// first are ignored, edges naming missing nodes are dropped, and bad weights and
    /// forces are left out. [`RapierLayout::skipped`] lists what the call left out.
    fn step(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        _viewport: &CanvasViewport,
        extras: &LayoutExtras<N>,
    ) -> DeltaMap<N> {
        self.advance(scene, state, dt, extras, None)
    }

    /// True when the layout was at rest after the last call: a world exists, no dynamic body moved faster
    /// than [`RestDetection::speed`](crate::config::RestDetection::speed) for [`REST_TIME`](crate::config::REST_TIME) seconds of simulated
    /// time, nothing (a drag, a release, a host move, a topology change) disturbed it
    /// meanwhile, and every dynamic body is asleep; or a [`Cooling`](crate::config::Cooling)
    /// schedule has ended and halted the world. Once true, calls report no motion until
    /// something disturbs the layout. Nodes the last call left out
    /// ([`RapierLayout::skipped`]) do not count: the layout can rest while one waits for
    /// usable values.
    ///
    /// It speaks of the last call only: after an edit, a drag or a pin it still reports
    /// what it did before, until a `step` has seen the change (step first, then ask; see
    /// [`Layout::is_converged`]). `state` is not read: the rest state is the layout's own.
    fn is_converged(&self, _state: &RapierLayoutState) -> bool {
        self.world.is_some() && self.heat.rest.converged
    }
}

// ── the stages of one call ────────────────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// One call; `known` lists the scene nodes a caller changed since the last call
    /// (`known.rs`), `None` for a host's scene.
    fn advance(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        extras: &LayoutExtras<N>,
        known: Option<&[usize]>,
    ) -> DeltaMap<N> {
        let watch = Stopwatch::start(&self.forces.profile);
        self.heat.stepped = false;
        let deltas = self.advance_untimed(scene, state, dt, extras, known);
        self.note_reports(extras.clusters.len());
        watch.stop(&mut self.forces.profile, |p| {
            p.calls += 1;
            &mut p.total
        });
        deltas
    }

    /// [`advance`](Self::advance), the call's stages.
    fn advance_untimed(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        extras: &LayoutExtras<N>,
        known: Option<&[usize]>,
    ) -> DeltaMap<N> {
        state.step_count = state.step_count.wrapping_add(1);
        if scene.nodes.is_empty() {
            self.drop_world();
            (self.matching.bad_nodes, self.matching.topology_problems) = (0, 0);
            self.forces.targets.problems = 0;
            self.note_skipped(scene, extras);
            return DeltaMap::default();
        }
        // 1. Plan.
        let (plan, joint_dt) = plan_frame(&self.config, state, dt);
        self.built.joint_dt = joint_dt;
        self.heat.spread.clear();
        // 2. Reconfigure.
        let reconfigured = self.apply_config_changes();
        // A layout that starts anew unfolds as a new one does.
        let unfolding_before = self.heat.state.unfolding && !self.built.start_again;
        let cold = self.builds_cold();
        // 3. Match and edit. A caller's list stands for the matching only while nothing
        // was reconfigured.
        let known =
            known.filter(|changed| !reconfigured && self.rematch_known(scene, extras, changed));
        let mut disturbed = known.is_none() && self.sync_topology(scene, extras);
        // 4. Sync in.
        disturbed |= self.sync_host(scene, extras, plan.frame_dt, known);
        disturbed |= self.sync_constraints(scene, extras);
        if cold {
            // NOTE: after the sync, which flips pinned bodies and reads the forces.
            disturbed = self.settle_cold();
        }
        self.note_skipped(scene, extras);
        let gravity = Vector2D::new(
            finite_or(state.gravity_x, 0.0),
            finite_or(state.gravity_y, 0.0),
        );
        let (world, spread) = (self.world.as_mut(), &mut self.heat.spread);
        disturbed |= self.host.sync_gravity(gravity, reconfigured, world, spread);
        // 5. Heat.
        let (world, forces) = (self.world.as_mut(), &mut self.forces);
        if !self
            .heat
            .start_frame(&self.config, disturbed, unfolding_before, world, forces)
        {
            return self.halted_frame(state, &plan);
        }
        let awake_before = self
            .world
            .as_ref()
            .map_or(0, RapierSceneWorld::awake_body_count);
        // 6. Simulate, then cool.
        if let Some(world) = self.world.as_mut() {
            let heat = self.heat.heat_world(&self.config, Some(&mut *world));
            let substeps = Substeps {
                config: &self.config,
                world,
                forces: &mut self.forces,
                drives: &self.host.drives,
                constraints: &mut self.constraints,
                clusters: &mut self.clusters,
                pool_awake: self.pool_awake,
            };
            substeps.run(&plan, gravity, heat);
        }
        self.host.land_flights(&self.config, self.world.as_mut());
        self.report.collect_recovered(self.world.as_mut());
        state.simulated_time += f64::from(plan.simulated());
        let in_flight = !self.host.flights.is_empty();
        let (world, forces) = (self.world.as_mut(), &mut self.forces);
        let simulated = plan.simulated();
        self.heat
            .cool(&self.config, simulated, world, forces, in_flight);
        self.hold_constraints();
        // 7. Sync out.
        let report = sync_out(
            scene,
            awake_before,
            &self.config.rest,
            self.world.as_mut(),
            &mut self.matching,
            (&mut self.forces, &mut self.constraints, &mut self.clusters),
        );
        // 8. Rest.
        self.heat.track_rest(
            &self.config,
            disturbed,
            &report,
            simulated,
            self.world.as_mut(),
        );
        report.deltas
    }
}
