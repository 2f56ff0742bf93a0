//! The bodies and pairs of one substep's disk separation: bodies gathered in the grid's
//! order (`grid.rs`), the pairs that may touch found among them, and each pair started
//! from the impulse it ended the last substep with (warm starting). The passes that
//! solve the pairs are in `passes.rs`.
//!
//! Working in the grid's order rather than by world slot keeps a pair's two bodies close
//! in memory (the same or a neighbouring cell): on a large graph the per-body arrays
//! outgrow the cache (`docs/performance.md`, At scale, gives the sizes), and the passes
//! run over every pair many times a substep.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};

use super::grid::Grid;
use super::passes::push;
use super::shapes::{box_contact, Side};
use super::{coincident_normal, shares, Collide, SLEEPING_OVERLAP};
use crate::parallel;
use crate::world::RapierSceneWorld;

/// Whether two bodies `d` apart (from the first to the second) that move `relative` to
/// each other over the substep, in a straight line, come within `within` of each other.
fn comes_within(d: Vector2D<f32>, relative: Vector2D<f32>, within: f32) -> bool {
    let speed_sq = relative.square_length();
    let t = if speed_sq > 0.0 {
        (-d.dot(relative) / speed_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (d + relative * t).square_length() <= within * within
}

/// The most pairs a substep solves, per body and in all: far above what disks that
/// cannot overlap much hold (jammed, or in a hot scatter's first contacts), and a bound
/// on the memory and time a crowd denser than disks can be (everything at one point:
/// O(n²) pairs) would otherwise take: without it, contacts from the first frame of a
/// large graph ran out of memory (`docs/performance.md` gives the counts and sizes).
pub(super) const PAIRS_PER_BODY: usize = 32;
pub(super) const PAIRS_AT_LEAST: usize = 4_096;

/// No local index: the body has no finite position, so it is in no pair.
pub(super) const NONE: u32 = u32::MAX;

/// Two bodies close enough to touch during the substep, by their local index (their
/// place in the grid's order), `a < b`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Pair {
    pub(super) a: u32,
    pub(super) b: u32,
    /// From `a` to `b`.
    pub(super) normal: Vector2D<f32>,
    /// Distance minus the sum of the radii (negative in an overlap).
    pub(super) separation: f32,
    /// The share of a change of relative speed each body takes: its inverse mass over
    /// the two's (0 for a body that does not give way).
    pub(super) share_a: f32,
    pub(super) share_b: f32,
}

/// What every body brings to the separation, by world slot, before it is put in the
/// grid's order.
#[derive(Debug, Default)]
pub(super) struct BySlot {
    /// The bounding radius, which the grid and the first test of a pair read.
    pub(super) radius: Vec<f32>,
    /// The outline as a box swept by a disk (`shapes.rs`): the box's half extents (zero
    /// for a disk) and the disk's radius.
    pub(super) inner: Vec<Vector2D<f32>>,
    pub(super) round: Vec<f32>,
    /// The bounding box's half width and half height, which the grid reads (filled
    /// from the radius where left empty).
    pub(super) half: Vec<Vector2D<f32>>,
    /// 0 for a body that does not give way.
    pub(super) inverse_mass: Vec<f32>,
    pub(super) velocity: Vec<Vector2D<f32>>,
    /// The displacement over the substep.
    pub(super) motion: Vec<Vector2D<f32>>,
    pub(super) sleeping: Vec<bool>,
    /// The world version the outlines (`radius`, `inner`, `round`, `half`) were read
    /// for: shapes change only with it.
    shapes_of: Option<u64>,
}

impl BySlot {
    /// Reads every body's outline, unless the world's version is the one they were
    /// read for.
    pub(super) fn read_shapes<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        let n = world.slot_count();
        if self.shapes_of == Some(world.version()) && self.radius.len() == n {
            return;
        }
        self.radius.clear();
        self.inner.clear();
        self.round.clear();
        self.half.clear();
        for s in 0..n {
            let shape = world.shape_at(s);
            let (inner, round) = shape.inner_and_round();
            self.radius.push(shape.bounding_radius());
            self.inner.push(inner);
            self.round.push(round);
            self.half.push(inner + Vector2D::new(round, round));
        }
        self.shapes_of = Some(world.version());
    }

    /// Clears what a substep brings (masses, velocities, motion, sleep), keeping the
    /// outlines.
    pub(super) fn clear_motion(&mut self) {
        self.inverse_mass.clear();
        self.velocity.clear();
        self.motion.clear();
        self.sleeping.clear();
    }

    pub(super) fn clear(&mut self) {
        self.shapes_of = None;
        self.radius.clear();
        self.inner.clear();
        self.round.clear();
        self.half.clear();
        self.inverse_mass.clear();
        self.velocity.clear();
        self.motion.clear();
        self.sleeping.clear();
    }
}

