//! The passes that solve one substep's pairs (projected Gauss–Seidel), lane by lane.
//!
//! The bodies are in the grid's order (`pairs.rs`), row of cells by row of cells, and a
//! pair's two bodies sit in the same or a neighbouring cell. Cut that order into blocks
//! of consecutive bodies, and most pairs lie inside one block: a block's pairs touch
//! only its own bodies' velocities, so the blocks are solved side by side under
//! `parallel`, and the few pairs between two blocks after them, in order. That is one
//! Gauss–Seidel order (block by block, then the pairs across), whatever the number of
//! threads: the blocks are cut by the pairs' count, never by the pool's size, so a pass
//! gives the same bits on any number of threads.
//!
//! Without `parallel`, or with fewer than 8,192 pairs, there is one block, and the passes
//! solve the pairs in the order they always have.

use euclid::default::Vector2D;
use std::hash::Hash;

use super::pairs::Pair;
use super::{Collide, Softness, MAX_PUSH_SPEED, SLEEPING_OVERLAP, STREAMS, WAKE_SPEED};
use crate::parallel;
use crate::world::RapierSceneWorld;

/// The pairs a substep holds for each block it is cut into (one block below twice this):
/// fewer are not worth handing to another thread. The blocks are cut at bodies, so one
/// may hold fewer, or none where a body holds more than a block's share.
const PAIRS_PER_BLOCK: usize = 4_096;
/// The most blocks (a power of two, as every block count is, so that 2, 4 or 8 threads
/// get equal shares).
const MOST_BLOCKS: usize = 16;

/// Adds `change` (a change of the pair's relative normal speed) to `pair`'s `impulse`,
/// shared between its two bodies `a` and `b` (indices into `velocity`).
#[inline]
pub(super) fn push(
    pair: &Pair,
    impulse: &mut f32,
    velocity: &mut [Vector2D<f32>],
    (a, b): (usize, usize),
    change: f32,
) {
    if pair.share_a + pair.share_b == 0.0 {
        return;
    }
    *impulse += change;
    velocity[a] -= pair.normal * (change * pair.share_a);
    velocity[b] += pair.normal * (change * pair.share_b);
}

/// What a pass asks of every pair.
#[derive(Clone, Copy)]
struct PassRule {
    soft: Softness,
    inverse_dt: f32,
    /// Whether any body sleeps (else no pair tests for waking one).
    sleepers: bool,
}

/// The pairs and bodies one lane of a pass solves: the bodies `first..first + len` of
/// the grid's order, and pairs among them (a pair reaching outside is left to the pairs
/// across).
struct Lane<'a> {
    first: usize,
    pairs: &'a mut [Pair],
    impulses: &'a mut [f32],
    velocity: &'a mut [Vector2D<f32>],
    wake: Wake<'a>,
    /// The largest change of a pair's relative speed.
    largest: f32,
}

/// What waking a lane's bodies reads and writes, by the lane's own index.
struct Wake<'a> {
    sleeping: &'a mut [bool],
    inverse_mass: &'a mut [f32],
    /// A sleeping body's inverse mass once it wakes.
    wake_inverse_mass: &'a [f32],
    /// The bodies woken (local indices of the whole order), in the order they woke.
    woken: Vec<u32>,
}

impl Lane<'_> {
    /// The lane's own pairs, [`STREAMS`] far-apart runs of them at once, a pair of each
    /// in turn: consecutive pairs of one run share a body, so each waits on the last
    /// one's velocity, while pairs of different runs (far apart in the grid's order)
    /// rarely do, and the processor works on them side by side (a fifth less time a
    /// pass on `random_n100000_e250000`). Pairs reaching past the lane's bodies are
    /// skipped (`whole`: none do).
    fn own_pairs<const PUSH: bool>(&mut self, rule: PassRule, whole: bool) {
        // NOTE: the slices as locals, so the loop keeps them in registers.
        let Self {
            first,
            pairs,
            impulses,
            velocity,
            wake,
            largest,
        } = self;
        let (first, pairs, impulses, velocity) =
            (*first, &mut **pairs, &mut **impulses, &mut **velocity);
        let count = pairs.len();
        let end = (first + velocity.len()) as u32;
        let stride = count.div_ceil(STREAMS);
        let mut most = *largest;
        for i in 0..stride {
            for run in 0..STREAMS {
                let k = run * stride + i;
                if k < count && (whole || pairs[k].b < end) {
                    let change = solve::<PUSH>(pairs, impulses, velocity, wake, first, k, rule);
                    most = most.max(change);
                }
            }
        }
        *largest = most;
    }

    /// The pairs `listed`, in order.
    fn listed<const PUSH: bool>(&mut self, listed: &[u32], rule: PassRule) {
        let Self {
            first,
            pairs,
            impulses,
            velocity,
            wake,
            largest,
        } = self;
        for &k in listed {
            let change = solve::<PUSH>(pairs, impulses, velocity, wake, *first, k as usize, rule);
            *largest = largest.max(change);
        }
    }
}

