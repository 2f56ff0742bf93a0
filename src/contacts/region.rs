//! Where contacts can happen this substep when few bodies move: a drag or an edit on a
//! large layout at rest wakes a few dozen bodies among 100,000 asleep, and two bodies
//! that both stay where they are need no contact. The separation then takes only the
//! bodies whose bounding boxes reach a moving body's swept bounding box, instead of
//! sorting and searching every body of the world each substep.
//!
//! The moving bodies' boxes are marked on a coarse grid over the box around them all
//! ([`HotCells`]), and a body is in the region when its bounding box reaches a marked
//! cell: a few dozen moving bodies scattered over a layout hold only the bodies near
//! them, where the one box around them all held a large share of the layout
//! (`docs/performance.md` gives the counts).

use euclid::default::{Point2D, Vector2D};

use super::Collide;

/// Below this many bodies every body is taken: a full grid costs little there
/// (`docs/performance.md` gives the time).
const REGION_AT_LEAST: usize = 10_000;
/// The region is used while at most one body in this many moves: under one in ten, the
/// motion the grid's cells allow (that of nine bodies in ten) is none, so the full
/// search keeps no pair beyond a moving body's path and reach.
const MOVING_SHARE: usize = 16;
/// The coarse grid's cells along the longer side of the box around the moving bodies.
const HOT_SIDE: usize = 128;

/// The cells of a coarse grid that a moving body's swept box reaches, as a summed-area
/// table: whether a box reaches a marked cell is four reads, however many cells it spans.
#[derive(Debug, Default)]
pub(super) struct HotCells {
    /// The grid's top-left corner and its cells' side.
    origin: Point2D<f32>,
    cell: f32,
    /// How many cells across and down.
    columns: usize,
    rows: usize,
    /// First the marks' corners (a difference table), then how many marked cells lie
    /// above and left of each corner, `(columns + 1) × (rows + 1)`.
    sums: Vec<i32>,
}

impl HotCells {
    /// An empty grid over the box `lo`–`hi`.
    fn reset(&mut self, lo: Point2D<f32>, hi: Point2D<f32>) {
        let extent = hi - lo;
        self.origin = lo;
        self.cell = (extent.x.max(extent.y) / HOT_SIDE as f32).max(f32::MIN_POSITIVE);
        let count = |length: f32| ((length / self.cell) as usize).min(HOT_SIDE - 1) + 1;
        (self.columns, self.rows) = (count(extent.x), count(extent.y));
        self.sums.clear();
        self.sums.resize((self.columns + 1) * (self.rows + 1), 0);
    }

    /// The cells a box spans, as inclusive column and row ranges, clamped to the grid.
    /// The cell of a coordinate grows with it, so two boxes that meet share a cell.
    fn span(&self, lo: Point2D<f32>, hi: Point2D<f32>) -> (usize, usize, usize, usize) {
        let at = |v: f32, origin: f32, last: usize| {
            (((v - origin) / self.cell).max(0.0) as usize).min(last)
        };
        (
            at(lo.x, self.origin.x, self.columns - 1),
            at(hi.x, self.origin.x, self.columns - 1),
            at(lo.y, self.origin.y, self.rows - 1),
            at(hi.y, self.origin.y, self.rows - 1),
        )
    }

    /// Marks the cells the box `lo`–`hi` spans (before [`finish`](Self::finish)).
    fn mark(&mut self, lo: Point2D<f32>, hi: Point2D<f32>) {
        let (x0, x1, y0, y1) = self.span(lo, hi);
        let w = self.columns + 1;
        self.sums[y0 * w + x0] += 1;
        self.sums[y0 * w + x1 + 1] -= 1;
        self.sums[(y1 + 1) * w + x0] -= 1;
        self.sums[(y1 + 1) * w + x1 + 1] += 1;
    }

    /// Turns the marks into the summed-area table of the marked cells.
    fn finish(&mut self) {
        let (w, h) = (self.columns + 1, self.rows + 1);
        // How many marks cover each cell (the difference table summed)...
        for pass in 0..2 {
            for y in 0..h {
                for x in 0..w {
                    let i = y * w + x;
                    let (left, up) = (
                        if x > 0 { self.sums[i - 1] } else { 0 },
                        if y > 0 { self.sums[i - w] } else { 0 },
                    );
                    let diagonal = if x > 0 && y > 0 {
                        self.sums[i - w - 1]
                    } else {
                        0
                    };
                    self.sums[i] += left + up - diagonal;
                }
            }
            if pass == 0 {
                // ...then 1 for a marked cell, summed again, shifted a row and a column
                // so that entry (x, y) counts the marked cells above and left of it.
                for y in (0..h).rev() {
                    for x in (0..w).rev() {
                        let marked = x > 0 && y > 0 && self.sums[(y - 1) * w + x - 1] > 0;
                        self.sums[y * w + x] = i32::from(marked);
                    }
                }
            }
        }
    }

    /// Whether the box `lo`–`hi` reaches a marked cell.
    fn reaches(&self, lo: Point2D<f32>, hi: Point2D<f32>) -> bool {
        let (x0, x1, y0, y1) = self.span(lo, hi);
        let w = self.columns + 1;
        let at = |x: usize, y: usize| self.sums[y * w + x];
        at(x1 + 1, y1 + 1) - at(x0, y1 + 1) - at(x1 + 1, y0) + at(x0, y0) > 0
    }
}

