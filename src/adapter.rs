//! The adapter: [`RapierLayout`], which keeps one [`RapierSceneWorld`] alive across
//! frames and syncs the host's scene into it and the motion out of it.
//!
//! Each call runs four passes:
//! 1. **Topology**: match scene nodes to bodies; when nodes, edges or pins changed,
//!    patch the world (or rebuild it, by configuration).
//! 2. **Sync in**: body kinds follow pins, drags and unusable input, flipped in place;
//!    pinned and dragged bodies are driven to the host's positions; free bodies the host
//!    moved are put where the host put them.
//! 3. **Simulate**: the frame time in equal substeps.
//! 4. **Sync out**: each free node's displacement during this call.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::{RigidBodyType, Vector};
use serde::{Deserialize, Serialize};

use crate::bindings::{ColliderSpec, NodeAvatarBinding, SceneBodyKind};
use crate::config::{BodyKindPolicy, EdgeJoint, RapierLayoutConfig, TopologyUpdate};
use crate::events::SceneEvent;
use crate::forces::Forces;
use crate::input::scene::{CanvasNode, CanvasSceneInput, CanvasViewport};
use crate::input::topology::Topology;
use crate::input::validation::{node_is_valid, validate, LayoutError};
use crate::joints::scaled_spring;
use crate::layout::{DeltaMap, IdHasher, Layout, LayoutExtras};
use crate::sanitize::{finite_or, positive_or};
use crate::timestep::{fixed_timestep, StepPlan, DEFAULT_TIMESTEP};
use crate::world::{RapierSceneWorld, WorldOptions};

/// How long (simulated seconds) every dynamic body must stay under
/// [`RapierLayoutConfig::rest_speed`] before [`Layout::is_converged`] says so; the same
/// time rapier waits before putting a body to sleep.
pub const REST_TIME: f32 = 0.5;
/// Host moves of kinematic and fixed bodies per call that each wake the sleeping bodies
/// in their path; beyond them, every sleeping body is woken once.
const MAX_SWEEPS: usize = 16;

/// State the host keeps for a [`RapierLayout`] between frames.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RapierLayoutState {
    /// Number of `step` calls made with this state.
    pub step_count: u64,
    /// The fixed physics timestep in seconds; `0.0` (or any unusable value) means 1/60.
    pub dt: f32,
    /// Gravity along x, in world units per second². Default: `0.0`.
    pub gravity_x: f32,
    /// Gravity along y, in world units per second² (canvas y grows downwards).
    /// Default: `0.0`.
    pub gravity_y: f32,
    /// Simulated time so far, in seconds.
    pub simulated_time: f64,
}

/// Where a scene node stands this call, found in the topology pass.
#[derive(Clone, Copy, Debug)]
struct NodeMatch {
    /// Its body's slot, or `NO_SLOT` (no body, or a repeated id).
    slot: u32,
    valid: bool,
    pinned: bool,
}

const NO_SLOT: u32 = u32::MAX;

/// A kinematic body moving to the host's position over this call's substeps.
#[derive(Clone, Copy, Debug)]
struct Drive {
    slot: u32,
    from: Point2D<f32>,
    to: Point2D<f32>,
}

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
    topology_hash: u64,
    rebuilds: u64,
    patches: u64,
    /// Incremented per matching pass; marks which bodies the scene named.
    stamp: u64,
    /// The configuration the world was built with.
    applied: Option<RapierLayoutConfig>,
    /// The edges of the scene the topology was last computed from, to skip that work
    /// while the host passes the same edges.
    cached_edges: Vec<(N, N)>,
    matches: Vec<NodeMatch>,
    /// Last pass's matches, kept to reuse slots and the buffer.
    previous_matches: Vec<NodeMatch>,
    drives: Vec<Drive>,
    calm_time: f32,
    converged: bool,
    forces: Forces<N>,
    recovered: Vec<N>,
    /// This call's fixed timestep; new joints are tuned for it.
    fixed_dt: f32,
    /// The layout's heat under [`RapierLayoutConfig::cooling`], in `(0, 1]`.
    alpha: f32,
    /// Simulated time the heat has spent at its floor since the last reheat.
    cold_time: f32,
    /// Set by the cold stop: the world is not stepped until a disturbance, as d3-force
    /// stops its timer.
    halted: bool,
    /// The first unfolding: from the first build until the heat first reaches its floor
    /// (or the layout rests), when [`Cooling::first_contact_heat`](crate::Cooling) and
    /// [`Cooling::hot_contact_frequency`](crate::Cooling) apply.
    unfolding: bool,
    /// The gravity of the last call: a change is a disturbance.
    gravity: Vector2D<f32>,
}