/// Pair `k` of a lane whose first body is `first`: the change of its relative normal
/// speed that keeps it from closing beyond touching (and with `PUSH`, parts an
/// overlap), shared between its bodies; returns its size. Wakes a sleeping body pushed
/// into.
///
/// NOTE: written without branches on the pair's values (selects instead): whether a
/// pair touches, pushes or holds is all but random from one pair to the next, and a
/// mispredicted branch a pair cost more than its arithmetic (a third of a pass).
/// [`push`] branches only on whether both bodies hold, which is rare.
#[inline(always)]
fn solve<const PUSH: bool>(
    pairs: &mut [Pair],
    impulses: &mut [f32],
    velocity: &mut [Vector2D<f32>],
    wake: &mut Wake<'_>,
    first: usize,
    k: usize,
    rule: PassRule,
) -> f32 {
    let pair = pairs[k];
    let impulse = impulses[k];
    let (a, b) = (pair.a as usize - first, pair.b as usize - first);
    let closing = (velocity[b] - velocity[a]).dot(pair.normal);
    let s = pair.separation;
    // Apart: may close the gap within the substep, no more.
    let apart = -(closing + s * rule.inverse_dt);
    let touching = if PUSH {
        let soft = rule.soft;
        let bias = (soft.bias_rate * s).max(-MAX_PUSH_SPEED);
        -(closing + bias) * soft.mass_scale - soft.impulse_scale * impulse
    } else {
        -closing
    };
    let wanted = if s > 0.0 { apart } else { touching };
    if rule.sleepers && wanted > 0.0 && (wake.sleeping[a] || wake.sleeping[b]) {
        let neither = pair.share_a + pair.share_b == 0.0;
        if wanted > WAKE_SPEED || neither || s < -SLEEPING_OVERLAP {
            wake.pair(&mut pairs[k], first, (a, b));
        }
    }
    let change = wanted.max(-impulse);
    push(&pairs[k], &mut impulses[k], velocity, (a, b), change);
    change.abs()
}

impl Wake<'_> {
    /// A sleeping body of `pair` (lane indices `bodies`) pushed into, or overlapped,
    /// wakes and gives way (one that an awake body only rests against, more slowly than
    /// a body falls asleep, stays asleep), and the pair's shares follow.
    #[cold]
    fn pair(&mut self, pair: &mut Pair, first: usize, bodies: (usize, usize)) {
        for l in [bodies.0, bodies.1] {
            if self.sleeping[l] {
                self.sleeping[l] = false;
                self.inverse_mass[l] = self.wake_inverse_mass[l];
                self.woken.push((first + l) as u32);
            }
        }
        let (wa, wb) = (self.inverse_mass[bodies.0], self.inverse_mass[bodies.1]);
        let total = wa + wb;
        if total > 0.0 {
            (pair.share_a, pair.share_b) = (wa / total, wb / total);
        }
    }
}

impl Collide {
    /// Cuts the grid's order into the blocks the passes solve side by side, and lists
    /// the pairs across two blocks. One block without `parallel`, or for too few pairs.
    pub(super) fn cut_blocks(&mut self) {
        let wanted = if cfg!(feature = "parallel") {
            (self.pairs.len() / PAIRS_PER_BLOCK).min(MOST_BLOCKS)
        } else {
            1
        };
        // The largest power of two not above what is wanted, and at least one.
        self.cut_into(1usize << wanted.max(1).ilog2());
    }

