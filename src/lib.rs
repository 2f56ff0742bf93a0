//! # graph-canvas-layout
//!
//! A graph layout for Rust graph canvases on a persistent [Rapier2D](rapier2d) world.
//! Nodes are rigid disks or label boxes, edges are joints, and the world lives from frame to frame, so
//! a thrown node keeps flying, a pinned node holds, and a graph edit does not stop
//! everybody else's motion. The host keeps its own positions: each call returns the
//! displacement of every node that moved.
//!
//! ## Quick start
//! ```
//! use graph_canvas_layout::{
//!     euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport,
//!     Layout, LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState,
//! };
//!
//! // The host's graph, every node at one point: the first call already puts them
//! // where the layout wants them.
//! let mut scene = CanvasSceneInput::new(
//!     ["a", "b", "c"].map(|id| CanvasNode::new(id, Point2D::origin())).to_vec(),
//!     vec![CanvasEdge::new("a", "b"), CanvasEdge::new("b", "c")],
//! );
//! // stress() keeps every two nodes near their graph distance: the recommended preset.
//! let mut layout = RapierLayout::new(RapierLayoutConfig::stress());
//! let mut state = RapierLayoutState::default();
//! let mut extras = LayoutExtras::default();
//! extras.pinned.insert("a"); // an anchor
//!
//! // One call per frame with the frame's elapsed time; the host applies the deltas.
//! // The viewport is part of the `Layout` trait and not read by this layout.
//! for _frame in 0..300 {
//!     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &CanvasViewport::default(), &extras);
//!     scene.apply_deltas(&deltas);
//! }
//! assert!(layout.is_converged(&state), "at rest within 5 s");
//! assert_eq!(scene.nodes[0].position, Point2D::origin(), "the pin held");
//! let [a, b, c] = [0, 1, 2].map(|i| scene.nodes[i].position);
//! let (ab, ac) = ((b - a).length(), (c - a).length());
//! assert!(ab > 32.0 && ac > 1.5 * ab, "a path: a–b {ab}, a–c {ac}");
//! ```
//!
//! ## The contract in short
//! - [`Layout::step`] returns per-node deltas of this call only; pinned and dragged
//!   nodes never appear in it.
//! - Pinned nodes never move by physics; dragged nodes sit exactly where the host puts
//!   them; releasing a drag throws the node with the pointer's speed over its last
//!   move, unless the pointer stood still for longer than
//!   [`throw.window`](crate::config::Throw::window) before the release.
//! - A free node the host moved itself (undo, snap) is put where the host put it.
//! - [`RapierLayout::try_step`] rejects bad input with a [`LayoutError`] and changes
//!   nothing; [`Layout::step`] leaves bad elements out and never panics.
//! - A [`Flow`] ([`RapierLayoutConfig::with_flow`]) and
//!   [`LayoutExtras::constraints`] are hard: a flow's edges hold after every substep
//!   wherever the bodies allow (a pinned or dragged node does not give way), the host's
//!   separations and rows within a few substeps, every one within a unit at rest; and
//!   [`RapierLayout::violated_constraints`] names what could not hold.
//! - [`LayoutWorker`](crate::worker::LayoutWorker) steps a layout on a thread of its own for graphs whose step would
//!   cost the UI thread its frame rate: the host sends what changes and reads the
//!   newest positions without waiting.
//!
//! ## How it is built
//! The root holds the contract and the names of the usual loop; [`prelude`] imports
//! them at once. The public modules hold the rest: [`scene`] (per-node forces' parts,
//! scene files, the topology hash), [`config`] (the configuration's groups and models),
//! [`world`] (the world's types and limits), [`worker`], [`profile`] and [`quality`].
//!
//! One [`Layout::step`] runs these stages in order (`src/adapter/mod.rs`, `advance`),
//! each borrowing only the part of the layout it touches:
//! 1. **Plan** (`adapter/substeps.rs`): the frame time as equal substeps.
//! 2. **Reconfigure** (`adapter/reconfigure.rs`): a changed configuration drops the
//!    world or replaces its joints.
//! 3. **Match and edit** (`adapter/matching.rs`, `adapter/edits.rs`): scene nodes to
//!    bodies; a changed topology patches the world, or builds it (under
//!    [`RapierLayoutConfig::stress`] from the stress model's start, `stress/`).
//! 4. **Sync in** (`adapter/sync_in.rs`, `adapter/drag.rs`, `adapter/node_forces.rs`):
//!    pins, drags, throws, host moves, per-node forces, gravity.
//! 5. **Heat** (`adapter/heat/`): a disturbance reheats all of a cooling layout or the
//!    neighbourhood it touched.
//! 6. **Simulate** (`adapter/substeps.rs`, `simulate/`): per substep the drives, the
//!    forces of `forces/` and the stress terms run from one registry, one rapier step,
//!    the disk separation of `contacts/`, the hard constraints and a flow's edges of
//!    `constraints/`; then the heat cools.
//! 7. **Sync out** (`adapter/sync_out.rs`): each free node's displacement.
//! 8. **Rest** (`adapter/heat/rest.rs`): the convergence signal.
//!
//! `docs/design.md` in the repository gives the module map with what each module
//! imports (one way, no cycle), and the physics of each preset; `docs/quality.md`,
//! `docs/feel.md`, `docs/performance.md` and `docs/tradeoff.md` hold the measurements.
//!
//! ## Feature flags
//! - `petgraph`: `CanvasSceneInput::from_petgraph` and `from_petgraph_with` for any
//!   petgraph graph (`&Graph`, `&StableGraph`, `&GraphMap`) with its own node ids, and
//!   `pub use petgraph` (0.8, the version egui_graphs builds on).
//! - `parallel`: the layout's own forces (Barnes–Hut repulsion, springs, stress terms)
//!   and contacts (pair search, Gauss–Seidel passes) on rayon's pool, and rapier's own
//!   parallel parts (its solver). The layout's work is cut into pieces that do not
//!   depend on the thread count, so a layout whose contacts are the layout's own
//!   ([`RapierLayoutConfig::force_directed`], [`RapierLayoutConfig::stress`]) is
//!   bit-identical on any number of threads. With fewer than 8,192 contact pairs a
//!   substep it is also bit-identical to a build without the feature; beyond, the passes solve the
//!   pairs block by block, a different order and the same picture. With rapier's
//!   contacts or joints, rapier decides (see `docs/performance.md`). `step` runs on the
//!   pool of the thread that calls it: rayon's global pool, or a pool of the host's own
//!   (`rayon::ThreadPool::install`, with rayon among the host's dependencies). A
//!   [`LayoutWorker`](crate::worker::LayoutWorker) steps on a pool of its own with one thread fewer than the
//!   machine has cores, so the UI thread keeps a core
//!   (`LayoutWorker::spawn_on_threads` chooses the count). From 2,048 awake bodies on,
//!   another thread of the pool stays awake through each substep of a call, taking its
//!   parts as they come, rather than sleeping between them
//!   ([`RapierLayout::set_pool_awake`] trades that back for an idle core).
//! - `enhanced-determinism`: rapier's cross-platform bit-exact math.
//!
//! ## FAQ
//! **Units?** World units are canvas pixels and seconds. Rapier's `length_unit` is set
//! to 100 (a typical node-plus-edge size), which scales its contact tolerances, sleep
//! threshold and speed cap to pixels. Mass is `density × disk area`; a label box
//! ([`CanvasNode::with_rect`]) weighs what a disk of the default radius weighs.
//!
//! **Why is nothing moving?** A graph already at its rest lengths does not move; bodies
//! asleep stay asleep until something touches them. With
//! [`BodyKindPolicy::AllKinematic`] nothing is simulated. Check also that the host adds
//! the deltas to its positions and passes them back.
//!
//! **Why does a node jump back?** It does not: the host's position is authoritative. A
//! free node whose position differs from its body's is teleported to the host's.
//!
//! **Two `dt`s?** [`Layout::step`]'s `dt` is the frame time: how long since the last
//! call (drags are measured against it). [`RapierLayoutState::dt`] is the physics'
//! fixed timestep: each call covers its frame time in substeps no longer than that
//! (default 1/60 s), up to [`FrameLimits::max_frame_time`](crate::config::FrameLimits::max_frame_time).
//!
//! **What is the viewport for?** Nothing, here: [`CanvasViewport`] is part of the
//! [`Layout`] contract for layouts that work on what is visible; this one lays out the
//! whole graph. Pass `&CanvasViewport::default()`.
//!
//! **Bad input?** [`Layout::step`] leaves out what it cannot use and goes on;
//! [`RapierLayout::skipped`] lists what the last call left out and why, and
//! [`RapierLayout::problems`] lists every problem of a scene at once.
//!
//! **How fast can a node fly?** [`Solver::max_speed`](crate::config::Solver::max_speed) (default 40,000 units
//! per second) caps every body; faster throws fly at the cap.
//!
//! **Jitter at rest?** A resting layout reports nothing: rapier puts bodies slower than
//! 5 units/s (`0.05 × length_unit`) for 0.5 s to sleep and they stop exactly,
//! [`Layout::is_converged`] waits for that, and displacements under
//! [`RestDetection::delta_epsilon`](crate::config::RestDetection::delta_epsilon) are not reported. Dense piles of disks pushed
//! together by springs settle more slowly; [`Accuracy::Precise`](crate::config::Accuracy::Precise) resolves their
//! contacts in fewer frames, and the layout presets keep nodes apart in the first place.
//!
//! **Very large coordinates?** Positions are `f32`: near 1e5 they resolve to 0.008 units,
//! near 1e6 to 0.06, near 1e7 to 1. The layout stays finite there, but motion finer than
//! the resolution is lost. Keep the graph within about ±1e5 of the origin (lay out in a
//! local frame and translate on display).
//!
//! **Which layout preset?** [`RapierLayoutConfig::stress`] to lay a graph out: it keeps
//! graph distances as stress majorization does (`docs/quality.md` compares its stress
//! with stress SGD's on the standard test graphs) and starts from a global layout, so the first
//! frame shows the graph's shape. [`RapierLayoutConfig::force_directed`] is d3-force's
//! model (repulsion, springs, collisions); `force_directed_fast` leaves out the
//! collisions. The default configuration has no layout forces: a physical canvas
//! arranged by hand, where springs and contacts alone pack a graph into a blob. Every
//! preset cools to rest, then stops stepping the world until the next drag, release,
//! host move or edit, which heats only the nodes near it.
//!
//! **Edges pointing one way, nodes in a row?** [`RapierLayoutConfig::with_flow`] with
//! [`Flow::down`](crate::config::Flow::down) (or up, left, right) for a directed graph;
//! [`Constraint::separation`](crate::scene::Constraint::separation) and
//! [`Constraint::align`](crate::scene::Constraint::align) in
//! [`LayoutExtras::constraints`] for the host's own order and lines. They are hard, not
//! pulls: per-node forces ([`NodeForces`]) are the soft kind.
//! [`Flow::in_layers`](crate::config::Flow::in_layers) puts the nodes in layers, the
//! picture of Graphviz `dot` (few crossings, none on a tree; higher stress).
//! `docs/flow.md` compares a flow with Graphviz `dot`.
//!
//! **Which accuracy level?** Independent of the preset: [`Accuracy::Balanced`](crate::config::Accuracy::Balanced) (default)
//! sits at the knee of the measured cost/error curve. [`Accuracy::Fast`](crate::config::Accuracy::Fast) is cheaper on
//! sparse graphs but slower in dense contact piles; [`Accuracy::Precise`](crate::config::Accuracy::Precise) costs several
//! times as much for trajectories and spring lengths closer to a fine-timestep
//! reference (`docs/tradeoff.md`, `cargo run --release --example tradeoff`).
//!
//! **Groups drawn as boxes?** [`LayoutExtras::clusters`]: each [`Cluster`] keeps its
//! members in a box no other node and no sibling box enters, nested by index;
//! [`RapierLayout::cluster_bounds`] gives the boxes and
//! [`RapierLayout::violated_clusters`] those that cannot hold (`docs/clusters.md`).
//!
//! **Timelines, layers, rings, soft groups?** Per-node [`NodeForces`] in
//! [`LayoutExtras::forces`]: a pull toward a target x or y, a ring, a group key
//! ([`RapierLayoutConfig::groups`]) and a lock of one axis, all inside the physics, so
//! they combine with springs, contacts, drags and throws. Strengths are d3-force's; to
//! hold nodes within a few units against `force_directed()`'s edge springs use 20 or
//! more (0.1 to 1 is a gentle bias).
//!
//! **Nodes pass through each other right after loading?** Under the layout presets,
//! contacts join the first unfolding once it has cooled to
//! [`Cooling::first_contact_heat`](crate::config::Cooling::first_contact_heat) (0.3: about 0.35 s under `stress()`, 0.8 s under
//! `force_directed()`): a fresh start moving fast through thousands of contact pairs
//! would cost most of the step. Set it to `None` for contacts from the first frame.
//!
//! **Where does a frame's time go?** [`RapierLayout::set_profiling`] and
//! [`RapierLayout::profile`]: a [`StepProfile`](crate::profile::StepProfile) splits the calls' time into the layout's
//! own forces, its contacts, rapier's step and the rest of the call (matching, sync,
//! deltas). Off by default; then a call reads no clock.
#![deny(missing_docs)]