impl<N> std::fmt::Debug for RapierLayout<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RapierLayout")
            .field("config", &self.config)
            .field("world", &self.world)
            .field("topology_hash", &self.topology_hash)
            .field("rebuilds", &self.rebuilds)
            .field("patches", &self.patches)
            .field("converged", &self.converged)
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
            topology_hash: 0,
            rebuilds: 0,
            patches: 0,
            stamp: 0,
            applied: None,
            cached_edges: Vec::new(),
            matches: Vec::new(),
            previous_matches: Vec::new(),
            drives: Vec::new(),
            calm_time: 0.0,
            converged: false,
            forces: Forces::default(),
            recovered: Vec::new(),
            fixed_dt: DEFAULT_TIMESTEP,
            alpha: 1.0,
            cold_time: 0.0,
            halted: false,
            unfolding: false,
            gravity: Vector2D::zero(),
        }
    }

    /// Whether a persistent world exists.
    pub fn has_world(&self) -> bool {
        self.world.is_some()
    }

    /// The hash of the topology (node ids, undirected edges, pins) the world models; 0
    /// before the first build and after an empty scene. Independent of input order.
    pub fn current_topology_hash(&self) -> u64 {
        self.topology_hash
    }

    /// The persistent world, if any.
    pub fn world(&self) -> Option<&RapierSceneWorld<N>> {
        self.world.as_ref()
    }

    /// How many times a world was built from scratch.
    pub fn rebuild_count(&self) -> u64 {
        self.rebuilds
    }

    /// How many topology changes were applied to the existing world in place.
    pub fn patch_count(&self) -> u64 {
        self.patches
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
    pub fn topology_changed(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> bool {
        self.candidate_topology(scene, extras)
            .is_some_and(|topology| topology.hash != self.topology_hash)
    }

    /// The layout's heat under [`RapierLayoutConfig::cooling`] after the last call: 1
    /// at the first build, at least [`Cooling::reheat`](crate::Cooling::reheat) after a
    /// disturbance, falling to [`Cooling::min_alpha`](crate::Cooling::min_alpha)
    /// over [`Cooling::duration`](crate::Cooling::duration). `None` without a schedule.
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
    /// assert!(alpha < 0.5 && alpha > 0.1, "one second of an 8 s schedule: {alpha}");
    /// ```
    pub fn heat(&self) -> Option<f32> {
        self.config.cooling.map(|_| self.alpha)
    }

    /// Nodes whose bodies went non-finite during the last call (rapier quarantined
    /// them) and were put back, at rest, where they last were valid.
    pub fn recovered_nodes(&self) -> &[N] {
        &self.recovered
    }

    /// Drains the contact events recorded since the last call (empty unless
    /// [`RapierLayoutConfig::contact_events`] is on).
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
    /// [`LayoutError`] for a non-finite position, a NaN, infinite or negative radius, a
    /// repeated node id, or an edge naming a node that is not in the scene.
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
        validate(scene)?;
        Ok(self.advance(scene, state, dt, extras))
    }
}

impl<N: Clone + Eq + Hash> Layout<N> for RapierLayout<N> {
    type State = RapierLayoutState;

    /// Advances the layout by `dt` seconds and returns each free node's displacement.
    ///
    /// Never panics on bad input: a node with a non-finite position or an invalid
    /// radius is left out for this call (a node that already has a body stays where it
    /// is, with no delta, until the host gives it usable values), repeated ids after the
    /// first are ignored, and edges naming missing nodes are dropped.
    fn step(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        _viewport: &CanvasViewport,
        extras: &LayoutExtras<N>,
    ) -> DeltaMap<N> {
        self.advance(scene, state, dt, extras)
    }

    /// True when the layout is at rest: a world exists, no dynamic body moved faster
    /// than [`RapierLayoutConfig::rest_speed`] for [`REST_TIME`] seconds of simulated
    /// time, nothing (a drag, a release, a host move, a topology change) disturbed it
    /// meanwhile, and every dynamic body is asleep; or a [`Cooling`](crate::Cooling)
    /// schedule has ended and halted the world. Once true, calls report no motion until
    /// something disturbs the layout.
    fn is_converged(&self, _state: &RapierLayoutState) -> bool {
        self.world.is_some() && self.converged
    }
}

