//! A start that is already a layout: each component laid out by pivot MDS (`mds.rs`),
//! refined by stress SGD passes over the sparse model (`sgd.rs`), scaled to a length per
//! hop that seats the nodes' disks, and the components packed side by side (`pack.rs`).

use std::collections::HashMap;

use euclid::default::Point2D;

use super::mds::pivot_mds;
use super::model::SparseStress;
use super::pack::pack_components;
use super::sgd::{stress_passes, Rng};
use crate::graph::{Graph, UNREACHED};
use crate::input::layout::IdHasher;

/// Pivots pivot MDS uses per component (its cost grows with their square).
const MDS_PIVOTS: usize = 50;
/// The share of nodes whose nearest neighbour the length per hop seats without contact
/// (the densest tenth is left to the contacts).
const SEATED_SHARE: f32 = 0.9;

/// Graphs of up to this many nodes (in full components) start from the best of
/// [`SMALL_GRAPH_STARTS`] descents.
const SMALL_GRAPH: usize = 300;
const SMALL_GRAPH_STARTS: u64 = 4;

/// The stress of `xy` (hop units) over every pair of `model`'s full components, each
/// term weighted `1 / d²` (the unnormalised sum: only compared between layouts).
fn full_stress(model: &SparseStress, xy: &[[f32; 2]]) -> f64 {
    let mut total = 0.0;
    for i in 0..xy.len() {
        let (pivots, hops) = model.pivot_terms(i);
        for (&p, &d) in pivots.iter().zip(hops) {
            if (p as usize) <= i || d == 0 || d == UNREACHED {
                continue;
            }
            let (a, b) = (xy[i], xy[p as usize]);
            let e = f64::from(((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt());
            let d = f64::from(d);
            total += (e - d).powi(2) / (d * d);
        }
    }
    total
}

/// What the global start chose.
#[derive(Clone, Debug)]
pub(crate) struct Start {
    /// Each node's position, world units.
    pub(crate) positions: Vec<Point2D<f32>>,
    /// The length of a hop, world units.
    pub(crate) hop_length: f32,
}

/// How the start is made.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StartPlan {
    /// The shortest length a hop may have.
    pub(crate) min_length: f32,
    /// Whether the length grows until the disks are seated (else `min_length` exactly).
    pub(crate) fit: bool,
    /// The gap left between seated disks, world units.
    pub(crate) gap: f32,
    /// Stress SGD passes after pivot MDS.
    pub(crate) passes: usize,
    /// Where the packed components are centred.
    pub(crate) centre: Point2D<f32>,
}

/// The start layout of `graph` under `model`, for nodes of `radii`. `between` runs after
/// each descent pass on the positions and the world units a hop unit stands for (at
/// least: the hop length only grows from there), to hold hard constraints.
pub(crate) fn global_start(
    graph: &Graph,
    model: &SparseStress,
    radii: &[f32],
    plan: StartPlan,
    between: &mut dyn FnMut(&mut [[f32; 2]], f32),
) -> Start {
    let n = graph.len();
    let mut members: Vec<Vec<u32>> = vec![Vec::new(); model.sizes.len()];
    for (i, &c) in model.component.iter().enumerate() {
        members[c as usize].push(i as u32);
    }
    let mut xy = vec![[0.0_f32; 2]; n];
    for (c, nodes) in members.iter().enumerate() {
        mds_component(model, c, nodes, &mut xy);
    }
    if n <= SMALL_GRAPH && model.full.iter().all(|&full| full) {
        // A small graph's descent ends in one of a few local minima, by the order its
        // terms come in: the best of a few orders (each cheap on a graph this small:
        // `docs/performance.md` gives the time).
        let mut best: Option<(f64, Vec<[f32; 2]>)> = None;
        for seed in 0..SMALL_GRAPH_STARTS {
            let mut tried = xy.clone();
            let order = (plan.passes, 0x5eed + seed);
            stress_passes(graph, model, &mut tried, order, &mut |xy| {
                between(xy, plan.min_length)
            });
            let stress = full_stress(model, &tried);
            if best.as_ref().is_none_or(|(s, _)| stress < *s) {
                best = Some((stress, tried));
            }
        }
        xy = best.map_or(xy, |(_, tried)| tried);
    } else {
        let order = (plan.passes, 0x5eed);
        stress_passes(graph, model, &mut xy, order, &mut |xy| {
            between(xy, plan.min_length)
        });
    }
    let hop_length = if plan.fit {
        plan.min_length
            .max(seating_length(&members, &xy, radii, plan.gap))
    } else {
        plan.min_length
    };
    let mut positions: Vec<Point2D<f32>> = xy
        .iter()
        .map(|&[x, y]| Point2D::new(x * hop_length, y * hop_length))
        .collect();
    let largest = radii.iter().copied().fold(0.0, f32::max);
    pack_components(
        &mut positions,
        &members,
        largest + 0.5 * hop_length,
        plan.centre,
    );
    if members.len() > 1 {
        // Packing moves each component on its own: the constraints between them again.
        let mut xy: Vec<[f32; 2]> = positions.iter().map(|p| [p.x, p.y]).collect();
        between(&mut xy, 1.0);
        for (p, [x, y]) in positions.iter_mut().zip(xy) {
            *p = Point2D::new(x, y);
        }
    }
    Start {
        positions,
        hop_length,
    }
}

/// Pivot MDS of component `c` (its `nodes`) into `xy`, in hop units, with a nudge
/// apart for nodes MDS puts on the same point (leaves of one node see every pivot at
/// the same distance).
fn mds_component(model: &SparseStress, c: usize, nodes: &[u32], xy: &mut [[f32; 2]]) {
    match nodes.len() {
        0 => return,
        1 => {
            xy[nodes[0] as usize] = [0.0, 0.0];
            return;
        }
        2 => {
            xy[nodes[0] as usize] = [0.0, 0.0];
            xy[nodes[1] as usize] = [1.0, 0.0];
            return;
        }
        _ => {}
    }
    let (first, last) = model.pivot_range[c];
    let count = (last - first) as usize;
    let hop = |m: usize, k: usize| model.hops[model.row[nodes[m] as usize] as usize + k];
    // The columns MDS uses: the first pivots (max-min order) of a sparse component;
    // max-min among every node of a full one.
    let columns: Vec<usize> = if model.full[c] {
        max_min_columns(nodes.len(), count, hop)
    } else {
        (0..count.min(MDS_PIVOTS)).collect()
    };
    let coordinates = pivot_mds(nodes.len(), columns.len(), |m, j| {
        let h = hop(m, columns[j]);
        let h = if h == UNREACHED { 0.0 } else { f32::from(h) };
        h * h
    });
    // The scale that fits the MDS distances to the pivots best (stress-weighted).
    let (mut num, mut den) = (0.0_f64, 0.0_f64);
    for (m, c) in coordinates.iter().enumerate() {
        for &j in &columns {
            let h = hop(m, j);
            if h == 0 || h == UNREACHED {
                continue;
            }
            let pivot = model.pivots[first as usize + j] as usize;
            let pm = nodes.binary_search(&(pivot as u32)).unwrap_or(0);
            let p = coordinates[pm];
            let e = f64::from(((c[0] - p[0]).powi(2) + (c[1] - p[1]).powi(2)).sqrt());
            let d = f64::from(h);
            num += e / d;
            den += e * e / (d * d);
        }
    }
    let scale = if den > 0.0 { (num / den) as f32 } else { 1.0 };
    let mut rng = Rng::new(0x6a09_e667 ^ c as u64);
    for (m, &i) in nodes.iter().enumerate() {
        let [x, y] = coordinates[m];
        xy[i as usize] = [
            x * scale + (rng.unit() - 0.5) * 0.02,
            y * scale + (rng.unit() - 0.5) * 0.02,
        ];
    }
}

/// Up to [`MDS_PIVOTS`] columns of a full component's hop table chosen max-min.
fn max_min_columns(nodes: usize, count: usize, hop: impl Fn(usize, usize) -> u16) -> Vec<usize> {
    let want = count.min(MDS_PIVOTS);
    let mut chosen = vec![0_usize];
    let mut nearest: Vec<u16> = (0..nodes).map(|m| hop(m, 0)).collect();
    while chosen.len() < want {
        let far = (0..nodes)
            .max_by_key(|&m| (nearest[m], usize::MAX - m))
            .unwrap_or(0);
        if nearest[far] == 0 {
            break;
        }
        chosen.push(far);
        for (m, near) in nearest.iter_mut().enumerate() {
            *near = (*near).min(hop(m, far));
        }
    }
    chosen
}

/// The length of a hop that seats [`SEATED_SHARE`] of the nodes apart from their
/// nearest neighbour in `xy` (hop units): for each node, the two disks' radii plus
/// `gap` over their distance in hops.
fn seating_length(members: &[Vec<u32>], xy: &[[f32; 2]], radii: &[f32], gap: f32) -> f32 {
    let mut needed: Vec<f32> = Vec::with_capacity(xy.len());
    let mut cells: HashMap<(i32, i32), Vec<u32>, IdHasher> = HashMap::default();
    for nodes in members.iter().filter(|m| m.len() > 1) {
        cells.clear();
        // Cells of about two nodes each: a random graph's nodes all lie within a few hops
        // of each other, and a cell of one hop would hold thousands.
        let (mut lo, mut hi) = ([f32::MAX; 2], [f32::MIN; 2]);
        for &i in nodes {
            let p = xy[i as usize];
            lo = [lo[0].min(p[0]), lo[1].min(p[1])];
            hi = [hi[0].max(p[0]), hi[1].max(p[1])];
        }
        let area = ((hi[0] - lo[0]) * (hi[1] - lo[1])).max(1e-6);
        let cell = (2.0 * area / nodes.len() as f32).sqrt().clamp(1e-3, 1.0);
        let key = |p: [f32; 2]| ((p[0] / cell).floor() as i32, (p[1] / cell).floor() as i32);
        for &i in nodes {
            cells.entry(key(xy[i as usize])).or_default().push(i);
        }
        for &i in nodes {
            let p = xy[i as usize];
            let (kx, ky) = key(p);
            let mut nearest: Option<(f32, u32)> = None;
            for x in kx - 1..=kx + 1 {
                for y in ky - 1..=ky + 1 {
                    for &j in cells.get(&(x, y)).into_iter().flatten() {
                        if j == i {
                            continue;
                        }
                        let q = xy[j as usize];
                        let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt();
                        if nearest.is_none_or(|(best, _)| d < best) {
                            nearest = Some((d, j));
                        }
                    }
                }
            }
            if let Some((d, j)) = nearest {
                let reach = radii[i as usize] + radii[j as usize] + gap;
                needed.push(reach / d.max(1e-3));
            }
        }
    }
    if needed.is_empty() {
        return 0.0;
    }
    let k = ((needed.len() as f32 * SEATED_SHARE) as usize).min(needed.len() - 1);
    *needed.select_nth_unstable_by(k, f32::total_cmp).1
}
