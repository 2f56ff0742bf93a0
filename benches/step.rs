//! Per-frame cost of the layout against rapier's own step, and what the persistent
//! world saves over a rebuild per frame.
//!
//! Moving-state benchmarks time frames 30..270 of a layout started from the scene file
//! (the graph is still in motion then) and restart from a fresh, warmed layout every 240
//! timed frames, so every sample measures the same kind of state: the mean frame of whole
//! windows, however few calls criterion asks for. `asleep` benchmarks
//! time a layout that `is_converged`. The `very_big` group times the first 60 frames of
//! a 100,000-node graph, the world's first build included: what a host waits through
//! when such a graph opens (about two minutes; alone: `cargo bench --bench step --
//! random_n100000`).

mod common;

use std::time::{Duration, Instant};

use common::*;
use criterion::{black_box, criterion_group, criterion_main, Criterion, SamplingMode};
use graph_canvas_layout::config::Accuracy;
use graph_canvas_layout::config::{Contacts, Solver};
use graph_canvas_layout::{Layout, RapierLayoutConfig};

const WARM: usize = 30;
const CHUNK: u64 = 240;

/// Times `step` over whole windows of frames `WARM..WARM + CHUNK` of fresh states made by
/// `make`, and scales the total to `iters` calls: every sample is the mean frame of
/// complete windows, so a slow benchmark, sampled a few calls at a time, is not timed on
/// its first frames only.
fn chunked<S>(iters: u64, mut make: impl FnMut() -> S, mut step: impl FnMut(&mut S)) -> Duration {
    let windows = iters.div_ceil(CHUNK).max(1);
    let mut total = Duration::ZERO;
    for _ in 0..windows {
        let mut state = make();
        for _ in 0..WARM {
            step(&mut state);
        }
        let started = Instant::now();
        for _ in 0..CHUNK {
            step(&mut state);
        }
        total += started.elapsed();
    }
    total.mul_f64(iters as f64 / (windows * CHUNK) as f64)
}

/// The layout's step while the graph moves; asserts it does move.
fn persistent(c: &mut Criterion, name: &str, config: RapierLayoutConfig, label: &str) {
    persistent_from(c, name, scene(name), config, label);
}

/// `scene` with the positions a default layout reaches after `frames` frames: the
/// random scenes start as a uniform scatter whose long edges collapse it for seconds, a
/// transient no canvas user looks at twice. Large scenes are timed from there.
fn relaxed(name: &str, frames: usize) -> graph_canvas_layout::CanvasSceneInput<u32> {
    let mut host = Host::new(scene(name), RapierLayoutConfig::default());
    for _ in 0..frames {
        host.frame();
    }
    host.scene
}

fn persistent_from(
    c: &mut Criterion,
    name: &str,
    scene: graph_canvas_layout::CanvasSceneInput<u32>,
    config: RapierLayoutConfig,
    label: &str,
) {
    let probe = {
        let mut host = Host::new(scene.clone(), config.clone());
        (0..WARM).map(|_| host.frame().len()).last().unwrap_or(0)
    };
    assert!(
        probe > 0,
        "{name}: nothing moves after {WARM} frames, the benchmark would time a resting world"
    );
    c.bench_function(&format!("step/{name}/{label}"), |b| {
        b.iter_custom(|iters| {
            chunked(
                iters,
                || Host::new(scene.clone(), config.clone()),
                |h| {
                    black_box(h.frame());
                },
            )
        })
    });
}

/// The first `frames` frames of a fresh layout of `name`, its first build included, as
/// the mean frame of whole runs (each run lays the graph out anew); asserts it moves.
fn first_frames(
    c: &mut Criterion,
    name: &str,
    config: RapierLayoutConfig,
    frames: u64,
    label: &str,
) {
    let scene = scene(name);
    let mut group = c.benchmark_group(format!("step/{name}"));
    // Every sample the same number of whole runs.
    group.sampling_mode(SamplingMode::Flat);
    group.bench_function(label, |b| {
        b.iter_custom(|iters| {
            let runs = iters.div_ceil(frames).max(1);
            let mut total = Duration::ZERO;
            for _ in 0..runs {
                let mut host = Host::new(scene.clone(), config.clone());
                let mut moved = 0;
                let started = Instant::now();
                for _ in 0..frames {
                    moved += black_box(host.frame()).len();
                }
                total += started.elapsed();
                assert!(moved > 0, "{name}: nothing moved in {frames} frames");
            }
            total.mul_f64(iters as f64 / (runs * frames) as f64)
        })
    });
    group.finish();
}

