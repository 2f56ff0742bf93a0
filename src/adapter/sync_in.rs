//! Sync in: the host's side of every node onto its body, before the simulation. Body
//! kinds follow pins, drags and unusable input, flipped in place (no rebuild, motion
//! kept); what each kind of node then needs:
//!
//! - **frozen** (unusable values this call): held still where it is;
//! - **free**: a release, unpin or unfreeze hands it back to the physics (a release
//!   throws it, `drag.rs`); a host edit puts it where the host put it, at rest;
//! - **held** (pinned or dragged): driven to the host's position, kinematically over the
//!   call's substeps or, for a static anchor, at once; sleeping bodies in its path are
//!   woken, which rapier does not do.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::{RigidBodyType, Vector};

use super::drag::{release_velocity, track_drag, Drive, Flight, Host};
use super::edits::{mass_of, shape_of};
use super::heat::Disturbances;
use super::matching::{Matching, NodeMatch, NO_SLOT};
use crate::config::{BodyKindPolicy, RapierLayoutConfig};
use crate::input::layout::LayoutExtras;
use crate::input::scene::{CanvasNode, CanvasSceneInput};
use crate::sanitize::finite_or;
use crate::world::bindings::ColliderSpec;
use crate::world::RapierSceneWorld;

/// Host moves of kinematic and fixed bodies per call that each wake the sleeping bodies
/// in their path; beyond them, every sleeping body is woken once (one O(n) pass instead
/// of one per move).
const MAX_SWEEPS: usize = 16;

/// What the host hands the sync in on one call.
pub(super) struct HostInput<'a, N> {
    pub(super) config: &'a RapierLayoutConfig,
    pub(super) scene: &'a CanvasSceneInput<N>,
    pub(super) extras: &'a LayoutExtras<N>,
    /// The call's frame time, for the pointer's speed.
    pub(super) frame_dt: f32,
    /// The scene nodes a caller listed as changed (`known.rs`), or `None` for all.
    pub(super) known: Option<&'a [usize]>,
}

impl<N: Clone + Eq + Hash> Host<N> {
    /// Returns whether the host disturbed the layout (drag, release, host move, pin
    /// change, radius edit), recording what it touched in `spread`. With `known`
    /// (`known.rs`), only the listed scene nodes are synced, and the nodes the last call
    /// moved take the positions they were told. `kept` is what the forces keep of every
    /// body ([`Forces::kept_bodies`](crate::simulate::Forces::kept_bodies)).
    pub(super) fn sync_in(
        &mut self,
        input: &HostInput<'_, N>,
        world: Option<&mut RapierSceneWorld<N>>,
        matching: &Matching<N>,
        spread: &mut Disturbances,
        kept: Option<(&[Point2D<f32>], &[bool])>,
    ) -> bool {
        let HostInput {
            config,
            scene,
            extras,
            frame_dt,
            known,
        } = *input;
        self.drives.clear();
        let Some(world) = world else {
            return false;
        };
        if known.is_some() {
            for &s in matching.moved() {
                // What the fast path below does for a free node the host moved by its
                // delta: its anchor is where the host has it.
                let (sync, anchor) = world.host_and_anchor_mut(s as usize);
                if sync.synced {
                    *anchor = sync.told;
                }
            }
        }
        let mut pass = SyncPass {
            world,
            drives: &mut self.drives,
            config,
            frame_dt,
            sweeps: 0,
            disturbances: spread,
            flights: &mut self.flights,
            kept,
        };
        let check_drags = !extras.dragging.is_empty();
        let matches = matching.matches();
        let mut disturbed = false;
        let mut sync = |node: &CanvasNode<N>, m: NodeMatch| {
            if m.slot != NO_SLOT {
                let dragging = m.valid && check_drags && extras.dragging.contains(&node.id);
                disturbed |= pass.node(node, m, dragging);
            }
        };
        match known {
            None => {
                for (node, &m) in scene.nodes.iter().zip(matches) {
                    sync(node, m);
                }
            }
            Some(listed) => {
                for &i in listed {
                    sync(&scene.nodes[i], matches[i]);
                }
                #[cfg(debug_assertions)]
                super::known::check_unlisted(pass.world, config, scene, extras, matches, listed);
            }
        }
        disturbed
    }

    /// A gravity change is a disturbance, and so is a new configuration: nothing in the
    /// scene changed, yet bodies at rest may now be pushed. Returns whether either
    /// happened.
    pub(super) fn sync_gravity(
        &mut self,
        gravity: Vector2D<f32>,
        reconfigured: bool,
        world: Option<&mut RapierSceneWorld<N>>,
        spread: &mut Disturbances,
    ) -> bool {
        let disturbed = reconfigured || gravity != self.gravity;
        if disturbed {
            spread.touch_everything();
            if let Some(world) = world {
                world.wake_dynamic_bodies();
            }
        }
        self.gravity = gravity;
        disturbed
    }
}

