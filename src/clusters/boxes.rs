//! The clusters' boxes, made from the inside out: a cluster's box holds its own
//! members' outlines and its nested clusters' boxes, grown by its padding. Beside each
//! box: how many bodies move with it and, per axis, whether one of them does not give
//! way (a pinned or dragged node, a locked axis), which makes the whole box hold still.

use super::tree::Tree;

/// An axis-aligned box as `[min, max]` corners; empty while min > max.
pub(super) type Bounds = [[f32; 2]; 2];

/// A box holding nothing.
pub(super) const EMPTY: Bounds = [[f32::INFINITY; 2], [f32::NEG_INFINITY; 2]];

/// The bodies the boxes are made of, by slot.
#[derive(Clone, Debug, Default)]
pub(super) struct Bodies {
    /// Centre of each body.
    pub(super) points: Vec<[f32; 2]>,
    /// Half width and half height of each body's outline.
    pub(super) half: Vec<[f32; 2]>,
    /// Per axis, whether the body gives way along it.
    pub(super) free: Vec<[bool; 2]>,
}

impl Bodies {
    /// The mean of the bodies' half widths and half heights (1 without bodies).
    pub(super) fn mean_half(&self) -> f32 {
        if self.half.is_empty() {
            return 1.0;
        }
        let sum: f64 = self.half.iter().map(|h| f64::from(h[0] + h[1])).sum();
        (sum / (2 * self.half.len()) as f64) as f32
    }

    /// The outline of the body in `slot`.
    pub(super) fn outline(&self, slot: usize) -> Bounds {
        let (p, h) = (self.points[slot], self.half[slot]);
        [[p[0] - h[0], p[1] - h[1]], [p[0] + h[0], p[1] + h[1]]]
    }
}

/// Each cluster's box, with what moves it.
#[derive(Clone, Debug, Default)]
pub(super) struct Boxes {
    /// By cluster: its box (empty for a cluster left out or without members).
    pub(super) bounds: Vec<Bounds>,
    /// By cluster: how many bodies it holds, nested clusters' included.
    pub(super) count: Vec<u32>,
    /// By cluster, per axis: whether a body it holds does not give way.
    pub(super) fixed: Vec<[bool; 2]>,
}

impl Boxes {
    /// Makes every held cluster's box from `bodies`, from the inside out.
    pub(super) fn make(&mut self, tree: &Tree, bodies: &Bodies) {
        let n = tree.held.len();
        self.bounds.clear();
        self.bounds.resize(n, EMPTY);
        self.count.clear();
        self.count.resize(n, 0);
        self.fixed.clear();
        self.fixed.resize(n, [false; 2]);
        for &c in &tree.inside_out {
            let c = c as usize;
            let (mut b, mut count, mut fixed) = (EMPTY, 0, [false; 2]);
            for &s in tree.own.of(c) {
                b = union(b, bodies.outline(s as usize));
                count += 1;
                let free = bodies.free[s as usize];
                fixed = [fixed[0] || !free[0], fixed[1] || !free[1]];
            }
            for &k in tree.children.of(c) {
                let k = k as usize;
                b = union(b, self.bounds[k]);
                count += self.count[k];
                fixed = [fixed[0] || self.fixed[k][0], fixed[1] || self.fixed[k][1]];
            }
            self.bounds[c] = grow(b, tree.padding[c]);
            self.count[c] = count;
            self.fixed[c] = fixed;
        }
    }

    /// How readily cluster `c` moves along `axis`: the inverse of the bodies it moves,
    /// 0 when one of them does not give way.
    pub(super) fn give(&self, c: usize, axis: usize) -> f32 {
        if self.fixed[c][axis] || self.count[c] == 0 {
            0.0
        } else {
            1.0 / self.count[c] as f32
        }
    }
}

/// The smallest box holding `a` and `b`.
pub(super) fn union(a: Bounds, b: Bounds) -> Bounds {
    [
        [a[0][0].min(b[0][0]), a[0][1].min(b[0][1])],
        [a[1][0].max(b[1][0]), a[1][1].max(b[1][1])],
    ]
}

/// `b` grown by `by` on every side (an empty box stays empty).
fn grow(b: Bounds, by: f32) -> Bounds {
    if is_empty(b) {
        return b;
    }
    [[b[0][0] - by, b[0][1] - by], [b[1][0] + by, b[1][1] + by]]
}

/// Whether `b` holds nothing.
pub(super) fn is_empty(b: Bounds) -> bool {
    !(b[0][0] <= b[1][0] && b[0][1] <= b[1][1])
}

/// How far `a` and `b` overlap along each axis (both positive when they overlap).
pub(super) fn overlap(a: Bounds, b: Bounds) -> [f32; 2] {
    [0, 1].map(|k| a[1][k].min(b[1][k]) - a[0][k].max(b[0][k]))
}
