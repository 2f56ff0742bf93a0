//! Drags and the hand-off that throws: a dragged node's pointer velocity measured against
//! the frame's real elapsed time, the velocity a release hands to the body, the flight
//! of a thrown node ([`RapierLayoutConfig::throw.flight_damping`](crate::config::Throw::flight_damping)),
//! and the drives that move kinematic bodies (dragged, or pinned and moved by the host)
//! to the host's position over a call's substeps.

use std::hash::Hash;

use euclid::default::{Point2D, Vector2D};
use rapier2d::prelude::Vector;

use crate::config::RapierLayoutConfig;
use crate::sanitize::finite_or;
use crate::world::slot::HostSync;
use crate::world::RapierSceneWorld;

/// A kinematic body moving to the host's position over this call's substeps.
#[derive(Clone, Copy, Debug)]
pub(super) struct Drive {
    pub(super) slot: u32,
    pub(super) from: Point2D<f32>,
    pub(super) to: Point2D<f32>,
}

/// Sets each driven body's next position for substep `k` of `substeps`: evenly along its
/// path, exactly at the host's position on the last substep.
pub(super) fn drive_kinematic_bodies<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    drives: &[Drive],
    k: u32,
    substeps: u32,
) {
    if drives.is_empty() {
        return;
    }
    let t = (k + 1) as f32 / substeps as f32;
    for drive in drives {
        let between = drive.from.lerp(drive.to, t);
        let target = if k + 1 == substeps || !between.is_finite() {
            drive.to
        } else {
            between
        };
        world
            .body_at_mut(drive.slot as usize)
            .set_next_kinematic_translation(Vector::new(target.x, target.y));
    }
}

/// After the call's substeps: a driven body rapier left short of where the host holds
/// it goes there. rapier moves a kinematic body to its target in a step, but not one
/// it leaves out of the step's active bodies (found by the `session` fuzz target:
/// `tests/regression_held_body_left_behind.rs`).
pub(super) fn land_driven_bodies<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    drives: &[Drive],
) {
    for drive in drives {
        let t = world.body_at(drive.slot as usize).translation();
        if (t.x, t.y) != (drive.to.x, drive.to.y) && drive.to.is_finite() {
            let body = world.body_at_mut(drive.slot as usize);
            body.set_translation(Vector::new(drive.to.x, drive.to.y), false);
            body.set_next_kinematic_translation(Vector::new(drive.to.x, drive.to.y));
        }
    }
}

/// Whether a driven kinematic body still carries the "moving fast" flag rapier's
/// continuous collision detection gave it while it was dynamic: rapier's CCD pass would
/// then clamp its commanded motion (a dragged node 0.75 of a frame's move behind the
/// pointer, found in a long random session with group forces), and the world's own
/// check over the awake bodies missed it there; the drives are every body this can
/// happen to.
pub(super) fn stale_ccd_in<N: Clone + Eq + Hash>(
    world: &RapierSceneWorld<N>,
    drives: &[Drive],
) -> bool {
    drives.iter().any(|drive| {
        let body = world.body_at(drive.slot as usize);
        body.is_kinematic() && body.is_ccd_active()
    })
}

/// Records this call's host position of a dragged node and, when the pointer moved, its
/// velocity over that move: what a release throws the node with, capped at `max_speed`.
///
/// Pointers report at their own rate, so a moving drag may show no motion in some
/// frames. A move is measured over the time since the pointer's previous report (this
/// frame plus the motionless frames before it), which gives a pointer reporting every
/// other frame its real speed; after a pause longer than `window` it is measured over
/// this frame alone (a flick from rest). The last move's velocity stands until the next
/// move, so an accelerating flick throws at the speed it reached, not an average of its
/// start. The first frame of a drag has no velocity yet.
pub(super) fn track_drag(
    host: &mut HostSync,
    position: Point2D<f32>,
    was_dragging: bool,
    frame_dt: f32,
    window: f32,
    max_speed: f32,
) {
    if !was_dragging {
        host.drag_velocity = Vector2D::zero();
        host.drag_still = 0.0;
    } else if position != host.drag_position {
        let since = host.drag_still + frame_dt;
        let over = if within_window(since, window) {
            since
        } else {
            frame_dt
        };
        let velocity = (position - host.drag_position) / over;
        host.drag_velocity = if velocity.is_finite() {
            clamp_speed(velocity, max_speed)
        } else {
            Vector2D::zero()
        };
        host.drag_still = 0.0;
    } else {
        host.drag_still += frame_dt;
    }
    host.drag_position = position;
}

