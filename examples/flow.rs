//! A directed graph laid out with its edges pointing down: this workspace's own
//! dependency graph (`scenes/crate_deps.json`, from `cargo metadata`) under
//! `RapierLayoutConfig::stress().with_flow(Flow::down(gap))`, against the same graph
//! without a flow. Prints, for each: the share of edges pointing down by at least
//! `gap - 1`, the edges the flow leaves free (those that close a directed cycle),
//! normalised stress, frames and wall time to rest, the step's p95; and writes
//! `target/flow/<scene>.svg`.
//!
//! Run with `cargo run --release --example flow [--gap G] [scene ...]`; the scene
//! defaults to `crate_deps`.

use std::time::Instant;

use graph_canvas_layout::config::Flow;
use graph_canvas_layout::{quality, CanvasSceneInput, Layout, RapierLayoutConfig};

mod common;

use common::{load, percentile, Host};

const FRAME: f32 = 1.0 / 60.0;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut gap = 60.0_f32;
    let mut scenes = Vec::new();
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        match arg.as_str() {
            "--gap" => gap = rest.next().and_then(|v| v.parse().ok()).expect("--gap G"),
            name => scenes.push(name.to_owned()),
        }
    }
    if scenes.is_empty() {
        scenes.push("crate_deps".to_owned());
    }
    std::fs::create_dir_all(format!("{}/target/flow", env!("CARGO_MANIFEST_DIR")))
        .expect("target/flow");
    println!(
        "scene | layout | edges down | least drop | exempt | stress | frames | ms to rest | step p95 ms"
    );
    for name in &scenes {
        let scene = load(name);
        for (label, config) in [
            ("stress()", RapierLayoutConfig::stress()),
            (
                "stress() + Flow::down",
                RapierLayoutConfig::stress().with_flow(Flow::down(gap)),
            ),
        ] {
            let mut host = Host::new(scene.clone(), config);
            let started = Instant::now();
            let mut steps = Vec::new();
            let mut frames = 0;
            while frames < 2_000 {
                let step = Instant::now();
                host.frame(FRAME);
                steps.push(step.elapsed().as_secs_f64() * 1e3);
                frames += 1;
                if host.layout.is_converged(&host.state) {
                    break;
                }
            }
            let wall = started.elapsed().as_secs_f64() * 1e3;
            steps.sort_by(f64::total_cmp);
            let exempt = host.layout.flow_exempt_edges().len();
            let down = share_down(&host.scene, gap, host.layout.flow_exempt_edges());
            let stress = quality::normalized_stress(&host.scene).unwrap_or(f64::NAN);
            let least = least_drop(&host.scene, host.layout.flow_exempt_edges());
            println!(
                "{name} | {label} | {:.1} % | {least:.2} | {exempt} | {stress:.4} | {frames} | {wall:.0} | {:.2}",
                down * 100.0,
                percentile(&steps, 0.95)
            );
            let title = format!("{name}: {label}, {:.1} % of edges down", down * 100.0);
            let file = if label.contains("Flow") {
                "flow"
            } else {
                "plain"
            };
            std::fs::write(
                format!(
                    "{}/target/flow/{name}_{file}.svg",
                    env!("CARGO_MANIFEST_DIR")
                ),
                common::svg::svg(&host.scene, &title, &[], &[], |_| common::svg::BLUE),
            )
            .expect("write picture");
        }
    }
}

/// The share of edges, exempt ones left out, whose target is at least `gap - 1` below
/// its source.
fn share_down(scene: &CanvasSceneInput<u32>, gap: f32, exempt: &[usize]) -> f64 {
    let y = |id: u32| scene.nodes[id as usize].position.y;
    let counted: Vec<_> = scene
        .edges
        .iter()
        .enumerate()
        .filter(|(i, _)| exempt.binary_search(i).is_err())
        .collect();
    let down = counted
        .iter()
        .filter(|(_, e)| y(e.target) - y(e.source) >= gap - 1.0)
        .count();
    down as f64 / counted.len().max(1) as f64
}

/// The least `target.y - source.y` over the edges, exempt ones left out.
fn least_drop(scene: &CanvasSceneInput<u32>, exempt: &[usize]) -> f32 {
    let y = |id: u32| scene.nodes[id as usize].position.y;
    scene
        .edges
        .iter()
        .enumerate()
        .filter(|(i, _)| exempt.binary_search(i).is_err())
        .map(|(_, e)| y(e.target) - y(e.source))
        .fold(f32::INFINITY, f32::min)
}
