//! Clusters kept in boxes: a graph of communities laid out under `stress()` with one
//! cluster per community, against the same graph without clusters. Prints a Markdown
//! table, for each: frames and wall time to rest, the step's p95, the mean time of a
//! call at rest, normalised stress,
//! overlapping disks and the clusters' violations at rest (members outside their box,
//! other nodes inside it, sibling boxes overlapping, each by more than a unit); and
//! writes `target/clusters/<scene>.svg` with the boxes drawn.
//!
//! `cargo run --release --example clusters -- [--repeat K] [--shuffled] [--padding P]
//! [scene ...]`; a scene is `communities_k{K}_m{M}` (K groups of M nodes,
//! `benches/common/generate.rs`), clustered by its groups, or a shipped scene
//! (`les_miserables`, `1138_bus`) clustered by the communities the Louvain method finds
//! (`common/communities.rs`); it defaults to `communities_k10_m50`,
//! `communities_k100_m100`, `les_miserables` and `1138_bus`.
//! `--shuffled` also runs as many clusters of the same sizes drawn regardless of the
//! communities (node `i` in cluster `7919 i mod K`): clusters that do not follow the
//! graph. `--padding P` pads every cluster by `P` units (default 10). `--motion` lays
//! each clustered graph out again, checking the clusters after every frame on the way to
//! rest, and measures what the frame that stopped the layout moved. Each scene's
//! communities are written to `target/clusters/<scene>_communities.json` for
//! `scripts/fcose`.

use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::quality::{self, ClusterViolations};
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::{CanvasSceneInput, Layout, RapierLayoutConfig};

#[path = "common/mod.rs"]
mod common;

use common::communities::louvain;
use common::svg::{svg, Guide, PALETTE};
use common::{load, Host, Timed};

const FRAME: f32 = 1.0 / 60.0;

/// Calls timed at rest after each run.
const REST_CALLS: usize = 200;

/// One layout run to rest (at most 2,000 frames).
struct Run {
    host: Host,
    timed: Timed,
    /// The mean wall time of a call at rest, after it (µs).
    rest_us: f64,
}

/// A `stress()` layout of `scene` with `clusters`, not yet stepped.
fn clustered(scene: &CanvasSceneInput<u32>, clusters: &[Cluster<u32>]) -> Host {
    let mut host = Host::new(scene.clone(), RapierLayoutConfig::stress());
    host.extras.clusters = clusters.to_vec();
    host
}

fn run(scene: &CanvasSceneInput<u32>, clusters: &[Cluster<u32>]) -> Run {
    let mut host = clustered(scene, clusters);
    let timed = host.settle_timed(FRAME, 2_000, |_| {});
    let started = std::time::Instant::now();
    for _ in 0..REST_CALLS {
        host.frame(FRAME);
    }
    let rest_us = started.elapsed().as_secs_f64() * 1e6 / REST_CALLS as f64;
    Run {
        host,
        timed,
        rest_us,
    }
}

/// How the clusters hold while a layout moves to rest.
#[derive(Default)]
struct Motion {
    /// Frames before the cold stop, and those ending with a violation deeper than a unit.
    frames: usize,
    violated: usize,
    /// The deepest violation any of them ended with.
    worst: f32,
    /// The frame that stopped the layout: nodes it moved more than a unit, the farthest.
    stopped: usize,
    farthest: f32,
}

/// Lays `scene` out with `clusters` from the start and checks every frame.
fn motion(scene: &CanvasSceneInput<u32>, clusters: &[Cluster<u32>]) -> Motion {
    let mut host = clustered(scene, clusters);
    let mut m = Motion::default();
    for _ in 0..2_000 {
        let deltas = host.frame(FRAME);
        if host.layout.is_converged(&host.state) {
            let moves = deltas.values().map(|d| d.length());
            m.stopped = moves.clone().filter(|&d| d > 1.0).count();
            m.farthest = moves.fold(0.0, f32::max);
            break;
        }
        m.frames += 1;
        let bounds = host.layout.cluster_bounds();
        let v = quality::cluster_violations(&host.scene, clusters, bounds, 16.0, 1.0);
        m.violated += usize::from(v.worst > 1.0);
        m.worst = m.worst.max(v.worst);
    }
    m
}

