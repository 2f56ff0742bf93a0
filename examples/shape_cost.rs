//! Where label boxes cost more than disks: `n10000_e25000` under `force_directed()`, once
//! with every node a disk (the file's radius) and once with every node a "node <id>"
//! box (7 units a character by 20), frames 30–270 (as the benches time them) in windows
//! of 30 frames. Per window: each scene's time a frame (the best of `runs` runs,
//! alternating), their ratio, and how far the layout has spread (the mean distance from
//! the centroid) and moves (the mean displacement a frame) at the window's start.
//!
//! Run with `cargo run --release --example shape_cost [runs]` (default 3).
//!
//! `shape_cost frames <disks|boxes> <n>` only runs that scene's first `n` frames, for a
//! count of instructions that a shared machine's load does not change: under
//! `valgrind --tool=callgrind`, the count for 270 frames less the count for 30 is
//! frames 30–270.

use std::time::Instant;

use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

mod common;

use common::generate::label_boxes;
use common::{load, Host};

const FRAME: f32 = 1.0 / 60.0;
const WINDOWS: usize = 8;
const WINDOW: usize = 30;

/// One run: per window, the time a frame (ms), the spread and the motion a frame.
fn run(scene: &CanvasSceneInput<u32>) -> Vec<(f64, f32, f32)> {
    let mut host = Host::new(scene.clone(), RapierLayoutConfig::force_directed());
    for _ in 0..WINDOW {
        host.frame(FRAME);
    }
    let ids: Vec<u32> = host.scene.nodes.iter().map(|n| n.id).collect();
    let n = ids.len() as f32;
    (0..WINDOWS)
        .map(|_| {
            let before: Vec<_> = ids.iter().map(|&id| host.pos(id)).collect();
            let centroid = before
                .iter()
                .fold(Vector2D::zero(), |sum, p| sum + p.to_vector())
                / n;
            let spread = before
                .iter()
                .map(|p| (p.to_vector() - centroid).length())
                .sum::<f32>()
                / n;
            let started = Instant::now();
            host.frame(FRAME);
            let mut elapsed = started.elapsed();
            let moved = ids
                .iter()
                .zip(&before)
                .map(|(&id, &p)| (host.pos(id) - p).length())
                .sum::<f32>()
                / n;
            let started = Instant::now();
            for _ in 1..WINDOW {
                host.frame(FRAME);
            }
            elapsed += started.elapsed();
            (elapsed.as_secs_f64() * 1e3 / WINDOW as f64, spread, moved)
        })
        .collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("frames") {
        let disks = load("n10000_e25000");
        let scene = match args.get(2).map(String::as_str) {
            Some("boxes") => label_boxes(disks, |_| false),
            _ => disks,
        };
        let frames: usize = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(WINDOW);
        let mut host = Host::new(scene, RapierLayoutConfig::force_directed());
        for _ in 0..frames {
            host.frame(FRAME);
        }
        return;
    }
    let runs: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(3)
        .max(1);
    let disks = load("n10000_e25000");
    let boxes = label_boxes(disks.clone(), |_| false);
    let mut best = [vec![f64::INFINITY; WINDOWS], vec![f64::INFINITY; WINDOWS]];
    let mut motion = [Vec::new(), Vec::new()];
    for _ in 0..runs {
        for (k, scene) in [&disks, &boxes].into_iter().enumerate() {
            let windows = run(scene);
            for (w, &(ms, _, _)) in windows.iter().enumerate() {
                best[k][w] = best[k][w].min(ms);
            }
            motion[k] = windows.iter().map(|&(_, s, m)| (s, m)).collect();
        }
    }
    println!("| frames | disks ms/frame | boxes ms/frame | boxes / disks | spread (disks, boxes) | moved a frame (disks, boxes) |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    for w in 0..WINDOWS {
        let (d, b) = (best[0][w], best[1][w]);
        let ((ds, dm), (bs, bm)) = (motion[0][w], motion[1][w]);
        println!(
            "| {}–{} | {d:.2} | {b:.2} | {:.2} | {ds:.0}, {bs:.0} | {dm:.2}, {bm:.2} |",
            WINDOW * (w + 1),
            WINDOW * (w + 2),
            b / d
        );
    }
    let mean = |k: usize| best[k].iter().sum::<f64>() / WINDOWS as f64;
    println!(
        "shape_cost: disks_ms={:.2} boxes_ms={:.2} ratio={:.2}",
        mean(0),
        mean(1),
        mean(1) / mean(0)
    );
}
