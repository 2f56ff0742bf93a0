//! The speed/accuracy trade, measured.
//!
//! For each solver setting, on `n200_e500` and `les_miserables`, this prints the cost
//! per simulated second and the error against a reference run (the `Precise` preset
//! with a 4× smaller timestep):
//! - RMS position error after 1 s and 5 s of simulated time,
//! - mean spring-length error at rest (|length − reference length|, after 20 s),
//! - energy drift of an undamped system over 5 s (no damping, no collisions).
//!
//! It writes `target/tradeoff.svg`: error after 1 s against time per simulated second.
//!
//! Run with `cargo run --release --example tradeoff`.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::time::Instant;

use graph_canvas_layout::config::Accuracy;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, EdgeJoint, Layout, LayoutExtras, RapierLayout,
    RapierLayoutConfig, RapierLayoutState,
};

mod common;

use common::load;
use graph_canvas_layout::config::{Contacts, Solver};

const FRAME: f32 = 1.0 / 60.0;

#[derive(Clone, Copy)]
struct Setting {
    name: &'static str,
    accuracy: Accuracy,
    timestep: f32,
}

// A timestep longer than the frame changes nothing (each call simulates its frame in
// substeps no longer than the timestep), so only shorter ones are listed.
const SETTINGS: [Setting; 6] = [
    Setting {
        name: "Fast",
        accuracy: Accuracy::Fast,
        timestep: 1.0 / 60.0,
    },
    Setting {
        name: "Balanced (default)",
        accuracy: Accuracy::Balanced,
        timestep: 1.0 / 60.0,
    },
    Setting {
        name: "4 iterations",
        accuracy: Accuracy::Custom {
            solver_iterations: 4,
            internal_pgs_iterations: 1,
            substeps: 1,
        },
        timestep: 1.0 / 60.0,
    },
    Setting {
        name: "Balanced, dt 1/120",
        accuracy: Accuracy::Balanced,
        timestep: 1.0 / 120.0,
    },
    Setting {
        name: "Precise",
        accuracy: Accuracy::Precise,
        timestep: 1.0 / 60.0,
    },
    Setting {
        name: "Precise, dt 1/120",
        accuracy: Accuracy::Precise,
        timestep: 1.0 / 120.0,
    },
];

const REFERENCE: Setting = Setting {
    name: "reference",
    accuracy: Accuracy::Precise,
    timestep: 1.0 / 240.0,
};

type Positions = HashMap<u32, Point2D<f32>>;

struct Run {
    at_quarter: Positions,
    at_1s: Positions,
    at_5s: Positions,
    at_rest: Positions,
    seconds_per_simulated_second: f64,
}

fn positions(scene: &CanvasSceneInput<u32>) -> Positions {
    scene.nodes.iter().map(|n| (n.id, n.position)).collect()
}

/// Simulates `frames` frames of 1/60 s; returns wall time.
fn simulate(
    layout: &mut RapierLayout<u32>,
    scene: &mut CanvasSceneInput<u32>,
    state: &mut RapierLayoutState,
    frames: usize,
) -> f64 {
    let extras = LayoutExtras::default();
    let started = Instant::now();
    for _ in 0..frames {
        let deltas = layout.step(scene, state, FRAME, &CanvasViewport::default(), &extras);
        scene.apply_deltas(&deltas);
    }
    started.elapsed().as_secs_f64()
}

fn run(scene: &CanvasSceneInput<u32>, setting: Setting) -> Run {
    let config = RapierLayoutConfig {
        solver: Solver {
            accuracy: setting.accuracy,
            ..Default::default()
        },
        ..Default::default()
    };
    let mut layout = RapierLayout::new(config);
    let mut state = RapierLayoutState {
        dt: setting.timestep,
        ..Default::default()
    };
    let mut scene = scene.clone();
    let t0 = simulate(&mut layout, &mut scene, &mut state, 15);
    let at_quarter = positions(&scene);
    let t1 = t0 + simulate(&mut layout, &mut scene, &mut state, 45);
    let at_1s = positions(&scene);
    let t5 = simulate(&mut layout, &mut scene, &mut state, 240);
    let at_5s = positions(&scene);
    simulate(&mut layout, &mut scene, &mut state, 900);
    Run {
        at_quarter,
        at_1s,
        at_5s,
        at_rest: positions(&scene),
        seconds_per_simulated_second: (t1 + t5) / 5.0,
    }
}

