//! Parting one level: the items nested directly in one cluster (or at the top level),
//! which are its nested clusters' boxes and its own members' outlines. Two items that
//! overlap, one of them a box, move apart along the axis they overlap least, in inverse
//! proportion to the bodies each moves; a box moves whole, with everything in it. An
//! item that does not give way leaves the whole move to the other. While the layout
//! moves, two sibling boxes meet at a wall instead (`walls.rs`). Two members' outlines
//! are the contacts' business, not this.

use super::boxes::{overlap, union, Bodies, Bounds, Boxes, EMPTY};
use super::tree::Tree;
use crate::graph::Lists;

/// One item of a level: a cluster's box or a body's outline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Item {
    Cluster(u32),
    Body(u32),
}

/// What a parting moves, by slot.
#[derive(Clone, Debug, Default)]
pub(super) struct Moves {
    /// By slot, per axis: whether a parting moved the body along it (its box's partings
    /// may have cancelled out).
    pub(super) pushed: Vec<[bool; 2]>,
    /// The slots moved, each once.
    pub(super) list: Vec<u32>,
    /// By cluster: how far its box moved in the level being parted, which its members
    /// have still to follow.
    offset: Vec<[f32; 2]>,
    /// By cluster, per axis: whether its box was parted along it in that level.
    parted: Vec<[bool; 2]>,
    /// By body (slot), then by cluster: whether a fixed or driven item pushed it this
    /// call.
    driven: Vec<bool>,
}

impl Moves {
    /// Starts over for `slots` bodies and `clusters` clusters.
    pub(super) fn clear(&mut self, slots: usize, clusters: usize) {
        for &s in &self.list {
            self.pushed[s as usize] = [false; 2];
        }
        self.list.clear();
        self.pushed.resize(slots, [false; 2]);
        self.offset.clear();
        self.offset.resize(clusters, [0.0; 2]);
        self.parted.clear();
        self.parted.resize(clusters, [false; 2]);
        self.driven.clear();
        self.driven.resize(slots + clusters, false);
    }

    /// Notes that a fixed or driven item pushed `item` this call.
    fn drive(&mut self, item: Item) {
        let k = self.driven_index(item);
        self.driven[k] = true;
    }

    /// Whether a fixed or driven item pushed `item` this call.
    fn is_driven(&self, item: Item) -> bool {
        self.driven[self.driven_index(item)]
    }

    /// Bodies by slot, then clusters.
    fn driven_index(&self, item: Item) -> usize {
        match item {
            Item::Body(s) => s as usize,
            Item::Cluster(c) => self.pushed.len() + c as usize,
        }
    }

    /// Moves body `s` by `by`, noting that it was parted along the axes of `parted`.
    pub(super) fn body(&mut self, bodies: &mut Bodies, s: usize, by: [f32; 2], parted: [bool; 2]) {
        if self.pushed[s] == [false; 2] {
            self.list.push(s as u32);
        }
        for axis in (0..2).filter(|&axis| parted[axis]) {
            bodies.points[s][axis] += by[axis];
            self.pushed[s][axis] = true;
        }
    }
}

/// A level's boxes, and a coarse grid of them for finding the outlines they overlap.
#[derive(Clone, Debug, Default)]
pub(super) struct Level {
    clusters: Vec<u32>,
    /// The grid: its corner, cell side and columns, and each cell's boxes.
    origin: [f32; 2],
    cell: f32,
    columns: usize,
    rows: usize,
    cells: Lists,
    /// By cluster: the last body that was checked against it (no box twice a body).
    seen: Vec<u32>,
}

/// The most sibling boxes that meet at walls while the layout moves; more move whole.
/// Among 100 clusters of 100 the walls held the boxes, but the clusters' edges pressed
/// them against the walls until their disks piled up (32,441 pairs overlapping at frame
/// 60, 484 left at rest); 60 clusters of 50 rested with none.
const WALLS_UP_TO: usize = 64;

/// The most cells along a side of the grid.
const MOST_CELLS: usize = 256;

