//! Finding the pairs of disks that may touch during a substep: a uniform grid, its cells
//! sorted by key, searched in the same and the neighbouring cells (and along the path of
//! a body that moves further than a cell allows). The grid's order of the bodies is the
//! order the separation works in (`pairs.rs`), so neighbours sit close in memory. The
//! separation itself is in `mod.rs` and `passes.rs`.

use euclid::default::{Point2D, Vector2D};

use super::pairs::{PAIRS_AT_LEAST, PAIRS_PER_BODY};
use crate::parallel;
use crate::sort::counting_sort;

/// A cell's key: row in the high half, column in the low half, both offset to be
/// non-negative, so keys sort row by row.
fn key(x: i64, y: i64) -> u64 {
    (((y + (1 << 31)) as u64) << 32) | ((x + (1 << 31)) as u64)
}

/// Fast bodies a run of the search along their paths takes (fixed, so the pairs found do
/// not depend on the thread count).
const FAST_RUN: usize = 128;
/// Bodies a run of the per-body maps of [`Grid::sort`] takes (side by side under
/// `parallel`; each body's value its own).
const MAP_RUN: usize = 2_048;

/// The most pairs a run of `bodies` fast bodies holds before it stops and is searched
/// again in order: what the pair search allows its bodies (`pairs.rs`), so the runs
/// side by side take no more memory than the search in order may.
fn run_bound(bodies: usize) -> usize {
    PAIRS_PER_BODY * bodies + PAIRS_AT_LEAST
}
/// Which motion a cell allows, as a share of the bodies: the rest search along their path.
const USUAL_SHARE: f64 = 0.9;

/// The grid over one substep's bodies.
#[derive(Debug, Default)]
pub(super) struct Grid {
    /// `(cell key, slot)` of every body with a finite position, sorted: the grid order.
    cells: Vec<(u64, u32)>,
    /// The width and height of a cell, the motion a cell allows and the largest half
    /// width and half height of a body's bounding box.
    cell: Vector2D<f32>,
    usual: f32,
    largest: Vector2D<f32>,
    /// Scratch for the motions' quantile.
    lengths: Vec<f32>,
    /// The fast bodies' swept boxes `(left, right, top, bottom, body)`.
    swept: Vec<(f32, f32, f32, f32, u32)>,
    /// The same, sorted by their left edge.
    by_left: Vec<(f32, f32, f32, f32, u32)>,
    /// Scratch for the sort of the cells.
    scratch: Vec<(u64, u32)>,
    /// After a sort by counting, where each row's bodies end in `cells` (from the row
    /// `top_row`): the rows' index, which spares a search along a path a search of all
    /// the cells for each row it crosses.
    counts: Vec<u32>,
    top_row: Option<i64>,
}

/// Sorts `cells` (`(key, slot)`, in slot order) by key, then slot. Where the grid's
/// rows and columns number no more than a few times the bodies (a layout, not a
/// scatter across the canvas), by two counting sorts, by column and then by row, each
/// keeping the order it finds (so the slots stay ascending within a cell): linear in
/// the bodies, where a comparison sort's O(n log n) was a visible share of the
/// contacts' time (`docs/performance.md` gives it); returns the top row then (and
/// `counts` holds where each row's bodies end). Otherwise by a comparison sort. Both
/// give the one order there is.
fn sort_cells(
    cells: &mut Vec<(u64, u32)>,
    scratch: &mut Vec<(u64, u32)>,
    counts: &mut Vec<u32>,
) -> Option<i64> {
    let &(first, _) = cells.first()?;
    let (row0, column0) = row_and_column(first);
    let ((mut top, mut bottom), (mut left, mut right)) = ((row0, row0), (column0, column0));
    for &(k, _) in cells.iter() {
        let (row, column) = row_and_column(k);
        (top, bottom) = (top.min(row), bottom.max(row));
        (left, right) = (left.min(column), right.max(column));
    }
    let (rows, columns) = ((bottom - top + 1) as u64, (right - left + 1) as u64);
    if rows + columns > 4 * cells.len() as u64 + 1_024 {
        parallel::sort_unstable(cells);
        return None;
    }
    let by_column = |k: u64| (row_and_column(k).1 - left) as usize;
    let by_row = |k: u64| (row_and_column(k).0 - top) as usize;
    counting_sort(cells, scratch, counts, columns as usize, by_column);
    counting_sort(scratch, cells, counts, rows as usize, by_row);
    Some(top)
}

