//! The crate's first job: a real graph laid out and drawn. `1138_bus` (a power network
//! of 1,138 nodes, from the standard graph-drawing collections) starts on a spiral and
//! is laid out with `RapierLayoutConfig::stress()` to rest, one `step` a frame; then a
//! leaf is thrown and its path followed. Writes `target/pictures/layout.svg` (the
//! layout and the throw) and prints its path.
//!
//! Run with `cargo run --release --example layout [scene]` (any scene of `scenes/`).

mod common;

use common::svg::{svg, BLUE};
use common::{load, Host};
use graph_canvas_layout::{quality, Layout, RapierLayoutConfig};

const FRAME: f32 = 1.0 / 60.0;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let name = std::env::args().nth(1).unwrap_or_else(|| "1138_bus".into());
    let mut host = Host::new(load(&name), RapierLayoutConfig::stress());
    let started = std::time::Instant::now();
    let frames = host.settle(FRAME, 3_000);
    let seconds = started.elapsed().as_secs_f64();
    let stress = quality::normalized_stress(&host.scene).unwrap_or(0.0);

    // Drag the leaf farthest from the centre outward at 3,600 units/s for 10 frames, let
    // go, and follow it.
    let centre = host.centre();
    let leaf = host.outermost_leaf().unwrap_or(host.scene.nodes[0].id);
    let out = (host.pos(leaf) - centre).normalize() * 60.0;
    let mut trail = vec![host.pos(leaf)];
    host.extras.dragging.insert(leaf);
    for _ in 0..10 {
        let p = host.pos(leaf);
        host.set_pos(leaf, p + out);
        host.frame(FRAME);
        trail.push(host.pos(leaf));
    }
    host.extras.dragging.clear();
    let mut after = 0;
    while after < 600 && !host.layout.is_converged(&host.state) {
        host.frame(FRAME);
        trail.push(host.pos(leaf));
        after += 1;
    }

    let dir = format!("{}/target/pictures", env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(&dir)?;
    let path = format!("{dir}/layout.svg");
    let title = format!(
        "{name} laid out by stress() in {frames} frames (normalised stress {stress:.3}); red: a leaf dragged out and let go"
    );
    std::fs::write(&path, svg(&host.scene, &title, &trail, &[], |_| BLUE))?;
    println!(
        "{name}: {} nodes laid out in {frames} frames ({seconds:.2} s), normalised stress {stress:.4}; a thrown leaf came to rest {after} frames after its release",
        host.scene.nodes.len()
    );
    println!("wrote {path}");
    Ok(())
}
