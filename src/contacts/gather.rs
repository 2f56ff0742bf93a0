//! The bodies of a substep's disk separation put in the grid's order (`grid.rs`): what
//! each brings, read by world slot (`BySlot`), copied to its local index, in runs of
//! [`GATHER_RUN`] local indices side by side under `parallel`. Each body's copy is its
//! own, so the arrays are the same on any number of threads.

use euclid::default::{Point2D, Vector2D};

use super::pairs::{BySlot, NONE};
use super::Collide;
use crate::parallel;

/// Local indices a run of the gather copies.
const GATHER_RUN: usize = 1_024;

/// The local arrays of one run of the grid's order, and the world slots it copies from.
struct Run<'a> {
    order: &'a [u32],
    points: &'a mut [Point2D<f32>],
    radius: &'a mut [f32],
    half: &'a mut [Vector2D<f32>],
    inner: &'a mut [Vector2D<f32>],
    round: &'a mut [f32],
    inverse_mass: &'a mut [f32],
    velocity: &'a mut [Vector2D<f32>],
    before: &'a mut [Vector2D<f32>],
    motion: &'a mut [Vector2D<f32>],
    sleeping: &'a mut [bool],
}

impl Run<'_> {
    /// Copies every body of the run from `by_slot` (positions from `points`).
    fn fill(&mut self, points: &[Point2D<f32>], by_slot: &BySlot) {
        for (l, &s) in self.order.iter().enumerate() {
            let s = s as usize;
            self.points[l] = points[s];
            self.radius[l] = by_slot.radius[s];
            self.half[l] = by_slot.half[s];
            self.inner[l] = by_slot.inner.get(s).copied().unwrap_or_default();
            self.round[l] = by_slot.round.get(s).copied().unwrap_or(by_slot.radius[s]);
            self.inverse_mass[l] = by_slot.inverse_mass[s];
            let velocity = by_slot.velocity.get(s).copied().unwrap_or_default();
            self.velocity[l] = velocity;
            self.before[l] = velocity;
            self.motion[l] = by_slot.motion[s];
            self.sleeping[l] = by_slot.sleeping.get(s).copied().unwrap_or(false);
        }
    }
}

/// `buffer` holding `n` entries (what it held is written over), in runs.
fn runs_of<T: Clone + Default>(buffer: &mut Vec<T>, n: usize) -> std::slice::ChunksMut<'_, T> {
    buffer.resize(n, T::default());
    buffer.chunks_mut(GATHER_RUN)
}

/// The next run of `runs` (every array has as many as the order).
fn next<'a, T>(runs: &mut std::slice::ChunksMut<'a, T>) -> &'a mut [T] {
    runs.next().unwrap_or_default()
}

impl Collide {
    /// Puts the bodies (positions `points`, the rest in `self.by_slot`) in the grid's
    /// order: fills `order`, `local` and the local arrays.
    pub(super) fn take_in_grid_order(&mut self, points: &[Point2D<f32>]) {
        let by_slot = &mut self.by_slot;
        if by_slot.half.len() < by_slot.radius.len() {
            let from = by_slot.half.len();
            by_slot
                .half
                .extend(by_slot.radius[from..].iter().map(|&r| Vector2D::new(r, r)));
        }
        let slots = self.grid.sort(
            points,
            &self.by_slot.half,
            &self.by_slot.motion,
            &self.region,
        );
        self.order.clear();
        self.order.extend(slots);
        self.local.clear();
        self.local.resize(points.len(), NONE);
        for (l, &s) in self.order.iter().enumerate() {
            self.local[s as usize] = l as u32;
        }
        let n = self.order.len();
        let mut points_runs = runs_of(&mut self.points, n);
        let mut radius = runs_of(&mut self.radius, n);
        let mut half = runs_of(&mut self.half, n);
        let mut inner = runs_of(&mut self.inner, n);
        let mut round = runs_of(&mut self.round, n);
        let mut inverse_mass = runs_of(&mut self.inverse_mass, n);
        let mut velocity = runs_of(&mut self.velocity, n);
        let mut before = runs_of(&mut self.before, n);
        let mut motion = runs_of(&mut self.motion, n);
        let mut sleeping = runs_of(&mut self.sleeping, n);
        let mut runs: Vec<Run<'_>> = self
            .order
            .chunks(GATHER_RUN)
            .map(|order| Run {
                order,
                points: next(&mut points_runs),
                radius: next(&mut radius),
                half: next(&mut half),
                inner: next(&mut inner),
                round: next(&mut round),
                inverse_mass: next(&mut inverse_mass),
                velocity: next(&mut velocity),
                before: next(&mut before),
                motion: next(&mut motion),
                sleeping: next(&mut sleeping),
            })
            .collect();
        let by_slot = &self.by_slot;
        parallel::for_each(&mut runs, || (), |(), run| run.fill(points, by_slot));
        self.boxes = self.inner.iter().any(|&i| i != Vector2D::zero());
    }
}