/// The bodies of a run of the grid's order (`RUN`) and the pairs found for them.
#[derive(Debug, Default)]
pub(super) struct RunPairs {
    pairs: Vec<Pair>,
    /// Whether the run's search ended without reaching its bound.
    complete: bool,
}

/// Bodies in neighbouring cells of the grid found in one run: a pass finds the
/// neighbouring cells' pairs in runs of this many bodies of the grid's order, side by
/// side under `parallel` (fixed, so the pairs do not depend on the thread count).
const RUN: usize = 1_024;

/// The pairs a run of the warm start looks up.
const WARM_RUN: usize = 1_024;

/// What the test of a candidate pair reads, by local index.
struct Candidates<'a> {
    points: &'a [Point2D<f32>],
    radius: &'a [f32],
    half: &'a [Vector2D<f32>],
    inner: &'a [Vector2D<f32>],
    round: &'a [f32],
    boxes: bool,
    inverse_mass: &'a [f32],
    motion: &'a [Vector2D<f32>],
    order: &'a [u32],
    /// The motion the grid's cells allow.
    slack: f32,
    margin: f32,
}

impl Candidates<'_> {
    /// Bodies `a < b` as a pair, or `None` if they cannot touch (nor come within the
    /// margin) this substep, or need nothing.
    fn pair(&self, a: u32, b: u32) -> Option<Pair> {
        let Self {
            points,
            radius,
            half,
            inner,
            round,
            boxes,
            inverse_mass,
            motion,
            order,
            slack,
            margin,
        } = *self;
        let (ia, ib) = (a as usize, b as usize);
        let d = points[ib] - points[ia];
        let relative = motion[ib] - motion[ia];
        if boxes {
            // Bounding boxes apart on an axis by more than the bodies move along it:
            // they cannot touch this substep (most of a wide label's neighbours in
            // the grid), found without a square root.
            let reach = half[ia] + half[ib];
            if d.x.abs() > reach.x + relative.x.abs() + margin
                || d.y.abs() > reach.y + relative.y.abs() + margin
            {
                return None;
            }
        }
        let reach = radius[ia] + radius[ib];
        let moved = relative.length();
        let near = reach + moved + margin;
        let distance_sq = d.square_length();
        if distance_sq > near * near {
            return None;
        }
        // Two bodies moving fast relative to each other are a pair only if their
        // paths come close: the disc above grows with the square of the motion, and
        // in a hot, dense crowd it held millions of pairs that pass far apart (a large
        // graph with contacts from the first frame ran out of memory:
        // `docs/performance.md`, beside `PAIRS_PER_BODY`).
        // Up to the usual motion the disc stands, as slack for what the solve
        // changes of the velocities.
        if moved > slack && !comes_within(d, relative, reach + margin + slack) {
            return None;
        }
        let distance = distance_sq.sqrt();
        // The direction two coincident bodies part along: one that depends only on
        // their two slots.
        let coincident = || {
            let (sa, sb) = (order[ia], order[ib]);
            if sa < sb {
                coincident_normal(sa, sb)
            } else {
                -coincident_normal(sb, sa)
            }
        };
        let outline = if boxes {
            box_contact(inner, round, (ia, ib), d, Side::CentreLine, coincident)
        } else {
            None
        };
        if outline.is_some_and(|(_, separation)| separation > moved + margin) {
            // Bounding disks close, outlines further apart than they move.
            return None;
        }
        let parted = match outline {
            Some((_, separation)) => separation >= -SLEEPING_OVERLAP,
            None => distance >= reach - SLEEPING_OVERLAP,
        };
        let still = motion[ia] == Vector2D::zero() && motion[ib] == Vector2D::zero();
        if inverse_mass[ia] == 0.0 && inverse_mass[ib] == 0.0 && still && parted {
            // Neither gives way nor moves, and they do not overlap: nothing to part.
            // (Two that fell asleep overlapping are woken and parted.)
            return None;
        }
        let (normal, separation) = outline.unwrap_or_else(|| {
            let normal = if distance > 1e-6 {
                d / distance
            } else {
                coincident()
            };
            (normal, distance - reach)
        });
        let (share_a, share_b) = shares(inverse_mass[ia], inverse_mass[ib]);
        Some(Pair {
            a,
            b,
            normal,
            separation,
            share_a,
            share_b,
        })
    }
}

