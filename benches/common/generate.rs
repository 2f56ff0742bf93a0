//! Seeded graph generators for scenes too large to ship as files, placed the way d3-force
//! places nodes without positions (its phyllotaxis spiral, as the shipped random scenes
//! are): a Barabási–Albert graph (hubs), a uniform random graph and a random geometric
//! graph. The same name gives
//! the same scene on every machine. Used by the benchmarks and the `quality` example.

use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasEdge, CanvasNode, CanvasSceneInput};

/// splitmix64: small, fast and the same everywhere.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n`.
    fn below(&mut self, n: usize) -> usize {
        ((u128::from(self.next()) * n as u128) >> 64) as usize
    }
}

/// d3-force's initial position of node `i`: radius `10 √(0.5 + i)`, angle `i π (3 − √5)`.
pub fn phyllotaxis(i: usize) -> Point2D<f32> {
    let radius = 10.0 * (0.5 + i as f64).sqrt();
    let angle = i as f64 * std::f64::consts::PI * (3.0 - 5.0_f64.sqrt());
    Point2D::new((radius * angle.cos()) as f32, (radius * angle.sin()) as f32)
}

fn spiral(n: usize, edges: Vec<(usize, usize)>) -> CanvasSceneInput<u32> {
    CanvasSceneInput::new(
        (0..n)
            .map(|i| CanvasNode::new(i as u32, phyllotaxis(i)))
            .collect(),
        edges
            .into_iter()
            .map(|(a, b)| CanvasEdge::new(a as u32, b as u32))
            .collect(),
    )
}

/// Barabási–Albert preferential attachment: a clique of `m + 1` nodes, then each new
/// node links to `m` distinct earlier nodes chosen with probability proportional to
/// their degree. `n × m` edges, about; a few hubs of high degree.
pub fn barabasi_albert(n: usize, m: usize, seed: u64) -> CanvasSceneInput<u32> {
    let mut rng = Rng(seed);
    let mut edges = Vec::with_capacity(n * m);
    // Every edge's two ends: drawing from it is drawing by degree.
    let mut ends: Vec<usize> = Vec::with_capacity(2 * n * m);
    let core = (m + 1).min(n);
    for a in 0..core {
        for b in a + 1..core {
            edges.push((a, b));
            ends.extend([a, b]);
        }
    }
    let mut chosen = Vec::with_capacity(m);
    for node in core..n {
        chosen.clear();
        while chosen.len() < m.min(node) {
            let target = ends[rng.below(ends.len())];
            if !chosen.contains(&target) {
                chosen.push(target);
            }
        }
        for &target in &chosen {
            edges.push((target, node));
            ends.extend([target, node]);
        }
    }
    spiral(n, edges)
}

/// `e` distinct edges between uniformly drawn pairs of `n` nodes, no self-loops.
pub fn random_graph(n: usize, e: usize, seed: u64) -> CanvasSceneInput<u32> {
    let mut rng = Rng(seed);
    let mut seen = std::collections::HashSet::with_capacity(e);
    let mut edges = Vec::with_capacity(e);
    while edges.len() < e.min(n * n.saturating_sub(1) / 2) {
        let (a, b) = (rng.below(n), rng.below(n));
        if a != b && seen.insert((a.min(b), a.max(b))) {
            edges.push((a, b));
        }
    }
    spiral(n, edges)
}

/// A planted partition (communities): `k` groups of `m` nodes each, every node
/// joined to `inner` random members of its own group and, with chance one in
/// `outer_every`, to one random node of another. Node `i` is in group `i / m`
/// ([`community`]). Distinct edges, no self-loops.
pub fn communities(
    k: usize,
    m: usize,
    inner: usize,
    outer_every: usize,
    seed: u64,
) -> CanvasSceneInput<u32> {
    let mut rng = Rng(seed);
    let n = k * m;
    let mut seen = std::collections::HashSet::new();
    let mut edges = Vec::new();
    let mut add = |a: usize, b: usize, edges: &mut Vec<(usize, usize)>| {
        if a != b && seen.insert((a.min(b), a.max(b))) {
            edges.push((a, b));
        }
    };
    for a in 0..n {
        let group = a / m;
        for _ in 0..inner {
            add(a, group * m + rng.below(m), &mut edges);
        }
        if k > 1 && rng.below(outer_every.max(1)) == 0 {
            let other = (group + 1 + rng.below(k - 1)) % k;
            add(a, other * m + rng.below(m), &mut edges);
        }
    }
    // Placed on the spiral in a random order, so a group is not a run of it.
    let mut place: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        place.swap(i, rng.below(i + 1));
    }
    let mut scene = spiral(n, edges);
    for node in &mut scene.nodes {
        node.position = phyllotaxis(place[node.id as usize]);
    }
    scene
}

/// The group of node `id` in a [`communities`] scene of groups of `m`.
pub fn community(id: u32, m: usize) -> usize {
    id as usize / m
}

