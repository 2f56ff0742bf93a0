//! The bodies the constraints name, by a local index: read from the world once per
//! projection (in slot order), projected on plain arrays, and written back once, only
//! where a pass moved them.

use std::hash::Hash;

use rapier2d::prelude::Vector;

use super::order::topological;
use super::{index, Row, Separation};
use crate::input::node_forces::AxisLock;
use crate::world::RapierSceneWorld;

/// No local index: the slot's body is named by no constraint.
const NONE: u32 = u32::MAX;

/// A separation by local index: `b` at least `gap` beyond `a` along `axis`.
#[derive(Clone, Copy, Debug)]
struct Link {
    a: u32,
    b: u32,
    axis: usize,
    gap: f32,
}

/// The constrained bodies and the constraints between them, by local index.
#[derive(Clone, Debug, Default)]
pub(super) struct Local {
    /// The world slot of each local body, ascending.
    slots: Vec<u32>,
    links: Vec<Link>,
    /// Each row's axis and its members' range in `members`.
    rows: Vec<(usize, std::ops::Range<usize>)>,
    members: Vec<u32>,
    /// Position, velocity and inverse mass along each axis (0: does not give way along
    /// it) of each local body, and the position and velocity read from the world.
    points: Vec<[f32; 2]>,
    speeds: Vec<[f32; 2]>,
    inverse_mass: Vec<[f32; 2]>,
    read: Vec<([f32; 2], [f32; 2])>,
}

