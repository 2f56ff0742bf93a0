//! The bodies the constraints name, by a local index, on plain arrays the passes
//! (`passes.rs`) project on. The arrays are kept from one projection to the next and
//! read again from the world only for the bodies it reports changed
//! (`world/changes.rs`): a drag on a settled 10,000-node graph under a flow changes a
//! thousand bodies a step, not ten thousand. A projection writes back only the bodies
//! it moved.

use std::hash::Hash;

use rapier2d::prelude::Vector;

use super::order::topological;
use super::sweep::SweepLog;
use super::watch::Watch;
use super::{index, Row, Separation};
use crate::input::node_forces::AxisLock;
use crate::world::{RapierSceneWorld, SlotsView};

/// No local index: the slot's body is named by no constraint.
pub(super) const NONE: u32 = u32::MAX;

/// A separation by local index: `b` at least `gap` beyond `a` along `axis`; `id` is its
/// index in the list it was compiled from.
#[derive(Clone, Copy, Debug)]
pub(super) struct Link {
    pub(super) a: u32,
    pub(super) b: u32,
    pub(super) axis: usize,
    pub(super) gap: f32,
    pub(super) id: u32,
}

/// The constrained bodies and the constraints between them, by local index.
#[derive(Clone, Debug, Default)]
pub(super) struct Local {
    /// The world slot of each local body, ascending, and each slot's local index.
    slots: Vec<u32>,
    local_of: Vec<u32>,
    /// In a topological order of their ends (`order.rs`).
    pub(super) links: Vec<Link>,
    /// Each row's axis and its members' range in `members`.
    pub(super) rows: Vec<(usize, std::ops::Range<usize>)>,
    pub(super) members: Vec<u32>,
    /// Position, velocity and inverse mass along each axis (0: does not give way along
    /// it) of each local body; the inverse mass before the locks; and what the world
    /// held when last read or written.
    pub(super) points: Vec<[f32; 2]>,
    pub(super) speeds: Vec<[f32; 2]>,
    pub(super) inverse_mass: Vec<[f32; 2]>,
    free_mass: Vec<[f32; 2]>,
    read: Vec<([f32; 2], [f32; 2])>,
    /// The axes the locks zeroed, by local index.
    locked: Vec<(u32, usize)>,
    /// Whether the arrays hold what the world held when its changes were last
    /// forgotten, apart from the changed slots.
    kept: bool,
    /// By local index: awake or moved in this projection (the passes visit the
    /// separations of these); and the list of them.
    hot: Vec<bool>,
    pub(super) hot_list: Vec<u32>,
    /// Whether a projection wrote a body back since the world's changes were last read.
    pub(super) wrote: bool,
    /// The bodies the sweeps moved (`sweep.rs`).
    pub(super) sweep_log: SweepLog,
    /// Each local body's separations, by place in `links` (`watch.rs`): those of body
    /// `l` are `adjacent[adjacent_start[l]..adjacent_start[l + 1]]`.
    pub(super) adjacent_start: Vec<u32>,
    pub(super) adjacent: Vec<u32>,
    /// The separations that can be short (`watch.rs`).
    pub(super) watch: Watch,
}

