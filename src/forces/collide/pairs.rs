//! The bodies and pairs of one substep's disk separation: bodies gathered in the grid's
//! order (`grid.rs`), the pairs that may touch found among them, and each pair started
//! from the impulse it ended the last substep with (warm starting). The passes that
//! solve the pairs are in `mod.rs`.
//!
//! Working in the grid's order rather than by world slot keeps a pair's two bodies close
//! in memory (the same or a neighbouring cell): at 100,000 bodies the per-body arrays no
//! longer fit a core's cache, and the passes run over every pair many times a substep.

use euclid::default::{Point2D, Vector2D};

use super::shapes::box_contact;
use super::{coincident_normal, Collide, SLEEPING_OVERLAP};

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
/// cannot overlap much hold (a jammed 100,000-node graph holds 4.5 a body, a hot
/// scatter's first contacts 16), and a bound on the memory and time a crowd denser than
/// disks can be (everything at one point) would otherwise take: without it, contacts
/// from the first frame of a 100,000-node graph took over 24 GB.
const PAIRS_PER_BODY: usize = 32;
const PAIRS_AT_LEAST: usize = 4_096;

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
}

impl BySlot {
    pub(super) fn clear(&mut self) {
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
        let by_slot = &self.by_slot;
        self.points.clear();
        self.radius.clear();
        self.inner.clear();
        self.round.clear();
        self.half.clear();
        self.inverse_mass.clear();
        self.velocity.clear();
        self.motion.clear();
        self.sleeping.clear();
        for (l, &s) in self.order.iter().enumerate() {
            let s = s as usize;
            self.local[s] = l as u32;
            self.points.push(points[s]);
            self.radius.push(by_slot.radius[s]);
            self.half.push(by_slot.half[s]);
            self.inner
                .push(by_slot.inner.get(s).copied().unwrap_or_default());
            self.round
                .push(by_slot.round.get(s).copied().unwrap_or(by_slot.radius[s]));
            self.inverse_mass.push(by_slot.inverse_mass[s]);
            self.velocity
                .push(by_slot.velocity.get(s).copied().unwrap_or_default());
            self.motion.push(by_slot.motion[s]);
            self.sleeping
                .push(by_slot.sleeping.get(s).copied().unwrap_or(false));
        }
        self.before.clear();
        self.before.extend_from_slice(&self.velocity);
        self.boxes = self.inner.iter().any(|&i| i != Vector2D::zero());
    }