// ── the four passes ───────────────────────────────────────────────────────────────────
impl<N: Clone + Eq + Hash> RapierLayout<N> {
    fn advance(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut RapierLayoutState,
        dt: f32,
        extras: &LayoutExtras<N>,
    ) -> DeltaMap<N> {
        state.step_count = state.step_count.wrapping_add(1);
        if scene.nodes.is_empty() {
            self.drop_world();
            return DeltaMap::default();
        }
        let (_, _, substeps) = self.config.accuracy.settings();
        let mut plan = StepPlan::new(
            dt,
            state.dt,
            self.config.max_frame_time,
            self.config.max_substeps,
        );
        // Accuracy presets split every step further; an unusable `dt` is still one whole
        // fixed step.
        plan.substeps = plan.substeps.saturating_mul(substeps);
        plan.substep_dt /= substeps as f32;
        // New joints are tuned for the longest substep this configuration takes.
        self.fixed_dt = fixed_timestep(state.dt) / substeps as f32;
        let reconfigured = self.apply_config_changes();
        let unfolding_before = self.unfolding;
        let mut disturbed = self.sync_topology(scene, extras);
        // Every drive comes with a disturbance from `sync_in`.
        disturbed |= self.sync_in(scene, extras, plan.frame_dt);
        let gravity = Vector2D::new(
            finite_or(state.gravity_x, 0.0),
            finite_or(state.gravity_y, 0.0),
        );
        if reconfigured || gravity != self.gravity {
            // Nothing in the scene changed, yet bodies at rest may now be pushed.
            disturbed = true;
            if let Some(world) = self.world.as_mut() {
                world.wake_dynamic_bodies();
            }
        }
        self.gravity = gravity;
        if disturbed && unfolding_before {
            // An interaction during the first unfolding: contacts in, and firm.
            self.end_unfolding();
        }
        if disturbed || self.config.cooling.is_none() {
            self.halted = false;
        }
        if self.halted {
            // Cooled and stopped: nothing moves until the next disturbance.
            state.simulated_time += f64::from(plan.simulated());
            self.recovered.clear();
            self.converged = true;
            return DeltaMap::default();
        }
        if let Some(cooling) = self.config.cooling {
            if disturbed {
                self.alpha = cooling.reheated(self.alpha);
                // Also when the reheat cannot lift the heat off its floor: a disturbed
                // layout gets half a second before it is stopped again.
                self.cold_time = 0.0;
            }
        }
        let awake_before = self
            .world
            .as_ref()
            .map_or(0, RapierSceneWorld::awake_body_count);
        self.simulate(&plan, gravity);
        self.recovered.clear();
        if let Some(world) = self.world.as_mut() {
            self.recovered.extend(world.take_recovered_nodes());
        }
        state.simulated_time += f64::from(plan.simulated());
        match self.config.cooling {
            Some(cooling) => {
                self.alpha = cooling.cooled(self.alpha, plan.simulated());
                self.stop_when_cold(cooling.floor(), plan.simulated());
                if self.alpha <= cooling.floor() {
                    self.end_unfolding();
                }
            }
            None => {
                self.end_unfolding();
            }
        }
        let (deltas, max_speed, awake) = self.sync_out(scene, awake_before);
        self.track_rest(disturbed, max_speed, awake, plan.simulated());
        if self.converged && self.end_unfolding() {
            // At rest before the heat let contacts in: rest again once any overlap they
            // find is parted.
            self.converged = false;
        }
        self.converged |= self.halted;
        deltas
    }

    fn drop_world(&mut self) {
        self.world = None;
        self.topology_hash = 0;
        self.applied = None;
        self.cached_edges.clear();
        self.converged = false;
        self.calm_time = 0.0;
        self.halted = false;
        self.forces.reset();
    }

    /// Config changes that the world's structure depends on drop it (rebuilt this call);
    /// a joint change replaces the joints in place. Returns whether anything changed:
    /// a new configuration is a disturbance, since it may move what was at rest.
    fn apply_config_changes(&mut self) -> bool {
        let Some(applied) = &self.applied else {
            return false;
        };
        if *applied == self.config {
            return false;
        }
        let structural = applied.material != self.config.material
            || applied.collisions != self.config.collisions
            || applied.contact_events != self.config.contact_events
            || applied.default_radius.to_bits() != self.config.default_radius.to_bits();
        if self.forces.any_active(applied) && !self.forces.any_active(&self.config) {
            // Forces stay on bodies until reset: drop the last repulsion and bias.
            if let Some(world) = self.world.as_mut() {
                world.reset_forces();
            }
        }
        if applied.cooling.is_some() != self.config.cooling.is_some() {
            // A schedule starts hot; without one the springs have their full stiffness.
            self.alpha = 1.0;
            if let Some(world) = self.world.as_mut() {
                world.set_spring_scale(1.0);
            }
        }
        if structural {
            self.world = None;
            self.topology_hash = 0;
        } else if applied.edge_joint != self.config.edge_joint
            || applied.spring_degree_exponent.to_bits()
                != self.config.spring_degree_exponent.to_bits()
        {
            if let Some(world) = self.world.as_mut() {
                world.clear_edge_joints();
            }
            // Forces the topology pass to re-insert every joint.
            self.topology_hash = 0;
            self.cached_edges.clear();
        }
        self.applied = Some(self.config.clone());
        true
    }

