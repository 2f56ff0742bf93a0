//! The projection's passes on the constrained bodies' arrays (`local.rs`):
//! Gauss–Seidel passes over the separations a hot body is in, the rows on their lines;
//! and how far the worst is from holding. The sweep that follows is in `sweep.rs`.

use super::local::{Link, Local};
use super::watch::{next_set, set, MOSTLY};

impl Local {
    /// The separations with a hot end, in order (those a pass visits), found through
    /// each hot body's separations on `bits` (kept between calls).
    pub(super) fn active_links(&self, active: &mut Vec<u32>, bits: &mut Vec<u64>) {
        active.clear();
        if self.hot_list.len() * MOSTLY > self.points_count() {
            active.extend((0..self.links.len() as u32).filter(|&k| {
                let c = self.links[k as usize];
                self.is_hot(c.a) || self.is_hot(c.b)
            }));
            return;
        }
        bits.clear();
        bits.resize(self.links.len().div_ceil(64), 0);
        for &l in &self.hot_list {
            for &k in self.links_of(l as usize) {
                set(bits, k);
            }
        }
        let mut k = 0;
        while let Some(j) = next_set(bits, k) {
            active.push(j as u32);
            k = j + 1;
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

    /// One Gauss–Seidel pass over the separations `active` lists, in order or in
    /// reverse (passes alternate: the separations are in a topological order, so one
    /// direction carries a push down a chain and the other up), then every row. A
    /// separation between two sleeping bodies held at the last projection's end, and
    /// the sweep sees to it if not.
    pub(super) fn pass(&mut self, active: &[u32], reverse: bool) {
        for k in 0..active.len() {
            let k = if reverse { active.len() - 1 - k } else { k };
            self.separate(self.links[active[k] as usize]);
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

    pub(super) fn shortfall(&self, c: &Link) -> f32 {
        c.gap - (self.points[c.b as usize][c.axis] - self.points[c.a as usize][c.axis])
    }

    /// Moves local body `l` by `by` along `axis` and adds `dv` to its speed along it,
    /// unless either would stop being finite.
    pub(super) fn shift(&mut self, l: usize, axis: usize, by: f32, dv: f32) {
        let (p, v) = (self.points[l][axis] + by, self.speeds[l][axis] + dv);
        if p.is_finite() && v.is_finite() && (by != 0.0 || dv != 0.0) {
            self.sweep_log.note(l, self.points[l], self.speeds[l]);
            self.points[l][axis] = p;
            self.speeds[l][axis] = v;
            self.heat(l);
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
