//! Long sessions a person runs by hand: memory stays flat and positions stay put.
//!
//! - `edits`: 1,000,000 calls on Les Misérables with continual edits (nodes and edges
//!   added and removed, drags, pins, host moves). After every call the world's body and
//!   joint counts must equal what the scene asks for; resident memory is printed every
//!   100,000 calls and must not grow by more than 10 % from call 100,000 to the end.
//! - `idle`: 1,000,000 calls of a free graph with no gravity that the host keeps calling
//!   after it rests. Positions must stay finite, and once at rest the graph's centre of
//!   mass must move less than a unit per 10,000 calls.
//!
//! Run with `cargo run --release --example soak [edits|idle] [calls] [preset]`, preset
//! `default` (the default) or `force_directed`. Exits with an error when a check fails.

use std::collections::HashSet;

use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    CanvasEdge, CanvasNode, CanvasSceneInput, EdgeJoint, Layout, RapierLayoutConfig,
};

mod common;

use common::{load, Host};

const FRAME: f32 = 1.0 / 60.0;

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * (self.next() >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// Resident and peak resident memory of this process, in KiB (Linux).
fn memory_kib() -> (u64, u64) {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    let field = |name: &str| {
        status
            .lines()
            .find(|l| l.starts_with(name))
            .and_then(|l| l.split_whitespace().nth(1))
            .and_then(|v| v.parse().ok())
            .unwrap_or(0)
    };
    (field("VmRSS:"), field("VmHWM:"))
}

/// The distinct undirected edges between the scene's nodes, self-loops left out.
fn edge_count(scene: &CanvasSceneInput<u32>) -> usize {
    let ids: HashSet<u32> = scene.nodes.iter().map(|n| n.id).collect();
    let pairs: HashSet<(u32, u32)> = scene
        .edges
        .iter()
        .filter(|e| e.source != e.target && ids.contains(&e.source) && ids.contains(&e.target))
        .map(|e| (e.source.min(e.target), e.source.max(e.target)))
        .collect();
    pairs.len()
}

fn edits(calls: usize, config: RapierLayoutConfig) -> Result<(), String> {
    let springs = !matches!(config.edge_joint, EdgeJoint::None);
    let mut host = Host::new(load("les_miserables"), config);
    let base = host.scene.nodes.len();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut next_id = 10_000;
    let mut at_100k = 0;
    for call in 1..=calls {
        let n = host.scene.nodes.len();
        match rng.below(10) {
            0 if n < base + 40 => {
                let near = host.scene.nodes[rng.below(n)].position;
                let id = next_id;
                next_id += 1;
                let p = near + Vector2D::new(rng.range(-60.0, 60.0), rng.range(-60.0, 60.0));
                host.scene.nodes.push(CanvasNode::new(id, p));
                let other = host.scene.nodes[rng.below(n)].id;
                host.scene.edges.push(CanvasEdge::new(id, other));
            }
            1 if n > base - 40 => {
                let id = host.scene.nodes.swap_remove(rng.below(n)).id;
                host.scene
                    .edges
                    .retain(|e| e.source != id && e.target != id);
                host.extras.pinned.remove(&id);
                host.extras.dragging.remove(&id);
            }
            2 => {
                let (a, b) = (
                    host.scene.nodes[rng.below(n)].id,
                    host.scene.nodes[rng.below(n)].id,
                );
                host.scene.edges.push(CanvasEdge::new(a, b));
            }
            3 if !host.scene.edges.is_empty() => {
                let i = rng.below(host.scene.edges.len());
                host.scene.edges.swap_remove(i);
            }
            4 => {
                let id = host.scene.nodes[rng.below(n)].id;
                let _ = host.extras.pinned.remove(&id) || host.extras.pinned.insert(id);
            }
            5 => {
                let id = host.scene.nodes[rng.below(n)].id;
                let _ = host.extras.dragging.remove(&id) || host.extras.dragging.insert(id);
            }
            6 => {
                let i = rng.below(n);
                host.scene.nodes[i].position =
                    Point2D::new(rng.range(-500.0, 500.0), rng.range(-500.0, 500.0));
            }
            _ => {}
        }
        for node in &mut host.scene.nodes {
            if host.extras.dragging.contains(&node.id) {
                node.position += Vector2D::new(3.0, -2.0);
            }
        }
        host.frame(FRAME);
        let world = host.layout.world().ok_or("no world")?;
        let joints = if springs { edge_count(&host.scene) } else { 0 };
        if world.body_count() != host.scene.nodes.len() || world.joint_count() != joints {
            return Err(format!(
                "call {call}: {} bodies and {} joints for {} nodes and {joints} edges",
                world.body_count(),
                world.joint_count(),
                host.scene.nodes.len()
            ));
        }
        if call % 100_000 == 0 {
            let (rss, peak) = memory_kib();
            println!(
                "call {call:>9}: {} nodes, {} edges, resident {rss} KiB, peak {peak} KiB",
                host.scene.nodes.len(),
                host.scene.edges.len()
            );
            if call == 100_000 {
                at_100k = rss;
            }
        }
    }
    let (rss, _) = memory_kib();
    if at_100k > 0 && rss as f64 > at_100k as f64 * 1.1 {
        return Err(format!(
            "resident memory grew from {at_100k} KiB at call 100,000 to {rss} KiB"
        ));
    }
    Ok(())
}

fn idle(calls: usize, config: RapierLayoutConfig) -> Result<(), String> {
    let mut host = Host::new(load("les_miserables"), config);
    let centre = |scene: &CanvasSceneInput<u32>| {
        let sum = scene
            .nodes
            .iter()
            .fold(Vector2D::zero(), |s, n| s + n.position.to_vector());
        sum / scene.nodes.len() as f32
    };
    let mut rest_at = None;
    let mut last = centre(&host.scene);
    let mut worst: f32 = 0.0;
    for call in 1..=calls {
        host.frame(FRAME);
        if rest_at.is_none() && host.layout.is_converged(&host.state) {
            rest_at = Some(call);
            last = centre(&host.scene);
            println!("at rest after {call} calls");
        }
        if call % 10_000 == 0 {
            if host.scene.nodes.iter().any(|n| !n.position.is_finite()) {
                return Err(format!("call {call}: a position is not finite"));
            }
            let c = centre(&host.scene);
            if rest_at.is_some() {
                let drift = (c - last).length();
                worst = worst.max(drift);
                if drift >= 1.0 {
                    return Err(format!(
                        "call {call}: the centre of mass moved {drift} units in 10,000 calls"
                    ));
                }
            }
            last = c;
            if call % 100_000 == 0 {
                let (rss, peak) = memory_kib();
                println!("call {call:>9}: centre ({:.3}, {:.3}), worst drift per 10,000 calls {worst:.2e}, resident {rss} KiB, peak {peak} KiB", c.x, c.y);
            }
        }
    }
    if rest_at.is_none() {
        return Err(format!("never at rest in {calls} calls"));
    }
    Ok(())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map_or("edits", String::as_str);
    let calls = args
        .get(2)
        .and_then(|a| a.parse().ok())
        .unwrap_or(1_000_000);
    let config = match args.get(3).map_or("default", String::as_str) {
        "force_directed" => RapierLayoutConfig::force_directed(),
        _ => RapierLayoutConfig::default(),
    };
    let started = std::time::Instant::now();
    let result = match mode {
        "idle" => idle(calls, config),
        _ => edits(calls, config),
    };
    println!(
        "{mode}: {calls} calls in {:.1} s",
        started.elapsed().as_secs_f64()
    );
    if let Err(e) = result {
        eprintln!("soak {mode} failed: {e}");
        std::process::exit(1);
    }
    println!("{mode}: every check held");
}
