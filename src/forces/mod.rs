//! Forces the layout puts on bodies every substep, beside what rapier solves itself
//! (joints, contacts, gravity): one force a file, each a [`BodyForce`], run in the order
//! of [`Forces::default`], the way d3-force's simulation runs its forces.
//!
//! - `many_body.rs`: many-body repulsion through the Barnes–Hut tree in `barnes_hut/`;
//! - `springs.rs`: the edge springs applied as forces, and d3-force's uneven share of a
//!   spring's pull between its ends (link bias);
//! - `center.rs`: the pull toward the centre;
//! - `position.rs`, `radial.rs`, `group.rs`: the host's per-node pulls toward an x, a y
//!   or a ring, and groups held together, read from the table in `targets.rs`;
//! - `collide.rs`: the layout's own disk separation (not a force: the velocity changes
//!   that part disks, worked out after the forces).
//!
//! Every body pushes (pinned and dragged ones too); only awake dynamic bodies are pushed.
//! [`Forces::apply`] sums the forces of one substep into buffers indexed by world slot
//! and sets each pushed body's force to its sum. A force may also report a stiffness per
//! body (springs do): the sum on a body of mass `m` is then divided by
//! `1 + (dt² k + dt c) / m`, an implicit Euler step on the body's own stiffness `k` and
//! damping `c` (the diagonal of the springs' Jacobian), so springs stiffer than the step
//! resolves stay stable and the body still comes to rest where its forces balance. The
//! host's pulls act along one direction each and report their stiffness as a matrix
//! (`targets.rs`), so the step slows a body only along the pull. A new force is one file
//! here and one line in [`Forces::default`].

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;
use serde::{Deserialize, Serialize};

use crate::config::cooling::Cooling;
use crate::config::{ContactSoftness, RapierLayoutConfig};
use crate::profile::{StepProfile, Stopwatch};
use crate::world::RapierSceneWorld;

pub(crate) mod barnes_hut;
mod bodies;
mod center;
mod group;
pub(crate) mod many_body;
mod position;
mod radial;
mod springs;
pub(crate) mod targets;

pub(crate) use bodies::Bodies;
use targets::NodeTargets;

/// What a force reads on one substep.
pub(crate) struct ForceContext<'a, N> {
    /// The world, for what a force caches about its bodies and joints.
    pub(crate) world: &'a RapierSceneWorld<N>,
    /// The layout's configuration; each force reads its own part.
    pub(crate) config: &'a RapierLayoutConfig,
    /// Every body's position, by world slot.
    pub(crate) points: &'a [Point2D<f32>],
    /// Every body's velocity, by world slot.
    pub(crate) velocities: &'a [Vector2D<f32>],
    /// Whether each body (by world slot) is pushed: dynamic and awake.
    pub(crate) pushed: &'a [bool],
    /// The layout's heat under its cooling schedule (1 without one).
    pub(crate) heat: f32,
    /// The substep's length, in seconds.
    pub(crate) dt: f32,
    /// The host's per-node forces, by world slot.
    pub(crate) targets: &'a NodeTargets,
}

/// How the forces on a node scale with its own heat after a local disturbance
/// ([`Cooling::reheat_hops`](crate::config::Cooling::reheat_hops)): as they did when the whole
/// layout was that hot, so a heated neighbourhood replays the schedule that laid it out.
#[derive(Clone, Copy, Debug)]
pub(crate) struct HeatLaw {
    /// The layout's heat (1 without a schedule).
    pub(crate) alpha: f32,
    pub(crate) cooling: Option<Cooling>,
    /// The springs' blend from `heat^spring_exponent` toward the heat
    /// ([`Cooling::stretch_limit`](crate::config::Cooling::stretch_limit)).
    pub(crate) blend: f32,
}

impl HeatLaw {
    /// The factors on a node's springs and on its other forces for its own heat `own`:
    /// what its heat gives them over what the layout's gives. `None` for a node no
    /// hotter than the layout.
    fn boosts(&self, own: f32) -> Option<(f32, f32)> {
        let cooling = self.cooling.filter(|_| own > self.alpha)?;
        let springs = |heat: f32| {
            let near = cooling.spring_scale(heat);
            if self.blend > 0.0 {
                near.powf(1.0 - self.blend) * heat.powf(self.blend)
            } else {
                near
            }
        };
        let boost = springs(own) / springs(self.alpha);
        let boost = if boost.is_finite() { boost } else { 1.0 };
        Some((boost, own / self.alpha))
    }
}

