//! Keep and resume: a layout saved whole ([`LayoutSnapshot`], taken by
//! [`RapierLayout::snapshot`] and put back by [`RapierLayout::restore`]) continues bit
//! for bit, and a layout built on a finished picture ([`RapierLayout::at_rest`]) starts
//! cold, as a layout that has come to rest.

use std::hash::Hash;

use euclid::default::Vector2D;
use serde::{Deserialize, Serialize};

use super::built::Built;
use super::drag::{Flight, Host};
use super::heat::Rest;
use super::heat::{Heat, HeatStage};
use super::matching::Matching;
use super::RapierLayout;
use crate::clusters::Clusters;
use crate::config::RapierLayoutConfig;
use crate::config::REST_TIME;
use crate::constraints::{Compiled, SavedConstraints};
use crate::input::clusters::Cluster;
use crate::input::snapshot_error::{check_counters, SnapshotError};
use crate::simulate::{Forces, SavedForces};
use crate::world::saved::SavedWorld;
use crate::world::RapierSceneWorld;

/// Everything a [`RapierLayout`] needs to continue exactly where it was: the
/// configuration it runs under, every body's position and velocity, rapier's contacts,
/// joints, islands and broad phase, the heat of the layout and of each node and where the
/// schedule stands, drags in progress with their pointer samples, thrown nodes in flight,
/// the rest state, per-node forces as the last call read them, and the contacts' warm
/// start. Taken by [`RapierLayout::snapshot`], put back by [`RapierLayout::restore`].
///
/// `Serialize + Deserialize` when `N` is, so a host can save it beside its document
/// (in a format that keeps `f32` exactly, as JSON through `serde_json` does) and restore
/// the layout in a later session: the restored layout gives the same deltas, bit for bit,
/// as the one that never stopped, for the same build, scene and extras. It stores what
/// the bodies are, not how the host drew them: under
/// [`force_directed`](RapierLayoutConfig::force_directed) its size grows linearly with
/// the nodes and edges, and it is larger with rapier's contacts, whose manifolds it
/// keeps (`docs/performance.md`, Keep and resume, gives the sizes as JSON).
///
/// # Example
/// ```
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode,
///     CanvasSceneInput, Layout, LayoutExtras, LayoutSnapshot, RapierLayout,
///     RapierLayoutConfig, RapierLayoutState};
/// let mut scene = CanvasSceneInput::new(
///     vec![CanvasNode::new(1_u32, Point2D::origin()), CanvasNode::new(2, Point2D::new(300.0, 0.0))],
///     vec![CanvasEdge::new(1, 2)],
/// );
/// let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
/// let (mut state, extras) = (RapierLayoutState::default(), LayoutExtras::default());
/// for _ in 0..10 {
///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
///     scene.apply_deltas(&deltas);
/// }
/// // Saved mid-motion, with the host's positions and state beside it.
/// let saved = serde_json::to_string(&layout.snapshot()).unwrap();
///
/// let mut resumed = RapierLayout::<u32>::default();
/// resumed.restore(serde_json::from_str::<LayoutSnapshot<u32>>(&saved).unwrap()).unwrap();
/// let mut other_state = state.clone();
/// let a = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
/// let b = resumed.step(&scene, &mut other_state, 1.0 / 60.0, &Default::default(), &extras);
/// assert_eq!(a[&1].x.to_bits(), b[&1].x.to_bits(), "the same motion, bit for bit");
/// ```
#[derive(Clone, Serialize, Deserialize)]
#[serde(bound(serialize = "N: Serialize", deserialize = "N: Deserialize<'de>"))]
pub struct LayoutSnapshot<N> {
    format: u32,
    config: RapierLayoutConfig,
    applied: Option<RapierLayoutConfig>,
    topology_hash: u64,
    weight_hash: u64,
    rebuilds: u64,
    patches: u64,
    stamp: u64,
    flights: Vec<Flight<N>>,
    heat: Heat,
    rest: Rest,
    forces: SavedForces,
    joint_dt: f32,
    gravity: Vector2D<f32>,
    cold_start: bool,
    world: Option<SavedWorld<N>>,
    /// The constraints the last call held (absent from snapshots of earlier builds: the
    /// first call after their restore takes the constraints as no edit).
    #[serde(default)]
    constraints: SavedConstraints<N>,
    /// The clusters the last call held (absent from snapshots of earlier builds, or
    /// before a first call: the first call after the restore takes the clusters as no
    /// edit).
    #[serde(default)]
    clusters: Option<Vec<Cluster<N>>>,
}

impl<N> LayoutSnapshot<N> {
    /// The snapshot format this build writes and reads. A snapshot of another format
    /// is refused ([`SnapshotError::Format`]); within a format, a snapshot restores in
    /// any build of the same rapier version, and continues bit for bit in the build that
    /// took it. Format 3 holds the grouped configuration ([`RapierLayoutConfig`]'s
    /// `springs`, `contacts`, `frame`, `solver`, `throw` and `rest`); format 2 (flat
    /// configuration fields) and format 1 (rapier's state not sealed) snapshots read but
    /// are refused.
    pub const FORMAT: u32 = 3;

