//! Sync out: each free node's displacement during this call, what the host was told
//! (so the next call can tell a host edit from a host that added the deltas), and the
//! motion figures the rest tracker reads.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;

use super::matching::{Matching, NO_SLOT};
use crate::clusters::Clusters;
use crate::config::RestDetection;
use crate::constraints::Compiled;
use crate::input::layout::{DeltaMap, IdHasher};
use crate::input::scene::CanvasSceneInput;
use crate::input::validation::{position_in_range, MAX_COORDINATE};
use crate::simulate::Forces;
use crate::world::RapierSceneWorld;

/// What one call reports.
#[derive(Debug)]
pub(super) struct FrameReport<N> {
    /// Per free node, the displacement this call produced.
    pub(super) deltas: DeltaMap<N>,
    /// The fastest awake dynamic body's speed, in world units per second.
    pub(super) max_speed: f32,
    /// How many dynamic bodies are awake.
    pub(super) awake: usize,
}

/// Reads the dynamic bodies that may have moved: those the world logged as changed, or
/// every body the scene names when it logged too many to say. `awake_before` is
/// rapier's count of simulated bodies before the step: when it was 0 and still is, and
/// neither the constraints' projection nor the clusters' parting moved a body (they move them after rapier's step, and
/// rapier counts a body it wakes that way only from its next step), nothing moved and
/// no body needs reading. Records the moved slots in `matching` and catches the forces'
/// and the constraints' kept bodies up.
pub(super) fn sync_out<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    awake_before: usize,
    rest: &RestDetection,
    world: Option<&mut RapierSceneWorld<N>>,
    matching: &mut Matching<N>,
    (forces, constraints, clusters): (&mut Forces<N>, &mut Compiled<N>, &mut Clusters<N>),
) -> FrameReport<N> {
    matching.moved_mut().clear();
    let epsilon = rest.delta_epsilon.max(0.0);
    let epsilon_sq = epsilon * epsilon;
    // Allocated on the first delta: a resting layout returns an empty map for free.
    let mut report = FrameReport {
        deltas: DeltaMap::with_hasher(IdHasher::default()),
        max_speed: 0.0,
        awake: 0,
    };
    let Some(world) = world else {
        return report;
    };
    let projected = clusters.take_moved() | constraints.moved_bodies();
    if awake_before == 0 && world.awake_body_count() == 0 && !projected {
        return report;
    }
    // The bodies that may have moved since the last call: those the world reports
    // changed (a few dozen on a settled graph disturbed in one place), or all.
    let moved = match world.changed_slots() {
        Some(changed) => {
            let mut slots = changed.to_vec();
            slots.sort_unstable();
            Moved::of(world, slots.iter().map(|&s| s as usize), epsilon_sq)
        }
        None => Moved::of(world, matched_slots(scene, matching), epsilon_sq),
    };
    #[cfg(debug_assertions)]
    if world.changed_slots().is_some() {
        let every = Moved::of(world, matched_slots(scene, matching), epsilon_sq);
        moved.check_against(every);
    }
    report.awake = moved.awake;
    let max_speed_sq = moved.max_speed_sq;
    // Told positions the host's f32 addition does not land on the body's exactly are
    // read again next call, when the world no longer reports them changed.
    let mut inexact = Vec::new();
    for &(s, mut delta) in &moved.deltas {
        let s = s as usize;
        if let Some(edge) = beyond_range(world.position_at(s)) {
            // The range is the host's too: a node pushed past it (disks wider than
            // the range apart) stops at its edge, where the host can hand it back.
            let body = world.body_at_mut(s);
            body.set_translation(Vector::new(edge.x, edge.y), true);
            body.set_linvel(Vector::ZERO, true);
            delta = edge - world.anchor_at(s);
        }
        let told = world.anchor_at(s) + delta;
        // The host adds the delta with the same f32 addition.
        world.host_at_mut(s).told = told;
        if told != world.position_at(s) {
            inexact.push(s);
        }
        if report.deltas.capacity() == 0 {
            report.deltas.reserve(moved.deltas.len());
        }
        report.deltas.insert(world.id_at(s).clone(), delta);
        matching.moved_mut().push(s as u32);
    }
    forces.catch_up(world);
    constraints.catch_up(world);
    world.forget_changes();
    for s in inexact {
        world.mark_changed(s);
    }
    report.max_speed = max_speed_sq.sqrt();
    report
}

/// The nearest point within ±[`MAX_COORDINATE`] of a position beyond it (`None` within).
fn beyond_range(p: Point2D<f32>) -> Option<Point2D<f32>> {
    let edge = |v: f32| v.clamp(-MAX_COORDINATE, MAX_COORDINATE);
    (!position_in_range(p) && p.is_finite()).then(|| Point2D::new(edge(p.x), edge(p.y)))
}

/// The world slot of every node the scene matched, in the scene's order.
fn matched_slots<'a, N: Clone + Eq + Hash>(
    scene: &'a CanvasSceneInput<N>,
    matching: &'a Matching<N>,
) -> impl Iterator<Item = usize> + 'a {
    scene
        .nodes
        .iter()
        .zip(matching.matches())
        .filter(|(_, m)| m.slot != NO_SLOT)
        .map(|(_, m)| m.slot as usize)
}

/// What the dynamic bodies in some slots did since the host was last told.
#[derive(Debug)]
struct Moved {
    /// Each body that moved more than the delta epsilon, with its displacement.
    deltas: Vec<(u32, Vector2D<f32>)>,
    /// The fastest awake body's speed, squared.
    max_speed_sq: f32,
    /// How many were awake.
    awake: usize,
}

impl Moved {
    fn of<N: Clone + Eq + Hash>(
        world: &RapierSceneWorld<N>,
        slots: impl Iterator<Item = usize>,
        epsilon_sq: f32,
    ) -> Self {
        let mut moved = Self {
            deltas: Vec::new(),
            max_speed_sq: 0.0,
            awake: 0,
        };
        for s in slots {
            let body = world.body_at(s);
            if !body.is_dynamic() {
                continue;
            }
            if !body.is_sleeping() {
                moved.max_speed_sq = moved.max_speed_sq.max(body.linvel().length_squared());
                moved.awake += 1;
            }
            let t = body.translation();
            let delta = Point2D::new(t.x, t.y) - world.anchor_at(s);
            if delta.square_length() > epsilon_sq && delta.is_finite() {
                moved.deltas.push((s as u32, delta));
            }
        }
        moved
    }

    /// Debug builds (the tests): the changed bodies report what every body does.
    #[cfg(debug_assertions)]
    fn check_against(&self, mut every: Self) {
        every.deltas.sort_unstable_by_key(|&(s, _)| s);
        let bits = |m: &Self| -> Vec<(u32, u32, u32)> {
            m.deltas
                .iter()
                .map(|&(s, d)| (s, d.x.to_bits(), d.y.to_bits()))
                .collect()
        };
        assert_eq!(
            (bits(self), self.awake, self.max_speed_sq.to_bits()),
            (bits(&every), every.awake, every.max_speed_sq.to_bits()),
            "the changed bodies' deltas, awake count and top speed against every body's"
        );
    }
}
