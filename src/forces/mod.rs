//! Forces the layout puts on bodies every substep, beside what rapier solves itself
//! (joints, contacts, gravity): one force a file, each a [`BodyForce`], the way d3-force
//! keeps its forces. The step runs them in the order of their registry
//! (`simulate/registry.rs`), the way d3-force's simulation runs its forces:
//!
//! - `many_body.rs`: many-body repulsion through the Barnes–Hut tree in `barnes_hut/`;
//! - `springs.rs`: the edge springs applied as forces, and d3-force's uneven share of a
//!   spring's pull between its ends (link bias);
//! - `center.rs`: the pull toward the centre;
//! - `position.rs`, `radial.rs`, `group.rs`: the host's per-node pulls toward an x, a y
//!   or a ring, and groups held together, read from the table in `targets.rs`;
//! - the stress terms, whose force lives with the stress model (`stress/force/`).
//!
//! The layout's own disk separation is not a force (velocity changes that part disks,
//! worked out after the forces) and lives beside them in `contacts/`.
//!
//! Every body pushes (pinned and dragged ones too); only awake dynamic bodies are pushed.
//! The forces of one substep are summed into buffers indexed by world slot
//! ([`ForceSums`]). A force may also report a stiffness per body (springs do): the sum
//! on a body of mass `m` is then divided by `1 + (dt² k + dt c) / m`, an implicit Euler
//! step on the body's own stiffness `k` and damping `c` (the diagonal of the springs'
//! Jacobian), so springs stiffer than the step resolves stay stable and the body still
//! comes to rest where its forces balance. The host's pulls act along one direction
//! each and report their stiffness as a matrix (`targets.rs`), so the step slows a body
//! only along the pull. A new force is one file here and one entry in the registry
//! (`simulate/registry.rs`: a field and its place in `each`).

use euclid::default::{Point2D, Vector2D};

use crate::config::RapierLayoutConfig;
use crate::world::RapierSceneWorld;

pub(crate) mod barnes_hut;
mod bodies;
pub(crate) mod center;
pub(crate) mod group;
pub(crate) mod many_body;
pub(crate) mod position;
pub(crate) mod radial;
pub(crate) mod springs;
pub(crate) mod targets;

pub(crate) use bodies::Bodies;
use targets::NodeTargets;

/// What a force reads on one substep.
pub(crate) struct ForceContext<'a, N> {
    /// The world, for what a force caches about its bodies and joints.
    pub(crate) world: &'a RapierSceneWorld<N>,
    /// The layout's configuration; each force reads its own part.
    pub(crate) config: &'a RapierLayoutConfig,
    /// Every body's position, by world slot.
    pub(crate) points: &'a [Point2D<f32>],
    /// Every body's velocity, by world slot.
    pub(crate) velocities: &'a [Vector2D<f32>],
    /// Whether each body (by world slot) is pushed: dynamic and awake.
    pub(crate) pushed: &'a [bool],
    /// The layout's heat under its cooling schedule (1 without one).
    pub(crate) heat: f32,
    /// The substep's length, in seconds.
    pub(crate) dt: f32,
    /// The host's per-node forces, by world slot.
    pub(crate) targets: &'a NodeTargets,
}

/// What the forces of one substep add up to, by world slot.
#[derive(Debug, Default)]
pub(crate) struct ForceSums {
    /// The force on each body, springs aside.
    pub(crate) forces: Vec<Vector2D<f32>>,
    /// The springs' force on each body.
    pub(crate) springs: Vec<Vector2D<f32>>,
    /// `dt² k + dt c` of each body's springs applied as forces: what the implicit step
    /// divides by (with the mass).
    pub(crate) resistance: Vec<f32>,
    /// The same of the host's pulls, which act along one direction `u` each: the sum of
    /// `(dt² k + dt c) u uᵀ` as `[xx, xy, yy]`, so that a pull along x leaves motion
    /// along y as free as without it.
    pub(crate) pulls: Vec<[f32; 3]>,
}

/// What a force of the spare lane ([`Lane::Spare`]) reads: positions and who is pushed,
/// not the world, so that it can run on another thread beside the springs.
pub(crate) struct SpareFrame<'a> {
    /// The layout's configuration; each force reads its own part.
    pub(crate) config: &'a RapierLayoutConfig,
    /// Every body's position, by world slot.
    pub(crate) points: &'a [Point2D<f32>],
    /// Whether each body (by world slot) is pushed: dynamic and awake.
    pub(crate) pushed: &'a [bool],
    /// The layout's heat under its cooling schedule (1 without one).
    pub(crate) heat: f32,
}

/// Where a force runs within a substep. The registry runs every active force's
/// [`prepare`](BodyForce::prepare) in order, then the spare lane beside the springs'
/// lane (side by side under `parallel`), then the in-order forces, then every
/// [`finish`](BodyForce::finish) in order: so each sum adds up in the same order
/// whatever thread worked a part out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Lane {
    /// Works from positions alone ([`BodyForce::apply_spare`]), into `forces` (the
    /// first to write them) or into state of its own that [`BodyForce::finish`] adds.
    Spare,
    /// Reads the world and writes only `springs` and `resistance`.
    Springs,
    /// Adds to every sum, after the forces before it in the registry.
    InOrder,
}

/// One force on bodies, applied every substep.
pub(crate) trait BodyForce<N>: Send + Sync {
    /// Whether `config` or the host's per-node `targets` ask for this force at all.
    fn is_active(&self, config: &RapierLayoutConfig, targets: &NodeTargets) -> bool;

    /// Where the force runs ([`Lane`]). Default: [`Lane::InOrder`].
    fn lane(&self) -> Lane {
        Lane::InOrder
    }

    /// Reads the world before the lanes run (the stress terms' model and pivots).
    /// Default: nothing.
    fn prepare(&mut self, _frame: &ForceContext<'_, N>) {}

    /// A force of the springs' lane or in order: adds this substep's force on every
    /// pushed body to `out` (by world slot; as long as the world has bodies). Default:
    /// nothing (the spare lane's forces work in [`apply_spare`](Self::apply_spare)).
    fn apply(&mut self, _frame: &ForceContext<'_, N>, _out: &mut ForceSums) {}

    /// A force of the spare lane: works this substep's force out from positions alone,
    /// into `out.forces` or into state of its own for [`finish`](Self::finish).
    /// Default: nothing (the other lanes' forces work in [`apply`](Self::apply)).
    fn apply_spare(&mut self, _frame: &SpareFrame<'_>, _out: &mut ForceSums) {}

    /// After every lane: adds what the spare lane worked out into state of its own.
    /// Default: nothing.
    fn finish(&mut self, _out: &mut ForceSums) {}

    /// Forgets what was cached about a world that is gone.
    fn reset(&mut self) {}
}
