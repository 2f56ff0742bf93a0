//! Under the `parallel` feature the layout's own forces (Barnes–Hut repulsion, the
//! contacts' pair search, the stress terms) and rapier's solver run on rayon's pool. The
//! work is cut into pieces that do not depend on the thread count and joined in order,
//! so a layout is bit-identical on one thread and on several (and, by the
//! `fingerprint` example, to a build without the feature).
//!
//! Run with `cargo test --features parallel --test parallel`.
#![cfg(feature = "parallel")]

mod common;

use common::*;
use graph_canvas_layout::RapierLayoutConfig;

/// Every node's position, as bits, after each of `frames` frames of `scene` laid out by
/// `config` on a pool of `threads` threads.
fn run(scene: &str, config: RapierLayoutConfig, threads: usize, frames: usize) -> Vec<Vec<u32>> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool");
    pool.install(|| {
        let mut host = Host::new(load_scene(scene), config);
        (0..frames)
            .map(|_| {
                host.frame(FRAME);
                host.scene
                    .nodes
                    .iter()
                    .flat_map(|n| [n.position.x.to_bits(), n.position.y.to_bits()])
                    .collect()
            })
            .collect()
    })
}

/// The first frame whose positions differ, with the first node that differs.
fn first_difference(a: &[Vec<u32>], b: &[Vec<u32>]) -> Option<(usize, usize)> {
    a.iter().zip(b).enumerate().find_map(|(frame, (x, y))| {
        x.iter()
            .zip(y)
            .position(|(p, q)| p != q)
            .map(|coordinate| (frame, coordinate / 2))
    })
}

/// 1138 nodes: three runs of the stress terms, two of the pair search and a few dozen
/// Barnes–Hut groups, so two threads split every force.
#[test]
fn a_layout_is_bit_identical_on_one_thread_and_on_two() {
    for (name, config) in [
        ("force_directed", RapierLayoutConfig::force_directed()),
        ("stress", RapierLayoutConfig::stress()),
    ] {
        let one = run("1138_bus", config.clone(), 1, 90);
        let two = run("1138_bus", config, 2, 90);
        assert_eq!(one.len(), 90, "{name}");
        let moved = one.first() != one.last();
        assert!(
            moved,
            "{name}: nothing moved in 90 frames, the test compares rests"
        );
        assert_eq!(
            first_difference(&one, &two),
            None,
            "{name}: (frame, node) where 2 threads first differ from 1"
        );
    }
}
