//! Work the layout spreads over rayon's pool under the `parallel` feature (and does in
//! order on the calling thread without it): one place that knows whether the feature is
//! on, so a force only says which of its parts are independent.
//!
//! Every use splits its work into pieces that do not depend on the thread count (a
//! Barnes–Hut group or subtree, a fixed run of links, bodies, pairs or stress nodes)
//! and puts their results together in the pieces' order, so what a piece computes, and
//! the sum it ends in, are the same on any number of threads, and with the feature on
//! or off. The contacts' passes (`contacts/passes.rs`) are the one exception to
//! the last: under the feature they solve the pairs block by block, an order fixed by
//! the pairs alone, which differs from the serial build's from two blocks on.
//!
//! [`with_pool_awake`] (`awake.rs`) keeps another thread of the pool awake through each
//! substep of a call, so a part does not wait for it to wake; it changes which thread
//! takes which piece, never what a piece computes.

#[cfg(feature = "parallel")]
use rayon::prelude::*;

/// Runs `f` on every item of `items`, each with a scratch state made by `init`: on
/// rayon's pool under `parallel` (a state for each piece of work rayon splits off, so
/// `f` must not let what a state held before change its result), in order with one
/// state for all otherwise.
pub(crate) fn for_each<T: Send, S>(
    items: &mut [T],
    init: impl Fn() -> S + Sync + Send,
    f: impl Fn(&mut S, &mut T) + Sync + Send,
) {
    // One item is done here: handing it to the pool from outside it would only wait.
    #[cfg(feature = "parallel")]
    if items.len() > 1 {
        items.par_iter_mut().for_each_init(init, f);
        return;
    }
    let mut scratch = init();
    for item in items {
        f(&mut scratch, item);
    }
}

/// Runs `a` and `b`, side by side under `parallel`, one after the other otherwise.
pub(crate) fn join<A: Send, B: Send>(
    a: impl FnOnce() -> A + Send,
    b: impl FnOnce() -> B + Send,
) -> (A, B) {
    #[cfg(feature = "parallel")]
    return rayon::join(a, b);
    #[cfg(not(feature = "parallel"))]
    (a(), b())
}

/// Runs `job` beside `here` and returns what `here` returns once both are done:
/// under `parallel`, `job` is handed to rayon's pool for another thread to take while
/// `here` runs on the calling thread (so `here` may touch what must stay on it); on a
/// thread of the pool, the calling thread runs `job` itself if no other took it, and
/// from outside the pool `job` waits in the pool's queue. Without the feature, `job`
/// then `here`. The two must not share what they write.
pub(crate) fn beside<R>(job: impl FnOnce() + Send, here: impl FnOnce() -> R) -> R {
    #[cfg(feature = "parallel")]
    return rayon::in_place_scope(|scope| {
        scope.spawn(|_| job());
        here()
    });
    #[cfg(not(feature = "parallel"))]
    {
        job();
        here()
    }
}

/// Below this many items a sort stays on the calling thread: waking the pool's other
/// threads costs about what they would save.
#[cfg(feature = "parallel")]
const PARALLEL_SORT: usize = 32_768;

/// Sorts `items` (unstable): on rayon's pool under `parallel` (from [`PARALLEL_SORT`]
/// items on). For items that are all
/// different, as every use's are, both give the same order.
pub(crate) fn sort_unstable<T: Ord + Send>(items: &mut [T]) {
    #[cfg(feature = "parallel")]
    if items.len() >= PARALLEL_SORT {
        items.par_sort_unstable();
        return;
    }
    items.sort_unstable();
}

/// `0..len` cut into runs of `run` (the last shorter): pieces fixed by the work alone,
/// never by the pool.
pub(crate) fn runs(len: usize, run: usize) -> impl Iterator<Item = std::ops::Range<usize>> {
    let run = run.max(1);
    (0..len.div_ceil(run)).map(move |r| r * run..((r + 1) * run).min(len))
}

/// Runs `f` on `buffer` cut into runs of `run` items ([`runs`]), each run with its range
/// of indices: side by side under `parallel`, in order otherwise (see [`for_each`]).
pub(crate) fn for_each_run<T: Send>(
    buffer: &mut [T],
    run: usize,
    f: impl Fn(std::ops::Range<usize>, &mut [T]) + Sync + Send,
) {
    let mut jobs = split_ranges(buffer, runs(buffer.len(), run));
    for_each(
        &mut jobs,
        || (),
        |(), (range, items)| f(range.clone(), items),
    );
}

/// Whether work handed to [`for_each`] may run on more than one thread: under
/// `parallel`, on a pool of two threads or more.
fn side_by_side() -> bool {
    #[cfg(feature = "parallel")]
    return rayon::current_num_threads() > 1;
    #[cfg(not(feature = "parallel"))]
    false
}

/// Fills `out` with `make(i)` for every `i` of `0..len` that `keep(i)` takes, in order,
/// from runs of `run` indices side by side under `parallel` (on a pool of two threads or
/// more): each run counts what it keeps, then writes it at its place; in one pass in
/// order otherwise. The same items in the same order on any number
/// of threads.
pub(crate) fn collect_runs<U: Copy + Default + Send>(
    len: usize,
    run: usize,
    out: &mut Vec<U>,
    keep: impl Fn(usize) -> bool + Sync + Send,
    make: impl Fn(usize) -> U + Sync + Send,
) {
    if !side_by_side() || len <= run {
        out.clear();
        out.extend((0..len).filter(|&i| keep(i)).map(make));
        return;
    }
    let mut counted: Vec<(std::ops::Range<usize>, usize)> =
        runs(len, run).map(|r| (r, 0)).collect();
    for_each(
        &mut counted,
        || (),
        |(), (range, count)| *count = range.clone().filter(|&i| keep(i)).count(),
    );
    out.clear();
    out.resize(counted.iter().map(|&(_, c)| c).sum(), U::default());
    let mut at = 0;
    let places = counted.iter().map(|&(_, c)| {
        at += c;
        at - c..at
    });
    let mut jobs: Vec<_> = split_ranges(out, places)
        .into_iter()
        .zip(counted.iter().map(|(range, _)| range.clone()))
        .collect();
    for_each(
        &mut jobs,
        || (),
        |(), ((_, out), range)| {
            let kept = range.clone().filter(|&i| keep(i));
            for (slot, i) in out.iter_mut().zip(kept) {
                *slot = make(i);
            }
        },
    );
}

/// Splits `buffer` into the disjoint, ascending `ranges` of it, each with its range.
///
/// # Panics
/// If the ranges are not ascending and disjoint, or run past the buffer.
pub(crate) fn split_ranges<T>(
    buffer: &mut [T],
    ranges: impl IntoIterator<Item = std::ops::Range<usize>>,
) -> Vec<(std::ops::Range<usize>, &mut [T])> {
    let mut rest = buffer;
    let mut at = 0;
    let mut out = Vec::new();
    for range in ranges {
        let tail = std::mem::take(&mut rest);
        let (_, tail) = tail.split_at_mut(range.start - at);
        let (mine, tail) = tail.split_at_mut(range.len());
        at = range.end;
        rest = tail;
        out.push((range, mine));
    }
    out
}

#[cfg(feature = "parallel")]
mod awake;
#[cfg(feature = "parallel")]
pub(crate) use awake::with_pool_awake;

/// Runs `f` (a substep with `awake` bodies awake): without `parallel` there
/// is no pool to keep awake.
#[cfg(not(feature = "parallel"))]
pub(crate) fn with_pool_awake<R>(_awake: usize, f: impl FnOnce() -> R) -> R {
    f()
}
