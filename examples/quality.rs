//! Layout quality of `RapierLayoutConfig::force_directed()` on the shipped real graphs,
//! with `is_converged` as the stopping rule: edge-length spread (coefficient of
//! variation), overlapping node pairs, edge crossings, frames to settle, and the step
//! time. `scripts/d3-quality.mjs` measures d3-force on the same scenes.
//!
//! Run with `cargo run --release --example quality [--fast | --default] [--starts N]
//! [--duration S] [--frames N] [--leave-out SETTING] [--write-scenes] [scene ...]`:
//! - `--fast`: `RapierLayoutConfig::force_directed_fast()`;
//! - `--default`: `RapierLayoutConfig::default()` (no repulsion, packing a graph into a
//!   blob; with `--frames 300` for `docs/performance.md`);
//! - `--duration S`: a cooling schedule of `S` seconds;
//! - `--frames N`: stop after `N` frames (default 3,000), to time the first frames;
//! - `--leave-out`: one of `spring_exponent`, `spring_degree_exponent`, `link_bias`,
//!   `first_contact_heat`, `hot_contact_frequency`, `stretch_limit`, `accuracy`,
//!   `contact_model`, `spring_model`, `reheat_hops`, `flight_damping` switched back to
//!   d3's plain setting or the default configuration's, as in `docs/performance.md`;
//! - `--write-scenes`: also writes each scene to `target/scenes/<name>.json`, where the
//!   d3 script finds the generated ones.
//!
//! Any shipped scene may be named (`n1000_e2500`, `n10000_e25000`), and generated ones:
//! `ba_n{N}_m{M}` (Barabási–Albert) and `random_n{N}_e{E}`, seeded, on d3's spiral
//! (`benches/common/generate.rs`). Crossings are counted pairwise, so above 3,000 edges
//! they are left out ("-"), as in the d3 script.
//!
//! `--starts N` lays each scene out N times, from the file's positions and then from
//! N − 1 copies jittered by up to half a unit (a fixed sequence, so runs repeat), and
//! prints the spread of the results instead of one run: a single run of a chaotic
//! layout can be lucky.

use std::time::Instant;

use graph_canvas_layout::config::Accuracy;
use graph_canvas_layout::scene::{SceneFile, SceneFileNode};
use graph_canvas_layout::{
    quality, CanvasSceneInput, CanvasViewport, Layout, LayoutExtras, RapierLayout,
    RapierLayoutConfig, RapierLayoutState,
};

mod common;

use common::load;

const SCENES: [&str; 6] = [
    "karate",
    "les_miserables",
    "florentine",
    "n200_e500",
    "tree_1023",
    "grid_30x30",
];
/// Frames after which a layout counts as not settling.
const MAX_FRAMES: usize = 3000;
/// Above this many edges, crossings (counted pairwise) are left out.
const PAIRWISE_LIMIT: usize = 3000;

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

/// What one layout run measured.
struct Run {
    frames: usize,
    cv: f32,
    mean_edge: f32,
    overlaps: Option<usize>,
    crossings: Option<usize>,
    micros_per_step: f64,
    /// Step times in microseconds, sorted.
    step_micros: Vec<f64>,
}

impl Run {
    /// The `q` quantile of the step times, in milliseconds.
    fn step_ms(&self, q: f64) -> f64 {
        let i = ((self.step_micros.len() as f64 - 1.0) * q).round() as usize;
        self.step_micros.get(i).copied().unwrap_or(0.0) / 1e3
    }
}

