//! A big graph off the UI thread: a random graph of 100,000 nodes and 250,000 edges
//! (the benches' seeded generator) laid out by a [`LayoutWorker`] under `stress()` while
//! a simulated UI loop runs at 60 frames per second, reading every position each frame.
//! Once it rests, the node nearest the centroid is dragged 100 units over 10 frames and
//! let go, and the loop runs until the layout rests again.
//!
//! Prints the UI thread's cost per frame (taking the newest frame, reading every
//! position, sending the drag), every frame but the first (before the worker's first
//! step), the worker's step times from the drag's start until rest, and how far the
//! nodes three or more hops from the dragged node (in its component) moved. The last line is
//! `big_graph: ui_p99_ms=X ui_max_ms=X drag_p95_ms=X far_mean=X`.
//!
//! Run with `cargo run --release --example big_graph [scene]` (any scene of `scenes/`
//! or a generator's name; default `random_n100000_e250000`).

mod common;

use std::time::{Duration, Instant};

use common::percentile;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::worker::LayoutWorker;
use graph_canvas_layout::{quality, RapierLayoutConfig};

const FRAME: Duration = Duration::from_micros(16_667);

/// The simulated UI thread: what it read and what its frames cost.
#[derive(Default)]
struct Ui {
    positions: Vec<Point2D<f32>>,
    /// The UI thread's cost of each timed frame.
    ui_ms: Vec<f64>,
    /// The worker's steps, as the frames deliver them.
    step_ms: Vec<f64>,
}

impl Ui {
    /// One UI frame: the newest positions taken and copied, as a canvas that draws them
    /// would; timed when `timed`.
    fn frame(&mut self, worker: &mut LayoutWorker<u32>, timed: bool) {
        let t = Instant::now();
        let frame = worker.frame();
        self.positions.clear();
        self.positions.extend_from_slice(&frame.positions);
        let spent = t.elapsed().as_secs_f64() * 1e3;
        if timed {
            self.ui_ms.push(spent);
        }
        self.step_ms
            .extend(frame.step_times.iter().map(|t| t.as_secs_f64() * 1e3));
    }
}

fn main() {
    let name = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "random_n100000_e250000".into());
    let scene = common::load(&name);
    let n = scene.nodes.len();
    let ids: Vec<u32> = scene.nodes.iter().map(|node| node.id).collect();
    // The graph, kept for the hop distances once the worker owns the scene.
    let graph = scene.clone();

    let started = Instant::now();
    let mut worker = LayoutWorker::spawn(scene, RapierLayoutConfig::stress());
    let mut ui = Ui::default();
    let mut frames = 0;
    loop {
        let tick = Instant::now();
        ui.frame(&mut worker, frames > 0);
        frames += 1;
        if worker.is_converged() {
            break;
        }
        std::thread::sleep(FRAME.saturating_sub(tick.elapsed()));
    }
    let to_rest = started.elapsed().as_secs_f64();
    let rest = ui.positions.clone();
    println!(
        "{name}: {n} nodes at rest through the worker after {to_rest:.1} s ({frames} UI frames, {} worker steps)",
        worker.frame().steps
    );

    // The drag: the node nearest the centroid, 100 units over 10 frames, then let go.
    let centroid = rest.iter().fold(Vector2D::zero(), |s, p| s + p.to_vector()) / n as f32;
    let dragged = (0..n)
        .min_by(|&a, &b| {
            (rest[a].to_vector() - centroid)
                .length()
                .total_cmp(&(rest[b].to_vector() - centroid).length())
        })
        .expect("a node");
    ui.step_ms.clear();
    for k in 1..=10 {
        let tick = Instant::now();
        worker.drag(
            ids[dragged],
            rest[dragged] + Vector2D::new(10.0 * k as f32, 0.0),
        );
        let send = tick.elapsed().as_secs_f64() * 1e3;
        ui.frame(&mut worker, true);
        if let Some(last) = ui.ui_ms.last_mut() {
            *last += send;
        }
        std::thread::sleep(FRAME.saturating_sub(tick.elapsed()));
    }
    let released = Instant::now();
    worker.release(ids[dragged]);
    // Until rest, or two minutes (a drag that keeps the graph moving is a finding).
    let mut rested = false;
    while released.elapsed() < Duration::from_secs(120) {
        let tick = Instant::now();
        ui.frame(&mut worker, true);
        if worker.is_converged() {
            rested = true;
            break;
        }
        std::thread::sleep(FRAME.saturating_sub(tick.elapsed()));
    }
    let hop = quality::hop_distances(&graph, &ids[dragged]);
    let far: Vec<f32> = (0..n)
        .filter(|&i| hop.get(&ids[i]).is_some_and(|&h| h >= 3))
        .map(|i| (ui.positions[i] - rest[i]).length())
        .collect();
    let far_mean = far.iter().sum::<f32>() / far.len().max(1) as f32;
    let (mut step_ms, mut ui_ms) = (ui.step_ms, ui.ui_ms);
    step_ms.sort_by(f64::total_cmp);
    ui_ms.sort_by(f64::total_cmp);
    let (ui_p99, ui_max) = (percentile(&ui_ms, 0.99), percentile(&ui_ms, 1.0));
    let drag_p95 = percentile(&step_ms, 0.95);
    println!(
        "UI thread per frame: p50 {:.3} ms, p99 {ui_p99:.3} ms, max {ui_max:.3} ms over {} frames",
        percentile(&ui_ms, 0.5),
        ui_ms.len()
    );
    println!(
        "drag: {} worker steps from its start to {} ({:.1} s after the release), p50 {:.1} ms, p95 {drag_p95:.1} ms; nodes 3+ hops away ({}) moved {far_mean:.3} on average",
        step_ms.len(),
        if rested { "rest" } else { "the two-minute cap, still moving" },
        released.elapsed().as_secs_f64(),
        percentile(&step_ms, 0.5),
        far.len()
    );
    println!(
        "big_graph: ui_p99_ms={ui_p99:.3} ui_max_ms={ui_max:.3} drag_p95_ms={drag_p95:.3} far_mean={far_mean:.3}"
    );
}