    /// The node's radius, or the configured default for 0 (an unusable default counts
    /// as 16), as the world stores it: finite and non-negative.
    fn radius_of(&self, node: &CanvasNode<N>) -> f32 {
        if node.radius > 0.0 && node.radius.is_finite() {
            node.radius
        } else {
            let default = self.config.default_radius;
            if default.is_finite() && default >= 0.0 {
                default
            } else {
                16.0
            }
        }
    }

    fn binding_for(&self, node: &CanvasNode<N>) -> NodeAvatarBinding<N> {
        NodeAvatarBinding {
            node_id: node.id.clone(),
            collider: ColliderSpec::Circle {
                radius: self.radius_of(node),
            },
            material: self.config.material,
            body_kind: SceneBodyKind::Dynamic,
        }
    }

    /// Matches scene nodes to bodies (`self.matches`) and returns whether anything told
    /// apart the scene's topology from the world's.
    fn match_nodes(&mut self, scene: &CanvasSceneInput<N>, extras: &LayoutExtras<N>) -> bool {
        self.stamp += 1;
        let stamp = self.stamp;
        let Some(world) = self.world.as_mut() else {
            self.matches.clear();
            return true;
        };
        let check_pins = !extras.pinned.is_empty();
        let mut changed = false;
        let mut seen = 0;
        std::mem::swap(&mut self.matches, &mut self.previous_matches);
        self.matches.clear();
        let previous = &self.previous_matches;
        for (i, node) in scene.nodes.iter().enumerate() {
            let valid = node_is_valid(node);
            let pinned = check_pins && extras.pinned.contains(&node.id);
            // The host usually passes its nodes in the same order: the slot found for this
            // index last call is checked with one id comparison instead of a hash lookup.
            let cached = previous
                .get(i)
                .map(|m| m.slot as usize)
                .filter(|&s| world.slots.get(s).is_some_and(|slot| slot.id == node.id));
            let slot = match cached.or_else(|| world.slot_of(&node.id)) {
                Some(s) if world.slots[s].stamp != stamp => {
                    let slot = &mut world.slots[s];
                    slot.stamp = stamp;
                    seen += 1;
                    changed |= slot.pinned != pinned;
                    s as u32
                }
                Some(_) => NO_SLOT, // a repeated id
                None => {
                    // A usable node without a body is new (or a repeat of a new id).
                    changed |= valid;
                    NO_SLOT
                }
            };
            self.matches.push(NodeMatch {
                slot,
                valid,
                pinned,
            });
        }
        changed || seen != world.slots.len()
    }

    fn edges_match_cache(&self, scene: &CanvasSceneInput<N>) -> bool {
        self.cached_edges.len() == scene.edges.len()
            && self
                .cached_edges
                .iter()
                .zip(&scene.edges)
                .all(|((s, t), e)| *s == e.source && *t == e.target)
    }

