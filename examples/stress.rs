//! Stress quality, measured: each scene laid out from its file to rest, flat out, with
//! `RapierLayoutConfig::stress()` (or another configuration), and its normalised stress
//! (`quality::normalized_stress`, the measure of `scripts/reference/stress.py`), frames and
//! wall time to rest, the first frame's time (the start included), step times and
//! overlapping disks at rest. Positions at rest are written to
//! `target/stress/<scene>.json` (`{"positions": [[x, y], ...]}`, the scene's node
//! order) for other tools to read.
//!
//! Run with `cargo run --release --example stress [--force-directed] [--pivots N|full]
//! [--full-up-to N] [--exact-hops H] [--period K] [--passes P] [--host-start]
//! [--fixed-length] [--contacts-at HEAT] [--duration S] [--frames N] [--svg]
//! [--write-scene] [--edits] [scene ...]`; scenes default to the graphs with structure
//! in `scenes/`. `--svg` draws each layout at rest to `target/stress/<scene>.svg`,
//! `--write-scene` writes it as a scene file, `--edits` measures edits on it.

use std::time::Instant;

use graph_canvas_layout::config::{StressModel, StressStart};
use graph_canvas_layout::{quality, Layout, RapierLayoutConfig};

mod common;

use common::{load, percentile, Host};