/// What the forces of one substep add up to, by world slot.
#[derive(Debug, Default)]
pub(crate) struct ForceSums {
    /// The force on each body, springs aside.
    pub(crate) forces: Vec<Vector2D<f32>>,
    /// The springs' force on each body.
    pub(crate) springs: Vec<Vector2D<f32>>,
    /// `dt² k + dt c` of each body's springs applied as forces: what the implicit step
    /// divides by (with the mass).
    pub(crate) resistance: Vec<f32>,
    /// The same of the host's pulls, which act along one direction `u` each: the sum of
    /// `(dt² k + dt c) u uᵀ` as `[xx, xy, yy]`, so that a pull along x leaves motion
    /// along y as free as without it.
    pub(crate) pulls: Vec<[f32; 3]>,
}

/// `m (M)⁻¹ f` with `M = (m + resistance) I + [[xx, xy], [xy, yy]]`: the implicit step
/// on a body's isotropic springs and its directed pulls at once.
fn implicit_with_pulls(
    f: Vector2D<f32>,
    m: f32,
    resistance: f32,
    [xx, xy, yy]: [f32; 3],
) -> Vector2D<f32> {
    let (a, c) = (m + resistance + xx, m + resistance + yy);
    let det = a * c - xy * xy;
    Vector2D::new(c * f.x - xy * f.y, a * f.y - xy * f.x) * (m / det)
}

/// Bodies a run of [`Forces::apply`]'s sums takes (fixed: each body's sum is its own).
const COMBINE_RUN: usize = 1_024;

/// One force on bodies, applied every substep.
pub(crate) trait BodyForce<N>: Send + Sync {
    /// Whether `config` or the host's per-node `targets` ask for this force at all.
    fn is_active(&self, config: &RapierLayoutConfig, targets: &NodeTargets) -> bool;

    /// Adds this substep's force on every pushed body to `out` (by world slot; as long
    /// as the world has bodies).
    fn apply(&mut self, frame: &ForceContext<'_, N>, out: &mut ForceSums);

    /// Forgets what was cached about a world that is gone.
    fn reset(&mut self) {}
}

/// The forces of a layout, with the buffers one substep sums them in.
pub(crate) struct Forces<N> {
    /// The repulsion, which writes every body's force first, and the springs, which
    /// write sums of their own: the two run side by side under `parallel`, the stress
    /// terms beside the springs too.
    many_body: many_body::ManyBodyForce,
    springs: springs::SpringForce,
    /// The forces that add to the repulsion's, in order.
    list: Vec<Box<dyn BodyForce<N>>>,
    bodies: Bodies,
    sums: ForceSums,
    collide: crate::contacts::Collide,
    /// The stress model's terms ([`RapierLayoutConfig::stress`]), kept apart from the
    /// list: the start hands it the model it built.
    pub(crate) stress: crate::stress::StressForce,
    /// The host's per-node forces for this call (`adapter/node_forces.rs` fills it).
    pub(crate) targets: NodeTargets,
    /// Whether the last substep set forces on bodies: rapier keeps a body's force until
    /// it is reset, so when no force is active any more they are cleared once.
    applied: bool,
    /// A stress layout's springs at its last cold stop (`stress/rest_bias.rs`).
    rest_bias: crate::stress::RestBias,
    /// Where the calls' time went, while the host measures it.
    pub(crate) profile: Option<StepProfile>,
}

impl<N: Clone + Eq + Hash> Default for Forces<N> {
    fn default() -> Self {
        // NOTE: order matters for the float sums (and bit-exact replays): many-body
        // (apart from the list) writes every entry first, these add to it in order.
        let list: Vec<Box<dyn BodyForce<N>>> = vec![
            Box::new(center::CenterPull),
            Box::new(position::PositionPull),
            Box::new(radial::RadialPull),
            Box::new(group::GroupPull::default()),
        ];
        Self {
            many_body: many_body::ManyBodyForce::default(),
            springs: springs::SpringForce::default(),
            list,
            bodies: Bodies::default(),
            sums: ForceSums::default(),
            collide: crate::contacts::Collide::default(),
            stress: crate::stress::StressForce::default(),
            targets: NodeTargets::default(),
            applied: false,
            rest_bias: crate::stress::RestBias::default(),
            profile: None,
        }
    }
}

impl<N> std::fmt::Debug for Forces<N> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Forces")
            .field("forces", &(self.list.len() + 2))
            .finish_non_exhaustive()
    }
}