/// The community size a `communities_k{K}_m{M}` name gives.
fn group_size(name: &str) -> Option<usize> {
    name.rsplit('_').next()?.strip_prefix('m')?.parse().ok()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut args = std::env::args().skip(1).peekable();
    let mut repeat = 1;
    let mut shuffled = false;
    let mut moving = false;
    let mut padding = graph_canvas_layout::scene::DEFAULT_CLUSTER_PADDING;
    let mut scenes = Vec::new();
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--shuffled" => shuffled = true,
            "--motion" => moving = true,
            "--padding" => {
                padding = args
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--padding P")
            }
            "--repeat" => {
                repeat = args
                    .next()
                    .and_then(|v| v.parse().ok())
                    .expect("--repeat K")
            }
            name => scenes.push(name.to_owned()),
        }
    }
    if scenes.is_empty() {
        scenes = [
            "communities_k10_m50",
            "communities_k100_m100",
            "les_miserables",
            "1138_bus",
        ]
        .map(String::from)
        .to_vec();
    }
    let mut edits = Vec::new();
    let mut motions = Vec::new();
    let out = format!("{}/target/clusters", env!("CARGO_MANIFEST_DIR"));
    std::fs::create_dir_all(&out).expect("target/clusters");
    println!("| scene | layout | frames | ms to rest | step p95 ms | µs a call at rest | stress | overlaps | members outside | intruders | overlapping boxes | worst |");
    println!("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for name in &scenes {
        let scene = load(name);
        // Each node's community, by scene index.
        let community: Vec<usize> = match group_size(name) {
            Some(m) => scene.nodes.iter().map(|n| n.id as usize / m).collect(),
            None => louvain(&scene),
        };
        let groups = community.iter().max().map_or(0, |&c| c + 1);
        let clusters_by = |group: &dyn Fn(usize) -> usize| {
            let mut members = vec![Vec::new(); groups];
            for (i, n) in scene.nodes.iter().enumerate() {
                members[group(i)].push(n.id);
            }
            members
                .into_iter()
                .map(|m| Cluster::new(m).with_padding(padding))
                .collect::<Vec<_>>()
        };
        let mut kinds = vec![
            ("`stress()`", Vec::new()),
            ("`stress()` + clusters", clusters_by(&|i| community[i])),
        ];
        if shuffled {
            let shuffled = clusters_by(&|i| (7919 * i) % groups);
            kinds.push(("`stress()` + shuffled clusters", shuffled));
        }
        // The communities, in scene order, for tools outside the crate
        // (`scripts/fcose`: the same clusters laid out by fCoSE).
        let listed: Vec<String> = community.iter().map(usize::to_string).collect();
        let path = format!("{out}/{name}_communities.json");
        let text = format!("{{\"community\": [{}]}}\n", listed.join(","));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{path}: {e}"));
        let community_of: std::collections::HashMap<u32, usize> = scene
            .nodes
            .iter()
            .zip(&community)
            .map(|(n, &c)| (n.id, c))
            .collect();
        let mut runs: Vec<Vec<Run>> = kinds.iter().map(|_| Vec::new()).collect();
        for _ in 0..repeat {
            for (k, (_, list)) in kinds.iter().enumerate() {
                runs[k].push(run(&scene, list));
            }
        }
        for (k, (label, list)) in kinds.iter().enumerate() {
            let r = &runs[k][0];
            let scene = &r.host.scene;
            let bounds = r.host.layout.cluster_bounds();
            let v = if list.is_empty() {
                ClusterViolations::default()
            } else {
                quality::cluster_violations(scene, list, bounds, 16.0, 1.0)
            };
            let stress = quality::normalized_stress(scene).unwrap_or(f64::NAN);
            let wall = median(runs[k].iter().map(|r| r.timed.wall_ms).collect());
            let p95 = median(runs[k].iter().map(|r| r.timed.p95_ms).collect());
            let rest = median(runs[k].iter().map(|r| r.rest_us).collect());
            println!(
                "| {name} | {label} | {} | {wall:.0} | {p95:.2} | {rest:.1} | {stress:.4} | {} | {} | {} | {} | {:.2} |",
                r.timed.frames,
                quality::overlapping_pairs(scene, 16.0, 1.0),
                v.members_outside,
                v.intruders,
                v.overlapping_siblings,
                v.worst
            );
            if k > 0 {
                let guides: Vec<Guide> = bounds
                    .iter()
                    .map(|b| Guide::Box(Point2D::new(b.min.x, b.min.y), b.max))
                    .collect();
                let title = format!(
                    "{name}: {label} ({} clusters; colour: community)",
                    list.len()
                )
                .replace('`', "");
                let colour = |id: u32| PALETTE[community_of[&id] % PALETTE.len()];
                let text = svg(scene, &title, &[], &guides, colour);
                let kind = if k == 1 { "" } else { "_shuffled" };
                let path = format!("{out}/{name}{kind}.svg");
                std::fs::write(&path, text).unwrap_or_else(|e| panic!("{path}: {e}"));
            }
        }
        let clustered = &mut runs[1][0].host;
        edits.push((name.clone(), widened(clustered, &kinds[1].1)));
        if moving {
            motions.push((name.clone(), motion(&scene, &kinds[1].1)));
        }
    }
    println!();
    println!("A changed cluster: cluster 0's padding widened from {padding} to 40 at rest.");
    println!();
    println!("| scene | nodes moved > 1 unit | in clusters | frames to rest | moved farthest |");
    println!("| --- | ---: | ---: | ---: | ---: |");
    for (name, e) in edits {
        println!(
            "| {name} | {} of {} | {} of {} | {} | {:.1} |",
            e.moved, e.nodes, e.clusters_moved, e.clusters, e.frames, e.farthest
        );
    }
    if !motions.is_empty() {
        println!();
        println!("While the layout moves to rest: frames ending with a violation deeper than a unit, the deepest, and what the frame that stopped it moved.");
        println!();
        println!(
            "| scene | frames violated | deepest | nodes the stop moved > 1 unit | farthest |"
        );
        println!("| --- | ---: | ---: | ---: | ---: |");
        for (name, m) in motions {
            println!(
                "| {name} | {} of {} | {:.1} | {} | {:.1} |",
                m.violated, m.frames, m.worst, m.stopped, m.farthest
            );
        }
    }
}

