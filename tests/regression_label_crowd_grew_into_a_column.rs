//! Regression: a crowd of label boxes grew into a column. Two overlapping boxes were
//! parted along their nearest side, which for a label three times as wide as high is
//! the top or bottom for five overlapping offsets in six. While `force_directed()`
//! unfolds a dense graph its contacts are soft and labels overlap by the thousand, so
//! the crowd was pushed only up and down: `n1000_e2500` with every node a "node <id>"
//! label rested 2.27 times as tall as wide (its disks: 1.01), still moving 1.94 units a
//! frame over its last 20 frames (its disks: 0.34), with 71 overlapping pairs. Boxes
//! are now parted along the side the line between their centres leaves the boxes' sum
//! by: 0.84 times as tall as wide, 0.43 units a frame, no overlap.

mod common;

#[path = "../benches/common/generate.rs"]
#[allow(dead_code)]
mod generate;

use common::*;
use generate::label_boxes;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{quality, Layout, RapierLayoutConfig};

/// The spread of the layout's nodes across and along: the standard deviations of x
/// and y.
fn spread(points: &[Point2D<f32>]) -> (f32, f32) {
    let n = points.len() as f32;
    let (mx, my) = (
        points.iter().map(|p| p.x).sum::<f32>() / n,
        points.iter().map(|p| p.y).sum::<f32>() / n,
    );
    let sx = (points.iter().map(|p| (p.x - mx).powi(2)).sum::<f32>() / n).sqrt();
    let sy = (points.iter().map(|p| (p.y - my).powi(2)).sum::<f32>() / n).sqrt();
    (sx, sy)
}

#[test]
fn a_crowd_of_labels_rests_as_round_as_its_graph() {
    let scene = label_boxes(load_scene("n1000_e2500"), |_| false);
    let ids: Vec<u32> = scene.nodes.iter().map(|n| n.id).collect();
    let mut host = Host::new(scene, RapierLayoutConfig::force_directed());
    // The mean displacement of every frame until the layout rests.
    let mut moved = Vec::new();
    for _ in 0..400 {
        let before: Vec<_> = ids.iter().map(|id| host.pos(id)).collect();
        host.frame(1.0 / 60.0);
        let sum: f32 = ids
            .iter()
            .zip(&before)
            .map(|(id, &p)| dist(host.pos(id), p))
            .sum();
        moved.push(sum / ids.len() as f32);
        if host.layout.is_converged(&host.state) {
            break;
        }
    }
    let frames = moved.len();
    let points: Vec<_> = ids.iter().map(|id| host.pos(id)).collect();
    let (sx, sy) = spread(&points);
    let tail = &moved[frames.saturating_sub(20)..];
    let last = tail.iter().sum::<f32>() / tail.len() as f32;
    let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 1.0);
    let line = format!(
        "at rest after {frames} frames: spread {sx:.0} across, {sy:.0} along \
         (tall / wide {:.2}), {last:.2} units a frame over the last 20 frames, {overlaps} overlaps",
        sy / sx
    );
    assert!(host.layout.is_converged(&host.state), "{line}");
    // A random graph has no direction: its disks rest 1.01 times as tall as wide, and a
    // label's width may flatten the crowd a little (0.84), not stand it up (2.27).
    assert!((sy / sx).max(sx / sy) <= 1.5, "{line}");
    // The disks move 0.34 units a frame over their last 20 frames, the column 1.94.
    assert!(last <= 1.0, "{line}");
    assert_eq!(overlaps, 0, "{line}");
}