impl Grid {
    /// Sorts the bodies (by slot) into the grid's cells and returns their slots in the
    /// grid's order (cell by cell, row by row; bodies without a finite position are left
    /// out). [`near_pairs`](Self::near_pairs) takes the bodies in this order.
    ///
    /// The cells are as wide as the widest body plus twice the usual motion (that of
    /// nine bodies in ten, up to a body's width), and as high as the highest body plus
    /// that, so two bodies that may touch and move no further are in the same or
    /// neighbouring cells. Larger cells would hold more bodies, and every two bodies of
    /// neighbouring cells are tested: label boxes, wide and low, get wide and low cells.
    /// `half` is each body's bounding box's half width and half height (a disk's radius
    /// twice). Only the bodies `keep` marks are sorted in (all of them when it is
    /// empty); the cells are sized from all.
    pub(super) fn sort(
        &mut self,
        points: &[Point2D<f32>],
        half: &[Vector2D<f32>],
        motion: &[Vector2D<f32>],
        keep: &[bool],
    ) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.largest = half.iter().fold(Vector2D::zero(), |l: Vector2D<f32>, &h| {
            Vector2D::new(l.x.max(h.x), l.y.max(h.y))
        });
        self.lengths.clear();
        self.lengths.resize(motion.len(), 0.0);
        parallel::for_each_run(&mut self.lengths, MAP_RUN, |range, lengths| {
            for (l, m) in lengths.iter_mut().zip(&motion[range]) {
                *l = m.length();
            }
        });
        let usual = if self.lengths.is_empty() {
            0.0
        } else {
            let at = ((self.lengths.len() - 1) as f64 * USUAL_SHARE) as usize;
            *self.lengths.select_nth_unstable_by(at, f32::total_cmp).1
        };
        self.usual = usual.min(2.0 * self.largest.x.max(self.largest.y));
        let side = |largest: f32| (2.0 * largest + 2.0 * self.usual).max(1.0);
        self.cell = Vector2D::new(side(self.largest.x), side(self.largest.y));
        let cell = self.cell;
        parallel::collect_runs(
            points.len(),
            MAP_RUN,
            &mut self.cells,
            |s| points[s].is_finite() && keep.get(s).is_none_or(|&k| k),
            |s| {
                let p = points[s];
                (key(index(p.x, cell.x), index(p.y, cell.y)), s as u32)
            },
        );
        self.top_row = sort_cells(&mut self.cells, &mut self.scratch, &mut self.counts);
        self.cells.iter().map(|&(_, s)| s)
    }

    /// The motion a cell allows (that of nine bodies in ten, up to a body's width), from
    /// the last [`sort`](Self::sort).
    pub(super) fn usual_motion(&self) -> f32 {
        self.usual
    }

    /// The bodies [`sort`](Self::sort) put in the grid.
    pub(super) fn len(&self) -> usize {
        self.cells.len()
    }

    /// Calls `pair(a, b)` for every two bodies in neighbouring cells with `a` at a place
    /// in `first` of the grid's order (the order of [`sort`](Self::sort), which
    /// `points` and `motion` follow) and `b` after it, once each and in order (by `a`,
    /// then `b`), until `pair` returns `false`; returns whether it never did. Disjoint
    /// runs of `first` find their pairs independently.
    ///
    /// With [`fast_pairs`](Self::fast_pairs) they find every two bodies whose bounding
    /// boxes (`half`) come to touch as they move.
    pub(super) fn near_pairs(
        &self,
        first: std::ops::Range<usize>,
        mut pair: impl FnMut(u32, u32) -> bool,
    ) -> bool {
        let cells = &self.cells;
        // The cells of the next row start at or after `below`: keys only grow.
        let mut below = match cells.get(first.start) {
            Some(&(k, _)) => cells.partition_point(|&(k2, _)| k2 < k + (1 << 32) - 1),
            None => return true,
        };
        for i in first {
            let k = cells[i].0;
            // The same cell (later entries) and the next cell of the same row.
            for (j, &(k2, _)) in cells.iter().enumerate().skip(i + 1) {
                if k2 > k + 1 {
                    break;
                }
                if !pair(i as u32, j as u32) {
                    return false;
                }
            }
            // The three cells of the next row.
            let next_row = k + (1 << 32) - 1;
            while below < cells.len() && cells[below].0 < next_row {
                below += 1;
            }
            for (j, &(k2, _)) in cells.iter().enumerate().skip(below) {
                if k2 > next_row + 2 {
                    break;
                }
                if !pair(i as u32, j as u32) {
                    return false;
                }
            }
        }
        true
    }

    /// Appends to `out` what `pair(a, b)` (`a < b`) makes of the bodies beyond the
    /// neighbouring cells that a body moving further than a cell allows may meet on
    /// its path, in no order and possibly twice: at most `room` of them, the first
    /// `room` a search in order finds.
    ///
    /// A fast body searches every cell along its path (in one pass over the bodies when
    /// the path crosses more rows than there are bodies) for the slower ones, in runs
    /// of [`FAST_RUN`] fast bodies side by side under `parallel`, joined in order; two
    /// fast bodies may cross paths far from where either starts, so their swept boxes
    /// are compared directly, sorted along x.
    pub(super) fn fast_pairs<T: Send>(
        &mut self,
        points: &[Point2D<f32>],
        half: &[Vector2D<f32>],
        motion: &[Vector2D<f32>],
        pair: impl Fn(u32, u32) -> Option<T> + Sync,
        room: usize,
        out: &mut Vec<T>,
    ) {
        let usual = self.usual;
        parallel::collect_runs(
            points.len(),
            MAP_RUN,
            &mut self.swept,
            |a| motion[a].length() > usual,
            |a| {
                let (from, to) = (points[a], points[a] + motion[a]);
                let (lo, hi) = (from.min(to), from.max(to));
                // Padded by the half extents and half the usual motion: two fast bodies
                // whose paths come within their extents and the usual motion overlap.
                let r = half[a] + Vector2D::new(0.5 * usual, 0.5 * usual);
                (lo.x - r.x, hi.x + r.x, lo.y - r.y, hi.y + r.y, a as u32)
            },
        );
        let fast = self.swept.len();
        let start = out.len();
        // Each run searches until it holds what its bodies may (a far denser crowd than
        // disks can be stops it early, and it is searched again below, in order).
        let mut runs: Vec<(std::ops::Range<usize>, Vec<T>, bool)> = (0..fast.div_ceil(FAST_RUN))
            .map(|r| {
                (
                    r * FAST_RUN..((r + 1) * FAST_RUN).min(fast),
                    Vec::new(),
                    true,
                )
            })
            .collect();
        // The fast bodies' paths against each other (below), side by side with the runs.
        let mut crossing = Vec::new();
        let mut by_left = std::mem::take(&mut self.by_left);
        {
            let grid = &*self;
            let pair = &pair;
            parallel::join(
                || {
                    parallel::for_each(
                        &mut runs,
                        || (),
                        |(), (bodies, found, complete)| {
                            let most = run_bound(bodies.len()).min(room);
                            for &(.., a) in &grid.swept[bodies.clone()] {
                                let a = a as usize;
                                *complete = grid.along_path(points[a], motion[a], |b| {
                                    grid.near(a, b) || {
                                        found.extend(pair(a.min(b) as u32, a.max(b) as u32));
                                        found.len() < most
                                    }
                                });
                                if !*complete {
                                    return;
                                }
                            }
                        },
                    );
                },
                || grid.paths_crossing(&mut by_left, pair, room, &mut crossing),
            );
        }
        self.by_left = by_left;
        let full = |out: &Vec<T>| out.len() >= start + room;
        let mut resume = None;
        for (bodies, found, complete) in runs {
            if !complete {
                resume = Some(bodies.start);
                break;
            }
            let left = (start + room).saturating_sub(out.len());
            out.extend(found.into_iter().take(left));
            if full(out) {
                return;
            }
        }
        if let Some(from) = resume {
            for &(.., a) in &self.swept[from..] {
                let a = a as usize;
                let more = self.along_path(points[a], motion[a], |b| {
                    self.near(a, b) || {
                        out.extend(pair(a.min(b) as u32, a.max(b) as u32));
                        !full(out)
                    }
                });
                if !more {
                    return;
                }
            }
        }
        let left = (start + room).saturating_sub(out.len());
        out.extend(crossing.into_iter().take(left));
    }

    /// Puts what `pair(a, b)` makes of every two fast bodies whose swept boxes overlap
    /// (and are not in neighbouring cells) in `out`, in the order of a sweep along x,
    /// the first `room` of them; `by_left` is scratch for the boxes sorted by their
    /// left edge.
    fn paths_crossing<T>(
        &self,
        by_left: &mut Vec<(f32, f32, f32, f32, u32)>,
        pair: impl Fn(u32, u32) -> Option<T>,
        room: usize,
        out: &mut Vec<T>,
    ) {
        by_left.clear();
        by_left.extend_from_slice(&self.swept);
        by_left.sort_unstable_by(|x, y| x.0.total_cmp(&y.0).then(x.4.cmp(&y.4)));
        for (i, &(_, right, top, bottom, a)) in by_left.iter().enumerate() {
            for &(left_b, _, top_b, bottom_b, b) in &by_left[i + 1..] {
                if left_b > right {
                    break;
                }
                let (a, b) = (a as usize, b as usize);
                if top_b <= bottom && top <= bottom_b && !self.near(a, b) {
                    out.extend(pair(a.min(b) as u32, a.max(b) as u32));
                    if out.len() >= room {
                        return;
                    }
                }
            }
        }
    }

    /// Whether bodies `a` and `b` (places in the grid's order) are in the same or
    /// neighbouring cells (their pairs came from [`near_pairs`](Self::near_pairs)).
    fn near(&self, a: usize, b: usize) -> bool {
        let ((row_a, column_a), (row_b, column_b)) = (
            row_and_column(self.cells[a].0),
            row_and_column(self.cells[b].0),
        );
        (row_a - row_b).abs() <= 1 && (column_a - column_b).abs() <= 1
    }

    /// Where row `y`'s bodies lie in `cells` (from the rows' index of a sort by
    /// counting; all the cells otherwise, which hold them too).
    fn row(&self, y: i64) -> std::ops::Range<usize> {
        let Some(top) = self.top_row else {
            return 0..self.cells.len();
        };
        let rows = self.counts.len().saturating_sub(1) as i64;
        match y - top {
            b if b < 0 => 0..0,
            b if b >= rows => self.cells.len()..self.cells.len(),
            b => {
                let b = b as usize;
                let start = if b == 0 { 0 } else { self.counts[b - 1] };
                start as usize..self.counts[b] as usize
            }
        }
    }

    /// Calls `found(b)` for the bodies in the cells along the path from `from` by
    /// `motion` (widened by the largest bodies and the usual motion), until it returns
    /// `false`; returns whether it never did.
    fn along_path(
        &self,
        from: Point2D<f32>,
        motion: Vector2D<f32>,
        mut found: impl FnMut(usize) -> bool,
    ) -> bool {
        let (cells, cell, usual) = (&self.cells, self.cell, self.usual);
        let reach = self.largest * 2.0 + Vector2D::new(usual, usual);
        let to = from + motion;
        let (lo, hi) = (from.min(to), from.max(to));
        let (top, bottom) = (index(lo.y - reach.y, cell.y), index(hi.y + reach.y, cell.y));
        let (left, right) = (index(lo.x - reach.x, cell.x), index(hi.x + reach.x, cell.x));
        if (bottom - top) as usize >= cells.len() {
            // A path across more rows than there are bodies (a drag across the
            // canvas): one pass over the bodies finds the same cells as a search of
            // every row.
            for (b, &(k, _)) in cells.iter().enumerate() {
                let (row, column) = row_and_column(k);
                if (top..=bottom).contains(&row) && (left..=right).contains(&column) && !found(b) {
                    return false;
                }
            }
            return true;
        }
        for y in top..=bottom {
            // Only the columns the path passes near in this row: a long diagonal
            // path's bounding box holds far more cells than the path. (A cell more
            // on every side, for the rounding of far coordinates.)
            let (row_top, cell64) = (y as f64 * f64::from(cell.y), f64::from(cell.y));
            let band = (
                (row_top - cell64) as f32 - reach.y,
                (row_top + 2.0 * cell64) as f32 + reach.y,
            );
            let Some((x0, x1)) = crossing(from, to, band) else {
                continue;
            };
            let near_left = (index(x0 - reach.x, cell.x) - 1).max(left);
            let near_right = (index(x1 + reach.x, cell.x) + 1).min(right);
            let (start, end) = (key(near_left, y), key(near_right, y));
            let row = self.row(y);
            let first = row.start + cells[row].partition_point(|&(k, _)| k < start);
            for (b, &(k2, _)) in cells.iter().enumerate().skip(first) {
                if k2 > end {
                    break;
                }
                if !found(b) {
                    return false;
                }
            }
        }
        true
    }
}