    /// Matches scene nodes to bodies and returns the scene's topology when it may differ
    /// from the world's; `None` when the cheap checks show it cannot.
    fn candidate_topology(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> Option<Topology> {
        let nodes_changed = self.match_nodes(scene, extras);
        if !nodes_changed && self.topology_hash != 0 && self.edges_match_cache(scene) {
            return None;
        }
        let world = self.world.as_ref();
        Some(Topology::of(scene, extras, |id| {
            world.is_some_and(|w| w.contains_node(id))
        }))
    }

    /// Pass 1. Returns whether the world's structure changed.
    fn sync_topology(&mut self, scene: &CanvasSceneInput<N>, extras: &LayoutExtras<N>) -> bool {
        let Some(topology) = self.candidate_topology(scene, extras) else {
            return false;
        };
        self.cached_edges.clear();
        self.cached_edges.extend(
            scene
                .edges
                .iter()
                .map(|e| (e.source.clone(), e.target.clone())),
        );
        if self.world.is_some() && topology.hash == self.topology_hash {
            return false;
        }
        let rebuild =
            self.world.is_none() || self.config.topology_update == TopologyUpdate::Rebuild;
        if rebuild {
            self.build_world(scene, &topology);
        } else {
            self.patch_world(scene, &topology);
        }
        self.topology_hash = topology.hash;
        if let Some(world) = self.world.as_mut() {
            world.set_topology_hash(topology.hash);
        }
        self.match_nodes(scene, extras);
        true
    }

    fn world_options(&self) -> WorldOptions {
        WorldOptions {
            collisions: self.config.collisions,
            contact_events: self.config.contact_events,
        }
    }

    fn build_world(&mut self, scene: &CanvasSceneInput<N>, topology: &Topology) {
        let mut world = RapierSceneWorld::with_options(self.world_options());
        world.set_timestep(self.fixed_dt);
        // A new world counts its versions from 0 again.
        self.forces.reset();
        // Contacts stay out of the first unfolding until the heat lets them in.
        world.set_contacts_enabled(!(self.unfolding || self.rebuilds == 0));
        let mut spread = CoincidenceSpreader::default();
        for &i in &topology.nodes {
            let node = &scene.nodes[i];
            // A node whose values are unusable this call keeps its old body's position.
            let position = if node_is_valid(node) {
                node.position
            } else {
                match self.world.as_ref().and_then(|w| w.get_position(&node.id)) {
                    Some(p) => p,
                    None => continue,
                }
            };
            world.insert_node(&self.binding_for(node), spread.place(position));
            world.rebase_initial_position(&node.id, position);
            // A drag in progress survives the rebuild, so its release still throws.
            let old = self
                .world
                .as_ref()
                .and_then(|w| Some(&w.slots[w.slot_of(&node.id)?]));
            if let (Some(old), Some(s)) = (old, world.slot_of(&node.id)) {
                let slot = &mut world.slots[s];
                slot.dragging = old.dragging;
                slot.drag_position = old.drag_position;
                slot.drag_velocity = old.drag_velocity;
            }
        }
        let degrees = topology.degrees(scene.nodes.len());
        for &(a, b) in &topology.edges {
            world.insert_edge_joint(
                &scene.nodes[a].id,
                &scene.nodes[b].id,
                &edge_joint_for(&self.config, degrees[a], degrees[b]),
            );
        }
        self.world = Some(world);
        self.applied = Some(self.config.clone());
        if self.rebuilds == 0 {
            self.alpha = 1.0; // later builds are disturbances: they reheat
            self.unfolding = true;
        }
        self.rebuilds += 1;
    }

    /// Inserts and removes only what changed; untouched bodies keep their motion.
    fn patch_world(&mut self, scene: &CanvasSceneInput<N>, topology: &Topology) {
        let bindings: Vec<NodeAvatarBinding<N>> = topology
            .nodes
            .iter()
            .map(|&i| self.binding_for(&scene.nodes[i]))
            .collect();
        let degrees = topology.degrees(scene.nodes.len());
        let config = self.config.clone();
        let edge_joint = |da: u32, db: u32| edge_joint_for(&config, da, db);
        let Some(world) = self.world.as_mut() else {
            return;
        };
        // Removals, in the world's own (deterministic) slot order.
        let mut keep: std::collections::HashSet<&N, IdHasher> =
            std::collections::HashSet::with_capacity_and_hasher(
                topology.nodes.len(),
                IdHasher::default(),
            );
        keep.extend(topology.nodes.iter().map(|&i| &scene.nodes[i].id));
        let gone: Vec<N> = world
            .node_ids()
            .filter(|id| !keep.contains(id))
            .cloned()
            .collect();
        for id in &gone {
            world.remove_node(id);
        }
        // Insertions, in scene order.
        world.set_timestep(self.fixed_dt);
        let mut spread = CoincidenceSpreader::default();
        for (binding, &i) in bindings.iter().zip(&topology.nodes) {
            if !world.contains_node(&binding.node_id) {
                let host = scene.nodes[i].position;
                world.insert_node(binding, spread.place(host));
                world.rebase_initial_position(&binding.node_id, host);
            }
        }
        // Joints: drop those whose edge went away, add the new ones.
        let index_of: std::collections::HashMap<&N, usize, IdHasher> = topology
            .nodes
            .iter()
            .map(|&i| (&scene.nodes[i].id, i))
            .collect();
        let wanted: std::collections::HashSet<(usize, usize), IdHasher> = topology
            .edges
            .iter()
            .map(|&(a, b)| (a.min(b), a.max(b)))
            .collect();
        world.retain_edge_joints(|a, b| match (index_of.get(a), index_of.get(b)) {
            (Some(&x), Some(&y)) => wanted.contains(&(x.min(y), x.max(y))),
            _ => false,
        });
        for &(a, b) in &topology.edges {
            world.insert_edge_joint(
                &scene.nodes[a].id,
                &scene.nodes[b].id,
                &edge_joint(degrees[a], degrees[b]),
            );
        }
        if degree_exponent(&config).is_some() {
            // Springs whose ends changed degree take their new share.
            world.retune_edge_joints(|a, b| match (index_of.get(a), index_of.get(b)) {
                (Some(&x), Some(&y)) => edge_joint(degrees[x], degrees[y]),
                _ => config.edge_joint,
            });
        }
        self.patches += 1;
    }

    /// The body type a node should have this call.
    fn desired_type(&self, valid: bool, pinned: bool, dragging: bool) -> Option<RigidBodyType> {
        if !valid {
            return None; // frozen where it is
        }
        let policy = self.config.body_kind_policy;
        Some(if pinned && policy == BodyKindPolicy::PinnedStatic {
            RigidBodyType::Fixed
        } else if pinned || dragging || policy == BodyKindPolicy::AllKinematic {
            RigidBodyType::KinematicPositionBased
        } else {
            RigidBodyType::Dynamic
        })
    }

    /// Pass 2. Returns whether the host disturbed the layout (drag, release, host move,
    /// pin change).
    fn sync_in(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        frame_dt: f32,
    ) -> bool {
        self.drives.clear();
        let max_speed = self.config.max_speed;
        let check_drags = !extras.dragging.is_empty();
        let mut disturbed = false;
        // Host-moved kinematic and fixed bodies this call (see `wake_bodies_near_sweep`).
        let mut sweeps = 0_usize;
        for (i, node) in scene.nodes.iter().enumerate() {
            let m = self.matches[i];
            if m.slot == NO_SLOT {
                continue;
            }
            let s = m.slot as usize;
            let dragging = m.valid && check_drags && extras.dragging.contains(&node.id);
            let desired = self.desired_type(m.valid, m.pinned, dragging);
            let radius = self.radius_of(node);
            let density = self.config.material.density;
            let Some(world) = self.world.as_mut() else {
                return disturbed;
            };
            if m.valid {
                if let ColliderSpec::Circle { radius: r } = world.slots[s].shape {
                    if r.to_bits() != radius.to_bits() {
                        world.set_shape_at(s, ColliderSpec::Circle { radius }, density);
                        disturbed = true;
                    }
                }
            }
            let was_dragging = world.slots[s].dragging;
            let host = node.position;
            let slot = &mut world.slots[s];
            if slot.synced
                && desired == Some(RigidBodyType::Dynamic)
                && !dragging
                && slot.told == host
            {
                // A free body the host left where it was told: nothing to sync, and no
                // need to touch the body at all (the common case at rest).
                slot.initial = host;
                continue;
            }
            // Read first: a mutable access marks the body as modified for rapier, which
            // then re-processes it (and may wake it) at the next step.
            let body = world.body_at(s);
            let current = body.body_type();
            let body_pos = Point2D::new(body.translation().x, body.translation().y);
            match desired {
                None => {
                    // Unusable input: hold the body still where it is.
                    if current == RigidBodyType::Dynamic {
                        let body = world.body_at_mut(s);
                        body.set_body_type(RigidBodyType::KinematicPositionBased, true);
                        body.set_linvel(Vector::ZERO, false);
                    }
                    let slot = &mut world.slots[s];
                    slot.dragging = false;
                    slot.synced = false;
                    slot.initial = body_pos;
                    continue;
                }
                Some(RigidBodyType::Dynamic) => {
                    if current != RigidBodyType::Dynamic {
                        // Release, unpin or unfreeze: in place, at the host's position,
                        // with the drag's velocity when it was thrown.
                        let velocity = if was_dragging && !m.pinned {
                            world.slots[s].drag_velocity
                        } else {
                            Vector2D::zero()
                        };
                        let body = world.body_at_mut(s);
                        body.set_body_type(RigidBodyType::Dynamic, true);
                        if body_pos != host {
                            body.set_translation(Vector::new(host.x, host.y), true);
                        }
                        body.set_linvel(Vector::new(velocity.x, velocity.y), true);
                        disturbed = true;
                    } else if !world.slots[s].fresh && moved_by_host(world.slots[s].told, host) {
                        let body = world.body_at_mut(s);
                        body.set_translation(Vector::new(host.x, host.y), true);
                        body.set_linvel(Vector::ZERO, true);
                        disturbed = true;
                    }
                }
                Some(kind) => {
                    if current != kind {
                        let body = world.body_at_mut(s);
                        body.set_body_type(kind, true);
                        body.set_linvel(Vector::ZERO, true);
                        disturbed = true;
                    }
                    if body_pos != host {
                        // Rapier does not wake a sleeping body that a kinematic or fixed
                        // body is moved into. Past a few such moves, one O(n) pass wakes
                        // everything instead of one pass per move.
                        sweeps += 1;
                        if sweeps <= MAX_SWEEPS {
                            world.wake_bodies_near_sweep(s, body_pos, host);
                        } else if sweeps == MAX_SWEEPS + 1 {
                            world.wake_dynamic_bodies();
                        }
                        if kind == RigidBodyType::Fixed {
                            world
                                .body_at_mut(s)
                                .set_translation(Vector::new(host.x, host.y), true);
                        } else {
                            self.drives.push(Drive {
                                slot: s as u32,
                                from: body_pos,
                                to: host,
                            });
                        }
                        disturbed = true;
                    }
                }
            }
            let slot = &mut world.slots[s];
            slot.fresh = false;
            slot.pinned = m.pinned;
            slot.initial = host;
            slot.told = host;
            if dragging {
                let velocity = (host - slot.drag_position) / frame_dt;
                slot.drag_velocity = if was_dragging && velocity.is_finite() {
                    clamp_speed(velocity, max_speed)
                } else {
                    Vector2D::zero()
                };
                slot.drag_position = host;
                disturbed = true;
            }
            slot.dragging = dragging;
            slot.synced = desired == Some(RigidBodyType::Dynamic) && !dragging;
        }
        disturbed
    }

    /// Ends the first unfolding: contacts in (if they were left out) and firm from here
    /// on, so interactions always push. Returns whether contacts were let in.
    fn end_unfolding(&mut self) -> bool {
        if !self.unfolding {
            return false;
        }
        self.unfolding = false;
        match self.world.as_mut() {
            Some(world) if !world.contacts_enabled() => {
                world.set_contacts_enabled(true);
                true
            }
            _ => false,
        }
    }

    /// Pass 3.
    fn simulate(&mut self, plan: &StepPlan, gravity: Vector2D<f32>) {
        let config = &self.config;
        let Some(world) = self.world.as_mut() else {
            return;
        };
        let length_unit = positive_or(config.length_unit, 1.0);
        let mut contact_softness = config.contact_softness;
        let heat = match config.cooling {
            Some(cooling) => {
                // Springs follow heat^spring_exponent in steps of 5 %: each re-tune touches
                // every joint. A graph far from its rest lengths lets them fade toward the
                // heat itself (blended by its median stretch, read at each re-tune).
                let target = cooling.spring_scale(self.alpha);
                let scale = world.spring_scale();
                let at_floor = self.alpha <= cooling.floor();
                if (target - scale).abs() > 0.05 * scale || at_floor {
                    let limit = cooling.stretch_limit.unwrap_or(f32::INFINITY);
                    // A no-op when already there.
                    world.set_spring_scale_by_stretch(target, self.alpha, limit);
                }
                if self.unfolding {
                    let cold = contact_softness.coefficients().natural_frequency;
                    contact_softness.natural_frequency =
                        cooling.contact_frequency(cold, self.alpha);
                }
                self.alpha
            }
            None => 1.0,
        };
        if self.unfolding && !world.contacts_enabled() {
            // Never below the floor, which the heat would not reach.
            let gate = config.cooling.and_then(|cooling| {
                let gate = cooling.first_contact_heat.filter(|gate| gate.is_finite())?;
                Some(gate.max(cooling.floor()))
            });
            if gate.is_none_or(|gate| heat <= gate) {
                world.set_contacts_enabled(true);
            }
        }
        let params = world.integration_parameters_mut();
        params.dt = plan.substep_dt;
        params.length_unit = length_unit;
        params.normalized_max_linear_velocity = if config.max_speed > 0.0 {
            config.max_speed / length_unit
        } else {
            f32::MAX
        };
        let (iterations, pgs_iterations, _) = config.accuracy.settings();
        params.num_solver_iterations = iterations;
        params.num_internal_pgs_iterations = pgs_iterations;
        params.contact_softness = contact_softness.coefficients();
        params.static_contact_softness = contact_softness.static_coefficients();
        for k in 0..plan.substeps {
            if !self.drives.is_empty() {
                let t = (k + 1) as f32 / plan.substeps as f32;
                for drive in &self.drives {
                    let between = drive.from.lerp(drive.to, t);
                    let target = if k + 1 == plan.substeps || !between.is_finite() {
                        drive.to
                    } else {
                        between
                    };
                    world
                        .body_at_mut(drive.slot as usize)
                        .set_next_kinematic_translation(Vector::new(target.x, target.y));
                }
            }
            if self.forces.any_active(config) {
                self.forces.apply(world, config, heat);
            }
            world.step(gravity);
        }
    }

    /// The end of a cooling schedule: once the heat has stayed at its floor for
    /// [`REST_TIME`], every dynamic body is halted (velocity zeroed) and the world is not
    /// stepped again until a disturbance, like d3-force stopping its simulation at
    /// `alphaMin`. Forces are a thousandth of their strength by then, but in a large
    /// connected graph a few bodies jostling in contact would otherwise keep the whole
    /// graph (one rapier island) awake for ever.
    fn stop_when_cold(&mut self, floor: f32, simulated: f32) {
        if self.alpha > floor {
            self.cold_time = 0.0;
            return;
        }
        self.cold_time += simulated;
        if let Some(world) = self.world.as_mut() {
            if self.cold_time >= REST_TIME {
                world.halt_dynamic_bodies();
                self.halted = true;
            }
        }
    }

    /// Pass 4. Returns the deltas, the fastest dynamic body's speed and how many dynamic
    /// bodies are awake.
    /// `awake_before` is rapier's count of simulated bodies before the step: when it
    /// was 0 and still is, nothing moved and no body needs reading.
    fn sync_out(
        &mut self,
        scene: &CanvasSceneInput<N>,
        awake_before: usize,
    ) -> (DeltaMap<N>, f32, usize) {
        let epsilon = self.config.delta_epsilon.max(0.0);
        let epsilon_sq = epsilon * epsilon;
        // Allocated on the first delta: a resting layout returns an empty map for free.
        let mut deltas = DeltaMap::with_hasher(IdHasher::default());
        let mut max_speed_sq: f32 = 0.0;
        let mut awake = 0;
        let Some(world) = self.world.as_mut() else {
            return (deltas, 0.0, 0);
        };
        if awake_before == 0 && world.awake_body_count() == 0 {
            return (deltas, 0.0, 0);
        }
        for (node, m) in scene.nodes.iter().zip(&self.matches) {
            if m.slot == NO_SLOT {
                continue;
            }
            let s = m.slot as usize;
            let body = world.body_at(s);
            if !body.is_dynamic() {
                continue;
            }
            if !body.is_sleeping() {
                max_speed_sq = max_speed_sq.max(body.linvel().length_squared());
                awake += 1;
            }
            let t = body.translation();
            let slot = &mut world.slots[s];
            let delta = Point2D::new(t.x, t.y) - slot.initial;
            if delta.square_length() > epsilon_sq && delta.is_finite() {
                // The host adds the delta with the same f32 addition.
                slot.told = slot.initial + delta;
                if deltas.capacity() == 0 {
                    deltas.reserve(scene.nodes.len());
                }
                deltas.insert(node.id.clone(), delta);
            }
        }
        (deltas, max_speed_sq.sqrt(), awake)
    }

    /// At rest: calm for [`REST_TIME`] and every dynamic body asleep, so a converged
    /// layout reports no motion at all until something disturbs it.
    fn track_rest(&mut self, disturbed: bool, max_speed: f32, awake: usize, simulated: f32) {
        let calm = max_speed.is_finite() && max_speed <= self.config.rest_speed;
        if disturbed || !calm {
            self.calm_time = 0.0;
        } else {
            self.calm_time += simulated;
        }
        self.converged = self.calm_time >= REST_TIME && awake == 0;
    }
}

/// The joint `config` gives an edge whose ends have `da` and `db` distinct neighbours:
/// [`RapierLayoutConfig::edge_joint`], with a spring's stiffness and damping divided by
/// `min(da, db)^exponent` ([`RapierLayoutConfig::spring_degree_exponent`]; unusable
/// exponents count as 0).
fn edge_joint_for(config: &RapierLayoutConfig, da: u32, db: u32) -> EdgeJoint {
    match degree_exponent(config) {
        Some(exponent) => {
            let share = (da.min(db).max(1) as f32).powf(exponent);
            scaled_spring(&config.edge_joint, |x| x / share)
        }
        None => config.edge_joint,
    }
}

/// [`RapierLayoutConfig::spring_degree_exponent`] when it scales anything: finite and
/// not zero.
fn degree_exponent(config: &RapierLayoutConfig) -> Option<f32> {
    let exponent = config.spring_degree_exponent;
    (exponent.is_finite() && exponent.abs() > 0.0).then_some(exponent)
}

/// `v` shortened to `max_speed` (no cap when `max_speed` is not positive).
fn clamp_speed(v: Vector2D<f32>, max_speed: f32) -> Vector2D<f32> {
    let speed = v.length();
    if max_speed > 0.0 && speed > max_speed && speed.is_finite() {
        v * (max_speed / speed)
    } else {
        v
    }
}

/// Spreads nodes inserted at exactly the same position along a golden-angle spiral
/// (k-th repeat at `√k` units), so contacts get distinct normals and push the nodes
/// apart radially instead of along one arbitrary axis.
#[derive(Default)]
struct CoincidenceSpreader {
    seen: std::collections::HashMap<(u32, u32), u32, IdHasher>,
}

impl CoincidenceSpreader {
    fn place(&mut self, p: Point2D<f32>) -> Point2D<f32> {
        let count = self.seen.entry((p.x.to_bits(), p.y.to_bits())).or_insert(0);
        let k = *count;
        *count += 1;
        if k == 0 {
            return p;
        }
        let angle = k as f32 * 2.399_963; // the golden angle, radians
        let r = (k as f32).sqrt();
        p + Vector2D::new(angle.cos(), angle.sin()) * r
    }
}

/// Whether the host moved a free node: its position differs from the one it was told
/// (its last position plus the last delta) by more than float noise at that magnitude.
/// A host that adds deltas with `+=` lands on it bit for bit; any edit, however small,
/// is honoured.
fn moved_by_host(told: Point2D<f32>, host: Point2D<f32>) -> bool {
    let gap_sq = (told - host).square_length();
    if gap_sq == 0.0 {
        return false;
    }
    let magnitude = told
        .x
        .abs()
        .max(told.y.abs())
        .max(host.x.abs())
        .max(host.y.abs());
    let tolerance = (magnitude * 4.0 * f32::EPSILON).max(f32::MIN_POSITIVE);
    gap_sq > tolerance * tolerance
}
