//! The layout's step on rayon pools of 1 and 2 threads (feature `parallel`), the 2
//! threads kept awake through the substeps (the default) and not
//! (`RapierLayout::set_pool_awake`): frames 30..30+N of a layout from the scene file, in
//! pools built in turn, best of three runs each (or `runs`; each figure its own best),
//! and the ratios to 1 thread; for the whole frame
//! and for the stages a [`StepProfile`] tells apart (the layout's own forces, its
//! contacts, rapier's step, and the rest of the call: matching, sync in and out,
//! deltas).
//!
//! Beside them, the machine's own ceiling: the same work with nothing shared and
//! nothing serial (an arithmetic chain, and sums streamed from 64 MB of memory, in 64
//! pieces) on pools of the same sizes, timed in each run, so a ratio reads against
//! what 2 threads of this machine give at best.
//!
//! `cargo run --release --features parallel --example threads -- [scene] [preset] [frames] [runs]`
//! (defaults `n10000_e25000 force_directed 240 3`; `preset` is `force_directed` or
//! `stress`; a generated name such as `random_n100000_e250000` works too).

mod common;

use std::hash::Hasher;
use std::time::{Duration, Instant};

use common::*;
use graph_canvas_layout::profile::StepProfile;
use graph_canvas_layout::RapierLayoutConfig;

const WARM: usize = 30;

/// What a run measured, in ms a frame: the whole frame, then the stages.
#[derive(Clone, Copy)]
struct Run {
    frame: f64,
    forces: f64,
    contacts: f64,
    rapier: f64,
    rest: f64,
}

impl Run {
    const INFINITE: Self = Self {
        frame: f64::INFINITY,
        forces: f64::INFINITY,
        contacts: f64::INFINITY,
        rapier: f64::INFINITY,
        rest: f64::INFINITY,
    };

    fn of(frame: Duration, profile: StepProfile, frames: usize) -> Self {
        let ms = |d: Duration| d.as_secs_f64() * 1000.0 / frames as f64;
        let stages = profile.forces + profile.contacts + profile.rapier;
        Self {
            frame: ms(frame),
            forces: ms(profile.forces),
            contacts: ms(profile.contacts),
            rapier: ms(profile.rapier),
            rest: ms(profile.total.saturating_sub(stages)),
        }
    }

    /// Each figure's best of the two.
    fn best(self, other: Self) -> Self {
        Self {
            frame: self.frame.min(other.frame),
            forces: self.forces.min(other.forces),
            contacts: self.contacts.min(other.contacts),
            rapier: self.rapier.min(other.rapier),
            rest: self.rest.min(other.rest),
        }
    }

    fn figures(self) -> [(&'static str, f64); 5] {
        [
            ("frame", self.frame),
            ("forces", self.forces),
            ("contacts", self.contacts),
            ("rapier", self.rapier),
            ("rest", self.rest),
        ]
    }
}

/// One run of `frames` frames after the first `WARM`, in a pool of `threads` kept awake
/// through the substeps or not (`RapierLayout::set_pool_awake`), and every node's final
/// position as bits.
fn time(
    name: &str,
    config: &RapierLayoutConfig,
    (threads, awake): (usize, bool),
    frames: usize,
) -> (Run, Vec<u32>) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool");
    let mut host = Host::new(load(name), config.clone());
    host.layout.set_pool_awake(awake);
    pool.install(|| {
        for _ in 0..WARM {
            host.frame(1.0 / 60.0);
        }
        host.layout.set_profiling(true);
        let started = Instant::now();
        for _ in 0..frames {
            host.frame(1.0 / 60.0);
        }
        let elapsed = started.elapsed();
        let profile = host.layout.profile().expect("profiling is on");
        let bits = host
            .scene
            .nodes
            .iter()
            .flat_map(|n| [n.position.x.to_bits(), n.position.y.to_bits()])
            .collect();
        (Run::of(elapsed, profile, frames), bits)
    })
}

/// Pieces of work with nothing shared: each an arithmetic chain (a logistic map with a
/// square root, as latency-bound as the layout's sums) or the sum of the piece's
/// 64th of `buffer` in 16 lanes (vectorised: bound by memory, the buffer being twice
/// the size of this machine's last cache).
fn ceiling_work(piece: usize, streamed: bool, buffer: &[f32]) -> f64 {
    if !streamed {
        let mut x = 0.5 + piece as f64 * 1e-6;
        let mut sum = 0.0;
        for i in 0..400_000_u32 {
            x = (x * 3.7 * (1.0 - x)).abs();
            sum += x.sqrt() * f64::from(i % 7);
        }
        sum
    } else {
        let share = buffer.len() / 64;
        let mut lanes = [0.0_f32; 16];
        for chunk in buffer[piece * share..(piece + 1) * share].chunks_exact(16) {
            for (lane, &v) in lanes.iter_mut().zip(chunk) {
                *lane += v;
            }
        }
        lanes.iter().map(|&l| f64::from(l)).sum()
    }
}

