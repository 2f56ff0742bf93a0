//! Layout quality of `RapierLayoutConfig::force_directed()` on the shipped real graphs,
//! with `is_converged` as the stopping rule: edge-length spread (coefficient of
//! variation), overlapping node pairs, edge crossings, frames to settle, and the step
//! time. `scripts/d3-quality.mjs` measures d3-force on the same scenes.
//!
//! Run with `cargo run --release --example quality [--fast] [scene ...]` (`--fast`:
//! `RapierLayoutConfig::force_directed_fast()`); any shipped scene may be
//! named (`n1000_e2500`, `n10000_e25000`). Overlaps and crossings are counted pairwise,
//! so above 3,000 nodes or edges they are left out ("-"), as in the d3 script.

use std::time::Instant;

use graph_canvas_layout::{
    quality, CanvasViewport, Layout, LayoutExtras, RapierLayout, RapierLayoutConfig,
    RapierLayoutState, SceneFile,
};

const SCENES: [&str; 6] = [
    "karate",
    "les_miserables",
    "florentine",
    "n200_e500",
    "tree_1023",
    "grid_30x30",
];

/// `GCL_TUNE="strength k c damping theta"` overrides the force-directed defaults, to explore.
fn tune(config: &mut RapierLayoutConfig) {
    let Ok(text) = std::env::var("GCL_TUNE") else {
        return;
    };
    let v: Vec<f32> = text
        .split_whitespace()
        .filter_map(|x| x.parse().ok())
        .collect();
    if let (Some(r), [s, k, c, d, t]) = (config.repulsion.as_mut(), v.as_slice()) {
        r.strength = *s;
        r.theta = *t;
        config.edge_joint = graph_canvas_layout::EdgeJoint::Spring {
            rest_length: 100.0,
            stiffness: *k,
            damping: *c,
        };
        config.material.linear_damping = *d;
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let fast = args.iter().any(|a| a == "--fast");
    let only: Vec<&String> = args.iter().filter(|a| *a != "--fast").collect();
    println!("| scene | nodes | edges | frames to settle | edge-length CV | mean edge | overlaps | crossings | µs per step |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    let names: Vec<&str> = if only.is_empty() {
        SCENES.to_vec()
    } else {
        only.iter().map(|s| s.as_str()).collect()
    };
    for name in names {
        let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("scene file");
        let mut scene = serde_json::from_str::<SceneFile>(&text)
            .expect("scene json")
            .into_scene();
        let mut config = if fast {
            RapierLayoutConfig::force_directed_fast()
        } else {
            RapierLayoutConfig::force_directed()
        };
        tune(&mut config);
        let default_radius = config.default_radius;
        let mut layout = RapierLayout::new(config);
        let mut state = RapierLayoutState::default();
        let extras = LayoutExtras::default();
        let mut frames = 0;
        let started = Instant::now();
        while !layout.is_converged(&state) && frames < 3000 {
            let deltas = layout.step(
                &scene,
                &mut state,
                1.0 / 60.0,
                &CanvasViewport::default(),
                &extras,
            );
            scene.apply_deltas(&deltas);
            frames += 1;
        }
        let per_step = started.elapsed().as_secs_f64() * 1e6 / f64::from(frames.max(1));
        println!(
            "| {name} | {} | {} | {}{} | {:.2} | {:.0} | {} | {} | {:.0} |",
            scene.nodes.len(),
            scene.edges.len(),
            frames,
            if frames >= 3000 { " (not settled)" } else { "" },
            quality::edge_length_cv(&scene).unwrap_or(0.0),
            quality::mean_edge_length(&scene).unwrap_or(0.0),
            pairwise(scene.nodes.len(), || quality::overlapping_pairs(
                &scene,
                default_radius,
                0.5
            )),
            pairwise(scene.edges.len(), || quality::edge_crossings(&scene)),
            per_step,
        );
    }
}

/// A pairwise count, or "-" above 3,000 elements.
fn pairwise(elements: usize, count: impl FnOnce() -> usize) -> String {
    if elements <= 3000 {
        count().to_string()
    } else {
        "-".to_string()
    }
}
