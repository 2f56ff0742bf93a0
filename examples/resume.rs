//! Keep and resume, measured: what a snapshot costs (its size as JSON, the time to take,
//! write, read and restore it) on a graph in motion, and a saved picture reopened with
//! `RapierLayout::at_rest` (how far anything moves, and what a drag then moves).
//!
//! - **Snapshot**: the scene laid out for 100 frames from the file, a node in flight
//!   and one dragged; then `snapshot()`, `serde_json::to_vec`, `serde_json::from_slice`
//!   and `restore()`, each the median of seven runs, and the next 200 frames compared
//!   bit for bit with the layout that never stopped.
//! - **At rest**: the scene laid out to rest, its positions reopened with `at_rest`; 300
//!   calls, then the leaf farthest from the centre dragged 100 units outward over 10
//!   frames and let go, run to rest.
//!
//! Run with `cargo run --release --example resume [--default | --fast | --stress]
//! [--no-picture] [scene ...]` (`force_directed()` by default; scenes default to
//! `n10000_e25000` for the snapshot and `1138_bus` for the picture; a generator's name
//! such as `random_n100000_e250000` works too).

use std::time::Instant;

use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::quality;
use graph_canvas_layout::{Layout, LayoutSnapshot, RapierLayout, RapierLayoutConfig};

mod common;

use common::{load, Host};

const FRAME: f32 = 1.0 / 60.0;

/// The median of `runs` timings of `f`, in milliseconds, and its last result.
fn median_ms<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut times = Vec::with_capacity(runs);
    let mut last = None;
    for _ in 0..runs {
        let started = Instant::now();
        last = Some(f());
        times.push(started.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    (times[runs / 2], last.expect("one run"))
}

fn snapshot(name: &str, config: &RapierLayoutConfig) {
    let mut host = Host::new(load(name), config.clone());
    let (thrown, dragged) = (0, 1);
    for frame in 0..100 {
        match frame {
            80 => {
                host.extras.dragging.insert(thrown);
            }
            81..=83 => {
                let p = host.pos(thrown);
                host.set_pos(thrown, p + Vector2D::new(30.0, 0.0));
            }
            84 => {
                host.extras.dragging.remove(&thrown);
                host.extras.dragging.insert(dragged);
            }
            85.. => {
                let p = host.pos(dragged);
                host.set_pos(dragged, p + Vector2D::new(0.0, 5.0));
            }
            _ => {}
        }
        host.frame(FRAME);
    }
    let nodes = host.scene.nodes.len();
    let edges = host.scene.edges.len();
    let (take, snap) = median_ms(7, || host.layout.snapshot());
    let (write, json) = median_ms(7, || serde_json::to_vec(&snap).expect("serialise"));
    let (read, back) = median_ms(7, || {
        serde_json::from_slice::<LayoutSnapshot<u32>>(&json).expect("deserialise")
    });
    let (restore, restored) = median_ms(7, || {
        let mut layout = RapierLayout::default();
        layout.restore(back.clone()).expect("restore");
        layout
    });
    let mut resumed = Host {
        scene: host.scene.clone(),
        layout: restored,
        state: host.state.clone(),
        extras: host.extras.clone(),
    };
    let mut same = true;
    for _ in 0..200 {
        let (a, b) = (host.frame(FRAME), resumed.frame(FRAME));
        same &= a.len() == b.len()
            && a.iter().all(|(id, d)| {
                b.get(id).is_some_and(|e| {
                    e.x.to_bits() == d.x.to_bits() && e.y.to_bits() == d.y.to_bits()
                })
            });
    }
    println!(
        "snapshot {name} ({nodes} nodes, {edges} edges): {:.1} MB as JSON, {:.0} bytes a node; take {take:.1} ms, to_vec {write:.0} ms, from_slice {read:.0} ms, restore {restore:.1} ms; next 200 frames bit-identical: {same}",
        json.len() as f64 / 1e6,
        json.len() as f64 / nodes as f64,
    );
}

fn picture(name: &str, config: &RapierLayoutConfig) {
    let mut settled = Host::new(load(name), config.clone());
    let frames = settled.settle(FRAME, 3000);
    let picture = settled.scene.clone();
    let mut host = Host::new(picture.clone(), config.clone());
    host.layout = RapierLayout::at_rest(config.clone());
    let started = Instant::now();
    let mut moved = 0;
    for _ in 0..300 {
        moved += host.frame(FRAME).len();
    }
    let idle_ms = started.elapsed().as_secs_f64() * 1e3 / 300.0;
    let before = host.scene.clone();
    let centre = host.centre();
    let leaf = host.outermost_leaf().expect("a leaf");
    let out = (host.pos(leaf) - centre).normalize() * 10.0;
    host.extras.dragging.insert(leaf);
    for _ in 0..10 {
        let p = host.pos(leaf);
        host.set_pos(leaf, p + out);
        host.frame(FRAME);
    }
    host.extras.dragging.clear();
    let to_rest = host.settle(FRAME, 3000);
    let rows = quality::displacement_by_hops(&before, &host.scene, &leaf, 4);
    let row = |r: &quality::Displacement| format!("{:.2} / {:.2}", r.mean, r.max);
    println!(
        "at_rest {name} (laid out in {frames} frames): 300 calls moved {moved} nodes ({idle_ms:.3} ms a call); a leaf dragged 100 units: hop 1 {}, hop 2 {}, hop 3+ {} (mean / most), at rest again in {to_rest} frames",
        row(&rows[1]),
        row(&rows[2]),
        row(&rows[3]),
    );
    let _ = host.layout.is_converged(&host.state);
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let config = if args.iter().any(|a| a == "--default") {
        RapierLayoutConfig::default()
    } else if args.iter().any(|a| a == "--stress") {
        RapierLayoutConfig::stress()
    } else if args.iter().any(|a| a == "--fast") {
        RapierLayoutConfig::force_directed_fast()
    } else {
        RapierLayoutConfig::force_directed()
    };
    let scenes: Vec<&str> = args
        .iter()
        .filter(|a| !a.starts_with("--"))
        .map(String::as_str)
        .collect();
    if scenes.is_empty() {
        snapshot("n10000_e25000", &config);
        picture("1138_bus", &config);
    } else {
        let pictures = !args.iter().any(|a| a == "--no-picture");
        for name in scenes {
            snapshot(name, &config);
            if pictures {
                picture(name, &config);
            }
        }
    }
}
