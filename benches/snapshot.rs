//! Keep and resume: taking a snapshot of a layout in motion and restoring it into a new
//! layout, at n = 10,000 under `force_directed()` (the scene laid out for 100 frames
//! from the file). Each asserts what it produced: a snapshot of every node, and a
//! restored layout whose next call moves the same nodes as the original's.
//!
//! `cargo bench --bench snapshot`.

mod common;

use std::time::Duration;

use common::*;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use graph_canvas_layout::{RapierLayout, RapierLayoutConfig};

fn snapshots(c: &mut Criterion) {
    let name = "n10000_e25000";
    let mut host = Host::new(scene(name), RapierLayoutConfig::force_directed());
    for _ in 0..100 {
        host.frame();
    }
    let n = host.scene.nodes.len();
    c.bench_function(&format!("snapshot/{name}/force_directed/take"), |b| {
        b.iter(|| black_box(host.layout.snapshot()))
    });
    let snapshot = host.layout.snapshot();
    assert_eq!(snapshot.node_count(), n, "a snapshot of every node");
    c.bench_function(&format!("snapshot/{name}/force_directed/restore"), |b| {
        b.iter_batched(
            || snapshot.clone(),
            |snapshot| {
                let mut layout = RapierLayout::<u32>::default();
                layout.restore(snapshot).expect("restores");
                layout
            },
            criterion::BatchSize::LargeInput,
        )
    });
    let mut resumed = Host {
        scene: host.scene.clone(),
        layout: RapierLayout::default(),
        state: host.state.clone(),
        extras: host.extras.clone(),
    };
    resumed.layout.restore(snapshot).expect("restores");
    let (a, b) = (host.frame(), resumed.frame());
    assert!(
        a.len() > n / 2 && a.len() == b.len(),
        "the restored layout moves {} nodes where the original moves {}",
        b.len(),
        a.len()
    );
}

criterion_group! {
    name = snapshot;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(4));
    targets = snapshots
}
criterion_main!(snapshot);