fn bare(c: &mut Criterion, name: &str, model: BareModel, label: &str) {
    bare_from(c, name, &scene(name), model, label);
}

fn bare_from(
    c: &mut Criterion,
    name: &str,
    scene: &graph_canvas_layout::CanvasSceneInput<u32>,
    model: BareModel,
    label: &str,
) {
    c.bench_function(&format!("step/{name}/{label}"), |b| {
        b.iter_custom(|iters| chunked(iters, || Bare::new(scene, model), |w| w.step()))
    });
}

/// The plan's first revision, a fresh world every frame, timed on the same states the
/// persistent layout passes through: the host positions of frames `WARM..WARM + CHUNK`
/// of a persistent run are replayed, each into a new layout that builds and steps once.
fn rebuild_per_step(c: &mut Criterion, name: &str) {
    let mut host = Host::new(scene(name), RapierLayoutConfig::default());
    for _ in 0..WARM {
        host.frame();
    }
    let states: Vec<_> = (0..CHUNK)
        .map(|_| {
            let s = host.scene.clone();
            host.frame();
            s
        })
        .collect();
    let mut i = 0;
    c.bench_function(&format!("step/{name}/rebuild_per_step"), |b| {
        b.iter(|| {
            let mut layout = graph_canvas_layout::RapierLayout::new(RapierLayoutConfig::default());
            let deltas = layout.step(
                &states[i],
                &mut Default::default(),
                FRAME,
                &Default::default(),
                &Default::default(),
            );
            assert!(!deltas.is_empty(), "frame {i} of {name} did not move");
            i = (i + 1) % states.len();
            deltas
        })
    });
}

fn asleep(c: &mut Criterion, name: &str) {
    let scene = scene(name);
    let mut host = Host::new(scene.clone(), RapierLayoutConfig::default());
    let mut frames = 0;
    while !host.layout.is_converged(&host.state) {
        host.frame();
        frames += 1;
        assert!(frames < 20_000, "{name} did not converge in 20,000 frames");
    }
    c.bench_function(&format!("step/{name}/asleep"), |b| {
        b.iter(|| black_box(host.frame()))
    });
    let mut bare_world = Bare::new(&host.scene, BareModel::Layout);
    for _ in 0..2000 {
        bare_world.step();
    }
    c.bench_function(&format!("step/{name}/rapier_floor_asleep"), |b| {
        b.iter(|| bare_world.step())
    });
}

fn topology_check(c: &mut Criterion) {
    let scene = scene("n200_e500");
    let mut host = Host::new(scene.clone(), RapierLayoutConfig::default());
    host.frame();
    let extras = host.extras.clone();
    c.bench_function("topology_check/n200_e500", |b| {
        b.iter(|| {
            assert!(!host
                .layout
                .topology_changed(black_box(&host.scene), &extras))
        })
    });
    let mut shuffled = scene.clone();
    shuffled.nodes.reverse();
    shuffled.edges.reverse();
    c.bench_function("topology_check/n200_e500/reordered_input", |b| {
        b.iter(|| assert!(!host.layout.topology_changed(black_box(&shuffled), &extras)))
    });
    c.bench_function("topology_hash/n200_e500", |b| {
        b.iter(|| graph_canvas_layout::scene::topology_hash(black_box(&scene), &extras))
    });
}

fn headline(c: &mut Criterion) {
    persistent(c, "n200_e500", RapierLayoutConfig::default(), "persistent");
    bare(c, "n200_e500", BareModel::Layout, "rapier_floor");
    bare(
        c,
        "n200_e500",
        BareModel::RotatingEvents,
        "rotating_events_floor",
    );
    // What each modelling choice saves.
    bare(
        c,
        "n200_e500",
        BareModel::LayoutRotating,
        "rapier_floor_rotating",
    );
    let no_collisions = RapierLayoutConfig {
        contacts: Contacts {
            enabled: false,
            ..Default::default()
        },
        ..Default::default()
    };
    persistent(c, "n200_e500", no_collisions, "persistent_no_collisions");
    let events = RapierLayoutConfig {
        contacts: Contacts {
            events: true,
            ..Default::default()
        },
        ..Default::default()
    };
    persistent(c, "n200_e500", events, "persistent_contact_events");
    rebuild_per_step(c, "n200_e500");
    topology_check(c);
    asleep(c, "n200_e500");
}

fn presets(c: &mut Criterion) {
    for (label, accuracy) in [
        ("fast", Accuracy::Fast),
        ("balanced", Accuracy::Balanced),
        ("precise", Accuracy::Precise),
    ] {
        let config = RapierLayoutConfig {
            solver: Solver {
                accuracy,
                ..Default::default()
            },
            ..Default::default()
        };
        persistent(c, "n200_e500", config, &format!("persistent_{label}"));
    }
}

