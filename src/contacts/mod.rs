//! Disk separation of the layout's own ([`ContactModel::Disks`](crate::config::ContactModel)):
//! d3-force's `forceCollide` as soft contact constraints between disks, solved the way
//! Box2D v3 solves its contacts ("soft step"), without rapier's pair bookkeeping.
//!
//! Around each rapier step of a substep:
//! 1. **before** ([`Collide::resolve`]): the pairs that may touch are found on a uniform
//!    grid (`grid.rs`); each starts from the impulse it ended the last substep with
//!    (warm starting), and a few projected Gauss–Seidel passes give every pair the
//!    normal impulse that keeps it from closing beyond touching and pushes an overlap
//!    apart as a spring of [`ContactSoftness`](crate::config::ContactSoftness)' frequency and
//!    damping ratio would (speed-limited);
//! 2. rapier moves the bodies with the resulting velocities;
//! 3. **after** ([`Collide::relax`]): passes without the push take out the speed the
//!    push left in the velocities, so parted disks stop instead of flying apart, and a
//!    contact pressed by a steady force holds still.
//!
//! The pairs are those within their relative motion of touching, and, for two bodies
//! moving fast relative to each other, only those whose paths come close; a substep
//! keeps at most 32 pairs a body (`pairs.rs`), so a crowd far denser than disks can be
//! costs bounded memory and time.
//!
//! Impulses only push (they stay at or above zero). Kinematic, fixed and sleeping bodies
//! do not give way; a sleeping body that an awake or driven one presses into wakes and
//! gives way from then on.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;

use crate::config::ContactSoftness;
use crate::forces::Bodies;
use crate::world::{RapierSceneWorld, SlotsView};

mod gather;
mod grid;
mod pairs;
mod passes;
mod projection;
mod region;
pub(crate) mod shapes;

use grid::Grid;
use pairs::{BySlot, Pair, NONE};
use shapes::{box_contact, Side};

/// A sleeping body that an awake one would push into faster than this (world units per
/// second: rapier's sleep threshold at the default length unit) wakes.
const WAKE_SPEED: f32 = 5.0;
/// Two bodies asleep with a deeper overlap than this (world units) are woken and parted.
const SLEEPING_OVERLAP: f32 = 0.25;
/// Passes over the pairs before the step, and after it. Fewer passes after the step
/// save time; four leave the pictures as eight did, and two leave overlaps at rest
/// (`docs/performance.md` gives the figures).
const PASSES: usize = 8;
const RELAX_PASSES: usize = 4;
/// Pairs a run of the separations after the step takes (side by side under `parallel`).
const SEPARATION_RUN: usize = 2_048;
/// Bodies a run of the reads after the step takes (fixed: each read is its own).
const READ_RUN: usize = 1_024;
/// How many runs of the pairs a pass works through side by side (more cost more than
/// they save: `docs/performance.md`).
const STREAMS: usize = 4;
/// A pass that changes no pair's relative speed by more than this (world units per
/// second) ends the passes.
const SETTLED_CHANGE: f32 = 0.05;
/// The fastest an overlap is pushed apart, in world units per second (rapier's own
/// limit at the default length unit: 10 lengths per second).
const MAX_PUSH_SPEED: f32 = 1_000.0;

/// The direction two coincident disks in slots `a < b` part along: one that depends
/// only on the two slots.
fn coincident_normal(a: u32, b: u32) -> Vector2D<f32> {
    let angle = a as f32 * 2.399_963 + b as f32 * 0.618_034;
    Vector2D::new(angle.cos(), angle.sin())
}

/// The bodies in pairs, as (world slot, local index), in slot order: `local` by slot,
/// `in_pair` by local index.
fn in_pairs<'a>(
    local: &'a [u32],
    in_pair: &'a [bool],
) -> impl Iterator<Item = (usize, usize)> + 'a {
    local
        .iter()
        .enumerate()
        .filter(move |&(_, &l)| l != NONE && in_pair[l as usize])
        .map(|(s, &l)| (s, l as usize))
}