/// The x-extent of the part of the segment `from`–`to` whose y lies in `band` (low,
/// high), or `None` where the segment does not reach the band.
fn crossing(from: Point2D<f32>, to: Point2D<f32>, (low, high): (f32, f32)) -> Option<(f32, f32)> {
    let dy = to.y - from.y;
    let (t0, t1) = if dy == 0.0 {
        if from.y < low || from.y > high {
            return None;
        }
        (0.0, 1.0)
    } else {
        let (a, b) = ((low - from.y) / dy, (high - from.y) / dy);
        (a.min(b).max(0.0), a.max(b).min(1.0))
    };
    if t0 > t1 {
        return None;
    }
    let (xa, xb) = (from.x + (to.x - from.x) * t0, from.x + (to.x - from.x) * t1);
    Some((xa.min(xb), xa.max(xb)))
}

/// The row and column of a cell's key.
fn row_and_column(k: u64) -> (i64, i64) {
    (
        (k >> 32) as i64 - (1 << 31),
        (k & 0xffff_ffff) as i64 - (1 << 31),
    )
}

/// The cell a coordinate falls in.
fn index(v: f32, cell: f32) -> i64 {
    (v / cell).floor().clamp(-1.0e9, 1.0e9) as i64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid of `points` (still disks of radius 4), sorted.
    fn sorted(points: &[Point2D<f32>]) -> Grid {
        let mut grid = Grid::default();
        let half = vec![Vector2D::new(4.0, 4.0); points.len()];
        let motion = vec![Vector2D::zero(); points.len()];
        let _ = grid.sort(points, &half, &motion, &[]).count();
        grid
    }

    /// A search along a path looks a row up in the rows' index a sort by counting
    /// leaves: every row's range holds exactly the bodies of that row, rows beyond the
    /// grid hold none, and a grid sorted by comparison (bodies scattered across far
    /// more rows than there are bodies) has no index and searches all the cells.
    #[test]
    fn the_rows_index_holds_each_rows_bodies() {
        // A band 60 units high left empty: rows within the grid that hold no body.
        let points: Vec<_> = (0..500)
            .map(|i| Point2D::new((i * 37 % 211) as f32 * 3.0, (i * 53 % 197) as f32 * 2.0))
            .filter(|p| !(150.0..210.0).contains(&p.y))
            .collect();
        let grid = sorted(&points);
        let top = grid
            .top_row
            .expect("a compact layout is sorted by counting");
        let rows: Vec<i64> = grid
            .cells
            .iter()
            .map(|&(k, _)| row_and_column(k).0)
            .collect();
        let bottom = *rows.last().expect("bodies");
        assert!(bottom - top >= 3, "rows {top}..={bottom}: too few to test");
        let mut empty = 0;
        for y in top - 2..=bottom + 2 {
            let expected: Vec<usize> = (0..rows.len()).filter(|&b| rows[b] == y).collect();
            empty += usize::from(expected.is_empty() && (top..=bottom).contains(&y));
            let found: Vec<usize> = grid.row(y).collect();
            assert_eq!(found, expected, "row {y} of {top}..={bottom}");
        }
        assert!(
            empty >= 3,
            "{empty} empty rows within the grid: the band left none"
        );
        let scattered: Vec<_> = (0..50)
            .map(|i| Point2D::new(0.0, i as f32 * 1.0e6))
            .collect();
        let grid = sorted(&scattered);
        assert_eq!(
            grid.top_row, None,
            "50 bodies over 50 million units of rows"
        );
        assert_eq!(grid.row(3), 0..50, "no index: every cell");
    }
}