mod adapter;
mod clusters;
pub mod config;
mod constraints;
mod contacts;
mod forces;
mod graph;
mod input;
mod parallel;
pub mod profile;
pub mod quality;
mod sanitize;
mod simulate;
mod sort;
mod stress;
mod timestep;
pub mod worker;
pub mod world;

pub use euclid;
#[cfg(feature = "petgraph")]
pub use petgraph;
pub use rapier2d;

// The contract (`Layout`, the scene, the Rapier layout and its world's types) and the
// errors and snapshots a host meets; the rest lives in the modules below.
pub use adapter::{LayoutSnapshot, RapierLayout, RapierLayoutState};
pub use config::{BodyKindPolicy, EdgeJoint, Flow, RapierLayoutConfig};
pub use input::clusters::Cluster;
pub use input::constraints::{Axis, Constraint};
pub use input::layout::{DeltaMap, Layout, LayoutExtras, NodeMap, NodeSet};
pub use input::node_forces::NodeForces;
pub use input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport};
pub use input::shape::NodeShape;
pub use input::snapshot_error::SnapshotError;
pub use input::validation::{LayoutError, MAX_COORDINATE};
pub use world::bindings::{
    ColliderSpec, EdgeJointSpec, NodeAvatarBinding, NodeSnapshot, PhysicsMaterial, SceneBodyKind,
};
pub use world::events::SceneEvent;
pub use world::RapierSceneWorld;