const FRAME: f32 = 1.0 / 60.0;
const SCENES: [&str; 11] = [
    "karate",
    "les_miserables",
    "florentine",
    "grid_30x30",
    "tree_1023",
    "1138_bus",
    "dwt_1005",
    "qh882",
    "USPowerGrid",
    "3elt",
    "rgg_10000",
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut config = RapierLayoutConfig::stress();
    let mut model = StressModel::default();
    let mut max_frames = 1_000;
    let mut write_scene = false;
    let mut edits = false;
    let mut pictures = false;
    let mut scenes: Vec<String> = Vec::new();
    let mut rest = args.iter();
    let value = |rest: &mut std::slice::Iter<String>, flag: &str| -> String {
        rest.next()
            .unwrap_or_else(|| panic!("{flag} takes a value"))
            .clone()
    };
    while let Some(arg) = rest.next() {
        match arg.as_str() {
            "--force-directed" => config = RapierLayoutConfig::force_directed(),
            "--pivots" => {
                let v = value(&mut rest, arg);
                model.pivots = (v != "full").then(|| v.parse().expect("--pivots N|full"));
            }
            "--full-up-to" => model.full_up_to = value(&mut rest, arg).parse().expect("nodes"),
            "--exact-hops" => model.exact_hops = value(&mut rest, arg).parse().expect("hops"),
            "--period" => model.pivot_period = value(&mut rest, arg).parse().expect("substeps"),
            "--passes" => model.start_passes = value(&mut rest, arg).parse().expect("passes"),
            "--host-start" => model.start = StressStart::HostPositions,
            "--fixed-length" => model.fit_length = false,
            "--contacts-at" => {
                let heat: f32 = value(&mut rest, arg).parse().expect("heat");
                if let Some(cooling) = config.cooling.as_mut() {
                    cooling.first_contact_heat = Some(heat);
                }
            }
            "--duration" => {
                let seconds: f32 = value(&mut rest, arg).parse().expect("seconds");
                if let Some(cooling) = config.cooling.as_mut() {
                    cooling.duration = seconds;
                }
            }
            "--write-scene" => write_scene = true,
            "--edits" => edits = true,
            "--svg" => pictures = true,
            "--frames" => max_frames = value(&mut rest, arg).parse().expect("frames"),
            name => scenes.push(name.to_string()),
        }
    }
    if config.stress.is_some() {
        config.stress = Some(model);
    }
    if scenes.is_empty() {
        scenes = SCENES.iter().map(|s| s.to_string()).collect();
    }
    std::fs::create_dir_all(format!("{}/target/stress", env!("CARGO_MANIFEST_DIR")))
        .expect("target/stress");
    println!("| scene | nodes | stress at rest | first frame's stress | frames to rest | wall time to rest (s) | first frame (ms) | step p50 / p95 (ms) | overlaps at rest | hop length |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for name in &scenes {
        let scene = load(name);
        if write_scene {
            // The scene file, for the reference tools (`scripts/reference`).
            let file = serde_json::json!({
                "nodes": scene.nodes.iter().map(|n| serde_json::json!({"id": n.id, "x": n.position.x, "y": n.position.y, "radius": 16.0})).collect::<Vec<_>>(),
                "edges": scene.edges.iter().map(|e| [e.source, e.target]).collect::<Vec<_>>(),
            });
            std::fs::write(
                format!(
                    "{}/target/stress/{name}.scene.json",
                    env!("CARGO_MANIFEST_DIR")
                ),
                file.to_string(),
            )
            .expect("write scene");
        }
        let mut host = Host::new(scene, config.clone());
        let mut times = Vec::new();
        let mut first_stress = 0.0;
        let mut frames = 0;
        while frames < max_frames {
            let started = Instant::now();
            host.frame(FRAME);
            times.push(started.elapsed().as_secs_f64());
            if frames == 0 {
                first_stress = quality::normalized_stress(&host.scene).unwrap_or(0.0);
            }
            frames += 1;
            if host.layout.is_converged(&host.state) {
                break;
            }
        }
        let total: f64 = times.iter().sum();
        let first = times[0];
        let mut steps: Vec<f64> = times[1..].to_vec();
        steps.sort_by(f64::total_cmp);
        let (p50, p95) = if steps.is_empty() {
            (0.0, 0.0)
        } else {
            (percentile(&steps, 0.5), percentile(&steps, 0.95))
        };
        let stress = quality::normalized_stress(&host.scene).unwrap_or(0.0);
        let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
        let hop = host
            .layout
            .world()
            .and_then(|w| w.edge_joint(&host.scene.edges[0].source, &host.scene.edges[0].target))
            .map_or(String::from("-"), |j| match j {
                graph_canvas_layout::EdgeJoint::Spring { rest_length, .. } => {
                    format!("{rest_length:.0}")
                }
                _ => String::from("-"),
            });
        let positions: Vec<[f32; 2]> = host
            .scene
            .nodes
            .iter()
            .map(|n| [n.position.x, n.position.y])
            .collect();
        std::fs::write(
            format!("{}/target/stress/{name}.json", env!("CARGO_MANIFEST_DIR")),
            serde_json::json!({ "positions": positions }).to_string(),
        )
        .expect("write positions");
        if pictures {
            let label = if config.stress.is_some() {
                "stress()"
            } else {
                "force_directed()"
            };
            let title = format!("{name}: {label} at rest, normalised stress {stress:.3}");
            std::fs::write(
                format!("{}/target/stress/{name}.svg", env!("CARGO_MANIFEST_DIR")),
                common::svg::svg(&host.scene, &title, &[], &[], |_| common::svg::BLUE),
            )
            .expect("write picture");
        }
        if edits {
            edit_costs(name, &mut host);
        }
        let converged = if host.layout.is_converged(&host.state) {
            ""
        } else {
            " (not at rest)"
        };
        println!(
            "| {name} | {} | {stress:.4} | {first_stress:.4} | {frames}{converged} | {total:.2} | {:.0} | {:.2} / {:.2} | {overlaps} | {hop} |",
            host.scene.nodes.len(),
            first * 1e3,
            p50 * 1e3,
            p95 * 1e3,
        );
    }
}

/// On the layout at rest: the first call after a leaf is added at node 0's position,
/// and after an edge is removed, each timed, and the frames until rest again.
fn edit_costs(name: &str, host: &mut Host) {
    let timed = |host: &mut Host, what: &str| {
        let started = Instant::now();
        host.frame(FRAME);
        let first = started.elapsed().as_secs_f64() * 1e3;
        let mut frames = 1;
        while frames < 600 && !host.layout.is_converged(&host.state) {
            host.frame(FRAME);
            frames += 1;
        }
        eprintln!("{name}: {what}: first call {first:.1} ms, at rest again in {frames} frames");
    };
    let id = host.scene.nodes.iter().map(|n| n.id).max().unwrap_or(0) + 1;
    let anchor = host.scene.nodes[0].id;
    let at = host.scene.nodes[0].position;
    host.scene
        .nodes
        .push(graph_canvas_layout::CanvasNode::new(id, at));
    host.scene
        .edges
        .push(graph_canvas_layout::CanvasEdge::new(anchor, id));
    timed(host, "a leaf added");
    host.scene.edges.remove(0);
    timed(host, "an edge removed");
}
