//! What one substep reads of every body, by world slot: read from rapier once, then
//! kept, and read again only for the bodies the world reports changed
//! (`world/changes.rs`). On a large settled graph a drag changes a few dozen bodies a
//! step, and reading every body from rapier each substep (O(n) for those few) was a
//! large share of the step (`docs/performance.md` gives it).

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::RigidBody;

use crate::parallel;
use crate::world::RapierSceneWorld;

/// Slots a run of a read of every body takes (fixed: each body's read is its own).
const READ_RUN: usize = 1_024;

/// What a substep reads of one body.
struct BodyState {
    point: Point2D<f32>,
    velocity: Vector2D<f32>,
    pushed: bool,
    sleeping: bool,
    next: Point2D<f32>,
}

impl BodyState {
    #[inline]
    fn of(body: &RigidBody) -> Self {
        let (t, v) = (body.translation(), body.linvel());
        let point = Point2D::new(t.x, t.y);
        let dynamic = body.is_dynamic();
        Self {
            point,
            velocity: Vector2D::new(v.x, v.y),
            pushed: dynamic && !body.is_sleeping(),
            sleeping: dynamic && body.is_sleeping(),
            next: if body.is_kinematic() {
                let next = body.next_position().translation;
                Point2D::new(next.x, next.y)
            } else {
                point
            },
        }
    }
}

/// Every body's state a substep reads, by world slot.
#[derive(Debug, Default)]
pub(crate) struct Bodies {
    pub(crate) points: Vec<Point2D<f32>>,
    /// Velocities; after the forces, what they will be from them (pushed bodies).
    pub(crate) velocities: Vec<Vector2D<f32>>,
    /// Dynamic and awake: pushed by the forces, and gives way in contacts.
    pub(crate) pushed: Vec<bool>,
    /// Where a kinematic body is driven to this substep (its position otherwise).
    pub(crate) next: Vec<Point2D<f32>>,
    /// Dynamic but asleep: does not give way until woken.
    pub(crate) sleeping: Vec<bool>,
    /// Whether every slot holds what rapier held when the world's changes were last
    /// forgotten, apart from the changed slots.
    kept: bool,
}

impl Bodies {
    /// Reads every body the world reports changed, or every body when it cannot say
    /// or nothing is kept.
    pub(crate) fn gather<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        let n = world.slot_count();
        match world.changed_slots() {
            Some(changed) if self.kept && self.points.len() == n => {
                for &s in changed {
                    self.read(s as usize, world.body_at(s as usize));
                }
            }
            _ => self.read_all(world),
        }
        #[cfg(debug_assertions)]
        self.check(world);
    }

    /// Before the world forgets its changes: reads the changed bodies, so what is kept
    /// stays what rapier holds.
    pub(crate) fn catch_up<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        match world.changed_slots() {
            Some(changed) if self.kept && self.points.len() == world.slot_count() => {
                for &s in changed {
                    self.read(s as usize, world.body_at(s as usize));
                }
            }
            _ => self.kept = false,
        }
    }

    /// Every body's position and whether it is a sleeping dynamic body, when kept
    /// (exact for every body the world has not reported changed since).
    pub(crate) fn kept(&self) -> Option<(&[Point2D<f32>], &[bool])> {
        self.kept.then_some((&self.points, &self.sleeping))
    }

    /// Forgets what is kept: the next gather reads every body (after a caller changed
    /// the buffers, or for another world).
    pub(crate) fn forget(&mut self) {
        self.kept = false;
    }

    /// Reads every body, in runs of [`READ_RUN`] slots side by side under `parallel`.
    fn read_all<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        let n = world.slot_count();
        self.points.clear();
        self.velocities.clear();
        self.pushed.clear();
        self.next.clear();
        self.sleeping.clear();
        self.points.resize(n, Point2D::origin());
        self.velocities.resize(n, Vector2D::zero());
        self.pushed.resize(n, false);
        self.next.resize(n, Point2D::origin());
        self.sleeping.resize(n, false);
        let view = world.slots_view();
        let runs = || parallel::runs(n, READ_RUN);
        let mut jobs: Vec<_> = parallel::split_ranges(&mut self.points, runs())
            .into_iter()
            .zip(parallel::split_ranges(&mut self.velocities, runs()))
            .zip(parallel::split_ranges(&mut self.pushed, runs()))
            .zip(parallel::split_ranges(&mut self.next, runs()))
            .zip(parallel::split_ranges(&mut self.sleeping, runs()))
            .map(|((((p, (_, v)), (_, pu)), (_, ne)), (_, sl))| (p, v, pu, ne, sl))
            .collect();
        parallel::for_each(
            &mut jobs,
            || (),
            |(), ((range, points), velocities, pushed, next, sleeping)| {
                for (k, s) in range.clone().enumerate() {
                    let state = BodyState::of(view.body_at(s));
                    (points[k], velocities[k], pushed[k]) =
                        (state.point, state.velocity, state.pushed);
                    (next[k], sleeping[k]) = (state.next, state.sleeping);
                }
            },
        );
        self.kept = true;
    }

    #[inline]
    fn read(&mut self, s: usize, body: &RigidBody) {
        let state = BodyState::of(body);
        self.points[s] = state.point;
        self.velocities[s] = state.velocity;
        self.pushed[s] = state.pushed;
        self.sleeping[s] = state.sleeping;
        self.next[s] = state.next;
    }

    /// Debug builds (the tests): what is kept is what reading every body gives.
    #[cfg(debug_assertions)]
    fn check<N: Clone + Eq + Hash>(&self, world: &RapierSceneWorld<N>) {
        let mut all = Self::default();
        all.read_all(world);
        let point = |p: Point2D<f32>| [p.x.to_bits(), p.y.to_bits()];
        let vector = |v: Vector2D<f32>| [v.x.to_bits(), v.y.to_bits()];
        let stale = (0..all.points.len().min(self.points.len())).find(|&s| {
            point(self.points[s]) != point(all.points[s])
                || vector(self.velocities[s]) != vector(all.velocities[s])
                || point(self.next[s]) != point(all.next[s])
                || self.pushed[s] != all.pushed[s]
                || self.sleeping[s] != all.sleeping[s]
        });
        assert!(
            stale.is_none() && self.points.len() == all.points.len(),
            "the kept state of the body in slot {stale:?} is not rapier's ({} kept, {} bodies)",
            self.points.len(),
            all.points.len()
        );
    }
}