impl Local {
    /// Indexes `separations` (visited in a topological order, `order.rs`) and `rows` for
    /// a world of `slot_count` slots. A link's id is its separation's place in
    /// `separations`.
    pub(super) fn index<'a>(
        &mut self,
        separations: impl Iterator<Item = &'a Separation> + Clone,
        rows: impl Iterator<Item = &'a Row> + Clone,
        slot_count: usize,
    ) {
        // Nothing by the old local indices outlives them.
        self.clear_hot();
        self.hot.clear();
        self.locked.clear();
        self.slots.clear();
        self.slots.extend(
            separations
                .clone()
                .flat_map(|c| [c.first, c.second])
                .chain(rows.clone().flat_map(|r| r.slots.iter().copied()))
                .filter(|&s| (s as usize) < slot_count),
        );
        self.slots.sort_unstable();
        self.slots.dedup();
        self.local_of.clear();
        self.local_of.resize(slot_count, NONE);
        for (k, &s) in self.slots.iter().enumerate() {
            self.local_of[s as usize] = k as u32;
        }
        let at = |s: u32| self.local_of.get(s as usize).copied().unwrap_or(NONE);
        let links: Vec<Link> = separations
            .enumerate()
            .filter_map(|(id, c)| {
                let (a, b) = (at(c.first), at(c.second));
                (a != NONE && b != NONE && a != b).then_some(Link {
                    a,
                    b,
                    axis: index(c.axis),
                    gap: c.gap,
                    id: id as u32,
                })
            })
            .collect();
        let ends: Vec<(u32, u32)> = links.iter().map(|c| (c.a, c.b)).collect();
        self.links.clear();
        self.links.extend(
            topological(self.slots.len(), &ends)
                .into_iter()
                .map(|k| links[k]),
        );
        self.rows.clear();
        self.members.clear();
        for row in rows {
            let start = self.members.len();
            self.members
                .extend(row.slots.iter().map(|&s| at(s)).filter(|&l| l != NONE));
            self.rows.push((index(row.axis), start..self.members.len()));
        }
        self.index_adjacent();
        self.kept = false;
    }

    /// Whether there is nothing to hold.
    pub(super) fn is_empty(&self) -> bool {
        self.links.is_empty() && self.rows.is_empty()
    }

    /// Reads the constrained bodies' positions, velocities and inverse masses: those
    /// the world reports changed, or all when it cannot say or nothing is kept. The
    /// awake dynamic ones are hot. A body's axis held by one of `locks` (slot, axis, coordinate)
    /// does not give way along it.
    pub(super) fn gather<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        locks: &[(u32, AxisLock, f32)],
    ) {
        self.clear_hot();
        if !self.read_changed(world, true) {
            self.read_all(world, true);
        }
        for &(l, axis) in &self.locked {
            self.inverse_mass[l as usize][axis] = self.free_mass[l as usize][axis];
        }
        self.locked.clear();
        for &(slot, axis, _) in locks {
            let l = self.local_of.get(slot as usize).copied().unwrap_or(NONE);
            if l != NONE {
                let axis = match axis {
                    AxisLock::X => 0,
                    AxisLock::Y => 1,
                };
                self.inverse_mass[l as usize][axis] = 0.0;
                self.locked.push((l, axis));
            }
        }
        #[cfg(debug_assertions)]
        self.check_kept(world);
    }

    /// Before the world forgets its changes: reads the changed bodies, so what is kept
    /// stays what the world holds.
    pub(super) fn catch_up<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        if !self.read_changed(world, false) {
            self.kept = false;
        }
        self.wrote = false;
    }

    /// Brings the arrays to what the world holds: the changed bodies, or all.
    pub(super) fn refresh<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        if !self.read_changed(world, false) {
            self.read_all(world, false);
        }
    }

    /// Reads the bodies the world reports changed, the awake dynamic ones hot when
    /// `hot`; false when nothing is kept or the world cannot say. Every awake dynamic
    /// body is among the changed (`world/changes.rs`), so the hot bodies are the same
    /// whichever way they were read: a layout restored from a snapshot projects as the
    /// one saved.
    fn read_changed<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        hot: bool,
    ) -> bool {
        let view = world.slots_view();
        match world.changed_slots() {
            Some(changed) if self.kept && self.local_of.len() == world.slot_count() => {
                for &s in changed {
                    let l = self.local_of[s as usize];
                    if l == NONE {
                        continue;
                    }
                    self.watch.touch(l, self.slots.len());
                    if self.read_body(l as usize, view) && hot {
                        self.heat(l as usize);
                    }
                }
                true
            }
            _ => false,
        }
    }

    /// Reads every constrained body, the awake dynamic ones hot when `hot`.
    fn read_all<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>, hot: bool) {
        let n = self.slots.len();
        self.read.resize(n, ([0.0; 2], [0.0; 2]));
        self.points.resize(n, [0.0; 2]);
        self.speeds.resize(n, [0.0; 2]);
        self.free_mass.resize(n, [0.0; 2]);
        self.inverse_mass.resize(n, [0.0; 2]);
        let view = world.slots_view();
        self.watch.watch_all();
        for l in 0..n {
            if self.read_body(l, view) && hot {
                self.heat(l);
            }
        }
        self.kept = self.local_of.len() == world.slot_count();
    }

    /// Reads local body `l` from the world; true when it is dynamic and awake.
    fn read_body(&mut self, l: usize, view: SlotsView<'_>) -> bool {
        let s = self.slots[l] as usize;
        let body = view.body_at(s);
        let (t, v) = (body.translation(), body.linvel());
        self.read[l] = ([t.x, t.y], [v.x, v.y]);
        (self.points[l], self.speeds[l]) = self.read[l];
        let m = view.mass_at(s);
        let w = if body.is_dynamic() && m > 0.0 && m.is_finite() {
            1.0 / m
        } else {
            0.0
        };
        self.free_mass[l] = [w; 2];
        self.inverse_mass[l] = [w; 2];
        // Fixed bodies count as awake in rapier, changed or not: only dynamic ones.
        body.is_dynamic() && !body.is_sleeping()
    }

    /// In debug builds: every kept body is what the world holds.
    #[cfg(debug_assertions)]
    fn check_kept<N: Clone + Eq + Hash>(&self, world: &RapierSceneWorld<N>) {
        let view = world.slots_view();
        for (l, &s) in self.slots.iter().enumerate() {
            let (t, v) = (
                view.body_at(s as usize).translation(),
                view.body_at(s as usize).linvel(),
            );
            debug_assert_eq!(
                self.read[l],
                ([t.x, t.y], [v.x, v.y]),
                "the constraints' kept body in slot {s} is not the world's"
            );
        }
    }

    /// Marks local body `l` hot.
    pub(super) fn heat(&mut self, l: usize) {
        if self.hot.len() < self.slots.len() {
            self.hot.resize(self.slots.len(), false);
        }
        if !self.hot[l] {
            self.hot[l] = true;
            self.hot_list.push(l as u32);
        }
    }

    /// Marks every local body hot (the settling at the cold stop visits every
    /// separation).
    pub(super) fn heat_all(&mut self) {
        self.watch.watch_all();
        for l in 0..self.slots.len() {
            self.heat(l);
        }
    }

    /// How many bodies are indexed.
    pub(super) fn points_count(&self) -> usize {
        self.slots.len()
    }

    /// Whether the index was made for a world of `slot_count` slots.
    pub(super) fn fits(&self, slot_count: usize) -> bool {
        self.local_of.len() == slot_count
    }

    /// Whether local body `l` is hot.
    pub(super) fn is_hot(&self, l: u32) -> bool {
        self.hot.get(l as usize).is_some_and(|&h| h)
    }

    fn clear_hot(&mut self) {
        for &l in &self.hot_list {
            self.hot[l as usize] = false;
        }
        self.hot_list.clear();
    }

    /// Takes the constrained bodies' positions from `points` (by slot, `unit` world
    /// units each), every body free to move, at rest and hot. Nothing is kept after.
    pub(super) fn gather_points(&mut self, points: &[[f32; 2]], unit: f32) {
        self.clear_hot();
        self.kept = false;
        self.locked.clear();
        self.read.clear();
        self.read.extend(self.slots.iter().map(|&s| {
            let [x, y] = points.get(s as usize).copied().unwrap_or_default();
            ([x * unit, y * unit], [0.0; 2])
        }));
        self.inverse_mass.clear();
        self.inverse_mass.resize(self.slots.len(), [1.0; 2]);
        self.points.clear();
        self.points.extend(self.read.iter().map(|r| r.0));
        self.speeds.clear();
        self.speeds.resize(self.slots.len(), [0.0; 2]);
        self.heat_all();
    }

    /// Writes the positions back to `points` (by slot, `unit` world units each).
    pub(super) fn scatter_points(&self, points: &mut [[f32; 2]], unit: f32) {
        for (k, &s) in self.slots.iter().enumerate() {
            if let Some(p) = points.get_mut(s as usize) {
                *p = [self.points[k][0] / unit, self.points[k][1] / unit];
            }
        }
    }

    /// Writes back the hot bodies a pass moved, waking them, in slot order.
    pub(super) fn scatter<N: Clone + Eq + Hash>(&mut self, world: &mut RapierSceneWorld<N>) {
        self.hot_list.sort_unstable();
        for &l in &self.hot_list {
            let (l, s) = (l as usize, self.slots[l as usize] as usize);
            let (p, v) = (self.points[l], self.speeds[l]);
            if (p, v) == self.read[l] {
                continue;
            }
            let body = world.body_at_mut(s);
            body.set_translation(Vector::new(p[0], p[1]), true);
            body.set_linvel(Vector::new(v[0], v[1]), true);
            self.read[l] = (p, v);
            self.wrote = true;
        }
    }
}