fn rms(a: &Positions, b: &Positions) -> f32 {
    let sum: f32 = a.iter().map(|(id, p)| (*p - b[id]).square_length()).sum();
    (sum / a.len() as f32).sqrt()
}

fn spring_error(scene: &CanvasSceneInput<u32>, a: &Positions, reference: &Positions) -> f32 {
    let total: f32 = scene
        .edges
        .iter()
        .map(|e| {
            ((a[&e.source] - a[&e.target]).length()
                - (reference[&e.source] - reference[&e.target]).length())
            .abs()
        })
        .sum();
    total / scene.edges.len() as f32
}

/// Relative change of kinetic + spring energy over 5 s with no damping and no contacts.
fn energy_drift(scene: &CanvasSceneInput<u32>, setting: Setting) -> f32 {
    let (rest, k) = (100.0, 50.0);
    let mut config = RapierLayoutConfig {
        solver: Solver {
            accuracy: setting.accuracy,
            ..Default::default()
        },
        contacts: Contacts {
            enabled: false,
            ..Default::default()
        },
        edge_joint: EdgeJoint::Spring {
            rest_length: rest,
            stiffness: k,
            damping: 0.0,
        },
        ..Default::default()
    };
    config.material.linear_damping = 0.0;
    let mass = config.material.density * std::f32::consts::PI * 16.0 * 16.0;
    let mut layout = RapierLayout::new(config);
    let mut state = RapierLayoutState {
        dt: setting.timestep,
        ..Default::default()
    };
    let mut scene = scene.clone();
    let energy = |layout: &RapierLayout<u32>, scene: &CanvasSceneInput<u32>| -> f64 {
        let world = layout.world().expect("world");
        let kinetic: f64 = scene
            .nodes
            .iter()
            .map(|n| {
                0.5 * f64::from(mass)
                    * f64::from(world.linear_velocity(&n.id).unwrap().square_length())
            })
            .sum();
        let spring: f64 = scene
            .edges
            .iter()
            .map(|e| {
                let l = (world.get_position(&e.source).unwrap()
                    - world.get_position(&e.target).unwrap())
                .length();
                0.5 * f64::from(k) * f64::from(l - rest).powi(2)
            })
            .sum();
        kinetic + spring
    };
    simulate(&mut layout, &mut scene, &mut state, 1);
    let e0 = energy(&layout, &scene);
    simulate(&mut layout, &mut scene, &mut state, 300);
    let e1 = energy(&layout, &scene);
    ((e1 - e0) / e0) as f32
}

struct Row {
    scene: &'static str,
    name: &'static str,
    cost_ms: f64,
    rms_quarter: f32,
    rms_1s: f32,
    rms_5s: f32,
    spring: f32,
    drift: f32,
}

fn main() {
    let mut rows = Vec::new();
    for name in ["n200_e500", "les_miserables"] {
        let scene = load(name);
        let reference = run(&scene, REFERENCE);
        for setting in SETTINGS {
            // Best of three for the cost: the machine is shared.
            let runs: Vec<Run> = (0..3).map(|_| run(&scene, setting)).collect();
            let cost = runs
                .iter()
                .map(|r| r.seconds_per_simulated_second)
                .fold(f64::MAX, f64::min);
            let r = &runs[0];
            rows.push(Row {
                scene: name,
                name: setting.name,
                cost_ms: cost * 1e3,
                rms_quarter: rms(&r.at_quarter, &reference.at_quarter),
                rms_1s: rms(&r.at_1s, &reference.at_1s),
                rms_5s: rms(&r.at_5s, &reference.at_5s),
                spring: spring_error(&scene, &r.at_rest, &reference.at_rest),
                drift: energy_drift(&scene, setting),
            });
        }
    }
    println!("| scene | setting | ms per simulated s | RMS error 0.25 s | RMS error 1 s | RMS error 5 s | spring error at rest | energy drift 5 s (undamped) |");
    println!("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    for r in &rows {
        println!(
            "| {} | {} | {:.2} | {:.2} | {:.1} | {:.1} | {:.1} | {:+.1} % |",
            r.scene,
            r.name,
            r.cost_ms,
            r.rms_quarter,
            r.rms_1s,
            r.rms_5s,
            r.spring,
            r.drift * 100.0
        );
    }
    let path = format!("{}/target/tradeoff.svg", env!("CARGO_MANIFEST_DIR"));
    std::fs::write(&path, chart(&rows)).expect("write the chart");
    println!("\nchart: {path}");
}