/// What a host's scene is made of beyond the nodes and edges: per-node forces' parts,
/// the shipped scene files, the topology hash and, with feature `petgraph`, where a
/// graph without positions starts.
pub mod scene {
    pub use crate::input::clusters::{Cluster, DEFAULT_CLUSTER_PADDING};
    pub use crate::input::constraints::{Axis, Constraint};
    pub use crate::input::node_forces::{AxisLock, AxisTarget, NodeForces, RingTarget};
    #[cfg(feature = "petgraph")]
    pub use crate::input::petgraph::NodeStart;
    pub use crate::input::scene::{CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport};
    pub use crate::input::scene_file::{SceneFile, SceneFileNode};
    pub use crate::input::shape::NodeShape;
    pub use crate::input::topology::topology_hash;
    pub use crate::input::validation::MAX_COORDINATE;
}

/// The names a host imports for the usual loop: `use graph_canvas_layout::prelude::*;`.
/// The [`Layout`] trait comes in unnamed (its methods in scope, its name free for
/// egui_graphs' `Layout` or a host's own).
pub mod prelude {
    pub use crate::Layout as _;
    pub use crate::{
        Axis, CanvasEdge, CanvasNode, CanvasSceneInput, CanvasViewport, Constraint, DeltaMap, Flow,
        LayoutError, LayoutExtras, LayoutSnapshot, NodeForces, NodeShape, RapierLayout,
        RapierLayoutConfig, RapierLayoutState, SnapshotError,
    };
}

// Plumbing the crate's own tests, examples and benches reach for: not part of the API.
#[doc(hidden)]
pub use forces::barnes_hut::ManyBody;
#[doc(hidden)]
pub use input::layout::IdHasher;
#[doc(hidden)]
#[cfg(feature = "petgraph")]
pub use input::petgraph::{spiral_position, SPIRAL_SPACING};
#[doc(hidden)]
pub use timestep::{StepPlan, DEFAULT_TIMESTEP, MIN_TIMESTEP};

/// The README's examples run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