/// `force_directed()` (repulsion, shared and biased springs, contacts, cooling) while
/// the graph unfolds: d3-force's tick on the same scenes is the yardstick (docs/performance.md).
fn force_directed(c: &mut Criterion) {
    first_frames(
        c,
        "1138_bus",
        RapierLayoutConfig::stress(),
        150,
        "stress_first_150",
    );
    for name in ["n200_e500", "n1000_e2500"] {
        persistent(
            c,
            name,
            RapierLayoutConfig::force_directed(),
            "force_directed",
        );
        persistent(
            c,
            name,
            RapierLayoutConfig::force_directed_fast(),
            "force_directed_fast",
        );
    }
}

fn scaling(c: &mut Criterion) {
    for name in [
        "n1000_e2500",
        "tree_1023",
        "grid_30x30",
        "star_2001",
        "ba_n2000",
    ] {
        persistent(c, name, RapierLayoutConfig::default(), "persistent");
    }
    rebuild_per_step(c, "n1000_e2500");
}

fn large(c: &mut Criterion) {
    // Both force-directed settings on the largest scene, unfolding from the file.
    persistent(
        c,
        "n10000_e25000",
        RapierLayoutConfig::force_directed_fast(),
        "force_directed_fast",
    );
    persistent(
        c,
        "n10000_e25000",
        RapierLayoutConfig::force_directed(),
        "force_directed",
    );
    // The same with every node a label box ("node <id>", 7 units a character by 20):
    // what shape-aware contacts cost over disks.
    persistent_from(
        c,
        "n10000_e25000",
        generate::label_boxes(scene("n10000_e25000"), |_| false),
        RapierLayoutConfig::force_directed(),
        "force_directed_boxes",
    );
    // Disks of the boxes' area (radius 20): what size alone costs.
    let mut wide = scene("n10000_e25000");
    for node in &mut wide.nodes {
        node.radius = 20.0;
    }
    persistent_from(
        c,
        "n10000_e25000",
        wide,
        RapierLayoutConfig::force_directed(),
        "force_directed_disks_r20",
    );
    // The stress model: the first 150 frames, start included (its graphs rest within
    // them): the flat-out wall time to rest that docs/quality.md sets beside sfdp's.
    for name in ["3elt", "rgg_10000", "n10000_e25000"] {
        first_frames(
            c,
            name,
            RapierLayoutConfig::stress(),
            150,
            "stress_first_150",
        );
    }
    // Hubs: Barabási–Albert, 10,000 nodes, m = 2, on d3's spiral.
    persistent(
        c,
        "ba_n10000_m2",
        RapierLayoutConfig::force_directed(),
        "force_directed",
    );
    for name in ["n5000_e12500", "n10000_e25000"] {
        let start = relaxed(name, 300);
        persistent_from(
            c,
            name,
            start.clone(),
            RapierLayoutConfig::default(),
            "persistent",
        );
        let fast = RapierLayoutConfig {
            solver: Solver {
                accuracy: Accuracy::Fast,
                ..Default::default()
            },
            ..Default::default()
        };
        persistent_from(c, name, start.clone(), fast, "persistent_fast");
        bare_from(c, name, &start, BareModel::Layout, "rapier_floor");
        bare_from(
            c,
            name,
            &start,
            BareModel::RotatingEvents,
            "rotating_events_floor",
        );
    }
}

criterion_group! {
    name = small;
    config = Criterion::default().sample_size(30).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(4));
    targets = headline, presets, force_directed, scaling
}
/// The first 60 frames of a random graph of 100,000 nodes and 250,000 edges (seeded,
/// on d3's spiral): docs/performance.md sets their mean beside d3-force's tick. And the stress
/// model's first frame on it and on a random geometric graph of 100,000 nodes.
fn huge(c: &mut Criterion) {
    first_frames(
        c,
        "random_n100000_e250000",
        RapierLayoutConfig::force_directed(),
        60,
        "force_directed_first_60",
    );
    // The stress model's first frame, the global start included.
    for name in ["random_n100000_e250000", "rgg_n100000"] {
        first_frames(
            c,
            name,
            RapierLayoutConfig::stress(),
            1,
            "stress_first_frame",
        );
    }
}

criterion_group! {
    name = big;
    config = Criterion::default().sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(8));
    targets = large
}
criterion_group! {
    name = very_big;
    // Each sample times whole 60-frame runs (about 10 s each).
    config = Criterion::default().sample_size(10).warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(90));
    targets = huge
}
criterion_main!(small, big, very_big);
