//! A host loop on a real graph (Les Misérables co-appearances, 77 nodes, 254 edges).
//!
//! The graph settles for a while, then the "pointer" grabs a node, drags it across
//! several frames, lets go, and the example reports what happened: the speed at release,
//! how far the node flew, and how many frames until the layout reports rest.
//!
//! Run with `cargo run --release --example throw [path/to/scene.json]`.

use std::time::Instant;

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, DeltaMap, Layout, LayoutExtras, RapierLayout,
    RapierLayoutState,
};

const FRAME: f32 = 1.0 / 60.0;

/// The host's side of the contract: it owns the positions and adds the deltas.
struct Canvas {
    scene: CanvasSceneInput<u32>,
    layout: RapierLayout<u32>,
    state: RapierLayoutState,
    extras: LayoutExtras<u32>,
    step_time: std::time::Duration,
}

impl Canvas {
    fn frame(&mut self) -> DeltaMap<u32> {
        let started = Instant::now();
        let deltas = self.layout.step(
            &self.scene,
            &mut self.state,
            FRAME,
            &CanvasViewport::default(),
            &self.extras,
        );
        self.step_time += started.elapsed();
        self.scene.apply_deltas(&deltas);
        deltas
    }

    fn position(&self, id: u32) -> Point2D<f32> {
        self.scene
            .nodes
            .iter()
            .find(|n| n.id == id)
            .map(|n| n.position)
            .expect("node in scene")
    }

    fn move_to(&mut self, id: u32, p: Point2D<f32>) {
        if let Some(n) = self.scene.nodes.iter_mut().find(|n| n.id == id) {
            n.position = p;
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| format!("{}/scenes/les_miserables.json", env!("CARGO_MANIFEST_DIR")));
    let file: SceneFile = serde_json::from_str(&std::fs::read_to_string(&path)?)?;
    let scene = file.into_scene();
    println!(
        "scene {path}: {} nodes, {} edges",
        scene.nodes.len(),
        scene.edges.len()
    );

    let mut canvas = Canvas {
        scene,
        layout: RapierLayout::default(),
        state: RapierLayoutState::default(),
        extras: LayoutExtras::default(),
        step_time: Default::default(),
    };

    // 1. Let the graph move for two seconds.
    for _ in 0..120 {
        canvas.frame();
    }
    let grabbed = canvas.scene.nodes[canvas.scene.nodes.len() / 2].id;
    println!(
        "after 120 frames: the graph moved; grabbing node {grabbed} at {:?}",
        canvas.position(grabbed)
    );

    // 2. Drag it across 12 frames, accelerating to the right.
    canvas.extras.dragging.insert(grabbed);
    canvas.frame();
    let mut last = canvas.position(grabbed);
    for i in 1..=12 {
        let p = last + Vector2D::new(2.0 * i as f32, -0.5 * i as f32);
        canvas.move_to(grabbed, p);
        let deltas = canvas.frame();
        assert!(
            !deltas.contains_key(&grabbed),
            "a dragged node never gets a delta"
        );
        last = p;
    }
    let pointer_speed = Vector2D::new(24.0, -6.0).length() / FRAME;

    // 3. Release and watch it fly.
    canvas.extras.dragging.clear();
    let release_at = canvas.position(grabbed);
    canvas.frame();
    let world = canvas
        .layout
        .world()
        .expect("a world exists after the first step");
    let release_speed = world.linear_velocity(&grabbed).map_or(0.0, |v| v.length());
    println!(
        "released at {release_at:?}: thrown at the pointer's {pointer_speed:.0} units/s; \
         after one free frame against {} stretched springs it flies at {release_speed:.0} units/s",
        canvas
            .scene
            .edges
            .iter()
            .filter(|e| e.source == grabbed || e.target == grabbed)
            .count()
    );

    let mut frames_to_rest = None;
    let mut farthest: f32 = 0.0;
    for frame in 1..=6000 {
        canvas.frame();
        farthest = farthest.max((canvas.position(grabbed) - release_at).length());
        if canvas.layout.is_converged(&canvas.state) {
            frames_to_rest = Some(frame);
            break;
        }
    }
    println!("the node flew {farthest:.0} units from where it was released before the springs pulled it back");
    match frames_to_rest {
        Some(f) => println!(
            "the layout reported rest {f} frames ({:.1} s) after the release",
            f as f32 * FRAME
        ),
        None => println!("the layout was still moving 6000 frames after the release"),
    }
    let calls = canvas.state.step_count;
    println!(
        "{calls} calls, {:.1} µs per step on average; rebuilds {}, patches {}",
        canvas.step_time.as_secs_f64() * 1e6 / calls as f64,
        canvas.layout.rebuild_count(),
        canvas.layout.patch_count()
    );
    Ok(())
}
