//! One other thread of the pool kept awake through a call's substeps (under
//! `parallel`), so the substeps' parallel parts do not wait for it to wake.
//!
//! A rayon thread with no work spins a little and then sleeps; asleep, it takes 20 to
//! 70 µs to wake (on this project's 2-core virtual machine), and a substep of 10,000
//! bodies holds some twenty parallel parts of tens of µs each, with serial work between
//! them. So [`with_pool_awake`] hands the pool one job that takes the pool's work as it
//! comes ([`rayon::yield_now`]) and yields its core to the system between looks, until
//! the substeps end. Which thread takes which part changes no result.
//!
//! The job must never hold up the work below it on its thread's stack, which would
//! wait for it while it waits for the substeps to end. So it leaves at once on a thread
//! that runs substeps (its caller's, or another layout's) or keeps awake already; as
//! the oldest job the substeps hand the pool, it is taken before any of their parts
//! (rayon steals oldest first, and a thread outside the pool injects in order); and it
//! leaves after [`IDLE_LIMIT`] without work, which bounds what it can hold up where
//! layouts step side by side on one pool.

use std::cell::Cell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// From this many awake bodies on, [`with_pool_awake`] keeps a thread awake.
const AWAKE_FROM: usize = 2_048;

/// How long the thread kept awake waits without work before it leaves (longer than
/// rapier's step between two parts at 10,000 bodies, about a millisecond).
const IDLE_LIMIT: Duration = Duration::from_millis(2);

thread_local! {
    /// How many [`with_pool_awake`] calls run on this thread.
    static STEPPING: Cell<u32> = const { Cell::new(0) };
    /// Whether this thread runs a [`keep_awake`] already.
    static KEEPING: Cell<bool> = const { Cell::new(false) };
}

/// Runs `f`, the substeps of a call with `awake` bodies awake, with one other thread
/// of the pool kept awake from [`AWAKE_FROM`] bodies on.
pub(crate) fn with_pool_awake<R>(awake: usize, f: impl FnOnce() -> R) -> R {
    let alone = rayon::current_thread_index().is_some() && rayon::current_num_threads() < 2;
    if awake < AWAKE_FROM || alone {
        return f();
    }
    let done = AtomicBool::new(false);
    rayon::in_place_scope(|scope| {
        scope.spawn(|_| keep_awake(&done));
        // However `f` ends (a panic too): else the scope would wait for ever.
        let _finish = Finish::new(&done);
        f()
    })
}

/// Marks its thread as running substeps while it lives, and sets `done` when dropped.
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
fn keep_awake(done: &AtomicBool) {
    if STEPPING.get() > 0 || KEEPING.get() {
        return;
    }
    KEEPING.set(true);
    // Cleared however the loop ends (a part that panics too).
    let _kept = Kept;
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