impl Level {
    /// Parts the level of `clusters` (boxes) and `bodies_here` (outlines), with
    /// `boxes` made for it. Returns how far the parting moved anything, at most.
    pub(super) fn part(
        &mut self,
        clusters: &[u32],
        bodies_here: impl Iterator<Item = u32>,
        ctx: &mut Ctx<'_>,
    ) -> f32 {
        let mut moved = 0.0_f32;
        // Box against box, by turns in list order: while the layout moves, at a wall
        // between them (`walls.rs`); at the start and the cold stop, for a check, and
        // among more than `WALLS_UP_TO` siblings, whole.
        let walled = ctx.walls() && clusters.len() <= WALLS_UP_TO;
        for (k, &a) in clusters.iter().enumerate() {
            for &b in &clusters[k + 1..] {
                let (a, b) = (Item::Cluster(a), Item::Cluster(b));
                // A box a pinned or dragged node holds, or one such a box pushed, moves
                // those in its way whole, a chain of them at once.
                let by = if walled && !ctx.held(a) && !ctx.held(b) {
                    super::walls::wall(ctx, a, b)
                } else {
                    ctx.part(a, b)
                };
                moved = moved.max(by);
            }
        }
        self.index(clusters, ctx.boxes);
        // No box to meet (columns 0): the bodies have nothing to part from.
        if self.columns > 0 {
            for s in bodies_here {
                let outline = ctx.bodies.outline(s as usize);
                let [lo, hi] = [outline[0], outline[1]].map(|p| self.cell_of(p));
                for row in lo[1]..=hi[1] {
                    for column in lo[0]..=hi[0] {
                        let cell = row * self.columns + column;
                        for &c in self.cells.of(cell) {
                            if std::mem::replace(&mut self.seen[c as usize], s) != s {
                                let by = ctx.part(Item::Cluster(c), Item::Body(s));
                                moved = moved.max(by);
                            }
                        }
                    }
                }
            }
        }
        ctx.carry(clusters);
        moved
    }

    /// The grid cell (column, row) of point `p`, clamped to the grid.
    fn cell_of(&self, p: [f32; 2]) -> [usize; 2] {
        let at = |k: usize, most: usize| {
            let t = ((p[k] - self.origin[k]) / self.cell).floor();
            if t.is_nan() || t < 0.0 {
                0
            } else {
                (t as usize).min(most - 1)
            }
        };
        [at(0, self.columns), at(1, self.rows)]
    }

    /// Files the boxes of `clusters` in a grid of about one cell per box.
    fn index(&mut self, clusters: &[u32], boxes: &Boxes) {
        self.clusters.clear();
        self.clusters.extend(
            clusters
                .iter()
                .copied()
                .filter(|&c| !super::boxes::is_empty(boxes.bounds[c as usize])),
        );
        self.columns = 0;
        let all = self
            .clusters
            .iter()
            .fold(EMPTY, |u, &c| union(u, boxes.bounds[c as usize]));
        if self.clusters.is_empty() || !(all[1][0] - all[0][0]).is_finite() {
            return;
        }
        let side = [all[1][0] - all[0][0], all[1][1] - all[0][1]];
        let per_box = (side[0] * side[1] / self.clusters.len() as f32).sqrt();
        let most = side[0].max(side[1]) / MOST_CELLS as f32;
        self.cell = per_box.max(most).max(f32::MIN_POSITIVE);
        self.origin = all[0];
        let count = |s: f32| ((s / self.cell).ceil() as usize).clamp(1, MOST_CELLS);
        (self.columns, self.rows) = (count(side[0]), count(side[1]));
        let mut filed: Vec<(u32, u32)> = Vec::new();
        for &c in &self.clusters {
            let b = boxes.bounds[c as usize];
            let [lo, hi] = [b[0], b[1]].map(|p| self.cell_of(p));
            for row in lo[1]..=hi[1] {
                for column in lo[0]..=hi[0] {
                    filed.push(((row * self.columns + column) as u32, c));
                }
            }
        }
        self.cells = Lists::from_pairs(self.columns * self.rows, &filed);
        self.seen.clear();
        self.seen.resize(boxes.bounds.len(), u32::MAX);
    }
}

/// What a parting reads and moves.
pub(super) struct Ctx<'a> {
    pub(super) tree: &'a Tree,
    pub(super) bodies: &'a mut Bodies,
    pub(super) boxes: &'a mut Boxes,
    pub(super) moves: &'a mut Moves,
    /// The farthest a parting moves two free items apart that nothing drives. Boxes
    /// held apart against the stress's pull, parted whole at once, swung the bodies into
    /// each other faster than the speed cap, and the contacts' search along their paths
    /// took most of a 10,000-node frame; a step at a time, they part over a few frames
    /// and the cold stop parts the rest whole.
    pub(super) most: f32,
    /// A check instead of a parting: by cluster, set when its box overlaps an item of
    /// its level by more than [`UNHELD`]; nothing moves.
    pub(super) unheld: Option<&'a mut [bool]>,
}

/// How deep an overlap a check notes as a cluster not held (world units): the unit the
/// layout's other reports allow.
pub(super) const UNHELD: f32 = 1.0;

