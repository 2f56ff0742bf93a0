//! What a topology edit costs: one node added to `n5000_e12500` patched in place
//! against a rebuild, a pin toggled, an edge removed, each timed as the whole `step`
//! call that applies it, beside the same call with no edit.

mod common;

use std::time::Duration;

use common::*;
use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion};
use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::RapierLayoutConfig;

fn ready(name: &str, mode: TopologyUpdate) -> Host {
    let mut host = Host::new(
        scene(name),
        RapierLayoutConfig {
            topology_update: mode,
            ..Default::default()
        },
    );
    host.frame();
    host
}

fn edits(c: &mut Criterion) {
    let name = "n5000_e12500";
    let mut group = c.benchmark_group(format!("edit/{name}"));
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(10));
    group.bench_function("no_edit", |b| {
        b.iter_batched(
            || ready(name, TopologyUpdate::Incremental),
            |mut h| black_box(h.frame()),
            BatchSize::PerIteration,
        )
    });
    for (label, mode) in [
        ("add_node/incremental", TopologyUpdate::Incremental),
        ("add_node/rebuild", TopologyUpdate::Rebuild),
    ] {
        group.bench_function(label, |b| {
            b.iter_batched(
                || ready(name, mode),
                |mut h| {
                    h.scene.nodes.push(graph_canvas_layout::CanvasNode::new(
                        99_999,
                        graph_canvas_layout::euclid::default::Point2D::new(7.0, 7.0),
                    ));
                    h.scene
                        .edges
                        .push(graph_canvas_layout::CanvasEdge::new(99_999, 0));
                    let d = h.frame();
                    assert!(h.layout.world().unwrap().contains_node(&99_999));
                    d
                },
                BatchSize::PerIteration,
            )
        });
    }
    group.bench_function("toggle_pin", |b| {
        b.iter_batched(
            || ready(name, TopologyUpdate::Incremental),
            |mut h| {
                h.extras.pinned.insert(17);
                let d = h.frame();
                assert_eq!(h.layout.rebuild_count(), 1);
                d
            },
            BatchSize::PerIteration,
        )
    });
    group.bench_function("remove_edge", |b| {
        b.iter_batched(
            || ready(name, TopologyUpdate::Incremental),
            |mut h| {
                h.scene.edges.pop();
                let d = h.frame();
                assert_eq!(h.layout.patch_count(), 1);
                d
            },
            BatchSize::PerIteration,
        )
    });
    group.finish();
}

criterion_group!(benches, edits);
criterion_main!(benches);