/// The shares of a change of a pair's relative speed its two bodies take, from their
/// inverse masses `wa` and `wb` (none where neither gives way).
fn shares(wa: f32, wb: f32) -> (f32, f32) {
    let total = wa + wb;
    if total > 0.0 {
        (wa / total, wb / total)
    } else {
        (0.0, 0.0)
    }
}

/// Marks in `read` which of `n` bodies (local indices) are in any of `pairs`.
fn mark_in_pairs(read: &mut Vec<bool>, n: usize, pairs: &[Pair]) {
    read.clear();
    read.resize(n, false);
    for pair in pairs {
        read[pair.a as usize] = true;
        read[pair.b as usize] = true;
    }
}

/// The soft-constraint coefficients of one substep (Box2D v3's `b2Softness`).
#[derive(Clone, Copy, Debug)]
struct Softness {
    bias_rate: f32,
    mass_scale: f32,
    impulse_scale: f32,
}

impl Softness {
    fn new(contacts: ContactSoftness, dt: f32) -> Self {
        let c = contacts.coefficients();
        let omega = 2.0 * std::f32::consts::PI * c.natural_frequency;
        let a1 = 2.0 * c.damping_ratio + dt * omega;
        let a2 = dt * omega * a1;
        let a3 = 1.0 / (1.0 + a2);
        Self {
            bias_rate: omega / a1,
            mass_scale: a2 * a3,
            impulse_scale: a3,
        }
    }
}

/// The buffers of the disk separation, kept from substep to substep.
///
/// The bodies are taken in the grid's order (`pairs.rs`): `order[l]` is the world slot
/// of local body `l` and `local[s]` the local index of slot `s`; the per-body arrays
/// below are by local index.
#[derive(Debug, Default)]
pub(crate) struct Collide {
    grid: Grid,
    by_slot: BySlot,
    order: Vec<u32>,
    local: Vec<u32>,
    /// Sorted by their first body, which starts its pairs at `rows[a]`.
    pairs: Vec<Pair>,
    /// Each pair's normal impulse so far, divided by the mass (a change of relative
    /// speed); apart from the pairs, which the passes only read.
    impulses: Vec<f32>,
    rows: Vec<u32>,
    /// The pairs fast bodies found beyond the neighbouring cells, before they join `pairs`.
    extra: Vec<Pair>,
    /// The buffer the two are merged into.
    merged: Vec<Pair>,
    /// The pairs found run by run (`pairs.rs`).
    runs: Vec<pairs::RunPairs>,
    points: Vec<Point2D<f32>>,
    /// The bounding radius and bounding box's half extents, and the outline as a box
    /// swept by a disk (`shapes.rs`).
    radius: Vec<f32>,
    half: Vec<Vector2D<f32>>,
    inner: Vec<Vector2D<f32>>,
    round: Vec<f32>,
    /// Whether any body is a box (else every pair is measured as two disks).
    boxes: bool,
    /// By slot, the bodies this substep's separation takes (`region.rs`); empty for
    /// every body.
    region: Vec<bool>,
    /// The slots of the bodies that give way or are driven (with a finite position), in
    /// slot order.
    moving: Vec<u32>,
    /// The cells the moving bodies reach, as the region is marked.
    hot: region::HotCells,
    inverse_mass: Vec<f32>,
    /// Each body's velocity during the solve, and what it was before.
    velocity: Vec<Vector2D<f32>>,
    before: Vec<Vector2D<f32>>,
    /// Each body's displacement over the substep as the pairs are found.
    motion: Vec<Vector2D<f32>>,
    /// Which bodies (local indices) are in a pair: marked by `resolve`, and read anew
    /// after the step by `relax`.
    read: Vec<bool>,
    /// By slot, the velocity change of the last [`resolve`](Self::resolve).
    changes: Vec<Vector2D<f32>>,
    /// After the step, by slot: the new position and velocity of each body in a pair.
    fresh: Vec<(Point2D<f32>, Vector2D<f32>)>,
    /// Dynamic bodies asleep (until a pair wakes them).
    sleeping: Vec<bool>,
    /// Last substep's pairs `(slot a, slot b, impulse)`, for warm starting, and the
    /// world version they belong to (slots change with the bodies).
    last: Vec<(u32, u32, f32)>,
    last_version: Option<u64>,
    /// The softness of the last [`resolve`](Self::resolve).
    softness: Option<Softness>,
    /// The pair each of `last` warm-starts, by index (`NONE`: gone).
    warm: Vec<u32>,
    /// By local index, a sleeping body's inverse mass once it wakes (0 for the rest).
    wake_inverse_mass: Vec<f32>,
    /// The blocks the passes solve side by side (`passes.rs`).
    cut: passes::Cut,
}