/// `--leave-out SETTING`: one departure of `force_directed()` from d3-force switched
/// back, to measure what it does.
fn leave_out(config: &mut RapierLayoutConfig, setting: &str) {
    let cooling = config
        .cooling
        .as_mut()
        .expect("force-directed presets cool");
    match setting {
        "spring_exponent" => cooling.spring_exponent = 1.0,
        "spring_degree_exponent" => config.springs.degree_exponent = 1.0,
        "link_bias" => config.springs.link_bias = 0.0,
        "first_contact_heat" => cooling.first_contact_heat = None,
        "hot_contact_frequency" => cooling.hot_contact_frequency = None,
        "stretch_limit" => cooling.stretch_limit = None,
        "accuracy" => config.solver.accuracy = Accuracy::Balanced,
        "contact_model" => {
            config.contacts.model = graph_canvas_layout::config::ContactModel::Rapier
        }
        "spring_model" => config.springs.model = graph_canvas_layout::config::SpringModel::Joints,
        "reheat_hops" => cooling.reheat_hops = None,
        "flight_damping" => config.throw.flight_damping = None,
        other => panic!(
            "--leave-out takes spring_exponent, spring_degree_exponent, link_bias, \
             first_contact_heat, hot_contact_frequency, stretch_limit, accuracy, contact_model, \
             spring_model, reheat_hops or flight_damping, not {other:?}"
        ),
    }
}

/// Lays `scene` out until `is_converged` (or `max_frames`) and measures the result.
fn run(mut scene: CanvasSceneInput<u32>, config: &RapierLayoutConfig, max_frames: usize) -> Run {
    let config = config.clone();
    let default_radius = config.default_radius;
    let mut layout = RapierLayout::new(config);
    let mut state = RapierLayoutState::default();
    let extras = LayoutExtras::default();
    let mut frames = 0;
    let mut step_micros = Vec::new();
    let started = Instant::now();
    while !layout.is_converged(&state) && frames < max_frames {
        let step_started = Instant::now();
        let deltas = layout.step(
            &scene,
            &mut state,
            1.0 / 60.0,
            &CanvasViewport::default(),
            &extras,
        );
        step_micros.push(step_started.elapsed().as_secs_f64() * 1e6);
        scene.apply_deltas(&deltas);
        frames += 1;
    }
    step_micros.sort_by(f64::total_cmp);
    let micros_per_step = started.elapsed().as_secs_f64() * 1e6 / frames.max(1) as f64;
    Run {
        frames,
        cv: quality::edge_length_cv(&scene).unwrap_or(0.0),
        mean_edge: quality::mean_edge_length(&scene).unwrap_or(0.0),
        overlaps: Some(quality::overlapping_pairs(&scene, default_radius, 0.5)),
        crossings: (scene.edges.len() <= PAIRWISE_LIMIT).then(|| quality::edge_crossings(&scene)),
        micros_per_step,
        step_micros,
    }
}

/// The scene's positions moved by up to half a unit each way; start 0 is the file's.
fn jittered(mut scene: CanvasSceneInput<u32>, start: u64) -> CanvasSceneInput<u32> {
    if start == 0 {
        return scene;
    }
    let mut seed = start;
    let mut next = move || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (seed >> 40) as f32 / (1_u64 << 24) as f32 - 0.5
    };
    for node in &mut scene.nodes {
        node.position.x += next();
        node.position.y += next();
    }
    scene
}

