//! The last parting of disks before a layout halts at the end of its schedule: the
//! overlaps the soft contacts still hold are projected apart on positions, the way
//! d3-force's `forceCollide` moves nodes, so a halted layout has none. The soft contacts
//! of every substep are in `mod.rs`.
//!
//! A soft contact under a steady push holds an overlap of about the push's acceleration
//! over its squared angular frequency, and a cooling layout halts while some disks are
//! still closing in; over a few thousand disks that leaves a few overlaps past half a
//! unit. The projection moves each dynamic body of an overlapping pair by its share (its
//! inverse mass over the pair's) of the overlap, pass after pass, until none is deeper
//! than [`PARTED`] or [`PASSES`] are done. Kinematic and fixed bodies do not move.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;

use super::shapes::{box_contact, Side};
use super::Collide;
use crate::world::RapierSceneWorld;

/// Passes over the overlapping pairs at most.
const PASSES: usize = 32;
/// An overlap shallower than this (world units) counts as parted.
const PARTED: f32 = 0.01;
/// Pairs this much (world units) further apart than touching are watched too: the
/// projection may push a body into them.
const MARGIN: f32 = 2.0;

impl Collide {
    /// Moves the dynamic bodies of every overlapping pair apart on their positions (not
    /// their velocities: the world halts right after). Returns the largest distance a
    /// body was moved, in world units.
    pub(crate) fn part_overlaps<N: Clone + Eq + Hash>(
        &mut self,
        world: &mut RapierSceneWorld<N>,
    ) -> f32 {
        let n = world.slot_count();
        let mut start = std::mem::take(&mut self.points);
        start.clear();
        self.by_slot.clear();
        for s in 0..n {
            let body = world.body_at(s);
            let t = body.translation();
            start.push(Point2D::new(t.x, t.y));
            let shape = world.shape_at(s);
            let (inner, round) = shape.inner_and_round();
            self.by_slot.radius.push(shape.bounding_radius());
            self.by_slot.inner.push(inner);
            self.by_slot.round.push(round);
            self.by_slot.half.push(inner + Vector2D::new(round, round));
            self.by_slot.inverse_mass.push(if body.is_dynamic() {
                1.0 / world.mass_at(s)
            } else {
                0.0
            });
            // Widens the grid's cells by the margin.
            self.by_slot.motion.push(Vector2D::new(MARGIN, 0.0));
        }
        // Every body: a cold stop parts what any pair still holds.
        self.region.clear();
        self.take_in_grid_order(&start);
        self.find_pairs(MARGIN);
        let from = self.points.clone();
        for _ in 0..PASSES {
            if self.project_pass() < PARTED {
                break;
            }
        }
        let mut farthest = 0.0_f32;
        for (l, (&p, &from)) in self.points.iter().zip(&from).enumerate() {
            if p != from && p.is_finite() {
                farthest = farthest.max((p - from).length());
                world
                    .body_at_mut(self.order[l] as usize)
                    .set_translation(Vector::new(p.x, p.y), false);
            }
        }
        // What the soft contacts kept belongs to positions that are gone.
        self.last.clear();
        self.pairs.clear();
        self.read.clear();
        farthest
    }

    /// One Gauss–Seidel pass of position projection. Returns the deepest overlap it met.
    fn project_pass(&mut self) -> f32 {
        let mut deepest = 0.0_f32;
        for pair in &self.pairs {
            let (a, b) = (pair.a as usize, pair.b as usize);
            let d = self.points[b] - self.points[a];
            let outline = if self.boxes {
                box_contact(&self.inner, &self.round, (a, b), d, Side::Nearest, || {
                    pair.normal
                })
            } else {
                None
            };
            let (normal, overlap) = match outline {
                Some((normal, separation)) => (normal, -separation),
                None => {
                    let distance = d.length();
                    let normal = if distance > 1e-6 {
                        d / distance
                    } else {
                        pair.normal
                    };
                    (normal, self.radius[a] + self.radius[b] - distance)
                }
            };
            if overlap <= 0.0 {
                continue;
            }
            deepest = deepest.max(overlap);
            self.points[a] -= normal * (overlap * pair.share_a);
            self.points[b] += normal * (overlap * pair.share_b);
        }
        deepest
    }
}
