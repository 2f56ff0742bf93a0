//! Under the `parallel` feature the layout's own forces (Barnes–Hut repulsion, the
//! springs, the stress terms), its contacts (the pair search and the Gauss–Seidel
//! passes, block by block) and rapier's solver run on rayon's pool. The work is cut into
//! pieces that do not depend on the thread count and joined in order, so a layout is
//! bit-identical on one thread and on several. With fewer than 8,192 contact pairs (one
//! block of the passes) it is also the same bits as a build without the feature (the
//! `fingerprint` example); beyond, the passes solve the pairs in the blocks' order.
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
    pool.install(|| positions_after(Host::new(load_scene(scene), config), frames))
}

/// Every node's position, as bits, after each of `frames` frames of `host`.
fn positions_after(mut host: Host<u32>, frames: usize) -> Vec<Vec<u32>> {
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

/// 10,000 nodes and 25,000 springs: the contacts' passes cut into blocks (16,000 to
/// 52,000 pairs a substep once contacts start, at frame 50 or so), the springs summed
/// body by body, the pair search, the warm start and the tree's points in runs: all of
/// it the same bits on one thread and on two.
#[test]
fn a_large_layout_is_bit_identical_on_one_thread_and_on_two() {
    let frames = 100;
    let one = run(
        "n10000_e25000",
        RapierLayoutConfig::force_directed(),
        1,
        frames,
    );
    let two = run(
        "n10000_e25000",
        RapierLayoutConfig::force_directed(),
        2,
        frames,
    );
    let moved = one[frames - 2] != one[frames - 1];
    assert!(moved, "nothing moved by frame {frames}");
    assert_eq!(
        first_difference(&one, &two),
        None,
        "(frame, node) where 2 threads first differ from 1"
    );
}

/// The default configuration leaves contacts and edges to rapier (colliders and
/// joints), whose parallel solver splits its work by the pool's size: on a given
/// number of threads, a layout is still the same bits run after run.
#[test]
fn rapiers_contacts_give_the_same_bits_on_the_same_pool() {
    let first = run("1138_bus", RapierLayoutConfig::default(), 2, 60);
    let again = run("1138_bus", RapierLayoutConfig::default(), 2, 60);
    assert!(first.first() != first.last(), "nothing moved in 60 frames");
    assert_eq!(
        first_difference(&first, &again),
        None,
        "(frame, node) where a second run on 2 threads first differs"
    );
}

/// A worker on a pool of one thread of its own (the host's UI thread keeps the other
/// core) lays a ring out to rest, with the node the host pinned where it was.
#[test]
fn a_worker_on_a_pool_of_its_own_lays_a_ring_out() {
    use graph_canvas_layout::euclid::default::Point2D;
    use graph_canvas_layout::{CanvasEdge, CanvasNode, CanvasSceneInput, LayoutWorker};
    let scene = CanvasSceneInput::new(
        (0..12)
            .map(|i| CanvasNode::new(i, Point2D::new(i as f32, 0.0)))
            .collect(),
        (0..12).map(|i| CanvasEdge::new(i, (i + 1) % 12)).collect(),
    );
    let mut extras = graph_canvas_layout::LayoutExtras::default();
    extras.pinned.insert(0);
    let mut worker = LayoutWorker::spawn_on_threads(
        scene,
        RapierLayoutConfig::stress(),
        extras,
        std::time::Duration::from_millis(2),
        1,
    );
    let started = std::time::Instant::now();
    while !worker.is_converged() {
        assert!(
            started.elapsed().as_secs() < 60,
            "not at rest within a minute"
        );
        std::thread::sleep(std::time::Duration::from_millis(5));
        worker.frame();
    }
    let (pinned, across) = (worker.position(&0).unwrap(), worker.position(&6).unwrap());
    assert_eq!(pinned, Point2D::new(0.0, 0.0), "the pinned node moved");
    assert!(
        (across - pinned).length() > 100.0,
        "opposite nodes of the ring {:?} apart",
        across - pinned
    );
}

/// From 2,048 awake bodies on, the pool's other threads stay awake through a call's
/// substeps unless the host says otherwise (`RapierLayout::set_pool_awake`). Awake or
/// not, and called from a pool's thread or from a thread outside any pool (rayon's
/// global pool then takes the parts), `3elt` (4,720 nodes) is the same bits: which
/// thread takes which part changes nothing, and nothing waits for ever.
#[test]
fn keeping_the_pool_awake_changes_no_bit() {
    let frames = 30;
    let host = |awake: bool| {
        let mut host = Host::new(load_scene("3elt"), RapierLayoutConfig::force_directed());
        host.layout.set_pool_awake(awake);
        host
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a rayon pool");
    let awake = pool.install(|| positions_after(host(true), frames));
    let asleep = pool.install(|| positions_after(host(false), frames));
    assert!(
        awake[0] != awake[frames - 1],
        "nothing moved in {frames} frames"
    );
    assert_eq!(
        first_difference(&awake, &asleep),
        None,
        "(frame, node) where a pool left to sleep first differs from one kept awake"
    );
    // From a thread of no pool: a deadlock between the caller and the threads kept
    // awake would never answer, so the wait is bounded (far above the second or so the
    // frames take).
    let (sender, receiver) = std::sync::mpsc::channel();
    let outside = host(true);
    std::thread::spawn(move || sender.send(positions_after(outside, frames)));
    let limit = std::time::Duration::from_secs(300);
    let outside = receiver.recv_timeout(limit).unwrap_or_else(|e| {
        panic!("frames called from outside any pool: no answer in {limit:?} ({e})")
    });
    assert_eq!(
        first_difference(&awake, &outside),
        None,
        "(frame, node) where frames called from outside any pool first differ"
    );
}

/// Two layouts stepped side by side on one pool of 2 threads (`rayon::join`, frame by
/// frame), each handing the pool a thread to keep awake through its substeps while the
/// other's parts run on the same threads: both finish with the same bits as each laid
/// out alone. (A thread kept awake for one layout above the other's parts on its stack
/// could hold both up; the wait is bounded so that a hang fails.)
#[test]
fn layouts_stepped_side_by_side_on_one_pool_keep_their_bits() {
    let frames = 20;
    let host = || Host::new(load_scene("3elt"), RapierLayoutConfig::force_directed());
    let alone = run("3elt", RapierLayoutConfig::force_directed(), 2, frames);
    let (sender, receiver) = std::sync::mpsc::channel();
    let (mut first, mut second) = (host(), host());
    std::thread::spawn(move || {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .expect("a rayon pool");
        let bits = |host: &Host<u32>| -> Vec<u32> {
            host.scene
                .nodes
                .iter()
                .flat_map(|n| [n.position.x.to_bits(), n.position.y.to_bits()])
                .collect()
        };
        let side_by_side: Vec<(Vec<u32>, Vec<u32>)> = pool.install(|| {
            (0..frames)
                .map(|_| {
                    rayon::join(|| first.frame(FRAME), || second.frame(FRAME));
                    (bits(&first), bits(&second))
                })
                .collect()
        });
        sender.send(side_by_side)
    });
    let limit = std::time::Duration::from_secs(300);
    let side_by_side = receiver
        .recv_timeout(limit)
        .unwrap_or_else(|e| panic!("two layouts side by side: no answer in {limit:?} ({e})"));
    let (first, second): (Vec<_>, Vec<_>) = side_by_side.into_iter().unzip();
    assert_eq!(
        first_difference(&alone, &first),
        None,
        "(frame, node) where the first of two layouts side by side differs from one alone"
    );
    assert_eq!(
        first_difference(&alone, &second),
        None,
        "(frame, node) where the second of two layouts side by side differs from one alone"
    );
}