    /// The pairs that may touch, or come within `margin` of touching, each once,
    /// ordered by their local indices, and where each body's pairs start (`rows`).
    pub(super) fn find_pairs(&mut self, margin: f32) {
        let Self {
            grid,
            pairs,
            points,
            radius,
            half,
            inner,
            round,
            boxes,
            inverse_mass,
            motion,
            order,
            extra,
            ..
        } = self;
        let boxes = *boxes;
        pairs.clear();
        extra.clear();
        let slack = grid.usual_motion();
        let budget = PAIRS_PER_BODY * points.len() + PAIRS_AT_LEAST;
        grid.pairs(points, half, motion, |a, b, beyond| {
            if pairs.len() + extra.len() >= budget {
                // A crowd far denser than disks can be (thousands of nodes added at one
                // point, contacts from a hot scatter's first frame): the pairs found so
                // far are solved, the rest wait for a later substep.
                return false;
            }
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
                    return true;
                }
            }
            let reach = radius[ia] + radius[ib];
            let moved = relative.length();
            let near = reach + moved + margin;
            let distance_sq = d.square_length();
            if distance_sq > near * near {
                return true;
            }
            // Two bodies moving fast relative to each other are a pair only if their
            // paths come close: the disc above grows with the square of the motion, and
            // in a hot, dense crowd it held millions of pairs that pass far apart (a
            // 100,000-node graph with contacts from the first frame ran out of memory).
            // Up to the usual motion the disc stands, as slack for what the solve
            // changes of the velocities.
            if moved > slack && !comes_within(d, relative, reach + margin + slack) {
                return true;
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
                box_contact(inner, round, (ia, ib), d, coincident)
            } else {
                None
            };
            if outline.is_some_and(|(_, separation)| separation > moved + margin) {
                // Bounding disks close, outlines further apart than they move.
                return true;
            }
            let parted = match outline {
                Some((_, separation)) => separation >= -SLEEPING_OVERLAP,
                None => distance >= reach - SLEEPING_OVERLAP,
            };
            let still = motion[ia] == Vector2D::zero() && motion[ib] == Vector2D::zero();
            if inverse_mass[ia] == 0.0 && inverse_mass[ib] == 0.0 && still && parted {
                // Neither gives way nor moves, and they do not overlap: nothing to part.
                // (Two that fell asleep overlapping are woken and parted.)
                return true;
            }
            let (normal, separation) = outline.unwrap_or_else(|| {
                let normal = if distance > 1e-6 {
                    d / distance
                } else {
                    coincident()
                };
                (normal, distance - reach)
            });
            let pair = Pair {
                a,
                b,
                normal,
                separation,
                share_a: 0.0,
                share_b: 0.0,
            };
            if beyond {
                extra.push(pair);
            } else {
                pairs.push(pair);
            }
            true
        });
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

    /// Starts each pair from the impulse it ended the last substep with, found by its
    /// two slots.
    pub(super) fn warm_start(&mut self, version: u64) {
        if self.last_version != Some(version) {
            return;
        }
        let last = std::mem::take(&mut self.last);
        for &(sa, sb, impulse) in &last {
            let (Some(&a), Some(&b)) = (self.local.get(sa as usize), self.local.get(sb as usize))
            else {
                continue;
            };
            if a == NONE || b == NONE {
                continue;
            }
            let (a, b) = (a.min(b), a.max(b));
            let row = self.rows[a as usize] as usize..self.rows[a as usize + 1] as usize;
            if let Some(k) = row.into_iter().find(|&k| self.pairs[k].b == b) {
                self.push(k, impulse);
            }
        }
        self.last = last;
    }

    /// Keeps the impulses of the pairs that pushed, by their slots, for the next substep.
    pub(super) fn keep_impulses(&mut self, version: u64) {
        self.last.clear();
        let order = &self.order;
        self.last.extend(
            self.pairs
                .iter()
                .zip(&self.impulses)
                .filter(|(_, &impulse)| impulse > 0.0)
                .map(|(p, &impulse)| (order[p.a as usize], order[p.b as usize], impulse)),
        );
        self.last_version = Some(version);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fixed sequence in `[0, 1)`.
    fn sequence(seed: u64) -> impl FnMut() -> f32 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 40) as f32 / (1_u64 << 24) as f32
        }
    }

    /// Every two bodies that touch as they move over the substep are found once, in
    /// order, whether they move within a cell or further: the grid's cells allow the
    /// motion of nine bodies in ten, the rest search the strip along their path, and two
    /// fast bodies crossing paths find each other by their swept boxes. Pairs moving
    /// fast relative to each other are kept only where their paths come close.
    #[test]
    fn finds_every_pair_that_may_touch_once_and_in_order() {
        for seed in 1..=6 {
            let mut next = sequence(seed);
            let n = 600;
            let mut collide = Collide::default();
            let mut points = Vec::new();
            for s in 0..n {
                // A dense cluster, with one body in eight moving far (up to 12 radii)
                // and one in fifty across it and beyond, diagonally (a path far longer
                // than the cells, searched row by row along its strip).
                points.push(Point2D::new(next() * 400.0, next() * 300.0));
                let reach = if s % 50 == 0 {
                    3_000.0
                } else if s % 8 == 0 {
                    200.0
                } else {
                    6.0
                };
                collide.by_slot.radius.push(4.0 + next() * 12.0);
                collide.by_slot.inverse_mass.push(1.0);
                collide.by_slot.velocity.push(Vector2D::zero());
                collide.by_slot.motion.push(Vector2D::new(
                    (next() - 0.5) * reach,
                    (next() - 0.5) * reach,
                ));
                collide.by_slot.sleeping.push(false);
            }
            // Two fast bodies that cross paths, far from where either starts.
            for k in 0..10 {
                let meet = Point2D::new(500.0 + 60.0 * k as f32, 100.0 * seed as f32);
                for (from, motion) in [
                    (Vector2D::new(-300.0, 0.0), Vector2D::new(600.0, 0.0)),
                    (Vector2D::new(0.0, -300.0), Vector2D::new(0.0, 600.0)),
                ] {
                    points.push(meet + from);
                    collide.by_slot.radius.push(8.0);
                    collide.by_slot.inverse_mass.push(1.0);
                    collide.by_slot.velocity.push(Vector2D::zero());
                    collide.by_slot.motion.push(motion);
                    collide.by_slot.sleeping.push(false);
                }
            }
            let n = points.len();
            collide.take_in_grid_order(&points);
            collide.find_pairs(0.0);
            let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
            assert!(
                found.windows(2).all(|w| w[0] < w[1]),
                "seed {seed}: pairs out of order or twice"
            );
            let (p, r, m) = (&collide.points, &collide.radius, &collide.motion);
            // The closest two bodies come as they move over the substep.
            let closest = |a: usize, b: usize| {
                let (d, v) = (p[b] - p[a], m[b] - m[a]);
                let t = if v.square_length() > 0.0 {
                    (-d.dot(v) / v.square_length()).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                (d + v * t).length()
            };
            let mut expected = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    if closest(a, b) <= r[a] + r[b] {
                        expected.push((a as u32, b as u32));
                    }
                }
            }
            // Exactly the pairs the rule keeps: within their relative motion of touching
            // at the start, and, when that motion is above the usual one (the slack),
            // coming within the slack of touching on their paths. Fast bodies' paths and
            // swept boxes must find every such pair the neighbouring cells do not hold.
            let slack = collide.grid.usual_motion();
            let mut kept = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    let (reach, moved) = (r[a] + r[b], (m[b] - m[a]).length());
                    if (p[b] - p[a]).length() <= reach + moved
                        && (moved <= slack || closest(a, b) <= reach + slack)
                    {
                        kept.push((a as u32, b as u32));
                    }
                }
            }
            let unfound: Vec<_> = kept
                .iter()
                .filter(|e| found.binary_search(e).is_err())
                .collect();
            assert!(
                found.len() == kept.len() && unfound.is_empty(),
                "seed {seed}: found {} pairs, the rule keeps {}; first not found {:?}",
                found.len(),
                kept.len(),
                unfound.first()
            );
            let missing: Vec<_> = expected
                .iter()
                .filter(|e| found.binary_search(e).is_err())
                .collect();
            assert!(
                missing.is_empty() && !expected.is_empty(),
                "seed {seed}: {} of {} pairs missed, first {:?}",
                missing.len(),
                expected.len(),
                missing.first()
            );
        }
    }

    /// Label boxes of many widths and heights, still: every two whose outlines touch or
    /// overlap are found (the grid's cells are as wide as the widest box and as high as
    /// the highest, and the test of a pair drops only bounding boxes apart on an axis).
    #[test]
    fn finds_every_pair_of_boxes_that_touch() {
        for seed in 1..=4 {
            let mut next = sequence(seed);
            let mut collide = Collide::default();
            let mut points = Vec::new();
            for _ in 0..500 {
                points.push(Point2D::new(next() * 600.0, next() * 300.0));
                let half = Vector2D::new(5.0 + next() * 35.0, 3.0 + next() * 9.0);
                collide.by_slot.radius.push(half.length());
                collide.by_slot.half.push(half);
                collide.by_slot.inner.push(half);
                collide.by_slot.round.push(0.0);
                collide.by_slot.inverse_mass.push(1.0);
                collide.by_slot.velocity.push(Vector2D::zero());
                collide.by_slot.motion.push(Vector2D::zero());
                collide.by_slot.sleeping.push(false);
            }
            collide.take_in_grid_order(&points);
            collide.find_pairs(0.0);
            let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
            let (p, inner) = (&collide.points, &collide.inner);
            let mut missing = Vec::new();
            let mut touching = 0;
            for a in 0..p.len() {
                for b in a + 1..p.len() {
                    let d = p[b] - p[a];
                    let (_, separation) =
                        super::super::shapes::contact(d, inner[a] + inner[b], 0.0, Vector2D::zero);
                    if separation <= 0.0 {
                        touching += 1;
                        if found.binary_search(&(a as u32, b as u32)).is_err() {
                            missing.push((a, b, separation));
                        }
                    }
                }
            }
            assert!(
                missing.is_empty() && touching > 0,
                "seed {seed}: {} of {touching} touching boxes missed, first {:?}",
                missing.len(),
                missing.first()
            );
        }
    }

    /// A crowd far denser than disks can be (every body within a unit of one point, as
    /// when thousands of nodes are added at one point): every two bodies touch, and the
    /// search keeps to its budget, the pairs found first, in order and each once,
    /// instead of the half-million pairs of all two of them.
    #[test]
    fn a_crowd_denser_than_disks_keeps_to_the_budget() {
        let mut next = sequence(7);
        let n = 1_000;
        let mut collide = Collide::default();
        let points: Vec<_> = (0..n)
            .map(|_| Point2D::new(next() - 0.5, next() - 0.5))
            .collect();
        for _ in 0..n {
            collide.by_slot.radius.push(16.0);
            collide.by_slot.inverse_mass.push(1.0);
            collide.by_slot.velocity.push(Vector2D::zero());
            collide.by_slot.motion.push(Vector2D::zero());
            collide.by_slot.sleeping.push(false);
        }
        collide.take_in_grid_order(&points);
        collide.find_pairs(0.0);
        let budget = PAIRS_PER_BODY * n + PAIRS_AT_LEAST;
        let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
        assert_eq!(
            found.len(),
            budget,
            "{} pairs kept of the {} that touch",
            found.len(),
            n * (n - 1) / 2
        );
        assert!(
            found.windows(2).all(|w| w[0] < w[1]),
            "pairs out of order or twice"
        );
        assert_eq!(
            collide.rows[n] as usize, budget,
            "rows count every pair kept"
        );
    }
}
