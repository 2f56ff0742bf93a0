//! The projection after each rapier step: Gauss–Seidel passes over the separations and
//! rows, moving dynamic bodies only.

use std::hash::Hash;

use rapier2d::prelude::Vector;

use super::{along, Compiled, Row, Separation, PASSES};
use crate::input::constraints::Axis;
use crate::world::RapierSceneWorld;

impl Compiled {
    /// Projects until every constraint holds within a tenth of
    /// [`HELD_WITHIN`](super::compile::HELD_WITHIN), or `rounds` times [`PASSES`]
    /// passes: what the world rests with when it halts.
    pub(crate) fn settle<N: Clone + Eq + Hash>(
        &self,
        world: &mut RapierSceneWorld<N>,
        rounds: usize,
    ) {
        for _ in 0..rounds {
            let worst = self
                .separations
                .iter()
                .map(|c| c.shortfall(world))
                .chain(self.rows.iter().map(|r| r.spread(world) / 2.0))
                .fold(0.0_f32, f32::max);
            if worst <= 0.1 * super::compile::HELD_WITHIN {
                return;
            }
            self.project(world);
        }
    }

    /// Projects every constraint onto `world`'s bodies, [`PASSES`] times.
    pub(crate) fn project<N: Clone + Eq + Hash>(&self, world: &mut RapierSceneWorld<N>) {
        if self.separations.is_empty() && self.rows.is_empty() {
            return;
        }
        for _ in 0..PASSES {
            for &separation in &self.separations {
                separate(world, separation);
            }
            for row in &self.rows {
                line_up(world, row);
            }
        }
    }
}

/// A body's inverse mass, 0 for one that does not give way.
fn inverse_mass<N: Clone + Eq + Hash>(world: &RapierSceneWorld<N>, s: usize) -> f32 {
    if world.body_at(s).is_dynamic() {
        let m = world.mass_at(s);
        if m > 0.0 && m.is_finite() {
            1.0 / m
        } else {
            0.0
        }
    } else {
        0.0
    }
}

/// Moves the body in `s` by `by` along `axis` and adds `dv` to its speed along it.
fn shift<N: Clone + Eq + Hash>(
    world: &mut RapierSceneWorld<N>,
    s: usize,
    axis: Axis,
    by: f32,
    dv: f32,
) {
    if by == 0.0 && dv == 0.0 {
        return;
    }
    let body = world.body_at_mut(s);
    let (mut p, mut v) = (body.translation(), body.linvel());
    match axis {
        Axis::X => {
            p.x += by;
            v.x += dv;
        }
        Axis::Y => {
            p.y += by;
            v.y += dv;
        }
    }
    if p.is_finite() && v.is_finite() {
        body.set_translation(Vector::new(p.x, p.y), true);
        body.set_linvel(Vector::new(v.x, v.y), true);
    }
}

/// Holds one separation: parts its bodies when closer than the gap, and takes out the
/// speed that closes them further.
fn separate<N: Clone + Eq + Hash>(world: &mut RapierSceneWorld<N>, c: Separation) {
    let (a, b) = (c.first as usize, c.second as usize);
    if a == b {
        return;
    }
    let (wa, wb) = (inverse_mass(world, a), inverse_mass(world, b));
    let w = wa + wb;
    if w <= 0.0 {
        return;
    }
    let speed = |world: &RapierSceneWorld<N>, s: usize| {
        let v = world.body_at(s).linvel();
        along(c.axis, v.x, v.y)
    };
    let short = c.shortfall(world);
    if short < 0.0 {
        return;
    }
    let closing = (speed(world, a) - speed(world, b)).max(0.0);
    shift(world, a, c.axis, -short * wa / w, -closing * wa / w);
    shift(world, b, c.axis, short * wb / w, closing * wb / w);
}

/// Puts a row's bodies on one line: the line of its immovable bodies (their mean), or
/// else their mass-weighted mean, each at that line's speed along the axis.
fn line_up<N: Clone + Eq + Hash>(world: &mut RapierSceneWorld<N>, row: &Row) {
    let (mut fixed, mut fixed_count) = (0.0_f64, 0_u32);
    let (mut sum, mut speed, mut weight) = (0.0_f64, 0.0_f64, 0.0_f64);
    for &s in &row.slots {
        let s = s as usize;
        let t = world.body_at(s).translation();
        let x = f64::from(along(row.axis, t.x, t.y));
        let w = f64::from(inverse_mass(world, s));
        if w == 0.0 {
            fixed += x;
            fixed_count += 1;
        } else {
            let v = world.body_at(s).linvel();
            let m = 1.0 / w;
            sum += m * x;
            speed += m * f64::from(along(row.axis, v.x, v.y));
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
    for &s in &row.slots {
        let s = s as usize;
        if inverse_mass(world, s) == 0.0 {
            continue;
        }
        let t = world.body_at(s).translation();
        let v = world.body_at(s).linvel();
        let by = (line - f64::from(along(row.axis, t.x, t.y))) as f32;
        let dv = (line_speed - f64::from(along(row.axis, v.x, v.y))) as f32;
        shift(world, s, row.axis, by, dv);
    }
}

impl Separation {
    /// How far its second body is short of the gap (0 or less when it holds).
    pub(crate) fn shortfall<N: Clone + Eq + Hash>(&self, world: &RapierSceneWorld<N>) -> f32 {
        let at = |s: u32| {
            let t = world.body_at(s as usize).translation();
            along(self.axis, t.x, t.y)
        };
        self.gap - (at(self.second) - at(self.first))
    }
}

impl Row {
    /// The distance between the row's two farthest bodies across its line.
    pub(crate) fn spread<N: Clone + Eq + Hash>(&self, world: &RapierSceneWorld<N>) -> f32 {
        let (mut low, mut high) = (f32::INFINITY, f32::NEG_INFINITY);
        for &s in &self.slots {
            let t = world.body_at(s as usize).translation();
            let x = along(self.axis, t.x, t.y);
            low = low.min(x);
            high = high.max(x);
        }
        (high - low).max(0.0)
    }
}
