//! A directed graph laid out with its edges pointing down: this workspace's own
//! dependency graph (`scenes/crate_deps.json`, from `cargo metadata`) under
//! `RapierLayoutConfig::stress().with_flow(Flow::down(gap))`, against the same graph
//! under `stress()` without a flow. Prints a Markdown table, for each: the share of
//! edges pointing down by at least `gap - 1` and the least drop, the edges the flow
//! leaves free (those that close a directed cycle), overlapping disks, edge crossings,
//! normalised stress, frames and wall time to rest, and the step's p95; and writes
//! `target/flow/<scene>_flow.svg` and `_plain.svg`.
//!
//! `cargo run --release --example flow -- [--gap G] [--repeat K] [--layers] [--dot]
//! [--drag] [--subtrees] [--subtree-padding P] [--passes 1,2,4] [scene ...]`; the scene defaults to `crate_deps`.
//! - `--layers`: the flow in layers too (`Flow::in_layers`), written to `_layers.svg`.
//! - `--repeat K`: each layout K times, by turns; the times are the medians.
//! - `--dot`: Graphviz `dot` on the same graph (`apt-get install graphviz`): the same
//!   figures and its wall time.
//! - `--drag`: at rest, the busiest node dragged around a circle for 180 frames, with and
//!   without the flow: the worst shortfall after the drag's first 10 frames, and the
//!   step's p95.
//! - `--subtrees`: the flow with each subtree a cluster nested in its parent's
//!   (`subtrees.rs`), written to `_subtrees.svg`; `--subtree-padding P` sets their
//!   padding (default 15).
//! - `--passes`: the flow (and with `--layers` the flow in layers) under each number of
//!   constraint passes per substep: the worst shortfall of any frame, stress, crossings,
//!   frames to rest, the constraints' time a frame (`StepProfile::constraints`) and the
//!   step's p95; with `--drag`, the drag's worst shortfall, step p95 and constraints'
//!   time a frame.

use graph_canvas_layout::config::{Flow, Solver};
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[path = "../common/mod.rs"]
mod common;
mod dot;
mod drag;
mod measure;
mod subtrees;

use common::{load, Host};
use measure::{worst_shortfall, Figures};

const FRAME: f32 = 1.0 / 60.0;

struct Options {
    gap: f32,
    dot: bool,
    layers: bool,
    drag: bool,
    subtrees: bool,
    subtree_padding: f32,
    passes: Vec<u32>,
    repeat: usize,
    scenes: Vec<String>,
}

fn options() -> Options {
    let mut o = Options {
        gap: 60.0,
        dot: false,
        layers: false,
        drag: false,
        subtrees: false,
        subtree_padding: 15.0,
        passes: Vec::new(),
        repeat: 1,
        scenes: Vec::new(),
    };
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut rest = args.iter();
    while let Some(arg) = rest.next() {
        match arg.as_str() {
            "--gap" => o.gap = rest.next().and_then(|v| v.parse().ok()).expect("--gap G"),
            "--dot" => o.dot = true,
            "--layers" => o.layers = true,
            "--repeat" => {
                o.repeat = rest
                    .next()
                    .and_then(|v| v.parse().ok())
                    .filter(|&k| k > 0)
                    .expect("--repeat K")
            }
            "--drag" => o.drag = true,
            "--subtrees" => o.subtrees = true,
            "--subtree-padding" => {
                o.subtree_padding = rest
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--subtree-padding P")
            }
            "--passes" => {
                o.passes = rest
                    .next()
                    .map(|v| v.split(',').filter_map(|p| p.parse().ok()).collect())
                    .expect("--passes 1,2,4")
            }
            name => o.scenes.push(name.to_owned()),
        }
    }
    if o.scenes.is_empty() {
        o.scenes.push("crate_deps".to_owned());
    }
    o
}

/// One layout run to rest (at most 2,000 frames).
struct Run {
    host: Host,
    frames: usize,
    wall_ms: f64,
    p95_ms: f64,
    /// The worst edge's shortfall after each frame.
    shortfall: Vec<f32>,
}

