//! Label boxes against disks: each graph laid out from its file to rest with every node
//! a disk, then with every node a box of 7 units a character of "node <id>" by 20 (and
//! qh882 mixed: every third node a disk of radius 16), under `force_directed()` and
//! `stress()`. Prints frames to rest, overlapping pairs (more than 1 unit inside each
//! other on both axes), the edge-length CV (centre to centre), the mean edge length,
//! normalised stress and the picture's shape (the standard deviation of y over that of
//! x: 1 for a round picture). `n1000_e2500`, a dense random graph, is a crowd of
//! overlapping labels while `force_directed()` unfolds it.
//!
//! Run with `cargo run --release --example shapes`.

use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{quality, CanvasSceneInput, RapierLayoutConfig};

mod common;

use common::generate::label_boxes;
use common::svg::{svg, BLUE};
use common::{load, Host};

const FRAME: f32 = 1.0 / 60.0;

/// The standard deviation of the nodes' y over that of their x.
fn tall_over_wide(scene: &CanvasSceneInput<u32>) -> f32 {
    let points: Vec<Point2D<f32>> = scene.nodes.iter().map(|n| n.position).collect();
    let n = points.len() as f32;
    let deviation = |v: &dyn Fn(&Point2D<f32>) -> f32| {
        let mean = points.iter().map(v).sum::<f32>() / n;
        (points.iter().map(|p| (v(p) - mean).powi(2)).sum::<f32>() / n).sqrt()
    };
    deviation(&|p| p.y) / deviation(&|p| p.x)
}

fn main() {
    let presets = [
        ("force_directed", RapierLayoutConfig::force_directed()),
        ("stress", RapierLayoutConfig::stress()),
    ];
    println!(
        "| graph | nodes | preset | frames to rest | overlaps | edge CV | mean edge | stress | tall / wide |"
    );
    println!("| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    for (graph, kinds) in [("1138_bus", false), ("qh882", true), ("n1000_e2500", false)] {
        let file = load(graph);
        let variants: Vec<(&str, CanvasSceneInput<u32>)> = if kinds {
            vec![
                ("disks", file.clone()),
                ("mixed", label_boxes(file.clone(), |id| id % 3 == 0)),
            ]
        } else {
            vec![
                ("disks", file.clone()),
                ("boxes", label_boxes(file.clone(), |_| false)),
            ]
        };
        for (preset, config) in &presets {
            for (kind, scene) in &variants {
                let mut host = Host::new(scene.clone(), config.clone());
                let frames = host.settle(FRAME, 3_000);
                let overlaps = quality::overlapping_pairs(&host.scene, config.default_radius, 1.0);
                let cv = quality::edge_length_cv(&host.scene).unwrap_or(f32::NAN);
                let mean = quality::mean_edge_length(&host.scene).unwrap_or(f32::NAN);
                let stress = quality::normalized_stress(&host.scene).unwrap_or(f64::NAN);
                let shape = tall_over_wide(&host.scene);
                println!(
                    "| {graph} | {kind} | {preset} | {frames} | {overlaps} | {cv:.3} | {mean:.1} | {stress:.4} | {shape:.2} |"
                );
                if *kind != "disks" {
                    let dir = format!("{}/target/pictures", env!("CARGO_MANIFEST_DIR"));
                    let _ = std::fs::create_dir_all(&dir);
                    let path = format!("{dir}/shapes_{graph}_{kind}_{preset}.svg");
                    let title = format!(
                        "{graph}, {kind}, {preset}(): {frames} frames, {overlaps} overlaps"
                    );
                    let picture = svg(&host.scene, &title, &[], &[], |_| BLUE);
                    std::fs::write(&path, picture).expect("write the picture");
                }
            }
        }
    }
}