/// What widening one cluster's padding moved.
struct Edit {
    nodes: usize,
    moved: usize,
    clusters: usize,
    clusters_moved: usize,
    frames: usize,
    farthest: f32,
}

/// Widens cluster 0's padding from 10 to 40 in `host` (at rest with `list`) and runs
/// it to rest again: how many nodes, and of how many clusters, moved more than a unit.
fn widened(host: &mut Host, list: &[Cluster<u32>]) -> Edit {
    let before: Vec<Point2D<f32>> = host.scene.nodes.iter().map(|n| n.position).collect();
    host.extras.clusters[0] = list[0].clone().with_padding(40.0);
    let frames = host.settle(FRAME, 2_000);
    let cluster_of: std::collections::HashMap<u32, usize> = list
        .iter()
        .enumerate()
        .flat_map(|(c, cl)| cl.members().iter().map(move |&id| (id, c)))
        .collect();
    let mut moved = 0;
    let mut touched = std::collections::BTreeSet::new();
    let mut farthest = 0.0_f32;
    for (node, was) in host.scene.nodes.iter().zip(&before) {
        let d = (node.position - *was).length();
        farthest = farthest.max(d);
        if d > 1.0 {
            moved += 1;
            touched.extend(cluster_of.get(&node.id).copied());
        }
    }
    Edit {
        nodes: before.len(),
        moved,
        clusters: list.len(),
        clusters_moved: touched.len(),
        frames,
        farthest,
    }
}
