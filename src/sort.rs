//! A stable counting sort of `(key, index)` entries by a bucket of the key: the cells
//! of the contacts' grid (`contacts/grid.rs`, by column and then by row) and the
//! Barnes–Hut tree's order (`forces/barnes_hut/order.rs`, by the cell at depth 6).

/// Moves `from` into `to` ordered by `bucket` (below `buckets`), keeping the order of
/// entries in the same bucket. Leaves `counts[b]` at the end of bucket `b`'s entries in
/// `to` (so bucket `b` is `counts[b - 1]..counts[b]`, the first from 0).
pub(crate) fn counting_sort(
    from: &[(u64, u32)],
    to: &mut Vec<(u64, u32)>,
    counts: &mut Vec<u32>,
    buckets: usize,
    bucket: impl Fn(u64) -> usize,
) {
    counts.clear();
    counts.resize(buckets + 1, 0);
    for &(k, _) in from {
        counts[bucket(k) + 1] += 1;
    }
    for b in 0..buckets {
        counts[b + 1] += counts[b];
    }
    to.clear();
    to.resize(from.len(), (0, 0));
    for &entry in from {
        let at = &mut counts[bucket(entry.0)];
        to[*at as usize] = entry;
        *at += 1;
    }
}