/// One call's sync.
struct SyncPass<'a, N> {
    world: &'a mut RapierSceneWorld<N>,
    drives: &'a mut Vec<Drive>,
    config: &'a RapierLayoutConfig,
    /// The frame's real elapsed time, which drag speeds are measured against.
    frame_dt: f32,
    /// Host moves of kinematic and fixed bodies so far (see [`SyncPass::wake_in_path`]).
    sweeps: usize,
    /// The nodes this call disturbs.
    disturbances: &'a mut Disturbances,
    /// Thrown nodes in flight.
    flights: &'a mut Vec<Flight<N>>,
    /// What the forces keep of every body's position and sleep (`forces/bodies.rs`).
    kept: Option<(&'a [Point2D<f32>], &'a [bool])>,
}

impl<N: Clone + Eq + Hash> SyncPass<'_, N> {
    /// Syncs one matched node; returns whether it disturbed the layout.
    // NOTE: inlined into the loop over every node, where a call per node would cost a
    // resting layout a noticeable share of its step (`docs/performance.md` gives it).
    #[inline(always)]
    fn node(&mut self, node: &CanvasNode<N>, m: NodeMatch, dragging: bool) -> bool {
        let s = m.slot as usize;
        let policy = self.config.body_kind_policy;
        let mut disturbed = false;
        if m.valid {
            disturbed |= sync_shape(self.world, s, self.config, node);
        }
        let host = node.position;
        let (sync, anchor) = self.world.host_and_anchor_mut(s);
        // What `desired_type` makes dynamic, checked first for the common case.
        let dynamic = m.valid && !m.pinned && !dragging && policy != BodyKindPolicy::AllKinematic;
        if dynamic && sync.synced && sync.told == host {
            // A free body the host left where it was told: nothing to sync, and no need
            // to touch the body at all (the common case at rest).
            *anchor = host;
            if disturbed {
                self.disturbances.touch(s, true);
            }
            return disturbed;
        }
        let was_dragging = sync.dragging;
        let desired = desired_type(policy, m.valid, m.pinned, dragging);
        // Its anchor and what the host was told change below: its delta is read again.
        self.world.mark_changed(s);
        // NOTE: read first: a mutable access marks the body as modified for rapier,
        // which then re-processes it (and may wake it) at the next step.
        let body = self.world.body_at(s);
        let current = body.body_type();
        let body_pos = Point2D::new(body.translation().x, body.translation().y);
        match desired {
            None => {
                freeze(self.world, s, current, body_pos);
                return disturbed;
            }
            Some(RigidBodyType::Dynamic) => {
                let thrown = current != RigidBodyType::Dynamic && was_dragging;
                disturbed |= free(
                    self.world,
                    s,
                    current,
                    body_pos,
                    host,
                    self.config.throw.window,
                );
                if thrown {
                    self.take_off(s, &node.id);
                }
            }
            Some(kind) => {
                // Held: the body takes `kind` and goes to the host's position, at once
                // for a fixed body, over the substeps for a kinematic one.
                disturbed |= flip_to(self.world, s, current, kind);
                if body_pos != host {
                    self.wake_in_path(s, body_pos, host);
                    if kind == RigidBodyType::Fixed {
                        self.world
                            .body_at_mut(s)
                            .set_translation(Vector::new(host.x, host.y), true);
                    } else {
                        self.drives.push(Drive {
                            slot: m.slot,
                            from: body_pos,
                            to: host,
                        });
                    }
                    disturbed = true;
                }
            }
        }
        self.world.set_anchor_at(s, host);
        let sync = self.world.host_at_mut(s);
        sync.fresh = false;
        sync.told = host;
        if dragging {
            track_drag(
                sync,
                host,
                was_dragging,
                self.frame_dt,
                self.config.throw.window,
                self.config.solver.max_speed,
            );
            disturbed = true;
        }
        sync.dragging = dragging;
        sync.synced = desired == Some(RigidBodyType::Dynamic) && !dragging;
        if disturbed {
            // A dragged or thrown node heats its neighbours, not itself.
            self.disturbances.touch(s, !(dragging || was_dragging));
        }
        disturbed
    }

    /// A node thrown this call flies with
    /// [`flight_damping`](crate::config::Throw::flight_damping) until it turns back.
    fn take_off(&mut self, s: usize, id: &N) {
        let Some(damping) = self.config.throw.flight_damping else {
            return;
        };
        let v = self.world.body_at(s).linvel();
        let v = Vector2D::new(v.x, v.y);
        if v.length() <= self.config.rest.speed || !v.is_finite() {
            return;
        }
        self.world
            .body_at_mut(s)
            .set_linear_damping(finite_or(damping, 0.0).max(0.0));
        self.flights.retain(|f| f.id != *id);
        self.flights.push(Flight {
            id: id.clone(),
            direction: v.normalize(),
            landed: false,
        });
    }

    /// Wakes the sleeping bodies in the path of the held body in `s` moving from `from`
    /// to `to`: rapier does not wake a sleeping body that a kinematic or fixed body is
    /// moved into. Past [`MAX_SWEEPS`] moves in one call, one pass wakes every body
    /// instead.
    fn wake_in_path(&mut self, s: usize, from: Point2D<f32>, to: Point2D<f32>) {
        self.sweeps += 1;
        if self.sweeps <= MAX_SWEEPS {
            self.world.wake_bodies_near_sweep(s, from, to, self.kept);
        } else if self.sweeps == MAX_SWEEPS + 1 {
            self.world.wake_dynamic_bodies();
        }
    }
}

