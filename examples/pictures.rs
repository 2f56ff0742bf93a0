//! Pictures of the layout, headless: Les Misérables before and after settling with
//! `force_directed()`, and the trajectory of a thrown node over time. Writes
//! `target/pictures/{before,after,throw}.svg`.
//!
//! Run with `cargo run --release --example pictures`.

use std::fmt::Write as _;

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, Layout, LayoutExtras, RapierLayout, RapierLayoutConfig,
    RapierLayoutState, SceneFile,
};

const FRAME: f32 = 1.0 / 60.0;

fn svg(scene: &CanvasSceneInput<u32>, trail: &[Point2D<f32>], title: &str) -> String {
    let pts = scene
        .nodes
        .iter()
        .map(|n| n.position)
        .chain(trail.iter().copied());
    let (mut lo, mut hi) = (
        Point2D::new(f32::MAX, f32::MAX),
        Point2D::new(f32::MIN, f32::MIN),
    );
    for p in pts {
        lo = lo.min(p);
        hi = hi.max(p);
    }
    let pad = 40.0;
    let (w, h) = (hi.x - lo.x + 2.0 * pad, hi.y - lo.y + 2.0 * pad);
    let at = |p: Point2D<f32>| (p.x - lo.x + pad, p.y - lo.y + pad);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}" font-family="sans-serif">"#
    );
    let _ = writeln!(
        out,
        r#"<rect width="100%" height="100%" fill="white"/><text x="12" y="24" font-size="16">{title}</text>"#
    );
    let position: std::collections::HashMap<u32, Point2D<f32>> =
        scene.nodes.iter().map(|n| (n.id, n.position)).collect();
    for e in &scene.edges {
        let ((x1, y1), (x2, y2)) = (at(position[&e.source]), at(position[&e.target]));
        let _ = writeln!(
            out,
            r##"<line x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}" stroke="#999" stroke-width="1"/>"##
        );
    }
    if trail.len() > 1 {
        let path: Vec<String> = trail
            .iter()
            .map(|p| {
                let (x, y) = at(*p);
                format!("{x:.1},{y:.1}")
            })
            .collect();
        let _ = writeln!(
            out,
            r##"<polyline points="{}" fill="none" stroke="#d62728" stroke-width="2"/>"##,
            path.join(" ")
        );
        for (i, p) in trail.iter().enumerate().step_by(10) {
            let (x, y) = at(*p);
            let _ = writeln!(
                out,
                r##"<circle cx="{x:.1}" cy="{y:.1}" r="3" fill="#d62728"/><text x="{:.1}" y="{:.1}" font-size="10" fill="#d62728">{:.2}s</text>"##,
                x + 4.0,
                y - 4.0,
                i as f32 * FRAME
            );
        }
    }
    for n in &scene.nodes {
        let (x, y) = at(n.position);
        let r = if n.radius > 0.0 { n.radius } else { 16.0 };
        let _ = writeln!(
            out,
            r##"<circle cx="{x:.1}" cy="{y:.1}" r="{r}" fill="#1f77b4" fill-opacity="0.8" stroke="white"/>"##
        );
    }
    out.push_str("</svg>\n");
    out
}

fn frame(
    layout: &mut RapierLayout<u32>,
    scene: &mut CanvasSceneInput<u32>,
    state: &mut RapierLayoutState,
    extras: &LayoutExtras<u32>,
) {
    let deltas = layout.step(scene, state, FRAME, &CanvasViewport::default(), extras);
    scene.apply_deltas(&deltas);
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = format!("{}/target/pictures", env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(&dir)?;
    let text = std::fs::read_to_string(format!(
        "{}/scenes/les_miserables.json",
        env!("CARGO_MANIFEST_DIR")
    ))?;
    let mut scene = serde_json::from_str::<SceneFile>(&text)?.into_scene();
    std::fs::write(
        format!("{dir}/before.svg"),
        svg(&scene, &[], "les_miserables: scene file"),
    )?;

    let mut layout = RapierLayout::new(RapierLayoutConfig::force_directed());
    let mut state = RapierLayoutState::default();
    let mut extras = LayoutExtras::default();
    let mut frames = 0;
    while !layout.is_converged(&state) && frames < 3000 {
        frame(&mut layout, &mut scene, &mut state, &extras);
        frames += 1;
    }
    std::fs::write(
        format!("{dir}/after.svg"),
        svg(
            &scene,
            &[],
            &format!("les_miserables: force_directed(), at rest after {frames} frames"),
        ),
    )?;

    // Throw the first node to the right at about 1,500 units/s and follow it for 2 s.
    let id = scene.nodes[0].id;
    extras.dragging.insert(id);
    frame(&mut layout, &mut scene, &mut state, &extras);
    for _ in 0..3 {
        scene.nodes[0].position += Vector2D::new(25.0, -5.0);
        frame(&mut layout, &mut scene, &mut state, &extras);
    }
    extras.dragging.clear();
    let mut trail = vec![scene.nodes[0].position];
    for _ in 0..120 {
        frame(&mut layout, &mut scene, &mut state, &extras);
        trail.push(scene.nodes[0].position);
    }
    std::fs::write(
        format!("{dir}/throw.svg"),
        svg(
            &scene,
            &trail,
            "a node thrown at 1,530 units/s, its path over 2 s (dots every 1/6 s)",
        ),
    )?;
    println!("wrote {dir}/before.svg, after.svg and throw.svg (settled in {frames} frames)");
    Ok(())
}
