//! What a user feels on a settled graph, measured: a throw, and how far an edit or a
//! drag reaches.
//!
//! - **Throw**: the node farthest from the graph's centre is dragged 300 units outward
//!   over 10 frames (1,800 units/s) and let go. Printed: its outward speed in the frame
//!   after the release, how much further out it flies than where it was let go, its
//!   fastest speed back toward the centre, frames until the layout rests again, and the
//!   edge-length spread (CV) before and after.
//! - **Locality**: on the settled graph, a leaf is added to a leaf (placed 50 units
//!   beyond it), or a leaf is dragged 100 units outward over 10 frames and let go; the
//!   layout runs to rest. Printed: how far the nodes moved, by hop distance from the
//!   edited or dragged node (0, 1, 2, 3, 4+), mean and most.
//! - **Added nodes**: 20 leaves added at the position of the node nearest the centre
//!   (an interior node), joined to it; the layout runs to rest. Printed: how far that
//!   node moved, the farthest a leaf rests from it, overlapping disks, and how far the
//!   nodes 3+ hops from it moved.
//! - **Release**: a lone node dragged through the given positions, one frame each, and
//!   let go without motion. Printed: the speed it leaves with (its release-frame delta
//!   over the frame time) against the pointer's last move.
//!
//! Run with `cargo run --release --example feel [--stress] [--fast] [--default]
//! [--whole-graph] [scene ...]` (`force_directed()` by default; `--stress`:
//! `RapierLayoutConfig::stress()`; `--fast`: `force_directed_fast()`;
//! `--default`: the default configuration; `--whole-graph`: a disturbance reheats the
//! whole layout, `Cooling::reheat_hops` `None`); scenes default to `les_miserables`,
//! `karate` and `1138_bus`.

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::quality::{self, Displacement};
use graph_canvas_layout::{CanvasEdge, CanvasNode, CanvasSceneInput, Layout, RapierLayoutConfig};

mod common;

use common::{load, Host};

const FRAME: f32 = 1.0 / 60.0;
/// Frames a layout gets to come to rest.
const BUDGET: usize = 3000;

/// Drags `id` by `step` per frame for `frames` frames, then lets go.
fn drag(host: &mut Host, id: u32, step: Vector2D<f32>, frames: usize) {
    host.extras.dragging.insert(id);
    for _ in 0..frames {
        let node = host
            .scene
            .nodes
            .iter_mut()
            .find(|n| n.id == id)
            .expect("node");
        node.position += step;
        host.frame(FRAME);
    }
    host.extras.dragging.remove(&id);
}

fn degree(scene: &CanvasSceneInput<u32>, id: u32) -> usize {
    scene
        .edges
        .iter()
        .filter(|e| e.source == id || e.target == id)
        .count()
}

/// The throw, on a settled copy of `host`.
fn throw(mut host: Host, name: &str) {
    let cv_before = quality::edge_length_cv(&host.scene).unwrap_or(0.0);
    let centre = host.centre();
    let far = host
        .scene
        .nodes
        .iter()
        .max_by(|a, b| {
            (a.position - centre)
                .length()
                .total_cmp(&(b.position - centre).length())
        })
        .map(|n| n.id)
        .expect("nodes");
    let out = (host.pos(far) - centre).normalize();
    drag(&mut host, far, out * 30.0, 10);
    let released = host.pos(far);
    let released_out = (released - centre).dot(out);
    host.frame(FRAME);
    let after = (host.pos(far) - released).dot(out) / FRAME;
    let (mut furthest, mut fastest_back) = (0.0_f32, 0.0_f32);
    let mut last = host.pos(far);
    let mut frames = 1;
    while frames < BUDGET && !host.layout.is_converged(&host.state) {
        host.frame(FRAME);
        frames += 1;
        let p = host.pos(far);
        furthest = furthest.max((p - centre).dot(out) - released_out);
        fastest_back = fastest_back.max(-(p - last).dot(out) / FRAME);
        last = p;
    }
    let cv_after = quality::edge_length_cv(&host.scene).unwrap_or(0.0);
    println!(
        "| {name} | {far} | {after:.0} | {furthest:.0} | {fastest_back:.0} | {frames} | {cv_before:.3} → {cv_after:.3} |"
    );
}

fn print_hops(name: &str, what: &str, rows: &[Displacement], frames: usize) {
    let cells: Vec<String> = rows
        .iter()
        .map(|row| {
            if row.nodes == 0 {
                "–".to_string()
            } else {
                format!("{:.1} / {:.1}", row.mean, row.max)
            }
        })
        .collect();
    println!("| {name} | {what} | {} | {frames} |", cells.join(" | "));
}