impl Collide {
    /// Before the step: works out the velocity changes that keep disks apart over a
    /// substep of `dt` seconds and puts them on the bodies. `points` are the bodies'
    /// positions and `velocities` the velocities this substep's forces give them, by
    /// world slot. Returns whether any pair may touch; then call
    /// [`relax`](Self::relax) after the step.
    pub(crate) fn resolve<N: Clone + Eq + Hash>(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        bodies: &Bodies,
        contacts: ContactSoftness,
        dt: f32,
    ) -> bool {
        self.prepare(world, bodies, dt);
        self.mark_region(&bodies.points);
        self.take_in_grid_order(&bodies.points);
        self.find_pairs(0.0);
        if self.pairs.is_empty() {
            self.last.clear();
            self.softness = None;
            return false;
        }
        self.read_wake_masses(world);
        let warm = self.find_warm_starts(world.version());
        // The cut into blocks and the bodies in pairs (for `relax`) beside the warm start.
        let Self {
            cut,
            order,
            rows,
            pairs,
            read,
            warm: found,
            last,
            impulses,
            velocity,
            ..
        } = self;
        crate::parallel::beside(
            || {
                cut.cut_into(passes::blocks_for(pairs.len()), order.len(), rows, pairs);
                mark_in_pairs(read, order.len(), pairs);
            },
            || {
                if warm {
                    pairs::warm_start(found, last, pairs, impulses, velocity);
                }
            },
        );
        let softness = Softness::new(contacts, dt);
        self.softness = Some(softness);
        for _ in 0..PASSES {
            if self.pass(world, Some(softness), 1.0 / dt) < SETTLED_CHANGE {
                break;
            }
        }
        true
    }

    /// What the next substep warm-starts from: the last substep's pushing pairs `(slot
    /// a, slot b, impulse)` and the world version their slots belong to.
    pub(crate) fn warm_start_state(&self) -> (Vec<(u32, u32, f32)>, Option<u64>) {
        (self.last.clone(), self.last_version)
    }