/// What the forces carry from one call to the next, as a snapshot keeps it: the host's
/// per-node forces as the last call read them, whether forces are on the bodies, the
/// disk separation's warm-start impulses and the stress model with its held pivot sums.
/// Everything else they keep is a cache built again from the world.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct SavedForces {
    targets: NodeTargets,
    applied: bool,
    contacts: Vec<(u32, u32, f32)>,
    contacts_version: Option<u64>,
    /// The stress model and its pivot terms' held sums (empty without one).
    #[serde(default)]
    stress: crate::stress::StressForce,
    /// The springs' pull at the last cold stop (empty without one).
    #[serde(default)]
    rest_bias: crate::stress::RestBias,
}

impl<N: Clone + Eq + Hash> Forces<N> {
    /// What the next call needs of these forces to continue bit for bit.
    pub(crate) fn save(&self) -> SavedForces {
        let (contacts, contacts_version) = self.collide.warm_start_state();
        SavedForces {
            targets: self.targets.clone(),
            applied: self.applied,
            contacts,
            contacts_version,
            stress: self.stress.clone(),
            rest_bias: self.rest_bias.clone(),
        }
    }

    /// Forces that continue where `saved` was taken (their caches empty), once each
    /// part has checked what it reads.
    ///
    /// # Errors
    /// The part that does not agree, for [`SnapshotError::Inconsistent`].
    pub(crate) fn from_saved(mut saved: SavedForces) -> Result<Self, String> {
        saved.targets.restore_index()?;
        saved.stress.check()?;
        saved.rest_bias.check()?;
        let mut forces = Self {
            targets: saved.targets,
            applied: saved.applied,
            stress: saved.stress,
            rest_bias: saved.rest_bias,
            ..Self::default()
        };
        forces
            .collide
            .set_warm_start_state(saved.contacts, saved.contacts_version)?;
        Ok(forces)
    }

    /// Whether `config` asks for any force on bodies, or for the layout's own disk
    /// separation.
    pub(crate) fn any_active(&self, config: &RapierLayoutConfig) -> bool {
        config.contacts.separates_disks()
            || config.stress.is_some()
            || config.repulsion.is_some()
            || BodyForce::<N>::is_active(&self.springs, config, &self.targets)
            || self
                .list
                .iter()
                .any(|force| force.is_active(config, &self.targets))
    }

    /// What the forces keep of every body's position and sleep, if anything
    /// ([`Bodies::kept`]).
    pub(crate) fn kept_bodies(&self) -> Option<(&[Point2D<f32>], &[bool])> {
        self.bodies.kept()
    }

    /// Before the world forgets its changes (`sync_out`): reads the changed bodies into
    /// what the forces keep of every body.
    pub(crate) fn catch_up(&mut self, world: &RapierSceneWorld<N>) {
        self.bodies.catch_up(world);
    }

    /// Clears the forces the last substeps left on bodies, once, after the last active
    /// force went away (a host's last pull removed, a configuration without forces):
    /// without it a body would keep being pushed by a force nobody applies.
    pub(crate) fn release(&mut self, world: &mut RapierSceneWorld<N>) {
        if !std::mem::take(&mut self.applied) {
            return;
        }
        for s in 0..world.slot_count() {
            // NOTE: read first: a mutable access marks the body as modified for rapier.
            if world.body_at(s).user_force() != Vector::ZERO {
                world.body_at_mut(s).reset_forces(false);
            }
        }
    }

    /// Forgets every force's cache (the world was dropped or built anew).
    pub(crate) fn reset(&mut self) {
        self.targets = NodeTargets::default();
        self.bodies.forget();
        self.collide.forget_shapes();
        self.applied = false;
        BodyForce::<N>::reset(&mut self.springs);
        for force in &mut self.list {
            force.reset();
        }
        BodyForce::<N>::reset(&mut self.stress);
        // A new world counts its versions from 0 again.
        self.rest_bias = crate::stress::RestBias::default();
    }

    /// Sets every awake dynamic body's force to the sum of the active forces at `heat`
    /// for a substep of `dt` seconds, then (with the layout's own disk separation) the
    /// velocity changes that keep disks apart. Skipped while nothing is awake, so a
    /// resting layout stays cheap. Call [`settle`](Self::settle) after the step.
    pub(crate) fn apply(
        &mut self,
        world: &mut RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        law: HeatLaw,
        contacts: ContactSoftness,
        dt: f32,
    ) {
        if !world.may_move() {
            return;
        }
        self.applied = true;
        let heat = law.alpha;
        let n = world.slot_count();
        let watch = Stopwatch::start(&self.profile);
        self.bodies.gather(world);
        let hold_cold = self.rest_bias.holds(world, n);
        self.sum_forces(world, config, heat, dt, hold_cold);
        watch.stop(&mut self.profile, |p| &mut p.forces);
        self.rest_bias.take_from(
            world,
            &self.bodies.pushed,
            &mut self.sums.springs,
            &mut self.sums.forces,
        );
        let separate = config.contacts.separates_disks() && world.contacts_enabled();
        self.combine(world, law, separate.then_some(dt));
        if separate {
            let watch = Stopwatch::start(&self.profile);
            self.collide.resolve(world, &self.bodies, contacts, dt);
            watch.stop(&mut self.profile, |p| &mut p.contacts);
        }
        self.put_on_bodies(world, separate);
    }