/// Error after 1 s (log scale) against cost per simulated second, one series per scene.
fn chart(rows: &[Row]) -> String {
    let (w, h, m) = (720.0, 420.0, 60.0);
    let max_cost = rows.iter().map(|r| r.cost_ms).fold(0.0, f64::max) * 1.1;
    let lo = rows
        .iter()
        .map(|r| f64::from(r.rms_1s).max(1e-3))
        .fold(f64::MAX, f64::min)
        .log10()
        .floor();
    let hi = rows
        .iter()
        .map(|r| f64::from(r.rms_1s).max(1e-3))
        .fold(0.0, f64::max)
        .log10()
        .ceil()
        .max(lo + 1.0);
    let x = |c: f64| m + c / max_cost * (w - 2.0 * m);
    let y = |e: f32| h - m - ((f64::from(e).max(1e-3).log10() - lo) / (hi - lo)) * (h - 2.0 * m);
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">"#
    );
    let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<line x1="{m}" y1="{}" x2="{}" y2="{}" stroke="black"/>"#,
        h - m,
        w - m,
        h - m
    );
    let _ = writeln!(
        svg,
        r#"<line x1="{m}" y1="{m}" x2="{m}" y2="{}" stroke="black"/>"#,
        h - m
    );
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="{}" text-anchor="middle">ms of wall time per simulated second</text>"#,
        w / 2.0,
        h - 20.0
    );
    let _ = writeln!(
        svg,
        r#"<text x="16" y="{}" transform="rotate(-90 16 {})" text-anchor="middle">RMS position error after 1 s (world units, log)</text>"#,
        h / 2.0,
        h / 2.0
    );
    for decade in (lo as i32)..=(hi as i32) {
        let yy = y(10f32.powi(decade));
        let _ = writeln!(
            svg,
            r##"<line x1="{m}" y1="{yy}" x2="{}" y2="{yy}" stroke="#ddd"/><text x="{}" y="{}" text-anchor="end">1e{decade}</text>"##,
            w - m,
            m - 4.0,
            yy + 4.0
        );
    }
    for (scene, colour) in [("n200_e500", "#1f77b4"), ("les_miserables", "#d62728")] {
        let points: Vec<&Row> = rows.iter().filter(|r| r.scene == scene).collect();
        let mut sorted = points.clone();
        sorted.sort_by(|a, b| a.cost_ms.total_cmp(&b.cost_ms));
        let path: Vec<String> = sorted
            .iter()
            .map(|r| format!("{:.1},{:.1}", x(r.cost_ms), y(r.rms_1s)))
            .collect();
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" stroke="{colour}" stroke-opacity="0.4"/>"#,
            path.join(" ")
        );
        for r in points {
            let _ = writeln!(
                svg,
                r#"<circle cx="{:.1}" cy="{:.1}" r="4" fill="{colour}"/><text x="{:.1}" y="{:.1}" fill="{colour}">{}</text>"#,
                x(r.cost_ms),
                y(r.rms_1s),
                x(r.cost_ms) + 6.0,
                y(r.rms_1s) - 6.0,
                r.name
            );
        }
        let _ = writeln!(
            svg,
            r#"<text x="{}" y="{}" fill="{colour}">{scene}</text>"#,
            w - m - 110.0,
            if scene == "n200_e500" { m } else { m + 14.0 }
        );
    }
    svg.push_str("</svg>\n");
    svg
}