    /// Puts back what [`warm_start_state`](Self::warm_start_state) returned, or
    /// refuses impulses that are not finite (a damaged snapshot's).
    pub(crate) fn set_warm_start_state(
        &mut self,
        last: Vec<(u32, u32, f32)>,
        version: Option<u64>,
    ) -> Result<(), &'static str> {
        if !last.iter().all(|&(_, _, impulse)| impulse.is_finite()) {
            return Err("forces.contacts: an impulse not finite");
        }
        self.last = last;
        self.last_version = version;
        Ok(())
    }

    /// Forgets the outlines read for a world version (a new world counts its versions
    /// from 0 again).
    pub(crate) fn forget_shapes(&mut self) {
        self.by_slot.clear();
    }

    /// The velocity change [`resolve`](Self::resolve) gives each of the first `n`
    /// slots' bodies (zero for the rest), worked out in runs of slots side by side under
    /// `parallel`.
    pub(crate) fn changes(&mut self, n: usize) -> &[Vector2D<f32>] {
        self.changes.clear();
        self.changes.resize(n, Vector2D::zero());
        if self.softness.is_some() {
            let (local, velocity, before) = (&self.local, &self.velocity, &self.before);
            crate::parallel::for_each_run(&mut self.changes, READ_RUN, |range, changes| {
                for (change, s) in changes.iter_mut().zip(range) {
                    let l = local.get(s).map_or(NONE, |&l| l) as usize;
                    if let (Some(&v), Some(&b)) = (velocity.get(l), before.get(l)) {
                        *change = v - b;
                    }
                }
            });
        }
        &self.changes
    }

    /// After the step: passes without the push, from the bodies' new positions and
    /// velocities, then the impulses are kept for the next substep.
    pub(crate) fn relax<N: Clone + Eq + Hash>(&mut self, world: &mut RapierSceneWorld<N>, dt: f32) {
        if self.softness.take().is_none() {
            return;
        }
        let slots = world.slot_count();
        let n = self.order.len();
        // Only the bodies in pairs: their new velocities and positions, read in slot
        // order (rapier's bodies are in that order; on a large graph they outgrow the
        // cache, and the grid's order would miss it on every body).
        if self.read.len() != n {
            // Marked by `resolve` (beside the warm start); a search for pairs since
            // (`part_overlaps`) clears it.
            mark_in_pairs(&mut self.read, n, &self.pairs);
        }
        self.read_bodies_in_pairs(world.slots_view(), slots);
        // The world's bodies do not change between `resolve` and here.
        debug_assert!(self.order.iter().all(|&s| (s as usize) < slots));
        // Every body in a pair was read. In runs of pairs side by side under `parallel`
        // (each pair's own arithmetic: the same on any number of threads).
        let (points, inner, round, radius, boxes) = (
            &self.points,
            &self.inner,
            &self.round,
            &self.radius,
            self.boxes,
        );
        crate::parallel::for_each_run(&mut self.pairs, SEPARATION_RUN, |_, pairs| {
            for pair in pairs.iter_mut() {
                let (a, b) = (pair.a as usize, pair.b as usize);
                let d = points[b] - points[a];
                let outline = if boxes {
                    box_contact(inner, round, (a, b), d, Side::CentreLine, || pair.normal)
                } else {
                    None
                };
                pair.separation = match outline {
                    Some((_, separation)) => separation,
                    None => d.length() - (radius[a] + radius[b]),
                };
            }
        });
        for _ in 0..RELAX_PASSES {
            if self.pass(world, None, 1.0 / dt) < SETTLED_CHANGE {
                break;
            }
        }
        // The velocity changes put on rapier's bodies (on this thread: they touch the
        // world) beside the impulses kept for the next substep.
        let version = world.version();
        let Self {
            local,
            read,
            velocity,
            before,
            order,
            pairs,
            impulses,
            last,
            last_version,
            ..
        } = self;
        crate::parallel::beside(
            || pairs::keep_impulses(order, pairs, impulses, last),
            || {
                for (s, l) in in_pairs(&local[..slots.min(local.len())], read) {
                    let change = velocity[l] - before[l];
                    if change == Vector2D::zero() {
                        continue;
                    }
                    let body = world.body_at_mut(s);
                    if body.is_dynamic() {
                        let v = body.linvel() + Vector::new(change.x, change.y);
                        if v.is_finite() {
                            body.set_linvel(v, false);
                        }
                    }
                }
            },
        );
        *last_version = Some(version);
    }

    /// The new positions and velocities of the bodies in pairs: read by slot in runs
    /// (rapier's bodies are in that order; on a large graph they outgrow the cache, and
    /// the grid's order would miss it on every body), then copied to their local
    /// indices in runs, both side by side under `parallel`.
    fn read_bodies_in_pairs(&mut self, view: SlotsView<'_>, slots: usize) {
        let local = &self.local[..slots.min(self.local.len())];
        let read = &self.read;
        self.fresh.clear();
        self.fresh
            .resize(local.len(), (Point2D::origin(), Vector2D::zero()));
        let runs = |n: usize| crate::parallel::runs(n, READ_RUN);
        crate::parallel::for_each_run(&mut self.fresh, READ_RUN, |range, fresh| {
            for (k, s) in range.enumerate() {
                let l = local[s];
                if l != NONE && read[l as usize] {
                    let body = view.body_at(s);
                    let (t, v) = (body.translation(), body.linvel());
                    fresh[k] = (Point2D::new(t.x, t.y), Vector2D::new(v.x, v.y));
                }
            }
        });
        let (order, fresh) = (&self.order, &self.fresh);
        let n = order.len();
        let mut jobs: Vec<_> = crate::parallel::split_ranges(&mut self.points, runs(n))
            .into_iter()
            .zip(crate::parallel::split_ranges(&mut self.velocity, runs(n)))
            .zip(crate::parallel::split_ranges(&mut self.before, runs(n)))
            .collect();
        crate::parallel::for_each(
            &mut jobs,
            || (),
            |(), (((range, points), (_, velocity)), (_, before))| {
                for (k, l) in range.clone().enumerate() {
                    // Every body in a pair has a slot below `slots` (`relax` checks it in
                    // debug builds); one beyond would be skipped, as it always was.
                    if let (true, Some(&(p, v))) = (read[l], fresh.get(order[l] as usize)) {
                        (points[k], velocity[k], before[k]) = (p, v, v);
                    }
                }
            },
        );
    }

    /// Radii, inverse masses (0 for bodies that do not give way), velocities and
    /// predicted motion, by slot, in runs side by side under `parallel`; then the
    /// bodies that move, in slot order.
    fn prepare<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        bodies: &Bodies,
        dt: f32,
    ) {
        let by_slot = &mut self.by_slot;
        by_slot.clear_motion();
        by_slot.read_shapes(world);
        by_slot.sleeping.extend_from_slice(&bodies.sleeping);
        let n = bodies.points.len();
        by_slot.inverse_mass.resize(n, 0.0);
        by_slot.velocity.resize(n, Vector2D::zero());
        by_slot.motion.resize(n, Vector2D::zero());
        let view = world.slots_view();
        let runs = || crate::parallel::runs(n, READ_RUN);
        let mut jobs: Vec<_> = crate::parallel::split_ranges(&mut by_slot.inverse_mass, runs())
            .into_iter()
            .zip(crate::parallel::split_ranges(&mut by_slot.velocity, runs()))
            .zip(crate::parallel::split_ranges(&mut by_slot.motion, runs()))
            .collect();
        crate::parallel::for_each(
            &mut jobs,
            || (),
            |(), (((range, inverse_mass), (_, velocity)), (_, motion))| {
                for (k, s) in range.clone().enumerate() {
                    let p = bodies.points[s];
                    let (w, v) = if bodies.pushed[s] {
                        (1.0 / view.mass_at(s), bodies.velocities[s])
                    } else {
                        // Driven (kinematic) bodies move to where they are driven; the
                        // rest stay.
                        (0.0, (bodies.next[s] - p) / dt)
                    };
                    let v = if v.is_finite() { v } else { Vector2D::zero() };
                    (inverse_mass[k], velocity[k], motion[k]) = (w, v, v * dt);
                }
            },
        );
        let (inverse_mass, motion) = (&by_slot.inverse_mass, &by_slot.motion);
        crate::parallel::collect_runs(
            n,
            READ_RUN,
            &mut self.moving,
            |s| {
                (inverse_mass[s] > 0.0 || motion[s] != Vector2D::zero())
                    && bodies.points[s].is_finite()
            },
            |s| s as u32,
        );
    }

    /// The inverse mass each sleeping body in the grid's order takes when it wakes.
    fn read_wake_masses<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        self.wake_inverse_mass.clear();
        self.wake_inverse_mass
            .extend(self.order.iter().zip(&self.sleeping).map(|(&s, &asleep)| {
                if asleep {
                    1.0 / world.mass_at(s as usize)
                } else {
                    0.0
                }
            }));
    }

    /// Each pair's shares of a change of its relative speed, from the inverse masses
    /// (after a body woke), in runs of pairs side by side under `parallel`.
    fn share(&mut self) {
        let inverse_mass = &self.inverse_mass;
        crate::parallel::for_each_run(&mut self.pairs, SEPARATION_RUN, |_, pairs| {
            for pair in pairs {
                let (a, b) = (pair.a as usize, pair.b as usize);
                (pair.share_a, pair.share_b) = shares(inverse_mass[a], inverse_mass[b]);
            }
        });
    }
}
