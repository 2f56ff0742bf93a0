//! Barnes–Hut accuracy and cost against theta: mean and maximum relative force error
//! against the exact sum (theta = 0), and the time of one force pass over all nodes, at
//! n = 200, 1,000 and 10,000 (the shipped random scenes).
//!
//! Run with `cargo run --release --example barnes_hut`.

use std::time::Instant;

use graph_canvas_layout::config::Repulsion;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::ManyBody;

/// One force pass as the layout runs it: build, then every point's force.
fn forces(tree: &mut ManyBody, points: &[Point2D<f32>], theta: f32) -> Vec<Vector2D<f32>> {
    let r = Repulsion::default();
    tree.build(points);
    let mut out = Vec::new();
    tree.forces(r.strength, theta, r.min_distance, |_| true, &mut out);
    out
}

fn main() {
    println!("| n | theta | mean relative error | max relative error | ms per force pass (build + n queries) |");
    println!("| ---: | ---: | ---: | ---: | ---: |");
    for name in ["n200_e500", "n1000_e2500", "n10000_e25000"] {
        let path = format!("{}/scenes/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let file: SceneFile =
            serde_json::from_str(&std::fs::read_to_string(&path).expect("scene")).expect("json");
        let points: Vec<Point2D<f32>> = file.nodes.iter().map(|n| Point2D::new(n.x, n.y)).collect();
        let mut tree = ManyBody::default();
        let exact = forces(&mut tree, &points, 0.0);
        for theta in [0.0_f32, 0.3, 0.5, 0.7, 0.9, 1.2, 1.5] {
            let started = Instant::now();
            let mut passes = 0;
            let mut approx = Vec::new();
            while passes == 0 || started.elapsed().as_secs_f64() < 0.3 {
                approx = forces(&mut tree, &points, theta);
                passes += 1;
            }
            let ms = started.elapsed().as_secs_f64() * 1e3 / f64::from(passes);
            let errors: Vec<f32> = exact
                .iter()
                .zip(&approx)
                .map(|(e, a)| (*a - *e).length() / e.length().max(f32::MIN_POSITIVE))
                .collect();
            let mean = errors.iter().sum::<f32>() / errors.len() as f32;
            let max = errors.iter().copied().fold(0.0, f32::max);
            println!(
                "| {} | {theta} | {:.2e} | {:.2e} | {ms:.3} |",
                points.len(),
                mean,
                max
            );
        }
    }
}
