//! The tree's order: every finite point's Z-order code and index, sorted by code and
//! then index. From [`BUCKETS_FROM`] points on, by a counting sort on the code's top
//! [`BUCKET_BITS`] bits (the cell at depth 6 a point falls in) and then a sort of each
//! of those cells' entries, side by side under `parallel`: a bucket holds one run of the
//! order, so the result is the one order a whole sort gives, on any number of threads.
//! Below that, one whole sort on the calling thread, where a sort of that size costs
//! less than handing it to the pool.

use crate::parallel;
use crate::sort::counting_sort;

/// From this many entries on, the sort goes bucket by bucket.
const BUCKETS_FROM: usize = 8_192;

/// The code's top bits that name a bucket: the quadrants at depths 1 to 6.
const BUCKET_BITS: u32 = 12;

/// Entries a run of the buckets' sorts takes, about (whole buckets).
const SORT_RUN: usize = 1_024;

/// The codes' width: two bits per depth down to the deepest (`MAX_DEPTH`).
const CODE_BITS: u32 = 2 * super::MAX_DEPTH;

/// Sorts `entries` by code, then index, with `scratch` and `ends` as buffers.
pub(super) fn sort_entries(
    entries: &mut Vec<(u64, u32)>,
    scratch: &mut Vec<(u64, u32)>,
    ends: &mut Vec<u32>,
) {
    if entries.len() < BUCKETS_FROM {
        entries.sort();
        return;
    }
    let bucket = |code: u64| (code >> (CODE_BITS - BUCKET_BITS)) as usize;
    let buckets = 1_usize << BUCKET_BITS;
    // Stable: each bucket keeps the order it had (the last build's, nearly sorted).
    counting_sort(entries, scratch, ends, buckets, bucket);
    std::mem::swap(entries, scratch);
    // Bucket `b` starts where the one before it ends.
    let ends: &[u32] = ends;
    let at = |b: usize| if b == 0 { 0 } else { ends[b - 1] as usize };
    // Runs of whole buckets of about SORT_RUN entries, each bucket sorted on its own.
    let mut runs = Vec::new();
    let mut first = 0;
    for b in 1..=buckets {
        if b == buckets || at(b) - at(first) >= SORT_RUN {
            runs.push(first..b);
            first = b;
        }
    }
    let mut jobs = parallel::split_ranges(entries, runs.iter().map(|r| at(r.start)..at(r.end)));
    let mut jobs: Vec<_> = jobs.iter_mut().zip(&runs).collect();
    parallel::for_each(
        &mut jobs,
        || (),
        |(), ((range, run_entries), run)| {
            for b in run.clone() {
                run_entries[at(b) - range.start..at(b + 1) - range.start].sort();
            }
        },
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Codes spread over every bucket and crowded into a few, with ties broken by
    /// index: the same order as one whole sort.
    #[test]
    fn bucket_by_bucket_is_the_whole_sort() {
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let spread: Vec<(u64, u32)> = (0..20_000)
            .map(|i| (next() >> (64 - CODE_BITS), i))
            .collect();
        // Few distinct codes, in few buckets: many ties.
        let crowded: Vec<(u64, u32)> = (0..20_000)
            .rev()
            .map(|i| ((next() % 7) << (CODE_BITS - 3), i))
            .collect();
        for entries in [spread, crowded] {
            let mut whole = entries.clone();
            whole.sort();
            let mut buckets = entries;
            sort_entries(&mut buckets, &mut Vec::new(), &mut Vec::new());
            let first_difference = buckets.iter().zip(&whole).position(|(a, b)| a != b);
            assert_eq!(
                first_difference,
                None,
                "bucket sort against a whole sort of {} entries",
                whole.len()
            );
        }
    }
}
