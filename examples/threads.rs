//! The layout's step on rayon pools of 1 and 2 threads (feature `parallel`): frames
//! 30..30+N of a layout from the scene file, in pools built alternately, best of three
//! runs each, and the ratio.
//!
//! `cargo run --release --features parallel --example threads -- [scene] [preset] [frames]`
//! (defaults `n10000_e25000 force_directed 240`; `preset` is `force_directed` or
//! `stress`; a generated name such as `random_n100000_e250000` works too).

mod common;

use std::time::Instant;

use common::*;
use graph_canvas_layout::RapierLayoutConfig;

const WARM: usize = 30;
const RUNS: usize = 3;

/// The mean frame (ms) of `frames` frames after the first `WARM`, in a pool of `threads`,
/// and every node's final position as bits.
fn time(name: &str, config: &RapierLayoutConfig, threads: usize, frames: usize) -> (f64, Vec<u32>) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool");
    let mut host = Host::new(load(name), config.clone());
    pool.install(|| {
        for _ in 0..WARM {
            host.frame(1.0 / 60.0);
        }
        let started = Instant::now();
        for _ in 0..frames {
            host.frame(1.0 / 60.0);
        }
        let ms = started.elapsed().as_secs_f64() * 1000.0 / frames as f64;
        let bits = host
            .scene
            .nodes
            .iter()
            .flat_map(|n| [n.position.x.to_bits(), n.position.y.to_bits()])
            .collect();
        (ms, bits)
    })
}

fn main() {
    let mut args = std::env::args().skip(1);
    let name = args.next().unwrap_or_else(|| "n10000_e25000".into());
    let preset = args.next().unwrap_or_else(|| "force_directed".into());
    let frames: usize = args.next().and_then(|f| f.parse().ok()).unwrap_or(240);
    let config = match preset.as_str() {
        "stress" => RapierLayoutConfig::stress(),
        _ => RapierLayoutConfig::force_directed(),
    };
    let (mut best, mut bits) = ([f64::INFINITY; 2], [Vec::new(), Vec::new()]);
    for run in 0..RUNS {
        for (k, threads) in [1, 2].into_iter().enumerate() {
            let (ms, positions) = time(&name, &config, threads, frames);
            println!("{name} {preset} run {run}: {threads} thread(s) {ms:.2} ms a frame");
            best[k] = best[k].min(ms);
            bits[k] = positions;
        }
    }
    assert_eq!(bits[0], bits[1], "1 and 2 threads must give the same bits");
    println!(
        "threads: {name} {preset} best of {RUNS}: 1 thread {:.2} ms, 2 threads {:.2} ms, ratio {:.2} (same bits)",
        best[0],
        best[1],
        best[1] / best[0]
    );
}
