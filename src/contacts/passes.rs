//! The passes that solve one substep's pairs (projected Gauss–Seidel), lane by lane.
//!
//! The bodies are in the grid's order (`pairs.rs`), row of cells by row of cells, and a
//! pair's two bodies sit in the same or a neighbouring cell. Cut that order into blocks
//! of consecutive bodies, and most pairs lie inside one block: a block's pairs touch
//! only its own bodies' velocities, so the blocks are solved side by side under
//! `parallel`. The few pairs from one block into the next follow, by the boundary they
//! cross: those of boundaries 0, 2, 4, … side by side (each touches only its two
//! blocks, and no two of these share one; a lane takes both blocks' own pairs and then
//! these, so a pass holds two parts side by side, not three), then those of 1, 3, 5,
//! …; the rare pair reaching past the next block comes last, in order. That is one Gauss–Seidel order,
//! whatever the number of threads: the blocks are cut by the pairs' count, never by the
//! pool's size, so a pass gives the same bits on any number of threads. (Where a block
//! spans more than two rows of cells, the pairs of two boundaries share no body, and the
//! order gives the bits of the pairs across solved in index order.)
//!
//! Without `parallel`, or with fewer than 8,192 pairs, there is one block, and the passes
//! solve the pairs in the order they always have.

use euclid::default::Vector2D;
use std::hash::Hash;
use std::ops::Range;

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
    /// rarely do, and the processor works on them side by side, so a pass takes less
    /// time (`docs/performance.md` gives the figure). Pairs reaching past the lane's
    /// bodies are skipped (`whole`: none do).
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

    /// The lane cut in two at its `bodies`-th body and `pairs`-th pair: the first part
    /// takes the bodies and pairs before, the second the rest (each waking into a list
    /// of its own).
    fn split(&mut self, bodies: usize, pairs: usize) -> (Lane<'_>, Lane<'_>) {
        let (p1, p2) = self.pairs.split_at_mut(pairs);
        let (i1, i2) = self.impulses.split_at_mut(pairs);
        let (v1, v2) = self.velocity.split_at_mut(bodies);
        let (s1, s2) = self.wake.sleeping.split_at_mut(bodies);
        let (m1, m2) = self.wake.inverse_mass.split_at_mut(bodies);
        let (w1, w2) = self.wake.wake_inverse_mass.split_at(bodies);
        let lane =
            |first, pairs, impulses, velocity, sleeping, inverse_mass, wake_inverse_mass| Lane {
                first,
                pairs,
                impulses,
                velocity,
                wake: Wake {
                    sleeping,
                    inverse_mass,
                    wake_inverse_mass,
                    woken: Vec::new(),
                },
                largest: 0.0,
            };
        (
            lane(self.first, p1, i1, v1, s1, m1, w1),
            lane(self.first + bodies, p2, i2, v2, s2, m2, w2),
        )
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
/// mispredicted branch a pair cost more than its arithmetic (`docs/performance.md`
/// gives its share of a pass). [`push`] branches only on whether both bodies hold,
/// which is rare.
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

/// How many blocks a substep's `pairs` are cut into: one without `parallel` or for too
/// few pairs, else the largest power of two not above one a [`PAIRS_PER_BLOCK`].
pub(super) fn blocks_for(pairs: usize) -> usize {
    let wanted = if cfg!(feature = "parallel") {
        (pairs / PAIRS_PER_BLOCK).min(MOST_BLOCKS)
    } else {
        1
    };
    1usize << wanted.max(1).ilog2()
}

/// The blocks of the grid's order that the passes solve side by side, and the pairs
/// between them.
#[derive(Debug, Default)]
pub(super) struct Cut {
    /// Where each block starts, and the end of the last, as local indices.
    pub(super) blocks: Vec<u32>,
    /// The pairs from one block into the next, by boundary: each boundary's in order,
    /// as indices from its first block's first pair, starting at `across_ends[j]`.
    across: Vec<u32>,
    across_ends: Vec<u32>,
    /// The pairs reaching past the next block, by index, in order.
    far: Vec<u32>,
}

impl Cut {
    /// Cuts the grid's order of `bodies` bodies into `blocks` blocks of about as many
    /// of the `pairs` each (fewer where a body holds more than a block's share; `rows`:
    /// where each body's pairs start), and sorts the pairs between two blocks by the
    /// boundary they cross.
    pub(super) fn cut_into(&mut self, blocks: usize, bodies: usize, rows: &[u32], pairs: &[Pair]) {
        let count = pairs.len();
        self.blocks.clear();
        self.blocks.push(0);
        for j in 1..blocks {
            // The first body whose pairs start at or after this block's share of them.
            let target = (count * j / blocks) as u32;
            let at = rows[..bodies].partition_point(|&r| r < target) as u32;
            let last = *self.blocks.last().unwrap_or(&0);
            self.blocks.push(at.max(last));
        }
        self.blocks.push(bodies as u32);
        self.across.clear();
        self.across_ends.clear();
        self.far.clear();
        if blocks > 1 {
            // Block `j`'s pairs reaching past it: into the next block (listed by the
            // boundary, as indices from the block's first pair), or further.
            for j in 0..blocks - 1 {
                self.across_ends.push(self.across.len() as u32);
                let (end, next) = (self.blocks[j + 1], self.blocks[j + 2]);
                let first = rows[self.blocks[j] as usize] as usize;
                for (k, pair) in pairs
                    .iter()
                    .enumerate()
                    .take(rows[end as usize] as usize)
                    .skip(first)
                {
                    match pair.b {
                        b if b < end => {}
                        b if b < next => self.across.push((k - first) as u32),
                        _ => self.far.push(k as u32),
                    }
                }
            }
            self.across_ends.push(self.across.len() as u32);
        }
    }
}

impl Collide {
    /// Cuts the grid's order into `blocks` blocks ([`Cut::cut_into`]).
    #[cfg(test)]
    pub(super) fn cut_into(&mut self, blocks: usize) {
        (self.cut).cut_into(blocks, self.order.len(), &self.rows, &self.pairs);
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
    /// choice it need not make. Blocks `2i` and `2i + 1` make one lane, side by side with
    /// the others: each block's own pairs, then the pairs from the first into the
    /// second. Then the pairs across the boundaries between lanes, side by side; then
    /// the few reaching further, in order. Only pairs of disjoint bodies change places
    /// against "every block's own pairs, then the pairs across by boundary" (the
    /// module's order), so the bits are that order's. Returns the largest change and
    /// the bodies woken, in that order.
    fn pass_with<const PUSH: bool>(&mut self, rule: PassRule) -> (f32, Vec<u32>) {
        let Cut {
            blocks,
            across,
            across_ends,
            far,
        } = &self.cut;
        let rows = &self.rows;
        let mut solving = Solving {
            rows,
            pairs: &mut self.pairs,
            impulses: &mut self.impulses,
            velocity: &mut self.velocity,
            sleeping: &mut self.sleeping,
            inverse_mass: &mut self.inverse_mass,
            wake_inverse_mass: &self.wake_inverse_mass,
        };
        let (mut largest, mut woken) = (0.0_f32, Vec::new());
        // No block before a cut (no pairs): nothing to solve.
        let count = blocks.len().saturating_sub(1);
        if count == 1 {
            let every = blocks[0] as usize..blocks[1] as usize;
            let mut lanes = solving.lanes(std::slice::from_ref(&every));
            lanes[0].own_pairs::<PUSH>(rule, true);
            gather(lanes, &mut largest, &mut woken);
        } else {
            // Two blocks a lane: each block's own pairs, then those from the first into
            // the second (no other lane touches either block).
            let two: Vec<_> = (0..count)
                .step_by(2)
                .map(|j| blocks[j] as usize..blocks[(j + 2).min(count)] as usize)
                .collect();
            let mut jobs: Vec<_> = solving
                .lanes(&two)
                .into_iter()
                .zip((0..count).step_by(2))
                .map(|(lane, j)| (lane, j, [Vec::new(), Vec::new(), Vec::new()]))
                .collect();
            parallel::for_each(
                &mut jobs,
                || (),
                |(), (lane, j, woken)| {
                    let j = *j;
                    let bodies = (blocks[j + 1] - blocks[j]) as usize;
                    let pairs = (rows[blocks[j + 1] as usize] - rows[blocks[j] as usize]) as usize;
                    let (mut first, mut second) = lane.split(bodies, pairs);
                    first.own_pairs::<PUSH>(rule, false);
                    second.own_pairs::<PUSH>(rule, false);
                    let largest = first.largest.max(second.largest);
                    woken[0] = first.wake.woken;
                    woken[1] = second.wake.woken;
                    lane.largest = lane.largest.max(largest);
                    if j + 1 < count {
                        lane.listed::<PUSH>(
                            &across[across_ends[j] as usize..across_ends[j + 1] as usize],
                            rule,
                        );
                        woken[2] = std::mem::take(&mut lane.wake.woken);
                    }
                },
            );
            // Woken in the order of one block after another, then of the pairs across.
            let mut across_woken = Vec::new();
            for (lane, _, [a, b, c]) in jobs {
                largest = largest.max(lane.largest);
                woken.extend(a);
                woken.extend(b);
                across_woken.extend(c);
            }
            woken.extend(across_woken);
        }
        // The pairs across the boundaries between those lanes' blocks, side by side.
        let boundaries = blocks.len().saturating_sub(2);
        {
            let crossed: Vec<usize> = (1..boundaries).step_by(2).collect();
            let two: Vec<_> = crossed
                .iter()
                .map(|&j| blocks[j] as usize..blocks[j + 2] as usize)
                .collect();
            let mut lanes: Vec<_> = solving.lanes(&two).into_iter().zip(crossed).collect();
            parallel::for_each(
                &mut lanes,
                || (),
                |(), (lane, j)| {
                    let listed = &across[across_ends[*j] as usize..across_ends[*j + 1] as usize];
                    lane.listed::<PUSH>(listed, rule);
                },
            );
            gather(
                lanes.into_iter().map(|(lane, _)| lane),
                &mut largest,
                &mut woken,
            );
        }
        if !far.is_empty() {
            let every = 0..solving.velocity.len();
            let mut lanes = solving.lanes(std::slice::from_ref(&every));
            lanes[0].listed::<PUSH>(far, rule);
            gather(lanes, &mut largest, &mut woken);
        }
        (largest, woken)
    }
}

/// Adds what `lanes` found to the pass's `largest` change and the bodies it `woke`, in
/// the lanes' order.
fn gather<'a>(lanes: impl IntoIterator<Item = Lane<'a>>, largest: &mut f32, woke: &mut Vec<u32>) {
    for lane in lanes {
        *largest = largest.max(lane.largest);
        woke.extend(lane.wake.woken);
    }
}

/// The buffers a pass solves, to cut into lanes.
struct Solving<'a> {
    rows: &'a [u32],
    pairs: &'a mut [Pair],
    impulses: &'a mut [f32],
    velocity: &'a mut [Vector2D<f32>],
    sleeping: &'a mut [bool],
    inverse_mass: &'a mut [f32],
    wake_inverse_mass: &'a [f32],
}

impl Solving<'_> {
    /// A lane for each of `bodies` (ascending, disjoint ranges of the grid's order),
    /// with the pairs whose first body is among them.
    fn lanes(&mut self, bodies: &[Range<usize>]) -> Vec<Lane<'_>> {
        let rows = self.rows;
        let pair_ranges = bodies
            .iter()
            .map(|r| rows[r.start] as usize..rows[r.end] as usize);
        let wake_inverse_mass = self.wake_inverse_mass;
        parallel::split_ranges(self.pairs, pair_ranges.clone())
            .into_iter()
            .zip(parallel::split_ranges(self.impulses, pair_ranges))
            .zip(parallel::split_ranges(
                self.velocity,
                bodies.iter().cloned(),
            ))
            .zip(parallel::split_ranges(
                self.sleeping,
                bodies.iter().cloned(),
            ))
            .zip(parallel::split_ranges(
                self.inverse_mass,
                bodies.iter().cloned(),
            ))
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
            .collect()
    }
}

#[cfg(test)]
mod tests;
