//! The sweep after the passes (`passes.rs`): makes every separation hold where the
//! bodies allow, whatever the passes left. In order, a short separation's second body
//! moves on along the axis; then in reverse, its first body moves back. With the
//! separations in a topological order, each sweep carries a push through any chain at
//! once (a dragged node moves everything it pushes within the substep). Left short:
//! separations on a cycle (conflicting constraints), and those between bodies that do
//! not give way.
//!
//! Both orders run from the same start, one pushing on first and one back first, and
//! the bodies end halfway between the two: each is feasible where the constraints
//! allow, so halfway is too (separations are linear), and neither direction is
//! favoured. One order alone pushed a chain the forces squeeze the same way every
//! substep: a flow's picture drifted down, a layer sideways at 40,000 units a second
//! (`tests/regression_sweep_drift.rs`). Only the bodies a sweep moves are kept aside
//! and averaged: on a settled graph, none.

use super::local::{Link, Local};

/// The bodies a sweep moved, with what they held before it.
#[derive(Clone, Debug, Default)]
pub(super) struct SweepLog {
    /// Whether a sweep is running (moves are noted).
    on: bool,
    /// By local index, the sweep that last noted the body.
    stamp: Vec<u32>,
    sweep: u32,
    /// Each body moved: its local index, position and speed before the sweeps.
    before: Vec<(u32, [f32; 2], [f32; 2])>,
    /// Where the first sweep left each body it moved (the first entries of `before`).
    first: Vec<([f32; 2], [f32; 2])>,
}

impl SweepLog {
    /// Notes body `l` (at `point`, with `speed`) before a sweep first moves it.
    pub(super) fn note(&mut self, l: usize, point: [f32; 2], speed: [f32; 2]) {
        if self.on && self.stamp[l] != self.sweep {
            self.stamp[l] = self.sweep;
            self.before.push((l as u32, point, speed));
        }
    }

    /// Starts noting the moves of `n` bodies.
    fn start(&mut self, n: usize) {
        if self.stamp.len() != n || self.sweep == u32::MAX {
            self.stamp.clear();
            self.stamp.resize(n, 0);
            self.sweep = 0;
        }
        self.sweep += 1;
        self.before.clear();
        self.first.clear();
        self.on = true;
    }
}

impl Local {
    /// Makes every separation hold where the bodies allow: both sweeps, and halfway.
    pub(super) fn sweep(&mut self) {
        if self.links.is_empty() {
            return;
        }
        self.seed_watch();
        self.sweep_log.start(self.points.len());
        self.sweep_once(false);
        if self.sweep_log.before.is_empty() {
            self.sweep_log.on = false;
            self.keep_short();
            return;
        }
        // The first sweep's result aside, and its bodies back where they were.
        let mut log = std::mem::take(&mut self.sweep_log);
        for &(l, point, speed) in &log.before {
            let l = l as usize;
            log.first.push((self.points[l], self.speeds[l]));
            (self.points[l], self.speeds[l]) = (point, speed);
        }
        self.sweep_log = log;
        self.sweep_once(true);
        self.sweep_log.on = false;
        let log = &self.sweep_log;
        for (k, &(l, point, speed)) in log.before.iter().enumerate() {
            let l = l as usize;
            // A body only the second sweep moved: the first left it where it was.
            let (p, v) = log.first.get(k).copied().unwrap_or((point, speed));
            for axis in 0..2 {
                self.points[l][axis] = 0.5 * (self.points[l][axis] + p[axis]);
                self.speeds[l][axis] = 0.5 * (self.speeds[l][axis] + v[axis]);
            }
        }
        self.keep_short();
    }

    /// One sweep: on along the order then back, or back first.
    fn sweep_once(&mut self, back_first: bool) {
        let count = self.links.len();
        for turn in [back_first, !back_first] {
            // The candidates (`watch.rs`; every separation in a full sweep), read again
            // after each push, which may add some ahead.
            if turn {
                let mut k = count;
                while let Some(j) = self.watch.last_before(k) {
                    let c = self.links[j];
                    self.push(c, c.a as usize, -1.0);
                    k = j;
                }
            } else {
                let mut k = 0;
                while let Some(j) = self.watch.next_from(k, count) {
                    let c = self.links[j];
                    self.push(c, c.b as usize, 1.0);
                    k = j + 1;
                }
            }
        }
    }

    /// Moves local body `l` of separation `c` by its shortfall, `sign` along the axis.
    /// The speed that closes the two goes as in a pass, in inverse proportion to their
    /// masses: given all to the body moved, a sweep one way gave a chain momentum it
    /// never had.
    fn push(&mut self, c: Link, l: usize, sign: f32) {
        let short = self.shortfall(&c);
        // A shortfall that is not a number (a body off the finite range) moves nothing.
        if short.is_nan() || short <= 0.0 || self.inverse_mass[l][c.axis] == 0.0 {
            return;
        }
        self.shift(l, c.axis, sign * short, 0.0);
        self.watch_body(l);
        let (a, b) = (c.a as usize, c.b as usize);
        let (wa, wb) = (self.inverse_mass[a][c.axis], self.inverse_mass[b][c.axis]);
        let closing = (self.speeds[a][c.axis] - self.speeds[b][c.axis]).max(0.0);
        if closing > 0.0 {
            self.shift(a, c.axis, 0.0, -closing * wa / (wa + wb));
            self.shift(b, c.axis, 0.0, closing * wb / (wa + wb));
        }
    }
}