impl Collide {
    /// The pairs that may touch, or come within `margin` of touching, each once,
    /// ordered by their local indices, and where each body's pairs start (`rows`).
    ///
    /// The neighbouring cells' pairs are found in runs of [`RUN`] bodies of the grid's
    /// order, side by side under `parallel`, and joined in order: the same pairs as one
    /// search in order, on any number of threads.
    pub(super) fn find_pairs(&mut self, margin: f32) {
        let Self {
            grid,
            pairs,
            extra,
            runs,
            points,
            radius,
            half,
            inner,
            round,
            boxes,
            inverse_mass,
            motion,
            order,
            region,
            ..
        } = self;
        let test = Candidates {
            points,
            radius,
            half,
            inner,
            round,
            boxes: *boxes,
            inverse_mass,
            motion,
            order,
            slack: grid.usual_motion(),
            margin,
        };
        // Bounded by the world's bodies, not the region's: a drag through a pile in a
        // large world keeps the pairs the full search would.
        let budget = PAIRS_PER_BODY * points.len().max(region.len()) + PAIRS_AT_LEAST;
        let bodies = grid.len();
        runs.resize_with(bodies.div_ceil(RUN), Default::default);
        {
            let grid: &Grid = grid;
            let mut jobs: Vec<_> = runs.iter_mut().enumerate().collect();
            parallel::for_each(
                &mut jobs,
                || (),
                |(), (r, found)| {
                    let first = *r * RUN..((*r + 1) * RUN).min(bodies);
                    // A run alone holds at most what its bodies may (a run past that is
                    // searched again below, in order, for what the budget keeps).
                    let most = PAIRS_PER_BODY * first.len() + PAIRS_AT_LEAST;
                    found.pairs.clear();
                    found.complete = grid.near_pairs(first, |a, b| {
                        found.pairs.extend(test.pair(a, b));
                        found.pairs.len() < most
                    });
                },
            );
        }
        // The runs' pairs in order up to the budget. A run that reached its own bound (a
        // crowd far denser than disks can be: thousands of nodes added at one point,
        // contacts from a hot scatter's first frame) is searched again from its start,
        // in order, for what the budget keeps; the rest wait for a later substep.
        let (mut near, mut whole, mut resume) = (0, 0, None);
        for (r, found) in runs.iter().enumerate() {
            if near >= budget {
                break;
            }
            if !found.complete {
                resume = Some(r * RUN);
                break;
            }
            (near, whole) = (near + found.pairs.len(), r + 1);
        }
        let near = near.min(budget);
        let concat = |pairs: &mut Vec<Pair>| {
            pairs.clear();
            for found in &runs[..whole] {
                pairs.extend_from_slice(&found.pairs);
            }
            pairs.truncate(budget);
        };
        extra.clear();
        let fast = |grid: &mut Grid, room: usize, extra: &mut Vec<Pair>| {
            grid.fast_pairs(points, half, motion, |a, b| test.pair(a, b), room, extra);
        };
        if let Some(start) = resume {
            concat(pairs);
            grid.near_pairs(start..bodies, |a, b| {
                pairs.extend(test.pair(a, b));
                pairs.len() < budget
            });
            if pairs.len() < budget {
                fast(grid, budget - pairs.len(), extra);
            }
        } else if near < budget {
            // The room the runs leave is known: the fast bodies' search (on another
            // thread, if one is free) beside the copy of the runs' pairs.
            parallel::beside(|| fast(grid, budget - near, extra), || concat(pairs));
        } else {
            concat(pairs);
        }
        if !self.extra.is_empty() {
            self.merge_extra();
        }
        self.impulses.clear();
        self.impulses.resize(self.pairs.len(), 0.0);
        self.rows.clear();
        self.rows.resize(self.order.len() + 1, 0);
        for pair in &self.pairs {
            self.rows[pair.a as usize + 1] += 1;
        }
        for l in 0..self.order.len() {
            self.rows[l + 1] += self.rows[l];
        }
    }

