//! The per-node forces on the shipped graphs, as pictures and as numbers: a radial tree
//! and a timeline of karate by hops from its instructor, Les Misérables in four groups,
//! and karate's two leaders locked on one line. Writes
//! `target/pictures/{radial,timeline,groups,axis_lock}.svg` and prints how close each
//! layout keeps to what it was asked.
//!
//! `cargo run --release --example forces [-- --cost]`: with `--cost`, also the cost of
//! each force per step on `n10000_e25000` under `force_directed()` (60 frames from the
//! file, each force on every node at a strength too faint to change the motion, against
//! the same run without).

mod common;

use std::collections::HashMap;
use std::time::Instant;

use common::svg::{svg, Guide, BLUE, PALETTE};
use common::Host;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::quality::hop_distances;
use graph_canvas_layout::scene::AxisLock;
use graph_canvas_layout::{NodeForces, RapierLayoutConfig};

const FRAME: f32 = 1.0 / 60.0;

fn ids(host: &Host) -> Vec<u32> {
    host.scene.nodes.iter().map(|n| n.id).collect()
}

fn write(name: &str, picture: String) -> Result<(), Box<dyn std::error::Error>> {
    let dir = format!("{}/target/pictures", env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(&dir)?;
    std::fs::write(format!("{dir}/{name}.svg"), picture)?;
    Ok(())
}

/// Karate on rings 120 units apart by hops from node 0.
fn radial() -> Result<(), Box<dyn std::error::Error>> {
    let mut host = Host::new(common::load("karate"), RapierLayoutConfig::force_directed());
    let hops = hop_distances(&host.scene, &0);
    let ring = |id: u32| 120.0 * hops[&id] as f32;
    for id in ids(&host) {
        let forces = NodeForces::default().on_ring(0.0, 0.0, ring(id), 50.0);
        host.extras.forces.insert(id, forces);
    }
    let frames = host.settle(FRAME, 3_000);
    let off: Vec<f32> = ids(&host)
        .iter()
        .map(|&id| (host.pos(id).to_vector().length() - ring(id)).abs())
        .collect();
    let rings: Vec<Guide> = (1..=hops.values().copied().max().unwrap_or(0))
        .map(|k| Guide::Circle(Point2D::zero(), 120.0 * k as f32))
        .collect();
    let title = "karate: rings by hops from node 0 (strength 50)";
    write("radial", svg(&host.scene, title, &[], &rings, |_| BLUE))?;
    report("radial", frames, &off, "off its ring");
    Ok(())
}

/// Karate with x at a date (hops from node 0, 100 units apart), y left to the layout.
fn timeline() -> Result<(), Box<dyn std::error::Error>> {
    let mut host = Host::new(common::load("karate"), RapierLayoutConfig::force_directed());
    let hops = hop_distances(&host.scene, &0);
    let date = |id: u32| 100.0 * hops[&id] as f32;
    for id in ids(&host) {
        let forces = NodeForces::default().toward_x(date(id), 50.0);
        host.extras.forces.insert(id, forces);
    }
    let frames = host.settle(FRAME, 3_000);
    let off: Vec<f32> = ids(&host)
        .iter()
        .map(|&id| (host.pos(id).x - date(id)).abs())
        .collect();
    let lines: Vec<Guide> = (0..=hops.values().copied().max().unwrap_or(0))
        .map(|k| Guide::VerticalLine(100.0 * k as f32))
        .collect();
    let title = "karate: x by hops from node 0 (strength 50), y free";
    write("timeline", svg(&host.scene, title, &[], &lines, |_| BLUE))?;
    report("timeline", frames, &off, "off its date");
    Ok(())
}

/// Mean distance from each node to its group's centre.
fn spread(host: &Host, group: impl Fn(u32) -> u32) -> f32 {
    let mut members: HashMap<u32, Vec<Point2D<f32>>> = HashMap::new();
    for n in &host.scene.nodes {
        members.entry(group(n.id)).or_default().push(n.position);
    }
    let mut total = 0.0;
    for points in members.values() {
        let c = points
            .iter()
            .fold(Point2D::zero(), |s, p| s + p.to_vector())
            / points.len() as f32;
        total += points.iter().map(|p| (*p - c).length()).sum::<f32>();
    }
    total / host.scene.nodes.len() as f32
}

/// Les Misérables in four groups by `id % 4`, against the graph's own communities.
fn groups() -> Result<(), Box<dyn std::error::Error>> {
    let group = |id: u32| id % 4;
    let mut free = Host::new(
        common::load("les_miserables"),
        RapierLayoutConfig::force_directed(),
    );
    free.settle(FRAME, 3_000);
    let mut config = RapierLayoutConfig::force_directed();
    config.groups.pull = 0.1;
    config.groups.separation = 10.0;
    let mut host = Host::new(common::load("les_miserables"), config);
    for id in ids(&host) {
        host.extras
            .forces
            .insert(id, NodeForces::default().in_group(group(id)));
    }
    let frames = host.settle(FRAME, 3_000);
    let (off, on) = (spread(&free, group), spread(&host, group));
    let title = "les_miserables: four groups by id % 4 (pull 0.1, separation 10)";
    let colour = |id: u32| PALETTE[group(id) as usize % PALETTE.len()];
    write("groups", svg(&host.scene, title, &[], &[], colour))?;
    println!(
        "groups:   at rest after {frames} frames; mean distance to the group's centre {on:.1} \
         units ({off:.1} without the force)"
    );
    Ok(())
}

/// Karate's two leaders put on y = 0 and locked there; they slide along it.
fn axis_lock() -> Result<(), Box<dyn std::error::Error>> {
    let mut host = Host::new(common::load("karate"), RapierLayoutConfig::force_directed());
    host.settle(FRAME, 3_000);
    let centre = host.centre();
    for id in [0, 33] {
        let p = host.pos(id);
        host.set_pos(id, Point2D::new(p.x, centre.y));
        host.extras
            .forces
            .insert(id, NodeForces::default().locked(AxisLock::Y));
    }
    let before = [host.pos(0).x, host.pos(33).x];
    let frames = host.settle(FRAME, 3_000);
    let title = "karate: nodes 0 and 33 locked on the dashed line, sliding along it";
    let colour = |id: u32| {
        if id == 0 || id == 33 {
            PALETTE[3]
        } else {
            BLUE
        }
    };
    let rail = [Guide::HorizontalLine(centre.y)];
    write("axis_lock", svg(&host.scene, title, &[], &rail, colour))?;
    println!(
        "lock:     at rest after {frames} frames; nodes 0 and 33 {:.3} and {:.3} units off \
         the line, slid {:.1} and {:.1} units along it",
        (host.pos(0).y - centre.y).abs(),
        (host.pos(33).y - centre.y).abs(),
        host.pos(0).x - before[0],
        host.pos(33).x - before[1],
    );
    Ok(())
}

fn report(name: &str, frames: usize, off: &[f32], what: &str) {
    let mean = off.iter().sum::<f32>() / off.len() as f32;
    let worst = off.iter().copied().fold(0.0, f32::max);
    println!(
        "{name:9} at rest after {frames} frames; a node {mean:.2} units {what} on average, \
         {worst:.2} at worst"
    );
}

/// Mean step time over 60 frames from the file with `pick`'s forces on each node.
fn cost(pick: impl Fn(u32) -> Option<NodeForces>, config: RapierLayoutConfig) -> f64 {
    let mut host = Host::new(common::load("n10000_e25000"), config);
    for id in ids(&host) {
        if let Some(forces) = pick(id) {
            host.extras.forces.insert(id, forces);
        }
    }
    host.frame(FRAME);
    let start = Instant::now();
    for _ in 0..60 {
        host.frame(FRAME);
    }
    start.elapsed().as_secs_f64() * 1e3 / 60.0
}

/// What each force costs to work out, not what the layout it makes costs: every node
/// gets the force at strength 1e-6, so the graph moves as it does without one.
fn costs() {
    let fd = RapierLayoutConfig::force_directed;
    let faint = 1e-6;
    let mut grouped = fd();
    grouped.groups.pull = faint;
    let mut separated = grouped.clone();
    separated.groups.separation = faint;
    let group = |id: u32| Some(NodeForces::default().in_group(id % 100));
    type Pick = fn(u32) -> Option<NodeForces>;
    let runs: [(&str, Pick, RapierLayoutConfig); 5] = [
        ("none", |_| None, fd()),
        (
            "x target",
            |_| Some(NodeForces::default().toward_x(0.0, 1e-6)),
            fd(),
        ),
        (
            "ring",
            |_| Some(NodeForces::default().on_ring(0.0, 0.0, 500.0, 1e-6)),
            fd(),
        ),
        ("100 groups", group, grouped),
        ("100 groups, separation", group, separated),
    ];
    let mut base = 0.0;
    println!("cost per step, n10000_e25000, force_directed(), mean of 60 frames:");
    for (name, pick, config) in runs {
        let ms = cost(pick, config);
        if name == "none" {
            base = ms;
            println!("  {name:24} {ms:6.2} ms");
        } else {
            println!(
                "  {name:24} {ms:6.2} ms ({:+.2} ms, {:+.1} %)",
                ms - base,
                100.0 * (ms - base) / base
            );
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    radial()?;
    timeline()?;
    groups()?;
    axis_lock()?;
    println!("wrote target/pictures/{{radial,timeline,groups,axis_lock}}.svg");
    if std::env::args().any(|a| a == "--cost") {
        costs();
    }
    Ok(())
}