/// A leaf whose only neighbour is a leaf, or the leaf farthest from the centre.
fn leaf(host: &Host) -> u32 {
    let centre = host.centre();
    host.scene
        .nodes
        .iter()
        .filter(|n| degree(&host.scene, n.id) == 1)
        .max_by(|a, b| {
            (a.position - centre)
                .length()
                .total_cmp(&(b.position - centre).length())
        })
        .map(|n| n.id)
        .expect("a leaf")
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let config = if args.iter().any(|a| a == "--fast") {
        RapierLayoutConfig::force_directed_fast()
    } else if args.iter().any(|a| a == "--stress") {
        RapierLayoutConfig::stress()
    } else if args.iter().any(|a| a == "--default") {
        RapierLayoutConfig::default()
    } else {
        RapierLayoutConfig::force_directed()
    };
    let mut config = config;
    if args.iter().any(|a| a == "--whole-graph") {
        if let Some(cooling) = config.cooling.as_mut() {
            cooling.reheat_hops = None;
        }
    }
    let mut names: Vec<&str> = args
        .iter()
        .filter(|a| !a.starts_with("--"))
        .map(String::as_str)
        .collect();
    if names.is_empty() {
        names = vec!["les_miserables", "karate", "1138_bus"];
    }
    println!("| scene | thrown node | speed out after release (units/s) | flew further out | fastest back (units/s) | frames to rest | edge-length CV |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    let mut settled = Vec::new();
    for &name in &names {
        let mut host = Host::new(load(name), config.clone());
        host.settle(FRAME, BUDGET);
        settled.push((name, host.scene.clone()));
        throw(host, name);
    }
    println!();
    println!("| scene | disturbance | hop 0 mean / most | hop 1 | hop 2 | hop 3 | hop 4+ | frames to rest |");
    println!("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |");
    for (name, scene) in settled {
        // An edit: a new leaf on a leaf.
        let mut host = Host::new(scene.clone(), config.clone());
        host.settle(FRAME, BUDGET);
        let parent = leaf(&host);
        let centre = host.centre();
        let out = (host.pos(parent) - centre).normalize();
        let before = host.scene.clone();
        let id = host.scene.nodes.iter().map(|n| n.id).max().unwrap_or(0) + 1;
        host.scene
            .nodes
            .push(CanvasNode::new(id, host.pos(parent) + out * 50.0));
        host.scene.edges.push(CanvasEdge::new(parent, id));
        let frames = host.settle(FRAME, BUDGET);
        let rows = quality::displacement_by_hops(&before, &host.scene, &parent, 5);
        print_hops(name, "a leaf added to a leaf", &rows, frames);
        // A drag of a leaf, 100 units outward, released.
        let mut host = Host::new(scene, config.clone());
        host.settle(FRAME, BUDGET);
        let dragged = leaf(&host);
        let centre = host.centre();
        let out = (host.pos(dragged) - centre).normalize();
        let before = host.scene.clone();
        drag(&mut host, dragged, out * 10.0, 10);
        let frames = host.settle(FRAME, BUDGET);
        let rows = quality::displacement_by_hops(&before, &host.scene, &dragged, 5);
        print_hops(name, "a leaf dragged 100 units", &rows, frames);
    }
    println!();
    println!("| scene | centre node moved | farthest leaf from it | overlapping disks | 3+ hops: mean / most moved | frames to rest |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    for &name in &names {
        add_leaves(name, &config, 20);
    }
    println!();
    println!(
        "| pointer, one frame each (units) | pointer's last move (units/s) | thrown at (units/s) |"
    );
    println!("| --- | ---: | ---: |");
    for (xs, last) in [
        (&[0.0, 10.0, 30.0][..], 1_200.0),
        (&[0.0, 0.0, 20.0, 20.0, 40.0, 40.0][..], 600.0),
        (&[0.0, 10.0, 30.0, 30.0, 30.0, 30.0, 30.0][..], 0.0),
    ] {
        let speed = release_speed(&config, xs);
        // A throw of nothing prints as 0, not -0.
        let speed = if speed.abs() < 0.5 { 0.0 } else { speed };
        println!("| {xs:?} | {last:.0} | {speed:.0} |");
    }
}

/// `count` leaves added at the position of the node nearest the centre of `name` at
/// rest, joined to it, run to rest again.
fn add_leaves(name: &str, config: &RapierLayoutConfig, count: u32) {
    let mut host = Host::new(load(name), config.clone());
    host.settle(FRAME, BUDGET);
    let before = host.scene.clone();
    let centre = host.centre();
    let anchor = before
        .nodes
        .iter()
        .min_by(|a, b| {
            (a.position - centre)
                .length()
                .total_cmp(&(b.position - centre).length())
        })
        .map(|n| n.id)
        .expect("nodes");
    let at = host.pos(anchor);
    let first = before.nodes.iter().map(|n| n.id).max().unwrap_or(0) + 1;
    for id in first..first + count {
        host.scene.nodes.push(CanvasNode::new(id, at));
        host.scene.edges.push(CanvasEdge::new(anchor, id));
    }
    let frames = host.settle(FRAME, BUDGET);
    let farthest = (first..first + count)
        .map(|id| (host.pos(id) - host.pos(anchor)).length())
        .fold(0.0, f32::max);
    let far = quality::displacement_by_hops(&before, &host.scene, &anchor, 4)[3];
    println!(
        "| {name} | {:.1} | {farthest:.0} | {} | {:.2} / {:.1} | {frames} |",
        (host.pos(anchor) - at).length(),
        quality::overlapping_pairs(&host.scene, 16.0, 0.5),
        far.mean,
        far.max,
    );
}

/// A lone node dragged through `xs` (one frame each) and let go without motion: the
/// speed it leaves with.
fn release_speed(config: &RapierLayoutConfig, xs: &[f32]) -> f32 {
    let scene = CanvasSceneInput::new(vec![CanvasNode::new(1, Point2D::new(xs[0], 0.0))], vec![]);
    let mut host = Host::new(scene, config.clone());
    host.frame(FRAME);
    host.extras.dragging.insert(1);
    for &x in xs {
        host.set_pos(1, Point2D::new(x, 0.0));
        host.frame(FRAME);
    }
    host.extras.dragging.clear();
    host.frame(FRAME).get(&1).map_or(0.0, |d| d.x) / FRAME
}