    /// Merges the pairs fast bodies found on their paths (sorted and each once here)
    /// into the others, which are in order already and hold none of them.
    fn merge_extra(&mut self) {
        self.extra.sort_unstable_by_key(|p| (p.a, p.b));
        self.extra.dedup_by_key(|p| (p.a, p.b));
        let near = std::mem::take(&mut self.pairs);
        let mut merged = std::mem::take(&mut self.merged);
        merged.clear();
        let (mut i, mut j) = (0, 0);
        while i < near.len() || j < self.extra.len() {
            let take_near = j == self.extra.len()
                || (i < near.len() && (near[i].a, near[i].b) < (self.extra[j].a, self.extra[j].b));
            if take_near {
                merged.push(near[i]);
                i += 1;
            } else {
                merged.push(self.extra[j]);
                j += 1;
            }
        }
        self.pairs = merged;
        self.merged = near;
    }

    /// Finds the pair each impulse the last substep kept belongs to (`warm`), in fixed
    /// runs side by side under `parallel`; returns whether the impulses are for this
    /// world version (else nothing warm-starts). [`warm_start`] adds them.
    pub(super) fn find_warm_starts(&mut self, version: u64) -> bool {
        if self.last_version != Some(version) {
            return false;
        }
        let Self {
            last,
            local,
            rows,
            pairs,
            warm,
            ..
        } = self;
        warm.clear();
        warm.resize(last.len(), NONE);
        // Runs of a fixed length, one for all below it (not worth the pool's start).
        let run = if last.len() < WARM_RUN * 2 {
            last.len().max(1)
        } else {
            WARM_RUN
        };
        let (local, rows, pairs_found): (&[u32], &[u32], &[Pair]) = (local, rows, pairs);
        parallel::for_each_run(warm, run, |range, found| {
            for (k, &(sa, sb, _)) in found.iter_mut().zip(&last[range]) {
                let (Some(&a), Some(&b)) = (local.get(sa as usize), local.get(sb as usize)) else {
                    continue;
                };
                if a == NONE || b == NONE {
                    continue;
                }
                let (a, b) = (a.min(b), a.max(b));
                let row = rows[a as usize] as usize..rows[a as usize + 1] as usize;
                if let Some(at) = row.into_iter().find(|&k| pairs_found[k].b == b) {
                    *k = at as u32;
                }
            }
        });
        true
    }
}

/// Starts each pair from the impulse it ended the last substep with (`last`, each
/// found at pair `warm[i]`, or `NONE`), added in the order they were kept.
pub(super) fn warm_start(
    warm: &[u32],
    last: &[(u32, u32, f32)],
    pairs: &[Pair],
    impulses: &mut [f32],
    velocity: &mut [Vector2D<f32>],
) {
    for (&k, &(_, _, impulse)) in warm.iter().zip(last) {
        if k != NONE {
            let (k, pair) = (k as usize, &pairs[k as usize]);
            let ends = (pair.a as usize, pair.b as usize);
            push(pair, &mut impulses[k], velocity, ends, impulse);
        }
    }
}

/// The impulses of the `pairs` that pushed, as `(slot a, slot b, impulse)` (`order`: the
/// slot of each local index), kept in `last` for the next substep: found in runs of
/// pairs side by side under `parallel`, kept in order.
pub(super) fn keep_impulses(
    order: &[u32],
    pairs: &[Pair],
    impulses: &[f32],
    last: &mut Vec<(u32, u32, f32)>,
) {
    parallel::collect_runs(
        pairs.len(),
        RUN,
        last,
        |k| impulses[k] > 0.0,
        |k| {
            let p = pairs[k];
            (order[p.a as usize], order[p.b as usize], impulses[k])
        },
    );
}

#[cfg(test)]
mod tests;