/// Writes `scene` to `target/scenes/<name>.json` in the scene file format, for the d3
/// script.
fn write_scene(name: &str, scene: &CanvasSceneInput<u32>) {
    let file = SceneFile {
        nodes: scene
            .nodes
            .iter()
            .map(|n| SceneFileNode {
                id: n.id,
                x: n.position.x,
                y: n.position.y,
                radius: n.radius,
            })
            .collect(),
        edges: scene.edges.iter().map(|e| (e.source, e.target)).collect(),
    };
    let dir = format!("{}/target/scenes", env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(&dir).expect("target/scenes");
    let text = serde_json::to_string(&file).expect("scene json");
    std::fs::write(format!("{dir}/{name}.json"), text).expect("scene file written");
}

fn count(value: Option<usize>) -> String {
    value.map_or_else(|| "-".to_string(), |v| v.to_string())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut config = if args.iter().any(|a| a == "--fast") {
        RapierLayoutConfig::force_directed_fast()
    } else if args.iter().any(|a| a == "--default") {
        RapierLayoutConfig::default()
    } else {
        RapierLayoutConfig::force_directed()
    };
    tune(&mut config);
    let mut starts = 1_u64;
    let mut max_frames = MAX_FRAMES;
    let mut write_scenes = false;
    let mut names = Vec::new();
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        match arg.as_str() {
            "--fast" | "--default" => {}
            "--spring-forces" => {
                config.springs.model = graph_canvas_layout::config::SpringModel::Forces
            }
            "--disks" => config.contacts.model = graph_canvas_layout::config::ContactModel::Disks,
            "--starts" => {
                starts = rest
                    .next()
                    .and_then(|n| n.parse().ok())
                    .filter(|&n| n > 0)
                    .expect("--starts takes a positive count");
            }
            "--duration" => {
                let seconds: f32 = rest
                    .next()
                    .and_then(|n| n.parse().ok())
                    .expect("--duration takes seconds");
                if let Some(cooling) = config.cooling.as_mut() {
                    cooling.duration = seconds;
                }
            }
            "--frames" => {
                max_frames = rest
                    .next()
                    .and_then(|n| n.parse().ok())
                    .filter(|&n| n > 0)
                    .expect("--frames takes a positive count");
            }
            "--write-scenes" => write_scenes = true,
            "--leave-out" => {
                let setting = rest.next().expect("--leave-out takes a setting");
                leave_out(&mut config, setting);
            }
            name => names.push(name.to_string()),
        }
    }
    if names.is_empty() {
        names = SCENES.iter().map(|s| s.to_string()).collect();
    }
    if starts == 1 {
        println!("| scene | nodes | edges | frames to settle | edge-length CV | mean edge | overlaps | crossings | µs per step | step ms p50 / p95 / max | s to rest |");
        println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    } else {
        println!("| scene | starts | frames to settle (min–max) | edge-length CV mean | CV min–max | overlaps (all starts) |");
        println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    }
    for name in names {
        let scene = load(&name);
        if write_scenes {
            write_scene(&name, &scene);
        }
        let (nodes, edges) = (scene.nodes.len(), scene.edges.len());
        let runs: Vec<Run> = (0..starts)
            .map(|k| run(jittered(scene.clone(), k), &config, max_frames))
            .collect();
        let settled = |frames: usize| {
            if frames >= max_frames {
                " (not settled)"
            } else {
                ""
            }
        };
        if let [r] = runs.as_slice() {
            println!(
                "| {name} | {nodes} | {edges} | {}{} | {:.2} | {:.0} | {} | {} | {:.0} | {:.2} / {:.2} / {:.2} | {:.2} |",
                r.frames,
                settled(r.frames),
                r.cv,
                r.mean_edge,
                count(r.overlaps),
                count(r.crossings),
                r.micros_per_step,
                r.step_ms(0.5),
                r.step_ms(0.95),
                r.step_ms(1.0),
                r.micros_per_step * r.frames as f64 / 1e6,
            );
            continue;
        }
        let frames_min = runs.iter().map(|r| r.frames).min().unwrap_or(0);
        let frames_max = runs.iter().map(|r| r.frames).max().unwrap_or(0);
        let cv_mean = runs.iter().map(|r| f64::from(r.cv)).sum::<f64>() / runs.len() as f64;
        let cv_min = runs.iter().map(|r| r.cv).fold(f32::INFINITY, f32::min);
        let cv_max = runs.iter().map(|r| r.cv).fold(0.0_f32, f32::max);
        let overlaps: Option<usize> = runs.iter().map(|r| r.overlaps).sum();
        println!(
            "| {name} | {starts} | {frames_min}–{frames_max}{} | {cv_mean:.3} | {cv_min:.3}–{cv_max:.3} | {} |",
            settled(frames_max),
            count(overlaps),
        );
    }
}
