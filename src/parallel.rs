//! Work the layout spreads over rayon's pool under the `parallel` feature (and does in
//! order on the calling thread without it): one place that knows whether the feature is
//! on, so a force only says which of its parts are independent.
//!
//! Every use splits its work into pieces that do not depend on the thread count (a
//! Barnes–Hut group or subtree, a fixed run of links, bodies, pairs or stress nodes)
//! and puts their results together in the pieces' order, so what a piece computes, and
//! the sum it ends in, are the same on any number of threads, and with the feature on
//! or off. The contacts' passes (`forces/collide/passes.rs`) are the one exception to
//! the last: under the feature they solve the pairs block by block, an order fixed by
//! the pairs alone, which differs from the serial build's from two blocks on.
//!
//! [`with_pool_awake`] keeps the pool's other threads awake through a call's substeps,
//! so a part does not wait for a thread to wake; it changes which thread takes which
//! piece, never what a piece computes.

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

/// Below this many items a sort stays on the calling thread: waking the pool's other
/// threads costs about what they would save.
#[cfg(feature = "parallel")]
const PARALLEL_SORT: usize = 32_768;

/// Sorts `items` (stable): on rayon's pool under `parallel` (from [`PARALLEL_SORT`] items on). Both give the same order.
pub(crate) fn sort<T: Ord + Send>(items: &mut [T]) {
    #[cfg(feature = "parallel")]
    if items.len() >= PARALLEL_SORT {
        items.par_sort();
        return;
    }
    items.sort();
}

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

/// From this many awake bodies on, the pool's other threads are kept awake through a
/// call's substeps ([`with_pool_awake`]).
#[cfg(feature = "parallel")]
const AWAKE_FROM: usize = 2_048;

/// Runs `f`, the substeps of a call with `awake` bodies awake. Under `parallel`, from
/// [`AWAKE_FROM`] bodies on and with other threads in the pool, each of those threads
/// waits for `f`'s parallel parts awake (taking what work it finds, and yielding its
/// core to the system between looks) instead of going to sleep between them: a thread
/// asleep takes 20 to 70 µs to wake, and a substep of 10,000 bodies holds about twenty
/// parts, each of tens of µs. Which thread works on which part changes nothing in the
/// results.
pub(crate) fn with_pool_awake<R>(awake: usize, f: impl FnOnce() -> R) -> R {
    #[cfg(feature = "parallel")]
    {
        let caller = rayon::current_thread_index();
        let others = rayon::current_num_threads() - usize::from(caller.is_some());
        if awake >= AWAKE_FROM && others > 0 {
            let done = std::sync::atomic::AtomicBool::new(false);
            return rayon::in_place_scope(|scope| {
                for _ in 0..others {
                    scope.spawn(|_| keep_awake(&done, caller));
                }
                // Set however `f` ends (a panic too), or the scope would wait for ever.
                let _finish = Finish(&done);
                f()
            });
        }
    }
    #[cfg(not(feature = "parallel"))]
    let _ = awake;
    f()
}

/// Sets its flag when dropped.
#[cfg(feature = "parallel")]
struct Finish<'a>(&'a std::sync::atomic::AtomicBool);

#[cfg(feature = "parallel")]
impl Drop for Finish<'_> {
    fn drop(&mut self) {
        self.0.store(true, std::sync::atomic::Ordering::Release);
    }
}

#[cfg(feature = "parallel")]
thread_local! {
    /// Whether this thread runs a [`keep_awake`] already.
    static KEEPING: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Takes the pool's work as it comes until `done`. Leaves at once on the thread that
/// runs the substeps (`caller`; it picks a waiting job up only while it waits for a part
/// of its own, and would then hold itself up) and on a thread that keeps awake already.
#[cfg(feature = "parallel")]
fn keep_awake(done: &std::sync::atomic::AtomicBool, caller: Option<usize>) {
    use std::sync::atomic::Ordering;
    if rayon::current_thread_index() == caller || KEEPING.get() {
        return;
    }
    KEEPING.set(true);
    // Cleared however the loop ends (a part that panics too).
    let _kept = Kept;
    while !done.load(Ordering::Acquire) {
        match rayon::yield_now() {
            Some(rayon::Yield::Executed) => {}
            Some(rayon::Yield::Idle) => std::thread::yield_now(),
            None => break,
        }
    }
}

/// Clears this thread's [`KEEPING`] when dropped.
#[cfg(feature = "parallel")]
struct Kept;

#[cfg(feature = "parallel")]
impl Drop for Kept {
    fn drop(&mut self) {
        KEEPING.set(false);
    }
}
