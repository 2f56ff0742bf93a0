//! Pictures of the layout, headless: Les Misérables before and after settling with
//! `force_directed()`, and the trajectory of a thrown node over time. Writes
//! `target/pictures/{before,after,throw}.svg`.
//!
//! Run with `cargo run --release --example pictures`.

mod common;

use common::svg::{svg, BLUE};
use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, Layout, LayoutExtras, RapierLayout, RapierLayoutConfig,
    RapierLayoutState,
};

const FRAME: f32 = 1.0 / 60.0;

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
        svg(&scene, "les_miserables: scene file", &[], &[], |_| BLUE),
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
            &format!("les_miserables: force_directed(), at rest after {frames} frames"),
            &[],
            &[],
            |_| BLUE,
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
            "a node thrown at 1,530 units/s, its path over 2 s (dots every 1/6 s)",
            &trail,
            &[],
            |_| BLUE,
        ),
    )?;
    println!("wrote {dir}/before.svg, after.svg and throw.svg (settled in {frames} frames)");
    Ok(())
}