    /// Sums each pushed body's forces and springs at its own heat ([`HeatLaw`]) and
    /// takes the implicit step on its stiffness, in runs of [`COMBINE_RUN`] bodies side
    /// by side under `parallel` (each body's own arithmetic). A body whose sum is not
    /// finite is no longer pushed: it keeps the force it had, and what is kept of it no
    /// longer matches rapier, so it is read again at the next gather. With `velocity_dt`,
    /// also adds to each pushed body's velocity what its force gives it over that time
    /// (what the disk separation starts from).
    fn combine(&mut self, world: &mut RapierSceneWorld<N>, law: HeatLaw, velocity_dt: Option<f32>) {
        let n = self.sums.forces.len();
        let view = world.slots_view();
        let ForceSums {
            forces,
            springs,
            resistance,
            pulls,
        } = &mut self.sums;
        let (springs, resistance, pulls) = (&springs[..], &resistance[..], &pulls[..]);
        let runs = || crate::parallel::runs(n, COMBINE_RUN);
        let mut jobs: Vec<_> = crate::parallel::split_ranges(forces, runs())
            .into_iter()
            .zip(crate::parallel::split_ranges(
                &mut self.bodies.pushed,
                runs(),
            ))
            .zip(crate::parallel::split_ranges(
                &mut self.bodies.velocities,
                runs(),
            ))
            .map(|((forces, (_, pushed)), (_, velocities))| {
                (forces, pushed, velocities, Vec::new())
            })
            .collect();
        crate::parallel::for_each(
            &mut jobs,
            || (),
            |(), ((range, forces), pushed, velocities, lost)| {
                let bodies = range.clone().zip(forces.iter_mut()).zip(pushed.iter_mut());
                for (((s, f), pushed), v) in bodies.zip(velocities.iter_mut()) {
                    if !*pushed {
                        continue;
                    }
                    let mut resistance = resistance[s];
                    let mut pulls = pulls[s];
                    match law.boosts(view.host_at(s).heat) {
                        None => *f += springs[s],
                        Some((springs_boost, others)) => {
                            // Heated by a local disturbance.
                            *f = *f * others + springs[s] * springs_boost;
                            resistance *= springs_boost;
                            pulls = pulls.map(|r| r * springs_boost);
                        }
                    }
                    let mass = view.mass_at(s);
                    if pulls.iter().any(|r| *r != 0.0) {
                        *f = implicit_with_pulls(*f, mass, resistance, pulls);
                    } else if resistance > 0.0 {
                        *f *= mass / (mass + resistance);
                    }
                    if !f.is_finite() {
                        *pushed = false;
                        lost.push(s);
                    } else if let Some(dt) = velocity_dt {
                        // The velocity this substep's force gives.
                        *v += *f * (dt / mass);
                    }
                }
            },
        );
        for s in jobs.into_iter().flat_map(|(.., lost)| lost) {
            world.mark_changed(s);
        }
    }

    /// Sets each pushed body's force to its sum and adds the disk separation's velocity
    /// change (when `separate`) to each dynamic body it changed.
    fn put_on_bodies(&mut self, world: &mut RapierSceneWorld<N>, separate: bool) {
        let n = world.slot_count();
        let changes = if separate {
            self.collide.changes(n)
        } else {
            &[]
        };
        for s in 0..n {
            let change = changes.get(s).copied().unwrap_or_default();
            if !self.bodies.pushed[s] && change == Vector2D::zero() {
                continue;
            }
            let body = world.body_at_mut(s);
            if self.bodies.pushed[s] {
                let f = self.sums.forces[s];
                body.reset_forces(false);
                body.add_force(Vector::new(f.x, f.y), false);
            }
            if change != Vector2D::zero() && body.is_dynamic() {
                let v = body.linvel() + Vector::new(change.x, change.y);
                if v.is_finite() {
                    // Without waking: the bodies that gave way are awake already.
                    body.set_linvel(v, false);
                }
            }
        }
    }