    /// Cuts the grid's order into `blocks` blocks of about as many pairs each (fewer
    /// where a body holds more than a block's share).
    fn cut_into(&mut self, blocks: usize) {
        let (bodies, count) = (self.order.len(), self.pairs.len());
        self.blocks.clear();
        self.blocks.push(0);
        for j in 1..blocks {
            // The first body whose pairs start at or after this block's share of them.
            let target = (count * j / blocks) as u32;
            let at = self.rows[..bodies].partition_point(|&r| r < target) as u32;
            let last = *self.blocks.last().unwrap_or(&0);
            self.blocks.push(at.max(last));
        }
        self.blocks.push(bodies as u32);
        self.across.clear();
        if blocks > 1 {
            for w in self.blocks.windows(2) {
                let pairs = self.rows[w[0] as usize] as usize..self.rows[w[1] as usize] as usize;
                for k in pairs {
                    if self.pairs[k].b >= w[1] {
                        self.across.push(k as u32);
                    }
                }
            }
        }
    }

    /// One pass over the pairs: with `softness`, the push that parts an overlap;
    /// without, only what keeps each pair from closing. Returns the largest change of a
    /// pair's relative speed.
    pub(super) fn pass<N: Clone + Eq + Hash>(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        softness: Option<Softness>,
        inverse_dt: f32,
    ) -> f32 {
        // Asked once: a pair is tested for waking a body only while some body sleeps.
        let sleepers = self.sleeping.contains(&true);
        let rule = |soft| PassRule {
            soft,
            inverse_dt,
            sleepers,
        };
        let (largest, woken) = match softness {
            Some(soft) => self.pass_with::<true>(rule(soft)),
            None => self.pass_with::<false>(rule(Softness {
                bias_rate: 0.0,
                mass_scale: 1.0,
                impulse_scale: 0.0,
            })),
        };
        for &l in &woken {
            world
                .body_at_mut(self.order[l as usize] as usize)
                .wake_up(true);
        }
        if !woken.is_empty() {
            self.share();
        }
        largest
    }

    /// [`pass`](Self::pass), with the push (`PUSH`) or without, so the loop carries no
    /// choice it need not make: the blocks' own pairs side by side, then the pairs
    /// across blocks. Returns the largest change and the bodies woken, in order.
    fn pass_with<const PUSH: bool>(&mut self, rule: PassRule) -> (f32, Vec<u32>) {
        let Self {
            blocks,
            across,
            rows,
            pairs,
            impulses,
            velocity,
            sleeping,
            inverse_mass,
            wake_inverse_mass,
            ..
        } = self;
        let bodies = || blocks.windows(2).map(|w| w[0] as usize..w[1] as usize);
        let pair_ranges = || {
            blocks
                .windows(2)
                .map(|w| rows[w[0] as usize] as usize..rows[w[1] as usize] as usize)
        };
        let mut lanes: Vec<Lane> = parallel::split_ranges(pairs, pair_ranges())
            .into_iter()
            .zip(parallel::split_ranges(impulses, pair_ranges()))
            .zip(parallel::split_ranges(velocity, bodies()))
            .zip(parallel::split_ranges(sleeping, bodies()))
            .zip(parallel::split_ranges(inverse_mass, bodies()))
            .map(
                |(((((_, pairs), (_, impulses)), (range, velocity)), (_, sleeping)), (_, mass))| {
                    Lane {
                        first: range.start,
                        pairs,
                        impulses,
                        velocity,
                        wake: Wake {
                            sleeping,
                            inverse_mass: mass,
                            wake_inverse_mass: &wake_inverse_mass[range],
                            woken: Vec::new(),
                        },
                        largest: 0.0,
                    }
                },
            )
            .collect();
        let whole = lanes.len() == 1;
        if whole {
            lanes[0].own_pairs::<PUSH>(rule, true);
        } else {
            parallel::for_each(
                &mut lanes,
                || (),
                |(), lane| lane.own_pairs::<PUSH>(rule, false),
            );
        }
        let mut largest = 0.0_f32;
        let mut woken = Vec::new();
        for lane in lanes {
            largest = largest.max(lane.largest);
            woken.extend(lane.wake.woken);
        }
        if !across.is_empty() {
            let mut lane = Lane {
                first: 0,
                pairs,
                impulses,
                velocity,
                wake: Wake {
                    sleeping,
                    inverse_mass,
                    wake_inverse_mass,
                    woken,
                },
                largest,
            };
            lane.listed::<PUSH>(across, rule);
            (largest, woken) = (lane.largest, lane.wake.woken);
        }
        (largest, woken)
    }
}

#[cfg(test)]
mod tests;