impl Local {
    /// Indexes `separations` (visited in a topological order, `order.rs`) and `rows` for
    /// a world of `slot_count` slots.
    pub(super) fn index<'a>(
        &mut self,
        separations: impl Iterator<Item = &'a Separation> + Clone,
        rows: &[Row],
        slot_count: usize,
    ) {
        self.slots.clear();
        self.slots.extend(
            separations
                .clone()
                .flat_map(|c| [c.first, c.second])
                .chain(rows.iter().flat_map(|r| r.slots.iter().copied()))
                .filter(|&s| (s as usize) < slot_count),
        );
        self.slots.sort_unstable();
        self.slots.dedup();
        let mut local = vec![NONE; slot_count];
        for (k, &s) in self.slots.iter().enumerate() {
            local[s as usize] = k as u32;
        }
        let at = |s: u32| local.get(s as usize).copied().unwrap_or(NONE);
        let links: Vec<Link> = separations
            .filter_map(|c| {
                let (a, b) = (at(c.first), at(c.second));
                (a != NONE && b != NONE && a != b).then_some(Link {
                    a,
                    b,
                    axis: index(c.axis),
                    gap: c.gap,
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
    }

    /// Whether there is nothing to hold.
    pub(super) fn is_empty(&self) -> bool {
        self.links.is_empty() && self.rows.is_empty()
    }

    /// Reads the constrained bodies' positions, velocities and inverse masses; a body's
    /// axis held by one of `locks` (slot, axis, coordinate) does not give way along it.
    pub(super) fn gather<N: Clone + Eq + Hash>(
        &mut self,
        world: &RapierSceneWorld<N>,
        locks: &[(u32, AxisLock, f32)],
    ) {
        let view = world.slots_view();
        self.read.clear();
        self.inverse_mass.clear();
        for &s in &self.slots {
            let body = view.body_at(s as usize);
            let (t, v) = (body.translation(), body.linvel());
            self.read.push(([t.x, t.y], [v.x, v.y]));
            let m = view.mass_at(s as usize);
            let w = if body.is_dynamic() && m > 0.0 && m.is_finite() {
                1.0 / m
            } else {
                0.0
            };
            self.inverse_mass.push([w; 2]);
        }
        for &(slot, axis, _) in locks {
            if let Ok(l) = self.slots.binary_search(&slot) {
                let axis = match axis {
                    AxisLock::X => 0,
                    AxisLock::Y => 1,
                };
                self.inverse_mass[l][axis] = 0.0;
            }
        }
        self.points.clear();
        self.points.extend(self.read.iter().map(|r| r.0));
        self.speeds.clear();
        self.speeds.extend(self.read.iter().map(|r| r.1));
    }

    /// Takes the constrained bodies' positions from `points` (by slot, `unit` world
    /// units each), every body free to move and at rest.
    pub(super) fn gather_points(&mut self, points: &[[f32; 2]], unit: f32) {
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
    }

    /// Writes the positions back to `points` (by slot, `unit` world units each).
    pub(super) fn scatter_points(&self, points: &mut [[f32; 2]], unit: f32) {
        for (k, &s) in self.slots.iter().enumerate() {
            if let Some(p) = points.get_mut(s as usize) {
                *p = [self.points[k][0] / unit, self.points[k][1] / unit];
            }
        }
    }

    /// Writes back the bodies a pass moved, waking them.
    pub(super) fn scatter<N: Clone + Eq + Hash>(&self, world: &mut RapierSceneWorld<N>) {
        for (k, &s) in self.slots.iter().enumerate() {
            let (p, v) = (self.points[k], self.speeds[k]);
            if (p, v) == self.read[k] {
                continue;
            }
            let body = world.body_at_mut(s as usize);
            body.set_translation(Vector::new(p[0], p[1]), true);
            body.set_linvel(Vector::new(v[0], v[1]), true);
        }
    }

    /// How far the worst constraint that the bodies can still move toward holding is
    /// from holding: a separation's shortfall (none between two bodies that do not give
    /// way), half a row's spread.
    pub(super) fn worst(&self) -> f32 {
        let movable = |c: &&Link| {
            self.inverse_mass[c.a as usize][c.axis] > 0.0
                || self.inverse_mass[c.b as usize][c.axis] > 0.0
        };
        let links = self.links.iter().filter(movable).map(|c| self.shortfall(c));
        let rows = self.rows.iter().map(|(axis, range)| {
            let (low, high) = self.members[range.clone()].iter().fold(
                (f32::INFINITY, f32::NEG_INFINITY),
                |(low, high), &l| {
                    let x = self.points[l as usize][*axis];
                    (low.min(x), high.max(x))
                },
            );
            (high - low).max(0.0) / 2.0
        });
        links.chain(rows).fold(0.0_f32, f32::max)
    }

    /// One Gauss–Seidel pass over every separation, in order or in reverse (passes
    /// alternate: the separations are in a topological order, so one direction carries
    /// a push down a chain and the other up), then every row.
    pub(super) fn pass(&mut self, reverse: bool) {
        for k in 0..self.links.len() {
            let k = if reverse { self.links.len() - 1 - k } else { k };
            self.separate(self.links[k]);
        }
        self.line_up_rows();
    }

    /// Puts every row on its line.
    pub(super) fn line_up_rows(&mut self) {
        for k in 0..self.rows.len() {
            let (axis, range) = self.rows[k].clone();
            self.line_up(axis, range);
        }
    }

    /// Makes every separation hold where the bodies allow, whatever the passes left:
    /// in order, a short separation's second body moves on along the axis; then in
    /// reverse, its first body moves back. With the separations in a topological
    /// order, each sweep carries a push through any chain at once (a dragged node
    /// moves everything it pushes within the substep). Left short: separations on a
    /// cycle (conflicting constraints), and those between bodies that do not give way.
    pub(super) fn sweep(&mut self) {
        for k in 0..self.links.len() {
            let c = self.links[k];
            self.push(c, c.b as usize, 1.0);
        }
        for k in (0..self.links.len()).rev() {
            let c = self.links[k];
            self.push(c, c.a as usize, -1.0);
        }
    }

    /// Moves local body `l` of separation `c` by its shortfall, `sign` along the axis,
    /// with the speed that closes the two taken out.
    fn push(&mut self, c: Link, l: usize, sign: f32) {
        let short = self.shortfall(&c);
        if short <= 0.0 || self.inverse_mass[l][c.axis] == 0.0 {
            return;
        }
        let closing =
            (self.speeds[c.a as usize][c.axis] - self.speeds[c.b as usize][c.axis]).max(0.0);
        self.shift(l, c.axis, sign * short, sign * closing);
    }

    fn shortfall(&self, c: &Link) -> f32 {
        c.gap - (self.points[c.b as usize][c.axis] - self.points[c.a as usize][c.axis])
    }

    /// Moves local body `l` by `by` along `axis` and adds `dv` to its speed along it,
    /// unless either would stop being finite.
    fn shift(&mut self, l: usize, axis: usize, by: f32, dv: f32) {
        let (p, v) = (self.points[l][axis] + by, self.speeds[l][axis] + dv);
        if p.is_finite() && v.is_finite() {
            self.points[l][axis] = p;
            self.speeds[l][axis] = v;
        }
    }

    /// Holds one separation: parts its bodies when closer than the gap, and takes out
    /// the speed that closes them further.
    fn separate(&mut self, c: Link) {
        let (a, b) = (c.a as usize, c.b as usize);
        let (wa, wb) = (self.inverse_mass[a][c.axis], self.inverse_mass[b][c.axis]);
        let w = wa + wb;
        let short = self.shortfall(&c);
        if w <= 0.0 || short < 0.0 {
            return;
        }
        let closing = (self.speeds[a][c.axis] - self.speeds[b][c.axis]).max(0.0);
        self.shift(a, c.axis, -short * wa / w, -closing * wa / w);
        self.shift(b, c.axis, short * wb / w, closing * wb / w);
    }

    /// Puts a row's bodies on one line: the line of its immovable bodies (their mean),
    /// or else their mass-weighted mean, each at that line's speed along the axis.
    fn line_up(&mut self, axis: usize, range: std::ops::Range<usize>) {
        let (mut fixed, mut fixed_count) = (0.0_f64, 0_u32);
        let (mut sum, mut speed, mut weight) = (0.0_f64, 0.0_f64, 0.0_f64);
        for &l in &self.members[range.clone()] {
            let l = l as usize;
            let x = f64::from(self.points[l][axis]);
            let w = f64::from(self.inverse_mass[l][axis]);
            if w == 0.0 {
                fixed += x;
                fixed_count += 1;
            } else {
                let m = 1.0 / w;
                sum += m * x;
                speed += m * f64::from(self.speeds[l][axis]);
                weight += m;
            }
        }
        if weight == 0.0 {
            return;
        }
        let (line, line_speed) = if fixed_count > 0 {
            (fixed / f64::from(fixed_count), 0.0)
        } else {
            (sum / weight, speed / weight)
        };
        for k in range {
            let l = self.members[k] as usize;
            if self.inverse_mass[l][axis] == 0.0 {
                continue;
            }
            let by = (line - f64::from(self.points[l][axis])) as f32;
            let dv = (line_speed - f64::from(self.speeds[l][axis])) as f32;
            self.shift(l, axis, by, dv);
        }
    }
}