fn run(
    scene: &CanvasSceneInput<u32>,
    (config, clusters): (RapierLayoutConfig, &[Cluster<u32>]),
    gap: f32,
    profile: bool,
) -> Run {
    let mut host = Host::new(scene.clone(), config);
    host.extras.clusters = clusters.to_vec();
    host.layout.set_profiling(profile);
    let mut shortfall = Vec::new();
    let timed = host.settle_timed(FRAME, 2_000, |host| {
        let exempt = host.layout.flow_exempt_edges();
        shortfall.push(worst_shortfall(&host.scene, gap, exempt));
    });
    Run {
        p95_ms: timed.p95_ms,
        host,
        frames: timed.frames,
        wall_ms: timed.wall_ms,
        shortfall,
    }
}

fn row(name: &str, label: &str, f: &Figures, exempt: usize, frames: &str, ms: f64, p95: &str) {
    println!(
        "| {name} | {label} | {:.1} % | {:.2} | {exempt} | {} | {} | {:.4} | {frames} | {ms:.0} | {p95} |",
        f.down * 100.0,
        f.least_drop,
        f.overlaps,
        f.crossings,
        f.stress
    );
}

fn main() {
    let o = options();
    let dir = format!("{}/target/flow", env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(&dir).expect("target/flow");
    let flow = RapierLayoutConfig::stress().with_flow(Flow::down(o.gap));
    let layered = RapierLayoutConfig::stress().with_flow(Flow::down(o.gap).in_layers());
    if o.passes.is_empty() {
        println!("| scene | layout | edges down by gap − 1 | least drop | exempt | overlaps | crossings | stress | frames | ms to rest | step p95 ms |");
        println!("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    } else {
        println!("| scene | flow | passes | worst shortfall, any frame | stress | crossings | frames to rest | constraints ms a frame | step p95 ms | drag: worst shortfall | drag: step p95 ms | drag: constraints ms a frame |");
        println!(
            "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
        );
    }
    for name in &o.scenes {
        let scene = load(name);
        if !o.passes.is_empty() {
            let mut flows = vec![("free", flow.clone())];
            if o.layers {
                flows.push(("layers", layered.clone()));
            }
            for (kind, flow) in &flows {
                for &passes in &o.passes {
                    let config = RapierLayoutConfig {
                        solver: Solver {
                            constraint_passes: passes,
                            ..flow.solver
                        },
                        ..flow.clone()
                    };
                    let mut r = run(&scene, (config, &[]), o.gap, true);
                    let worst = r.shortfall.iter().copied().fold(0.0_f32, f32::max);
                    let f = Figures::of(&r.host.scene, o.gap, r.host.layout.flow_exempt_edges());
                    let profile = r.host.layout.profile().expect("profiling on");
                    let per_frame = profile.constraints.as_secs_f64() * 1e3 / r.frames as f64;
                    let dragged = if o.drag {
                        let d = drag::drag(&mut r.host, o.gap, FRAME);
                        format!("{:.2} | {:.2} | {:.3}", d.worst, d.p95_ms, d.stages_ms[3])
                    } else {
                        "– | – | –".to_string()
                    };
                    println!(
                        "| {name} | {kind} | {passes} | {worst:.2} | {:.4} | {} | {} | {per_frame:.3} | {:.2} | {dragged} |",
                        f.stress, f.crossings, r.frames, r.p95_ms
                    );
                }
            }
            continue;
        }
        // The two layouts by turns, `--repeat` times: the timings are medians, the
        // rest the same in every run.
        let mut configs = vec![
            (
                "`stress()`",
                RapierLayoutConfig::stress(),
                "plain",
                Vec::new(),
            ),
            (
                "`stress()` + `Flow::down`",
                flow.clone(),
                "flow",
                Vec::new(),
            ),
        ];
        if o.layers {
            let layers = ("`Flow::down(..).in_layers()`", layered.clone(), "layers");
            configs.push((layers.0, layers.1, layers.2, Vec::new()));
        }
        if o.subtrees {
            let subtrees = subtrees::clusters(&scene, o.subtree_padding);
            let label = "`Flow::down` + subtrees as clusters";
            configs.push((label, flow.clone(), "subtrees", subtrees));
        }
        let mut timings = vec![(Vec::new(), Vec::new()); configs.len()];
        let mut drags: Vec<Vec<drag::Drag>> = vec![Vec::new(); configs.len()];
        let mut last = Vec::new();
        for _ in 0..o.repeat {
            last.clear();
            for (k, (_, config, _, clusters)) in configs.iter().enumerate() {
                let mut r = run(&scene, (config.clone(), clusters), o.gap, false);
                timings[k].0.push(r.p95_ms);
                timings[k].1.push(r.wall_ms);
                // The layout at rest, before any drag.
                let exempt = r.host.layout.flow_exempt_edges().len();
                let f = Figures::of(&r.host.scene, o.gap, r.host.layout.flow_exempt_edges());
                last.push((f, exempt, r.frames, r.host.scene.clone()));
                if o.drag {
                    drags[k].push(drag::drag(&mut r.host, o.gap, FRAME));
                }
            }
        }
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        let p95: Vec<f64> = timings.iter_mut().map(|t| median(&mut t.0)).collect();
        for (k, ((label, _, file, _), (f, exempt, frames, laid))) in
            configs.iter().zip(&last).enumerate()
        {
            let shown = if k == 0 {
                format!("{:.2}", p95[0])
            } else {
                format!("{:.2} ({:.2} ×)", p95[k], p95[k] / p95[0])
            };
            let wall = median(&mut timings[k].1);
            row(name, label, f, *exempt, &frames.to_string(), wall, &shown);
            let title = format!("{name}: {label}, {:.1} % of edges down", f.down * 100.0);
            let picture = common::svg::svg(laid, &title, &[], &[], |_| common::svg::BLUE);
            std::fs::write(format!("{dir}/{name}_{file}.svg"), picture).expect("write picture");
        }
        if o.dot {
            match dot::layout(&scene) {
                Ok((laid, seconds)) => {
                    let f = Figures::of(&laid, 1.0, &[]);
                    row(
                        name,
                        "Graphviz `dot` (down: by 0)",
                        &f,
                        0,
                        "–",
                        seconds * 1e3,
                        "–",
                    );
                    let title = format!("{name}: Graphviz dot");
                    let picture = common::svg::svg(&laid, &title, &[], &[], |_| common::svg::BLUE);
                    std::fs::write(format!("{dir}/{name}_dot.svg"), picture)
                        .expect("write picture");
                }
                Err(e) => println!("| {name} | Graphviz `dot` | {e} |"),
            }
        }
        if o.drag {
            let mut p: Vec<Vec<f64>> = drags
                .iter()
                .map(|d| d.iter().map(|d| d.p95_ms).collect())
                .collect();
            let plain = median(&mut p[0]);
            let stages = |d: &[drag::Drag]| {
                let (s, awake) = (d[d.len() / 2].stages_ms, d[d.len() / 2].awake);
                format!(
                    "{awake} bodies awake; ms a frame: forces {:.2}, contacts {:.2}, rapier {:.2}, constraints {:.2}",
                    s[0], s[1], s[2], s[3]
                )
            };
            for k in 1..configs.len() {
                let worst = drags[k]
                    .iter()
                    .map(|d| d.worst_after_grace)
                    .fold(0.0_f32, f32::max);
                let any = drags[k].iter().map(|d| d.worst).fold(0.0_f32, f32::max);
                let flowing = median(&mut p[k]);
                println!(
                    "| {name} | {}: drag of node {} for 180 frames | worst shortfall after frame {}: {worst:.2} (any frame: {any:.2}) | step p95 {flowing:.2} ms vs {plain:.2} ms without the flow ({:.2} ×); {} vs {} |",
                    configs[k].0,
                    drags[k][0].node,
                    drag::GRACE,
                    flowing / plain,
                    stages(&drags[k]),
                    stages(&drags[0]),
                );
            }
        }
    }
}