/// The body type a node should have this call; `None` for unusable values (frozen).
pub(super) fn desired_type(
    policy: BodyKindPolicy,
    valid: bool,
    pinned: bool,
    dragging: bool,
) -> Option<RigidBodyType> {
    if !valid {
        return None;
    }
    Some(if pinned && policy == BodyKindPolicy::PinnedStatic {
        RigidBodyType::Fixed
    } else if pinned || dragging || policy == BodyKindPolicy::AllKinematic {
        RigidBodyType::KinematicPositionBased
    } else {
        RigidBodyType::Dynamic
    })
}

/// A radius or shape edit reshapes the body in place (its mass follows, as
/// [`mass_of`] says); returns whether the shape changed.
fn sync_shape<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    s: usize,
    config: &RapierLayoutConfig,
    node: &CanvasNode<N>,
) -> bool {
    let wanted = shape_of(config, node);
    let same = same_spec(world.shape_at(s), wanted);
    if !same {
        world.set_shape_at(s, wanted, mass_of(config, wanted));
    }
    !same
}

/// Whether two collider specs are the same bit for bit.
pub(super) fn same_spec(current: ColliderSpec, wanted: ColliderSpec) -> bool {
    match (current, wanted) {
        (ColliderSpec::Circle { radius: a }, ColliderSpec::Circle { radius: b }) => {
            a.to_bits() == b.to_bits()
        }
        (ColliderSpec::Rect { half_extents: a }, ColliderSpec::Rect { half_extents: b }) => {
            same_bits(a, b)
        }
        (
            ColliderSpec::RoundRect {
                half_extents: a,
                corner_radius: ca,
            },
            ColliderSpec::RoundRect {
                half_extents: b,
                corner_radius: cb,
            },
        ) => same_bits(a, b) && ca.to_bits() == cb.to_bits(),
        _ => false,
    }
}

/// Whether two vectors are the same bit for bit.
fn same_bits(a: Vector2D<f32>, b: Vector2D<f32>) -> bool {
    a.x.to_bits() == b.x.to_bits() && a.y.to_bits() == b.y.to_bits()
}

/// Unusable input: holds the body still where it is, and anchors it there.
fn freeze<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    s: usize,
    current: RigidBodyType,
    body_pos: Point2D<f32>,
) {
    if current == RigidBodyType::Dynamic {
        let body = world.body_at_mut(s);
        body.set_body_type(RigidBodyType::KinematicPositionBased, true);
        body.set_linvel(Vector::ZERO, false);
    }
    let sync = world.host_at_mut(s);
    sync.dragging = false;
    sync.synced = false;
    world.set_anchor_at(s, body_pos);
}

/// A node the physics moves. A release, unpin or unfreeze hands the body back in place
/// at the host's position, with the drag's velocity when it was thrown; a host edit of
/// a free node puts the body there, at rest. Returns whether either happened.
fn free<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    s: usize,
    current: RigidBodyType,
    body_pos: Point2D<f32>,
    host: Point2D<f32>,
    throw_window: f32,
) -> bool {
    let sync = *world.host_at(s);
    if current != RigidBodyType::Dynamic {
        let velocity = release_velocity(&sync, sync.dragging, throw_window);
        let body = world.body_at_mut(s);
        body.set_body_type(RigidBodyType::Dynamic, true);
        if body_pos != host {
            body.set_translation(Vector::new(host.x, host.y), true);
        }
        body.set_linvel(Vector::new(velocity.x, velocity.y), true);
        true
    } else if !sync.fresh && moved_by_host(sync.told, host) {
        let body = world.body_at_mut(s);
        body.set_translation(Vector::new(host.x, host.y), true);
        body.set_linvel(Vector::ZERO, true);
        true
    } else {
        false
    }
}

/// Flips a held body to `kind` in place, at rest; returns whether it was another kind.
fn flip_to<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    s: usize,
    current: RigidBodyType,
    kind: RigidBodyType,
) -> bool {
    if current == kind {
        return false;
    }
    let body = world.body_at_mut(s);
    body.set_body_type(kind, true);
    body.set_linvel(Vector::ZERO, true);
    true
}

/// Whether the host moved a free node: its position differs from the one it was told
/// (its last position plus the last delta) by more than float noise at that magnitude.
/// A host that adds deltas with `+=` lands on it bit for bit; any edit, however small,
/// is honoured.
fn moved_by_host(told: Point2D<f32>, host: Point2D<f32>) -> bool {
    let gap_sq = (told - host).square_length();
    if gap_sq == 0.0 {
        return false;
    }
    let magnitude = told
        .x
        .abs()
        .max(told.y.abs())
        .max(host.x.abs())
        .max(host.y.abs());
    let tolerance = (magnitude * 4.0 * f32::EPSILON).max(f32::MIN_POSITIVE);
    gap_sq > tolerance * tolerance
}