    /// The configuration the layout ran under (a restore puts it back).
    pub fn config(&self) -> &RapierLayoutConfig {
        &self.config
    }

    /// How many nodes have a body in the snapshot (0 before the first world).
    pub fn node_count(&self) -> usize {
        self.world.as_ref().map_or(0, SavedWorld::node_count)
    }

    /// How many edge joints the snapshot holds.
    pub fn joint_count(&self) -> usize {
        self.world.as_ref().map_or(0, SavedWorld::joint_count)
    }
}

impl<N> std::fmt::Debug for LayoutSnapshot<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LayoutSnapshot")
            .field("format", &self.format)
            .field("nodes", &self.node_count())
            .field("joints", &self.joint_count())
            .field("heat", &self.heat.alpha)
            .field("converged", &self.rest.converged)
            .field("config", &self.config)
            .finish_non_exhaustive()
    }
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// A layout whose first world starts cold on the scene's positions: a saved picture
    /// comes back as it was. Nothing moves until a disturbance (a drag, a host move, a
    /// pin, an edit), which heats only its neighbourhood, as in a layout that came to
    /// rest ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)); the first call
    /// returns no delta and [`is_converged`](crate::Layout::is_converged) is true after
    /// it. For a host that saved only its positions; a host that saved a
    /// [`snapshot`](Self::snapshot) gets the motion back too with
    /// [`restore`](Self::restore). Later worlds (after a configuration change that
    /// rebuilds, or an empty scene) start as usual.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode,
    ///     CanvasSceneInput, Layout, LayoutExtras, RapierLayout, RapierLayoutConfig,
    ///     RapierLayoutState};
    /// // A picture saved by an earlier session: its spring is stretched (rest 100).
    /// let scene = CanvasSceneInput::new(
    ///     vec![CanvasNode::new(1_u32, Point2D::origin()), CanvasNode::new(2, Point2D::new(300.0, 0.0))],
    ///     vec![CanvasEdge::new(1, 2)],
    /// );
    /// let mut layout = RapierLayout::at_rest(RapierLayoutConfig::force_directed());
    /// let (mut state, extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// for _ in 0..100 {
    ///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    ///     assert!(deltas.is_empty(), "nothing moves until a disturbance");
    ///     assert!(layout.is_converged(&state));
    /// }
    /// ```
    pub fn at_rest(config: RapierLayoutConfig) -> Self {
        let mut layout = Self::new(config);
        layout.built.cold_start = true;
        layout
    }

    /// Everything the next call needs to continue exactly where this layout is
    /// ([`LayoutSnapshot`]). Costs a copy of the world; writing it (serialising)
    /// adds a hash of rapier's sets, their seals (`docs/performance.md`, Keep and
    /// resume, gives the figures).
    pub fn snapshot(&self) -> LayoutSnapshot<N> {
        LayoutSnapshot {
            format: LayoutSnapshot::<N>::FORMAT,
            config: self.config.clone(),
            applied: self.built.applied.clone(),
            topology_hash: self.built.topology_hash,
            weight_hash: self.built.weight_hash,
            rebuilds: self.built.rebuilds,
            patches: self.built.patches,
            stamp: self.matching.stamp(),
            flights: self.host.flights.clone(),
            heat: self.heat.state,
            rest: self.heat.rest,
            forces: self.forces.save(),
            joint_dt: self.built.joint_dt,
            gravity: self.host.gravity,
            cold_start: self.built.cold_start,
            world: self.world.as_ref().map(RapierSceneWorld::save),
            constraints: self.constraints.save(),
            clusters: self.clusters.save(),
        }
    }

    /// Puts this layout where `snapshot` was taken, configuration included: the next
    /// calls, with the same scene and extras, give the same deltas bit for bit as the
    /// layout it was taken of (in the same build). A snapshot taken at rest restores at
    /// rest: the first call returns no delta. Nodes the scene no longer has, or has
    /// anew, are an edit on the next call (the same as when the host edits the graph);
    /// a node whose position the host changed meanwhile is a host move. To run under
    /// another configuration, set [`config`](Self::config) after the restore: the next
    /// call applies it as any configuration change.
    ///
    /// What the last call reported ([`skipped`](Self::skipped),
    /// [`recovered_nodes`](Self::recovered_nodes)) is not part of a snapshot.
    ///
    /// # What is checked
    /// A snapshot comes back from disk, from other builds and from other people, so a
    /// restore trusts none of it: after an `Ok`, no call can panic or go non-finite on
    /// what it restored.
    /// - **Rapier's state** (bodies, colliders, joints, islands, broad and narrow phase,
    ///   CCD, integration parameters) holds private handles and indices no caller can
    ///   check, so each set is sealed when the snapshot is written (serialised), by a
    ///   64-bit hash of what rapier wrote, and a set read back that no longer matches
    ///   its seal is refused. The seal finds damage (a changed value, a lost or
    ///   repeated item); it is no signature, and a snapshot edited on purpose with its
    ///   seals worked out again is trusted as rapier wrote it. A snapshot kept in
    ///   memory and never written holds the world's own sets and pays for no seal.
    /// - **The layout's own parts** are checked against each other and against rapier's:
    ///   every node's body and collider exists and is the one it names, ids and joints
    ///   are not repeated and every joint's ends and rapier joint exist; positions,
    ///   velocities, held forces and warm-start impulses are finite; the stress model's
    ///   terms index within its nodes, components, pivots and weight tables; the host's
    ///   forces as last read are ones a host could set; counts are below 2⁵³.
    /// - **Settings** (the configuration, heat, schedule) are used as any host setting
    ///   is: a value out of range is clamped where it is read, and the counts that bound
    ///   a call's work are capped (see [`Accuracy::Custom`](crate::config::Accuracy::Custom) and
    ///   [`max_substeps`](crate::config::FrameLimits::max_substeps)).
    ///
    /// A restore costs these checks, the seals' hashes and building the id lookups,
    /// linear in the snapshot's size: `docs/performance.md` (Keep and resume) gives the
    /// figures at 10,000 and 100,000 nodes and the command that measures them. The
    /// first call after it adds the O(n + e) topology check.
    ///
    /// # Errors
    /// [`SnapshotError::Format`] for a snapshot of another format,
    /// [`SnapshotError::Inconsistent`] naming the first part that does not agree; the
    /// layout is left as it was.
    pub fn restore(&mut self, snapshot: LayoutSnapshot<N>) -> Result<(), SnapshotError> {
        if snapshot.format != LayoutSnapshot::<N>::FORMAT {
            return Err(SnapshotError::Format {
                found: snapshot.format,
                expected: LayoutSnapshot::<N>::FORMAT,
            });
        }
        check_counters(&[
            (snapshot.rebuilds, "rebuilds"),
            (snapshot.patches, "patches"),
            (snapshot.stamp, "stamp"),
        ])?;
        let world = snapshot
            .world
            .map(RapierSceneWorld::from_saved)
            .transpose()?;
        let forces = Forces::from_saved(snapshot.forces).map_err(SnapshotError::Inconsistent)?;
        *self = Self {
            config: snapshot.config,
            world,
            built: Built {
                applied: snapshot.applied,
                topology_hash: snapshot.topology_hash,
                weight_hash: snapshot.weight_hash,
                rebuilds: snapshot.rebuilds,
                patches: snapshot.patches,
                joint_dt: snapshot.joint_dt,
                cold_start: snapshot.cold_start,
                // Set and spent within one call: never pending between calls.
                start_again: false,
            },
            matching: Matching::resumed(snapshot.stamp),
            host: Host {
                flights: snapshot.flights,
                gravity: snapshot.gravity,
                ..Host::default()
            },
            heat: HeatStage {
                state: snapshot.heat,
                rest: snapshot.rest,
                ..HeatStage::default()
            },
            forces,
            constraints: Compiled::restored(snapshot.constraints),
            clusters: Clusters::restored(snapshot.clusters),
            // A setting of the host's, not of the layout's state.
            pool_awake: self.pool_awake,
            ..Self::new(RapierLayoutConfig::default())
        };
        Ok(())
    }

    /// Whether this call builds the first world of an [`at_rest`](Self::at_rest) layout.
    pub(super) fn builds_cold(&self) -> bool {
        self.built.cold_start && self.world.is_none() && self.built.rebuilds == 0
    }

    /// Makes the world just built the one a layout has after coming to rest: heat at its
    /// floor, contacts in, every dynamic body asleep (and halted, under a cooling
    /// schedule), calm. What built it is no disturbance; a drag in this first call is.
    /// Returns whether anything disturbs the layout.
    pub(super) fn settle_cold(&mut self) -> bool {
        let Some(world) = self.world.as_mut() else {
            return false;
        };
        self.heat.state = Heat {
            unfolding: false,
            ..Heat::default()
        };
        if let Some(cooling) = self.config.cooling {
            self.heat.state.alpha = cooling.floor();
        }
        // Not stepped until a disturbance, with or without a cooling schedule: rapier
        // steps bodies put to sleep before their first step.
        self.heat.state.halted = true;
        world.set_contacts_enabled(true);
        world.sleep_dynamic_bodies_now();
        self.heat.rest = Rest {
            calm_time: REST_TIME,
            converged: true,
        };
        // The picture is the rest's balance (`stress/rest_bias.rs`), measured with the
        // springs at the floor's scale, as the first step will have them.
        self.heat.heat_world(&self.config, self.world.as_mut());
        if let Some(world) = self.world.as_mut() {
            let dt = world.integration_parameters().dt;
            self.forces
                .capture_rest(world, &self.config, self.heat.state.alpha, dt);
        }
        self.heat.spread.clear();
        for drive in &self.host.drives {
            self.heat.spread.touch(drive.slot as usize, false);
        }
        !self.host.drives.is_empty()
    }
}
