//! Another thread of the pool kept awake through a substep (under `parallel`), so the
//! substep's parallel parts do not wait for it to wake.
//!
//! A rayon thread with no work spins a little and then sleeps; asleep, it takes about as
//! long to wake as one of the parallel parts of a large layout's substep takes, and such
//! a substep holds many of them, with serial work between them (`docs/performance.md`,
//! the parallel feature, gives the figures). So [`with_pool_awake`] hands the pool one
//! job that takes the pool's work as it comes ([`rayon::yield_now`]) and yields its
//! core to the system between looks, until the substep ends. Which thread takes which
//! part changes no result.
//!
//! The job is detached (the substep does not wait for it to end), and it must never
//! hold up the work below it on its thread's stack for long. So it leaves at once on a
//! thread that runs substeps (its caller's, or another layout's) or keeps awake
//! already; it is the oldest job the substep hands the pool, so it is taken before any
//! of the substep's parts (rayon steals oldest first, and a thread outside the pool
//! injects in order), which rules out a keeper waiting on its own substep's parts; it
//! leaves once that substep ends, or after [`IDLE_LIMIT`] without work. Work of another
//! layout's that a keeper sits above (layouts stepping side by side on a pool of three
//! threads or more) waits for one of those.

use std::cell::Cell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// From this many awake bodies on, [`with_pool_awake`] keeps a thread awake.
const AWAKE_FROM: usize = 2_048;

/// How long the thread kept awake waits without work before it leaves: longer than
/// rapier's step, the longest serial work between two parts of a large layout's
/// substep (`docs/performance.md` gives its time).
const IDLE_LIMIT: Duration = Duration::from_millis(2);

thread_local! {
    /// How many [`with_pool_awake`] calls run on this thread.
    static STEPPING: Cell<u32> = const { Cell::new(0) };
    /// Whether this thread runs a [`keep_awake`] already.
    static KEEPING: Cell<bool> = const { Cell::new(false) };
}

/// What a substep and the job keeping a thread awake for it share.
#[derive(Default)]
struct Keeper {
    /// Set when the substep ends.
    done: AtomicBool,
    /// Set when the job starts keeping a thread awake (it may leave at once instead).
    started: AtomicBool,
}

/// Runs `f`, a substep with `awake` bodies awake, with another thread of the pool kept
/// awake from [`AWAKE_FROM`] bodies on.
pub(crate) fn with_pool_awake<R>(awake: usize, f: impl FnOnce() -> R) -> R {
    kept_awake(awake, |_| f())
}

/// [`with_pool_awake`], `f` given the keeper it handed the pool (`None`: none).
fn kept_awake<R>(awake: usize, f: impl FnOnce(Option<&Keeper>) -> R) -> R {
    let alone = rayon::current_thread_index().is_some() && rayon::current_num_threads() < 2;
    if awake < AWAKE_FROM || alone {
        return f(None);
    }
    let keeper = Arc::new(Keeper::default());
    let job = Arc::clone(&keeper);
    rayon::spawn(move || keep_awake(&job));
    // However `f` ends (a panic too): else the keeper would wait its idle limit out.
    let _finish = Finish::new(&keeper.done);
    f(Some(&keeper))
}

/// Marks its thread as running a substep while it lives, and sets `done` when dropped.
struct Finish<'a> {
    done: &'a AtomicBool,
}

impl<'a> Finish<'a> {
    fn new(done: &'a AtomicBool) -> Self {
        STEPPING.set(STEPPING.get() + 1);
        Self { done }
    }
}

impl Drop for Finish<'_> {
    fn drop(&mut self) {
        STEPPING.set(STEPPING.get() - 1);
        self.done.store(true, Ordering::Release);
    }
}

/// Takes the pool's work as it comes until `done`, or until it has found none for
/// [`IDLE_LIMIT`]; leaves at once on a thread that runs substeps or keeps awake already.
fn keep_awake(keeper: &Keeper) {
    let done = &keeper.done;
    if STEPPING.get() > 0 || KEEPING.get() || done.load(Ordering::Acquire) {
        return;
    }
    KEEPING.set(true);
    // Cleared however the loop ends.
    let _kept = Kept;
    keeper.started.store(true, Ordering::Release);
    let mut idle_since = None;
    while !done.load(Ordering::Acquire) {
        match rayon::yield_now() {
            Some(rayon::Yield::Executed) => idle_since = None,
            Some(rayon::Yield::Idle) => {
                let now = Instant::now();
                if now.duration_since(*idle_since.get_or_insert(now)) > IDLE_LIMIT {
                    break;
                }
                std::thread::yield_now();
            }
            None => break,
        }
    }
}

/// Clears this thread's [`KEEPING`] when dropped.
struct Kept;

impl Drop for Kept {
    fn drop(&mut self) {
        KEEPING.set(false);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a pool of two threads, a substep of enough awake bodies has the other thread
    /// kept awake: its keeper starts while the substep runs (waited for, bounded).
    /// Below the threshold, or on a pool of one thread, none is handed over.
    #[test]
    fn a_substep_keeps_the_other_thread_awake() {
        let pool = |threads| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("a rayon pool")
        };
        let limit = Duration::from_secs(10);
        let (two, one) = (pool(2), pool(1));
        let kept = two.install(|| {
            kept_awake(AWAKE_FROM, |keeper| {
                let keeper = keeper.expect("a keeper handed to a pool of two threads");
                let waited = Instant::now();
                while !keeper.started.load(Ordering::Acquire) && waited.elapsed() < limit {
                    std::thread::yield_now();
                }
                keeper.started.load(Ordering::Acquire)
            })
        });
        assert!(
            kept,
            "no keeper started within {limit:?} on a pool of two threads"
        );
        let below = two.install(|| kept_awake(AWAKE_FROM - 1, |k| k.is_some()));
        let alone = one.install(|| kept_awake(AWAKE_FROM, |k| k.is_some()));
        assert_eq!(
            (below, alone),
            (false, false),
            "keepers handed over below {AWAKE_FROM} awake bodies, on a pool of one thread"
        );
    }
}
