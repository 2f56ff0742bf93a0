//! Finding the pairs of disks that may touch during a substep: a uniform grid, its cells
//! sorted by key, searched in the same and the neighbouring cells (and along the path of
//! a body that moves further than a cell allows). The separation itself is in `mod.rs`.

use euclid::default::{Point2D, Vector2D};

/// A cell's key: row in the high half, column in the low half, both offset to be
/// non-negative, so keys sort row by row.
fn key(x: i64, y: i64) -> u64 {
    (((y + (1 << 31)) as u64) << 32) | ((x + (1 << 31)) as u64)
}

/// The grid over one substep's bodies.
#[derive(Debug, Default)]
pub(super) struct Grid {
    /// `(cell key, slot)` of every body, sorted.
    cells: Vec<(u64, u32)>,
}

impl Grid {
    /// Calls `pair(a, b)` for every two bodies (by slot) that may touch: within
    /// `radius[a] + radius[b]` plus their `motion` over the substep. Pairs come in cell
    /// order, so the same bodies give the same sequence; a pair may come twice.
    ///
    /// The cells are as wide as the largest disk plus twice the usual motion (the
    /// largest, up to a disk's width), so two bodies that may touch are in the same or
    /// neighbouring cells; a body moving further searches every cell along its path (in
    /// one pass over the bodies when the path crosses more rows than there are bodies).
    pub(super) fn pairs(
        &mut self,
        points: &[Point2D<f32>],
        radius: &[f32],
        motion: &[Vector2D<f32>],
        mut pair: impl FnMut(u32, u32),
    ) {
        let largest = radius.iter().copied().fold(0.0_f32, f32::max);
        let fastest = motion.iter().map(|m| m.length()).fold(0.0_f32, f32::max);
        let usual = fastest.min(2.0 * largest);
        let cell = (2.0 * largest + 2.0 * usual).max(1.0);
        let index = |v: f32| (v / cell).floor().clamp(-1.0e9, 1.0e9) as i64;
        self.cells.clear();
        self.cells.extend(
            points
                .iter()
                .enumerate()
                .filter(|(_, p)| p.is_finite())
                .map(|(s, &p)| (key(index(p.x), index(p.y)), s as u32)),
        );
        self.cells.sort_unstable();
        let cells = &self.cells;
        // The cells of the next row start at or after `below`: keys only grow.
        let mut below = 0;
        for (i, &(k, a)) in cells.iter().enumerate() {
            // The same cell (later entries) and the next cell of the same row.
            for &(k2, b) in &cells[i + 1..] {
                if k2 > k + 1 {
                    break;
                }
                pair(a, b);
            }
            // The three cells of the next row.
            let first = k + (1 << 32) - 1;
            while below < cells.len() && cells[below].0 < first {
                below += 1;
            }
            for &(k2, b) in &cells[below..] {
                if k2 > first + 2 {
                    break;
                }
                pair(a, b);
            }
        }
        // Bodies moving further than the cells allow search along their path.
        let reach = 2.0 * largest + usual;
        for (a, (&p, &m)) in points.iter().zip(motion).enumerate() {
            if m.length() <= usual || !p.is_finite() {
                continue;
            }
            let (from, to) = (p, p + m);
            let (lo, hi) = (from.min(to), from.max(to));
            let (top, bottom) = (index(lo.y - reach), index(hi.y + reach));
            let (left, right) = (index(lo.x - reach), index(hi.x + reach));
            if (bottom - top) as usize >= cells.len() {
                // A path across more rows than there are bodies (a drag across the
                // canvas): one pass over the bodies finds the same cells, in the same
                // (row by row) order, as a search of every row.
                for &(k, b) in cells {
                    let (row, column) = (
                        (k >> 32) as i64 - (1 << 31),
                        (k & 0xffff_ffff) as i64 - (1 << 31),
                    );
                    if (top..=bottom).contains(&row)
                        && (left..=right).contains(&column)
                        && b as usize != a
                    {
                        pair(a as u32, b);
                    }
                }
                continue;
            }
            for y in top..=bottom {
                let (start, end) = (key(index(lo.x - reach), y), key(index(hi.x + reach), y));
                let first = cells.partition_point(|&(k, _)| k < start);
                for &(k2, b) in &cells[first..] {
                    if k2 > end {
                        break;
                    }
                    if b as usize != a {
                        pair(a as u32, b);
                    }
                }
            }
        }
    }
}