/// Whether `seconds` without pointer motion still count as a moving pointer under a
/// throw window of `window` seconds (a hair of tolerance, so three frames of 1/60 s are
/// within 0.05 s).
fn within_window(seconds: f32, window: f32) -> bool {
    let window = finite_or(window, 0.0).max(0.0);
    seconds <= window * (1.0 + 1e-4)
}

/// The velocity a body takes when it turns dynamic: the pointer's last move when a drag
/// ended (a throw, also of a node unpinned in the same call) and the pointer moved within
/// the last `window` seconds; none after a pointer that stood still for longer, an unpin
/// or an unfreeze.
pub(super) fn release_velocity(host: &HostSync, was_dragging: bool, window: f32) -> Vector2D<f32> {
    if was_dragging && within_window(host.drag_still, window) {
        host.drag_velocity
    } else {
        Vector2D::zero()
    }
}

/// `v` shortened to `max_speed` (no cap when `max_speed` is not positive).
fn clamp_speed(v: Vector2D<f32>, max_speed: f32) -> Vector2D<f32> {
    let speed = v.length();
    if max_speed > 0.0 && speed > max_speed && speed.is_finite() {
        v * (max_speed / speed)
    } else {
        v
    }
}

/// A thrown node, from its release until it rests: damped as
/// [`flight_damping`](crate::config::Throw::flight_damping) says until it turns
/// back, and keeping the layout from its cold stop until it slows to rest.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub(super) struct Flight<N> {
    pub(super) id: N,
    /// The direction it was thrown in.
    pub(super) direction: Vector2D<f32>,
    /// It turned back: its damping is the material's again.
    pub(super) landed: bool,
}

/// The host sync's state between calls: kinematic bodies moving to the host's
/// positions, thrown nodes in flight, and the gravity of the last call.
#[derive(Debug)]
pub(super) struct Host<N> {
    /// Kinematic bodies moving to the host's positions over this call's substeps.
    pub(super) drives: Vec<Drive>,
    /// Thrown nodes in flight.
    pub(super) flights: Vec<Flight<N>>,
    /// The gravity of the last call: a change is a disturbance.
    pub(super) gravity: Vector2D<f32>,
}

impl<N> Default for Host<N> {
    fn default() -> Self {
        Self {
            drives: Vec::new(),
            flights: Vec::new(),
            gravity: Vector2D::zero(),
        }
    }
}

impl<N: Clone + Eq + Hash> Host<N> {
    /// Lands the thrown nodes that turned back, slowed, were grabbed or left (they take
    /// the material's damping again), and forgets those that rest.
    pub(super) fn land_flights(
        &mut self,
        config: &RapierLayoutConfig,
        world: Option<&mut RapierSceneWorld<N>>,
    ) {
        if self.flights.is_empty() {
            return;
        }
        let damping = finite_or(config.material.linear_damping, 0.0).max(0.0);
        let rest_speed = config.rest.speed;
        let Some(world) = world else {
            self.flights.clear();
            return;
        };
        self.flights.retain_mut(|flight| {
            let Some(s) = world.slot_of(&flight.id) else {
                return false;
            };
            let body = world.body_at(s);
            let v = body.linvel();
            let v = Vector2D::new(v.x, v.y);
            let moving = body.is_dynamic() && !body.is_sleeping() && v.length() > rest_speed;
            let outward = moving && v.dot(flight.direction) > 0.0;
            if !flight.landed && !outward {
                flight.landed = true;
                world.body_at_mut(s).set_linear_damping(damping);
            }
            moving
        });
    }
}