    /// At a stress layout's cold stop: what every dynamic body's springs (edges and
    /// stress terms) pull with where it rests, kept so that from here on the rest is
    /// their balance (`stress/rest_bias.rs`). Forgets it for other layouts.
    pub(crate) fn capture_rest(
        &mut self,
        world: &RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        heat: f32,
        dt: f32,
    ) {
        self.rest_bias = crate::stress::RestBias::default();
        if config.stress.is_none() || config.cooling.is_none() {
            // Without a schedule no node is ever heated, so the held pivot terms would
            // never be worked out again.
            return;
        }
        self.bodies.gather(world);
        // Every dynamic body counts as pushed here; what is kept of rapier's state is
        // put back after.
        let mut dynamic: Vec<bool> = (0..world.slot_count())
            .map(|s| world.body_at(s).is_dynamic())
            .collect();
        std::mem::swap(&mut self.bodies.pushed, &mut dynamic);
        // Every pivot term worked out afresh at the rest positions.
        self.stress.renew_pivot_terms();
        self.sum_forces(world, config, heat, dt, false);
        self.rest_bias = crate::stress::RestBias::capture(
            world,
            &self.bodies.pushed,
            &self.sums.springs,
            &self.sums.forces,
        );
        std::mem::swap(&mut self.bodies.pushed, &mut dynamic);
    }

    /// Clears the sums and adds every active force's pull on the bodies `self.bodies`
    /// (gathered) marks as pushed, the stress terms last, holding the pivot terms of
    /// nodes not heated when `hold_cold`.
    fn sum_forces(
        &mut self,
        world: &RapierSceneWorld<N>,
        config: &RapierLayoutConfig,
        heat: f32,
        dt: f32,
        hold_cold: bool,
    ) {
        let n = world.slot_count();
        for sums in [&mut self.sums.forces, &mut self.sums.springs] {
            sums.clear();
            sums.resize(n, Vector2D::zero());
        }
        self.sums.resistance.clear();
        self.sums.resistance.resize(n, 0.0);
        self.sums.pulls.clear();
        self.sums.pulls.resize(n, [0.0; 3]);
        let frame = ForceContext {
            world,
            config,
            points: &self.bodies.points,
            velocities: &self.bodies.velocities,
            pushed: &self.bodies.pushed,
            heat,
            dt,
            targets: &self.targets,
        };
        // The stress terms read the world first; then the repulsion and the stress terms
        // (on another thread, if one is free) beside the springs (on this one: they read
        // the world), each into sums of its own.
        let stress = &mut self.stress;
        let stress_step = if BodyForce::<N>::is_active(stress, config, &self.targets) {
            stress.hold_cold = hold_cold;
            stress.prepare(&frame)
        } else {
            None
        };
        let mut spring_sums = ForceSums {
            springs: std::mem::take(&mut self.sums.springs),
            resistance: std::mem::take(&mut self.sums.resistance),
            ..ForceSums::default()
        };
        let (many_body, forces) = (&mut self.many_body, &mut self.sums.forces);
        let (points, pushed) = (frame.points, frame.pushed);
        let springs = &mut self.springs;
        crate::parallel::beside(
            || {
                if let Some(repulsion) = &config.repulsion {
                    many_body.apply(repulsion, heat, points, pushed, forces);
                }
                if let Some(step) = stress_step {
                    stress.work_out(step, points, pushed);
                }
            },
            || {
                if BodyForce::<N>::is_active(springs, config, &self.targets) {
                    springs.apply(&frame, &mut spring_sums);
                }
            },
        );
        (self.sums.springs, self.sums.resistance) = (spring_sums.springs, spring_sums.resistance);
        for force in &mut self.list {
            if force.is_active(config, &self.targets) {
                force.apply(&frame, &mut self.sums);
            }
        }
        // Last, as the stress terms always were: the sums' bits do not depend on where
        // the terms were worked out.
        if let Some(step) = stress_step {
            self.stress.add_to(step, &mut self.sums);
        }
    }

    /// Forgets the rest's balance: the whole layout is laid out again.
    pub(crate) fn forget_rest(&mut self) {
        self.rest_bias = crate::stress::RestBias::default();
    }

    /// Before the world halts: projects the overlaps the disk separation still holds
    /// apart on positions. Returns the largest distance a body moved (world units).
    pub(crate) fn part_overlaps(&mut self, world: &mut RapierSceneWorld<N>) -> f32 {
        self.collide.part_overlaps(world)
    }

    /// After the step: what the disk separation does once the bodies have moved.
    pub(crate) fn settle(&mut self, world: &mut RapierSceneWorld<N>, dt: f32) {
        let watch = Stopwatch::start(&self.profile);
        self.collide.relax(world, dt);
        watch.stop(&mut self.profile, |p| &mut p.contacts);
    }
}