impl Collide {
    /// Marks in `self.region` (by slot) the bodies the separation takes this substep, or
    /// leaves it empty for all of them: with at least [`REGION_AT_LEAST`] bodies of
    /// which at most one in [`MOVING_SHARE`] moves (gives way or is driven), those whose
    /// bounding box reaches a cell of [`HotCells`] that a moving body's swept bounding
    /// box (widened by its motion) reaches.
    /// Two bodies outside it cannot touch a moving one, and two still bodies need no
    /// contact.
    pub(super) fn mark_region(&mut self, points: &[Point2D<f32>]) {
        self.region.clear();
        let by = &self.by_slot;
        let n = points.len();
        if n < REGION_AT_LEAST || by.half.len() < n {
            return;
        }
        // The moving bodies (`prepare` lists them): too many, and the region would hold
        // most bodies anyway.
        if self.moving.len() * MOVING_SHARE > n {
            return;
        }
        // The swept bounding box, widened by the motion's length: the full search keeps
        // a pair within the bodies' reach and their relative motion.
        let swept = |s: usize| {
            let (p, motion) = (points[s], by.motion[s]);
            let pad = by.half[s] + Vector2D::new(motion.length(), motion.length());
            let to = p + motion;
            (p.min(to) - pad, p.max(to) + pad)
        };
        let (mut lo, mut hi) = (
            Point2D::new(f32::INFINITY, f32::INFINITY),
            Point2D::new(f32::NEG_INFINITY, f32::NEG_INFINITY),
        );
        for &s in &self.moving {
            let (from, to) = swept(s as usize);
            lo = lo.min(from);
            hi = hi.max(to);
        }
        if !(lo.is_finite() && hi.is_finite()) {
            // Nothing moves: nothing to separate but overlaps among still bodies.
            return;
        }
        self.hot.reset(lo, hi);
        for &s in &self.moving {
            let (from, to) = swept(s as usize);
            self.hot.mark(from, to);
        }
        self.hot.finish();
        let hot = &self.hot;
        self.region
            .extend(points.iter().zip(&by.half).map(|(&p, &half)| {
                let (from, to) = (p - half, p + half);
                to.x >= lo.x
                    && from.x <= hi.x
                    && to.y >= lo.y
                    && from.y <= hi.y
                    && hot.reaches(from, to)
            }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two boxes marked on a grid over 0–1280: a box that meets either reaches a marked
    /// cell, edge to edge included; one a cell and more away from both does not.
    #[test]
    fn a_box_reaches_the_cells_a_marked_box_spans() {
        let p = |x: f32, y: f32| Point2D::new(x, y);
        let mut hot = HotCells::default();
        hot.reset(p(0.0, 0.0), p(1280.0, 640.0));
        hot.mark(p(100.0, 100.0), p(130.0, 120.0));
        hot.mark(p(1200.0, 600.0), p(1280.0, 640.0));
        hot.finish();
        let cases = [
            ((p(130.0, 120.0), p(140.0, 130.0)), true),
            ((p(0.0, 0.0), p(1280.0, 640.0)), true),
            ((p(1250.0, 630.0), p(1300.0, 700.0)), true),
            ((p(-50.0, -50.0), p(-10.0, -10.0)), false),
            ((p(200.0, 100.0), p(400.0, 500.0)), false),
            ((p(100.0, 140.0), p(130.0, 150.0)), false),
        ];
        for ((lo, hi), expected) in cases {
            assert_eq!(
                hot.reaches(lo, hi),
                expected,
                "the box {lo:?}–{hi:?} (cells of {} units)",
                hot.cell
            );
        }
    }

    /// 12,100 still disks on a square lattice, a few moving through them, two of them in
    /// opposite corners: the pairs with a moving body are the same whether every body is
    /// searched or only the region, which holds under one body in fifty (the box around
    /// the moving ones spans the whole lattice; the cells they reach do not).
    #[test]
    fn the_region_keeps_every_pair_of_a_moving_body() {
        let side = 110;
        let points: Vec<Point2D<f32>> = (0..side * side)
            .map(|i| Point2D::new((i % side) as f32 * 30.0, (i / side) as f32 * 30.0))
            .collect();
        let moving = [0_usize, 5_000, 5_001, 5_110, 7_777, 12_099];
        let pairs_with_moving = |region: bool| {
            let mut collide = Collide::default();
            for s in 0..points.len() {
                let by = &mut collide.by_slot;
                by.radius.push(16.0);
                by.half.push(Vector2D::new(16.0, 16.0));
                by.inner.push(Vector2D::zero());
                by.round.push(16.0);
                let moves = moving.contains(&s);
                by.inverse_mass.push(if moves { 1.0 } else { 0.0 });
                by.velocity.push(Vector2D::zero());
                by.motion.push(if moves {
                    Vector2D::new(7.0, -4.0)
                } else {
                    Vector2D::zero()
                });
                by.sleeping.push(!moves);
                if moves {
                    collide.moving.push(s as u32);
                }
            }
            if region {
                collide.mark_region(&points);
                assert!(!collide.region.is_empty(), "the region is in use");
            }
            collide.take_in_grid_order(&points);
            collide.find_pairs(0.0);
            let order = &collide.order;
            let mut found: Vec<(u32, u32)> = collide
                .pairs
                .iter()
                .map(|p| {
                    let (a, b) = (order[p.a as usize], order[p.b as usize]);
                    (a.min(b), a.max(b))
                })
                .filter(|&(a, b)| moving.contains(&(a as usize)) || moving.contains(&(b as usize)))
                .collect();
            found.sort_unstable();
            (found, collide.order.len())
        };
        let (all, searched_all) = pairs_with_moving(false);
        let (near, searched_near) = pairs_with_moving(true);
        assert!(
            all == near && !all.is_empty(),
            "{} pairs with a moving body over every body, {} over the region",
            all.len(),
            near.len()
        );
        assert!(
            searched_near * 50 < searched_all,
            "the region holds {searched_near} of {searched_all} bodies"
        );
    }
}
