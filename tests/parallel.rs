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

#[path = "../benches/common/generate.rs"]
#[allow(dead_code)]
mod generate;

use common::*;
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::RapierLayoutConfig;

/// Every node's position, as bits, after each of `frames` frames of `scene` laid out by
/// `config` on a pool of `threads` threads.
fn run(scene: &str, config: RapierLayoutConfig, threads: usize, frames: usize) -> Vec<Vec<u32>> {
    pool(threads).install(|| positions_after(Host::new(load_scene(scene), config), frames))
}

/// Every node's position in `host`'s scene, as bits.
fn bits(host: &Host<u32>) -> Vec<u32> {
    host.scene
        .nodes
        .iter()
        .flat_map(|n| [n.position.x.to_bits(), n.position.y.to_bits()])
        .collect()
}

/// Every node's position, as bits, after each of `frames` frames of `host`.
fn positions_after(mut host: Host<u32>, frames: usize) -> Vec<Vec<u32>> {
    (0..frames)
        .map(|_| {
            host.frame(FRAME);
            bits(&host)
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

/// Ten clusters of 100 (one per community) under stress(): the parting of the boxes,
/// between the parallel forces and rapier's step, gives the same bits on one thread and
/// on two.
#[test]
fn a_clustered_layout_is_bit_identical_on_one_thread_and_on_two() {
    let scene = generate::communities(10, 100, 3, 4, 7);
    let mut members = vec![Vec::new(); 10];
    for n in &scene.nodes {
        members[generate::community(n.id, 100)].push(n.id);
    }
    let clusters: Vec<Cluster<u32>> = members.into_iter().map(Cluster::new).collect();
    let run = |threads: usize| {
        pool(threads).install(|| {
            let mut host = Host::new(scene.clone(), RapierLayoutConfig::stress());
            host.extras.clusters = clusters.clone();
            positions_after(host, 90)
        })
    };
    let (one, two) = (run(1), run(2));
    assert_ne!(one.first(), one.last(), "nothing moved in 90 frames");
    assert_eq!(
        first_difference(&one, &two),
        None,
        "(frame, node) where 2 threads first differ from 1"
    );
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
    use graph_canvas_layout::worker::LayoutWorker;
    use graph_canvas_layout::{CanvasEdge, CanvasNode, CanvasSceneInput};
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

/// What `f` returns, run on a thread of its own: a hang fails the test after
/// `LIMIT` (far above the seconds these layouts take) instead of holding CI.
fn bounded<T: Send + 'static>(what: &str, f: impl FnOnce() -> T + Send + 'static) -> T {
    const LIMIT: std::time::Duration = std::time::Duration::from_secs(300);
    let (sender, receiver) = std::sync::mpsc::channel();
    std::thread::spawn(move || sender.send(f()));
    receiver
        .recv_timeout(LIMIT)
        .unwrap_or_else(|e| panic!("{what}: no answer in {LIMIT:?} ({e})"))
}

/// A `3elt` host (4,720 nodes, so a thread is kept awake through the first frames'
/// substeps unless `awake` is false).
fn host_3elt(awake: bool) -> Host<u32> {
    let mut host = Host::new(load_scene("3elt"), RapierLayoutConfig::force_directed());
    host.layout.set_pool_awake(awake);
    host
}

/// A pool of `threads` threads.
fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a rayon pool")
}

/// From 2,048 awake bodies on, another thread of the pool stays awake through each
/// substep unless the host says otherwise (`RapierLayout::set_pool_awake`). Awake or
/// not, on 2 or 4 threads, and called from a thread outside any pool (rayon's global
/// pool then takes the parts), `3elt` is the same bits: which thread takes which part
/// changes nothing, and nothing waits for ever.
#[test]
fn keeping_the_pool_awake_changes_no_bit() {
    const FRAMES: usize = 30;
    let on = |threads: usize, awake: bool| {
        bounded("frames on a pool", move || {
            pool(threads).install(|| positions_after(host_3elt(awake), FRAMES))
        })
    };
    let awake = on(2, true);
    assert!(
        awake[0] != awake[FRAMES - 1],
        "nothing moved in {FRAMES} frames"
    );
    for (label, other) in [
        ("2 threads left to sleep", on(2, false)),
        ("4 threads kept awake", on(4, true)),
        (
            "frames called from outside any pool",
            bounded("frames from outside any pool", || {
                positions_after(host_3elt(true), FRAMES)
            }),
        ),
    ] {
        assert_eq!(
            first_difference(&awake, &other),
            None,
            "(frame, node) where {label} first differ from 2 threads kept awake"
        );
    }
}

/// Two layouts stepped side by side on one pool (`rayon::join`, frame by frame), each
/// handing the pool a thread to keep awake through its substeps while the other's
/// parts run on the same threads: on 2 threads and on 4 (where a kept thread can take
/// the other layout's parts, and sit above them), both finish with the same bits as
/// each laid out alone, within a bounded wait.
#[test]
fn layouts_stepped_side_by_side_on_one_pool_keep_their_bits() {
    const FRAMES: usize = 20;
    let alone = run("3elt", RapierLayoutConfig::force_directed(), 2, FRAMES);
    for threads in [2, 4] {
        let (first, second): (Vec<Vec<u32>>, Vec<Vec<u32>>) =
            bounded("two layouts side by side", move || {
                let (mut first, mut second) = (host_3elt(true), host_3elt(true));
                pool(threads).install(|| {
                    (0..FRAMES)
                        .map(|_| {
                            rayon::join(|| first.frame(FRAME), || second.frame(FRAME));
                            (bits(&first), bits(&second))
                        })
                        .unzip()
                })
            });
        for (which, laid_out) in [("first", first), ("second", second)] {
            assert_eq!(
                first_difference(&alone, &laid_out),
                None,
                "{threads} threads: (frame, node) where the {which} of two layouts side by side differs from one alone"
            );
        }
    }
}