impl Ctx<'_> {
    /// The box of `item` as it stands.
    pub(super) fn bounds(&self, item: Item) -> Bounds {
        match item {
            Item::Cluster(c) => self.boxes.bounds[c as usize],
            Item::Body(s) => self.bodies.outline(s as usize),
        }
    }

    /// How much `item` gives way along `axis` (0: not at all).
    pub(super) fn give(&self, item: Item, axis: usize) -> f32 {
        match item {
            Item::Cluster(c) => self.boxes.give(c as usize, axis),
            Item::Body(s) => f32::from(u8::from(self.bodies.free[s as usize][axis])),
        }
    }

    /// Whether sibling boxes meet at walls (`walls.rs`) rather than move whole: while
    /// the layout moves, where a parting goes a step at a time; at the start and the
    /// cold stop (whole partings) and in a check they do not.
    pub(super) fn walls(&self) -> bool {
        self.most.is_finite() && self.unheld.is_none()
    }

    /// Whether `item` does not give way along an axis, or something that does not
    /// pushed it this call.
    pub(super) fn held(&self, item: Item) -> bool {
        self.moves.is_driven(item) || self.give(item, 0) == 0.0 || self.give(item, 1) == 0.0
    }

    /// How `a` and `b`, overlapping by `o`, part: along the axis they overlap least,
    /// unless neither gives way along it (an axis lock), then the other; and `b` the way
    /// its centre lies from `a`'s along it (1 forward, -1 back; ties: forward). `None`
    /// when neither gives way along either axis.
    pub(super) fn parting(&self, a: Item, b: Item, o: [f32; 2]) -> Option<(usize, f32)> {
        let gives = |k: usize| self.give(a, k) + self.give(b, k) > 0.0;
        let axis = match (gives(0), gives(1)) {
            (true, true) => usize::from(o[1] < o[0]),
            (true, false) => 0,
            (false, true) => 1,
            (false, false) => return None,
        };
        let centre = |x: Bounds| x[0][axis] + x[1][axis];
        let forward = centre(self.bounds(b)) >= centre(self.bounds(a));
        Some((axis, if forward { 1.0 } else { -1.0 }))
    }

    /// Parts `a` and `b` if they overlap; returns how far either moved.
    fn part(&mut self, a: Item, b: Item) -> f32 {
        let (ba, bb) = (self.bounds(a), self.bounds(b));
        let o = overlap(ba, bb);
        if !(o[0] > 0.0 && o[1] > 0.0) {
            return 0.0;
        }
        if let Some(unheld) = self.unheld.as_deref_mut() {
            if o[0].min(o[1]) > UNHELD {
                for item in [a, b] {
                    if let Item::Cluster(c) = item {
                        unheld[c as usize] = true;
                    }
                }
            }
            return 0.0;
        }
        let Some((axis, sign)) = self.parting(a, b, o) else {
            return 0.0;
        };
        // `b` goes the way its centre lies from `a`'s, by the overlap.
        let way = o[axis];
        let (mut ga, mut gb) = (self.give(a, axis), self.give(b, axis));
        // An item a fixed one pushed this call passes the push on whole, as if fixed:
        // a dragged box moves a chain of boxes ahead of it. Only two free items that
        // nothing drives part a step at a time (see `Ctx::most`).
        let driven = (self.moves.is_driven(a), self.moves.is_driven(b));
        match driven {
            (true, false) if gb > 0.0 => ga = 0.0,
            (false, true) if ga > 0.0 => gb = 0.0,
            _ => {}
        }
        let stepwise = ga > 0.0 && gb > 0.0 && driven == (false, false);
        let depth = if stepwise { way.min(self.most) } else { way };
        let (da, db) = (depth * ga / (ga + gb), depth * gb / (ga + gb));
        self.shift(a, axis, -sign * da);
        self.shift(b, axis, sign * db);
        if ga == 0.0 {
            self.moves.drive(b);
        } else if gb == 0.0 {
            self.moves.drive(a);
        }
        da.max(db)
    }

    /// Moves `item` by `by` along `axis`: a body at once, a box now and what is in it
    /// when the level is done ([`Ctx::carry`]: its members are no items of the level).
    pub(super) fn shift(&mut self, item: Item, axis: usize, by: f32) {
        if by == 0.0 || !by.is_finite() {
            return;
        }
        match item {
            Item::Body(s) => {
                let (mut by_axis, mut parted) = ([0.0; 2], [false; 2]);
                (by_axis[axis], parted[axis]) = (by, true);
                self.moves.body(self.bodies, s as usize, by_axis, parted);
            }
            Item::Cluster(c) => {
                self.moves.offset[c as usize][axis] += by;
                self.moves.parted[c as usize][axis] = true;
                let b = &mut self.boxes.bounds[c as usize];
                b[0][axis] += by;
                b[1][axis] += by;
            }
        }
    }

    /// Moves what is in each of `clusters` by what its box moved, and stops it along
    /// every axis its box was parted on (even where the partings cancelled out).
    fn carry(&mut self, clusters: &[u32]) {
        for &c in clusters {
            let c = c as usize;
            let by = std::mem::take(&mut self.moves.offset[c]);
            let parted = std::mem::take(&mut self.moves.parted[c]);
            if parted != [false; 2] {
                let (bodies, moves) = (&mut *self.bodies, &mut *self.moves);
                self.tree
                    .for_each_slot(c, |s| moves.body(bodies, s, by, parted));
            }
        }
    }
}