/// The ceiling's times (ms: the arithmetic, then the streamed sums) on a pool of
/// `threads`, and its result (the same on any).
fn ceiling(threads: usize, buffer: &[f32]) -> ([f64; 2], f64) {
    use rayon::prelude::*;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool");
    pool.install(|| {
        let (mut times, mut sum) = ([0.0; 2], 0.0);
        for (streamed, time) in [false, true].into_iter().zip(&mut times) {
            let started = Instant::now();
            let pieces: Vec<f64> = (0..64_usize)
                .into_par_iter()
                .map(|piece| ceiling_work(piece, streamed, buffer))
                .collect();
            *time = started.elapsed().as_secs_f64() * 1000.0;
            sum += pieces.iter().sum::<f64>();
        }
        (times, sum)
    })
}

fn main() {
    let mut args = std::env::args().skip(1);
    let name = args.next().unwrap_or_else(|| "n10000_e25000".into());
    let preset = args.next().unwrap_or_else(|| "force_directed".into());
    let frames: usize = args.next().and_then(|f| f.parse().ok()).unwrap_or(240);
    let runs: usize = args.next().and_then(|r| r.parse().ok()).unwrap_or(3).max(1);
    let config = match preset.as_str() {
        "stress" => RapierLayoutConfig::stress(),
        _ => RapierLayoutConfig::force_directed(),
    };
    // 1 thread; 2 threads awake through the substeps (the default); 2 threads that
    // sleep between the parallel parts.
    let pools = [(1, true), (2, true), (2, false)];
    let (mut best, mut bits) = ([Run::INFINITE; 3], [Vec::new(), Vec::new(), Vec::new()]);
    let buffer: Vec<f32> = (0..16 << 20).map(|i| (i % 1_000) as f32).collect();
    let mut ceiling_best = [[f64::INFINITY; 2]; 2];
    for run in 0..runs {
        let (one, sum_one) = ceiling(1, &buffer);
        let (two, sum_two) = ceiling(2, &buffer);
        assert_eq!(
            sum_one.to_bits(),
            sum_two.to_bits(),
            "the ceiling's pieces are fixed"
        );
        for (best, now) in ceiling_best.iter_mut().zip([one, two]) {
            *best = [best[0].min(now[0]), best[1].min(now[1])];
        }
        for (k, pool) in pools.into_iter().enumerate() {
            let (measured, positions) = time(&name, &config, pool, frames);
            let asleep = if pool.1 { "" } else { ", asleep between parts" };
            println!(
                "{name} {preset} run {run}: {} thread(s){asleep} {:.2} ms a frame",
                pool.0, measured.frame
            );
            best[k] = best[k].best(measured);
            bits[k] = positions;
        }
    }
    assert!(
        bits[0] == bits[1] && bits[1] == bits[2],
        "1 and 2 threads, awake or not, must give the same bits"
    );
    println!("stage     1 thread  2 threads  ratio  2 asleep  ratio  (ms a frame, best of {runs})");
    let rows = best[0]
        .figures()
        .into_iter()
        .zip(best[1].figures())
        .zip(best[2].figures());
    for (((stage, one), (_, two)), (_, asleep)) in rows {
        println!(
            "{stage:<9} {one:>8.2}  {two:>9.2}  {:>5.2}  {asleep:>8.2}  {:>5.2}",
            two / one,
            asleep / one
        );
    }
    let ceiling_ratio = |kind: usize| ceiling_best[1][kind] / ceiling_best[0][kind];
    for (kind, what) in ["arithmetic", "streamed"].into_iter().enumerate() {
        println!(
            "ceiling   {:>8.2}  {:>9.2}  {:>5.2}  ({what} work with nothing shared, ms for 64 pieces)",
            ceiling_best[0][kind],
            ceiling_best[1][kind],
            ceiling_ratio(kind)
        );
    }
    let own = |r: Run| r.forces + r.contacts;
    println!(
        "threads: {name} {preset} best of {runs}: 1 thread {:.2} ms, 2 threads {:.2} ms, ratio {:.2}; own forces and contacts ratio {:.2}; asleep between parts {:.2} and {:.2}; the machine's ceiling {:.2} and {:.2} (same bits, digest {:016x})",
        best[0].frame,
        best[1].frame,
        best[1].frame / best[0].frame,
        own(best[1]) / own(best[0]),
        best[2].frame / best[0].frame,
        own(best[2]) / own(best[0]),
        ceiling_ratio(0),
        ceiling_ratio(1),
        digest(&bits[0])
    );
}

/// An FNV-1a hash of the final positions' bits, to compare builds by.
fn digest(bits: &[u32]) -> u64 {
    let mut hash = Fnv::new();
    for &b in bits {
        hash.write_u32(b);
    }
    hash.finish()
}
