//! A drag on a layout at rest: the host moves one node around a circle of 200 units,
//! 2° a frame for 180 frames, then lets go. Measures each frame's step time and how far
//! the worst flow edge falls short of its gap.

use std::time::Instant;

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::CanvasSceneInput;

use crate::common::{percentile, Host};
use crate::measure::worst_shortfall;

/// The frames of a drag before the constraints must hold again.
pub const GRACE: usize = 10;

pub struct Drag {
    /// The node dragged: the one with the most edges.
    pub node: u32,
    /// The worst shortfall of any frame after the first [`GRACE`] frames.
    pub worst_after_grace: f32,
    /// The worst shortfall of any frame.
    pub worst: f32,
    pub p95_ms: f64,
}

/// Drags the scene's busiest node in `host` (at rest) and measures each frame.
pub fn drag(host: &mut Host, gap: f32, frame_dt: f32) -> Drag {
    let node = busiest(&host.scene);
    let centre = host.pos(node);
    let exempt = host.layout.flow_exempt_edges().to_vec();
    host.extras.dragging = [node].into_iter().collect();
    let (mut worst, mut worst_after_grace) = (0.0_f32, 0.0_f32);
    let mut steps = Vec::new();
    for frame in 1..=180 {
        let angle = (frame as f32 * 2.0).to_radians();
        let at = centre + Vector2D::new(angle.cos() - 1.0, angle.sin()) * 200.0;
        host.set_pos(node, Point2D::new(at.x, at.y));
        let started = Instant::now();
        host.frame(frame_dt);
        steps.push(started.elapsed().as_secs_f64() * 1e3);
        let short = worst_shortfall(&host.scene, gap, &exempt);
        worst = worst.max(short);
        if frame > GRACE {
            worst_after_grace = worst_after_grace.max(short);
        }
    }
    host.extras.dragging.clear();
    steps.sort_by(f64::total_cmp);
    Drag {
        node,
        worst_after_grace,
        worst,
        p95_ms: percentile(&steps, 0.95),
    }
}

/// The node with the most edges (the first of them).
fn busiest(scene: &CanvasSceneInput<u32>) -> u32 {
    let mut degree = vec![0_u32; scene.nodes.len()];
    for e in &scene.edges {
        degree[e.source as usize] += 1;
        degree[e.target as usize] += 1;
    }
    let best = (0..degree.len()).max_by_key(|&i| (degree[i], std::cmp::Reverse(i)));
    scene.nodes[best.unwrap_or(0)].id
}
