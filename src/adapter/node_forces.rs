//! The host's per-node forces ([`LayoutExtras::forces`]) onto the world, once per call
//! after sync in: the table the pulls read by slot (`forces/targets.rs`), a wake and
//! local heat for every node whose forces changed, and the axis locks, which are rapier
//! lock flags (the solver then treats the body as infinitely heavy along that axis)
//! plus a guard after every substep that holds the locked coordinate at the host's,
//! against the velocity changes the layout sets itself (disk separation, a
//! release) and the projection at the cold stop.

use std::hash::Hash;

use rapier2d::prelude::{LockedAxes, Vector};

use super::heat::Disturbances;
use super::matching::{Matching, NO_SLOT};
use super::sync_in::HostInput;
use super::RapierLayout;
use crate::forces::targets::NodeTargets;
use crate::input::layout::LayoutExtras;
use crate::input::node_forces::{AxisLock, NodeForces};
use crate::input::scene::CanvasSceneInput;
use crate::world::RapierSceneWorld;

/// Reads `extras.forces` for the scene's usable nodes (as `matching` found them) into
/// `targets`; returns whether any node's forces changed (a disturbance: those nodes are
/// woken, and touched in `spread`).
pub(super) fn sync_node_forces<N: Clone + Eq + Hash>(
    targets: &mut NodeTargets,
    scene: &CanvasSceneInput<N>,
    extras: &LayoutExtras<N>,
    matching: &Matching<N>,
    world: Option<&mut RapierSceneWorld<N>>,
    spread: &mut Disturbances,
) -> bool {
    targets.problems = 0;
    if extras.forces.is_empty() && targets.by_slot.is_empty() {
        return false;
    }
    let Some(world) = world else {
        *targets = NodeTargets::default();
        return false;
    };
    let n = world.slot_count();
    // The last call's table is the buffer this call's is written into.
    let mut by_slot = std::mem::take(&mut targets.by_slot);
    by_slot.clear();
    by_slot.resize(n, NodeForces::default());
    targets.locks.clear();
    if !extras.forces.is_empty() {
        for (node, &m) in scene.nodes.iter().zip(matching.matches()) {
            if m.slot == NO_SLOT || !m.valid {
                continue;
            }
            if let Some(forces) = extras.forces.get(&node.id) {
                let usable = forces.usable();
                targets.problems += usize::from(usable != *forces);
                by_slot[m.slot as usize] = usable;
                // Held at the host's coordinate, which a body just inserted beside
                // another at the same point (and spread a little) may not have.
                let p = node.position;
                match usable.lock {
                    Some(AxisLock::X) => targets.locks.push((m.slot, AxisLock::X, p.x)),
                    Some(AxisLock::Y) => targets.locks.push((m.slot, AxisLock::Y, p.y)),
                    None => {}
                }
            }
        }
    }
    // What each body had is kept with its slot (which moves with it when another
    // node is removed), so a change is told apart from the last call's by node.
    let mut changed = false;
    let mut any = false;
    for (s, now) in by_slot.iter().enumerate() {
        let key = now.key();
        any |= key != 0;
        let host = world.host_at_mut(s);
        let (was_key, was_lock) = (host.forces_key, host.lock);
        (host.forces_key, host.lock) = (key, now.lock);
        if was_lock != now.lock {
            set_lock(world, s, now.lock);
        }
        if was_key != key {
            changed = true;
            spread.touch(s, true);
            let body = world.body_at_mut(s);
            if body.is_dynamic() {
                body.wake_up(true);
            }
        }
    }
    if any {
        targets.by_slot = by_slot;
    }
    targets.index();
    changed
}

/// Sets the rapier lock flags of the body in slot `s` to `lock` (rotation stays locked),
/// and stops its motion along a newly locked axis.
fn set_lock<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    s: usize,
    lock: Option<AxisLock>,
) {
    let mut wanted = LockedAxes::ROTATION_LOCKED;
    match lock {
        Some(AxisLock::X) => wanted |= LockedAxes::TRANSLATION_LOCKED_X,
        Some(AxisLock::Y) => wanted |= LockedAxes::TRANSLATION_LOCKED_Y,
        None => {}
    }
    // NOTE: read first: a mutable access marks the body as modified for rapier.
    if world.body_at(s).locked_axes() == wanted {
        return;
    }
    let body = world.body_at_mut(s);
    body.set_locked_axes(wanted, true);
    let mut v = body.linvel();
    match lock {
        Some(AxisLock::X) => v.x = 0.0,
        Some(AxisLock::Y) => v.y = 0.0,
        None => return,
    }
    body.set_linvel(v, true);
}

/// Puts every locked dynamic body back on its locked coordinate, at no speed along it.
pub(super) fn hold_locked_axes<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    locks: &[(u32, AxisLock, f32)],
) {
    for &(slot, axis, value) in locks {
        let s = slot as usize;
        if s >= world.slot_count() {
            continue;
        }
        let body = world.body_at(s);
        if !body.is_dynamic() {
            continue;
        }
        let (mut t, mut v) = (body.translation(), body.linvel());
        let (coordinate, speed) = match axis {
            AxisLock::X => (&mut t.x, &mut v.x),
            AxisLock::Y => (&mut t.y, &mut v.y),
        };
        if coordinate.to_bits() == value.to_bits() && *speed == 0.0 {
            continue;
        }
        *coordinate = value;
        *speed = 0.0;
        let body = world.body_at_mut(s);
        body.set_translation(Vector::new(t.x, t.y), false);
        body.set_linvel(v, false);
    }
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Stage 4: the host's pins, drags, releases and moves onto the bodies, then its
    /// per-node forces. Returns whether the host disturbed the layout.
    pub(super) fn sync_host(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        frame_dt: f32,
        known: Option<&[usize]>,
    ) -> bool {
        let input = HostInput {
            config: &self.config,
            scene,
            extras,
            frame_dt,
            known,
        };
        let kept = self.forces.kept_bodies();
        let (world, spread) = (self.world.as_mut(), &mut self.heat.spread);
        // NOTE: every drive comes with a disturbance from `sync_in`.
        let mut disturbed = self
            .host
            .sync_in(&input, world, &self.matching, spread, kept);
        let (world, spread) = (self.world.as_mut(), &mut self.heat.spread);
        let targets = &mut self.forces.targets;
        disturbed |= sync_node_forces(targets, scene, extras, &self.matching, world, spread);
        disturbed
    }
}
