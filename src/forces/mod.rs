//! Forces the layout puts on bodies every substep, beside what rapier solves itself
//! (joints, contacts, gravity): one force a file, each a [`BodyForce`], run in the order
//! of [`Forces::default`], the way d3-force's simulation runs its forces.
//!
//! - `many_body.rs`: many-body repulsion through the Barnes–Hut tree in `barnes_hut/`;
//! - `link_bias.rs`: d3-force's uneven share of a spring's pull between its ends;
//! - `center.rs`: the pull toward the centre.
//!
//! Every body pushes (pinned and dragged ones too); only awake dynamic bodies are pushed.
//! [`Forces::apply`] sums the forces of one substep into a buffer indexed by world slot
//! and sets each pushed body's force to its sum. A new force is one file here and one
//! line in [`Forces::default`].

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;

use crate::config::RapierLayoutConfig;
use crate::world::RapierSceneWorld;

pub(crate) mod barnes_hut;
mod center;
mod link_bias;
pub(crate) mod many_body;

/// What a force reads on one substep.
pub(crate) struct ForceContext<'a, N> {
    /// The world, for what a force caches about its bodies and joints.
    pub(crate) world: &'a RapierSceneWorld<N>,
    /// The layout's configuration; each force reads its own part.
    pub(crate) config: &'a RapierLayoutConfig,
    /// Every body's position, by world slot.
    pub(crate) points: &'a [Point2D<f32>],
    /// Whether each body (by world slot) is pushed: dynamic and awake.
    pub(crate) pushed: &'a [bool],
    /// The layout's heat under its cooling schedule (1 without one).
    pub(crate) heat: f32,
}

/// One force on bodies, applied every substep.
pub(crate) trait BodyForce<N>: Send + Sync {
    /// Whether `config` asks for this force at all.
    fn is_active(&self, config: &RapierLayoutConfig) -> bool;

    /// Adds this substep's force on every pushed body to `forces` (by world slot; as
    /// long as the world has bodies).
    fn apply(&mut self, frame: &ForceContext<'_, N>, forces: &mut Vec<Vector2D<f32>>);

    /// Forgets what was cached about a world that is gone.
    fn reset(&mut self) {}
}

/// The forces of a layout, with the buffers one substep sums them in.
pub(crate) struct Forces<N> {
    list: Vec<Box<dyn BodyForce<N>>>,
    points: Vec<Point2D<f32>>,
    pushed: Vec<bool>,
    sums: Vec<Vector2D<f32>>,
}

impl<N: Clone + Eq + Hash> Default for Forces<N> {
    fn default() -> Self {
        // NOTE: order matters for the float sums (and bit-exact replays): many-body
        // writes every entry first, the others add to it.
        let list: Vec<Box<dyn BodyForce<N>>> = vec![
            Box::new(many_body::ManyBodyForce::default()),
            Box::new(link_bias::LinkBias::default()),
            Box::new(center::CenterPull),
        ];
        Self {
            list,
            points: Vec::new(),
            pushed: Vec::new(),
            sums: Vec::new(),
        }
    }
}

impl<N> std::fmt::Debug for Forces<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Forces")
            .field("forces", &self.list.len())
            .finish_non_exhaustive()
    }
}

impl<N: Clone + Eq + Hash> Forces<N> {
    /// Whether `config` asks for any force on bodies.
    pub(crate) fn any_active(&self, config: &RapierLayoutConfig) -> bool {
        self.list.iter().any(|force| force.is_active(config))
    }

    /// Forgets every force's cache (the world was dropped or built anew).
    pub(crate) fn reset(&mut self) {
        for force in &mut self.list {
            force.reset();
        }
    }

    /// Sets every awake dynamic body's force to the sum of the active forces at `heat`.
    /// Skipped while nothing is awake, so a resting layout stays cheap.
    pub(crate) fn apply(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        heat: f32,
    ) {
        if world.awake_body_count() == 0 {
            return;
        }
        let n = world.slot_count();
        self.points.clear();
        self.points.extend((0..n).map(|s| world.position_at(s)));
        self.pushed.clear();
        self.pushed.extend((0..n).map(|s| {
            let body = world.body_at(s);
            body.is_dynamic() && !body.is_sleeping()
        }));
        self.sums.clear();
        self.sums.resize(n, Vector2D::zero());
        let frame = ForceContext {
            world,
            config,
            points: &self.points,
            pushed: &self.pushed,
            heat,
        };
        for force in &mut self.list {
            if force.is_active(config) {
                force.apply(&frame, &mut self.sums);
            }
        }
        for (s, f) in self.sums.iter().enumerate() {
            if self.pushed[s] && f.is_finite() {
                let body = world.body_at_mut(s);
                body.reset_forces(false);
                body.add_force(Vector::new(f.x, f.y), false);
            }
        }
    }
}