/// A random geometric graph, as `scenes/rgg_10000.json` was built: `n` points uniform in
/// a square, each joined to its 3 nearest neighbours, the largest component kept and
/// renumbered in a random order, placed on d3's spiral. A proxy for road networks and
/// meshes: a mesh-like graph of large diameter.
pub fn random_geometric(n: usize, seed: u64) -> CanvasSceneInput<u32> {
    let mut rng = Rng(seed);
    let unit = |rng: &mut Rng| (rng.next() >> 11) as f64 / (1_u64 << 53) as f64;
    let points: Vec<(f64, f64)> = (0..n).map(|_| (unit(&mut rng), unit(&mut rng))).collect();
    // The 3 nearest by a uniform grid of about two points a cell, searched ring by ring.
    let side = ((n as f64 / 2.0).sqrt().ceil() as usize).max(1);
    let cell_of = |p: (f64, f64)| {
        (
            ((p.0 * side as f64) as usize).min(side - 1),
            ((p.1 * side as f64) as usize).min(side - 1),
        )
    };
    let mut cells = vec![Vec::new(); side * side];
    for (i, &p) in points.iter().enumerate() {
        let (cx, cy) = cell_of(p);
        cells[cy * side + cx].push(i);
    }
    let mut edges = std::collections::BTreeSet::new();
    for (i, &p) in points.iter().enumerate() {
        let (cx, cy) = cell_of(p);
        let mut best: Vec<(f64, usize)> = Vec::new();
        for ring in 0..side {
            let (lo_x, hi_x) = (cx.saturating_sub(ring), (cx + ring).min(side - 1));
            let (lo_y, hi_y) = (cy.saturating_sub(ring), (cy + ring).min(side - 1));
            for y in lo_y..=hi_y {
                for x in lo_x..=hi_x {
                    if x.abs_diff(cx) != ring && y.abs_diff(cy) != ring {
                        continue;
                    }
                    for &j in &cells[y * side + x] {
                        if j != i {
                            let q = points[j];
                            best.push(((p.0 - q.0).powi(2) + (p.1 - q.1).powi(2), j));
                        }
                    }
                }
            }
            best.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            best.truncate(3);
            // Beyond this ring every point is at least `ring / side` away.
            let reach = ring as f64 / side as f64;
            if best.len() == 3 && best[2].0 <= reach * reach {
                break;
            }
        }
        for &(_, j) in &best {
            edges.insert((i.min(j), i.max(j)));
        }
    }
    // The largest component, renumbered at random.
    let mut neighbours = vec![Vec::new(); n];
    for &(a, b) in &edges {
        neighbours[a].push(b);
        neighbours[b].push(a);
    }
    let mut component = vec![usize::MAX; n];
    let mut sizes = Vec::new();
    for s in 0..n {
        if component[s] != usize::MAX {
            continue;
        }
        let c = sizes.len();
        let (mut stack, mut size) = (vec![s], 0);
        component[s] = c;
        while let Some(u) = stack.pop() {
            size += 1;
            for &v in &neighbours[u] {
                if component[v] == usize::MAX {
                    component[v] = c;
                    stack.push(v);
                }
            }
        }
        sizes.push(size);
    }
    let largest = (0..sizes.len())
        .max_by_key(|&c| (sizes[c], usize::MAX - c))
        .unwrap_or(0);
    let mut kept: Vec<usize> = (0..n).filter(|&i| component[i] == largest).collect();
    for k in (1..kept.len()).rev() {
        kept.swap(k, rng.below(k + 1));
    }
    let mut number = vec![usize::MAX; n];
    for (new, &old) in kept.iter().enumerate() {
        number[old] = new;
    }
    let edges = edges
        .into_iter()
        .filter(|&(a, _)| component[a] == largest)
        .map(|(a, b)| (number[a], number[b]))
        .collect();
    spiral(kept.len(), edges)
}

/// The generated scene a name stands for: `ba_n{N}_m{M}`, `random_n{N}_e{E}`,
/// `rgg_n{N}` or `communities_k{K}_m{M}` (3 edges inside, one in four nodes joined
/// outside; seed 1).
pub fn by_name(name: &str) -> Option<CanvasSceneInput<u32>> {
    let number = |s: &str, prefix: char| s.strip_prefix(prefix)?.parse::<usize>().ok();
    let parts: Vec<&str> = name.split('_').collect();
    match parts.as_slice() {
        ["ba", n, m] => Some(barabasi_albert(number(n, 'n')?, number(m, 'm')?, 1)),
        ["random", n, e] => Some(random_graph(number(n, 'n')?, number(e, 'e')?, 1)),
        ["rgg", n] => Some(random_geometric(number(n, 'n')?, 1)),
        ["communities", k, m] => Some(communities(number(k, 'k')?, number(m, 'm')?, 3, 4, 1)),
        _ => None,
    }
}

/// The label the outside checks draw node `id` with, and its box: "node <id>", 7 units a
/// character, 20 high.
pub fn label_box(id: u32) -> (String, f32, f32) {
    let label = format!("node {id}");
    let width = 7.0 * label.len() as f32;
    (label, width, 20.0)
}

/// `scene` with every node a labelled box ([`label_box`]), except those `disk(id)` keeps
/// a disk of radius 16.
pub fn label_boxes(
    mut scene: CanvasSceneInput<u32>,
    disk: impl Fn(u32) -> bool,
) -> CanvasSceneInput<u32> {
    for node in &mut scene.nodes {
        if disk(node.id) {
            node.radius = 16.0;
        } else {
            let (label, width, height) = label_box(node.id);
            *node = node.clone().with_rect(width, height).with_label(label);
        }
    }
    scene
}
