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

#[derive(Clone)]
pub struct Drag {
    /// The node dragged: the one with the most edges.
    pub node: u32,
    /// The worst shortfall of any frame after the first [`GRACE`] frames.
    pub worst_after_grace: f32,
    /// The worst shortfall of any frame.
    pub worst: f32,
    pub p95_ms: f64,
    /// Where the drag's time went, per frame (ms): forces, contacts, rapier, constraints.
    pub stages_ms: [f64; 4],
    /// Dynamic bodies awake after a frame, on average: what the drag moves.
    pub awake: usize,
}

/// Drags the scene's busiest node in `host` (at rest) and measures each frame.
pub fn drag(host: &mut Host, gap: f32, frame_dt: f32) -> Drag {
    let node = busiest(&host.scene);
    let centre = host.pos(node);
    let exempt = host.layout.flow_exempt_edges().to_vec();
    host.extras.dragging = [node].into_iter().collect();
    host.layout.set_profiling(true);
    let (mut worst, mut worst_after_grace) = (0.0_f32, 0.0_f32);
    let (mut steps, mut awake) = (Vec::new(), 0);
    for frame in 1..=180 {
        let angle = (frame as f32 * 2.0).to_radians();
        let at = centre + Vector2D::new(angle.cos() - 1.0, angle.sin()) * 200.0;
        host.set_pos(node, Point2D::new(at.x, at.y));
        let started = Instant::now();
        host.frame(frame_dt);
        steps.push(started.elapsed().as_secs_f64() * 1e3);
        awake += host.layout.world().map_or(0, |w| w.awake_dynamic_count());
        let short = worst_shortfall(&host.scene, gap, &exempt);
        worst = worst.max(short);
        if frame > GRACE {
            worst_after_grace = worst_after_grace.max(short);
        }
    }
    host.extras.dragging.clear();
    let p = host.layout.profile().expect("profiling on");
    host.layout.set_profiling(false);
    let per_frame = |d: std::time::Duration| d.as_secs_f64() * 1e3 / steps.len() as f64;
    let stages_ms = [p.forces, p.contacts, p.rapier, p.constraints].map(per_frame);
    steps.sort_by(f64::total_cmp);
    Drag {
        awake: awake / steps.len(),
        stages_ms,
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
