//! Stress by stochastic gradient descent (Zheng, Pawar & Goodman 2018), over the terms
//! of the sparse model: each pass visits the nodes in a shuffled order and moves each
//! along every one of its terms (edges, exact terms, pivot terms) toward the term's
//! distance, by a step `μ = min(1, η·w)` whose `η` falls geometrically from `1 / w_min` to
//! `ε / w_max` over the passes. A term moves its own node only; the pair's other node
//! takes its own step when its turn comes. Positions are in hop units.

use super::model::SparseStress;
use crate::graph::{Graph, UNREACHED};

/// The last passes' step against the heaviest term: `ε` of s_gd2.
const EPSILON: f32 = 0.1;

/// A small deterministic generator (xorshift64*).
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed | 1)
    }

    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// A number in `[0, 1)`.
    pub(crate) fn unit(&mut self) -> f32 {
        (self.next() >> 40) as f32 / (1_u64 << 24) as f32
    }
}

/// The lightest and the heaviest weight of any term of `model` (edges weigh 1).
fn weight_range(model: &SparseStress) -> (f32, f32) {
    let (mut lo, mut hi) = (1.0_f32, 1.0_f32);
    for &d in &model.near_hops {
        let w = 1.0 / f32::from(d).powi(2);
        lo = lo.min(w);
        hi = hi.max(w);
    }
    for k in 0..model.pivots.len() {
        for &w in model.pivot_weights(k).iter().filter(|&&w| w > 0.0) {
            lo = lo.min(w);
            hi = hi.max(w);
        }
    }
    (lo, hi)
}

/// `passes` passes of stress SGD over `model`'s terms, moving `xy` (hop units). Nodes
/// whose position is the same as a term's other end are nudged apart along a direction
/// fixed by the pair. `between` runs after each pass: a projection onto hard
/// constraints there makes the descent minimise stress subject to them (the
/// constrained stress of IPSep-CoLa and DIG-CoLa, by projected gradient steps).
pub(crate) fn stress_passes(
    graph: &Graph,
    model: &SparseStress,
    xy: &mut [[f32; 2]],
    (passes, seed): (usize, u64),
    between: &mut dyn FnMut(&mut [[f32; 2]]),
) {
    let n = graph.len();
    if passes == 0 || n == 0 {
        return;
    }
    let (lo, hi) = weight_range(model);
    let (eta_max, eta_min) = (1.0 / lo, EPSILON / hi);
    let decay = if passes > 1 {
        (eta_min / eta_max).ln() / (passes - 1) as f32
    } else {
        0.0
    };
    let mut rng = Rng::new(seed);
    let pivot_terms: usize = (0..n).map(|i| model.pivot_terms(i).0.len()).sum();
    if pivot_terms <= PIVOT_TERM_BUDGET {
        // Every term, in a new order each pass (s_gd2's way).
        let mut terms = Vec::with_capacity(pivot_terms + graph.len() * 4);
        for i in 0..n {
            node_terms(graph, model, i, (1, 0), &mut terms);
        }
        for pass in 0..passes {
            shuffle(&mut terms, &mut rng);
            visit(xy, &terms, eta_max * (decay * pass as f32).exp());
            between(xy);
        }
        return;
    }
    // A large graph: each pass visits the nodes in a new order, a block of them at a
    // time, the block's terms gathered and visited in a new order (memory holds one
    // block's terms, not the whole graph's, O(n × pivots)), and takes a sample of
    // each node's pivot terms, every `every`-th from a place drawn anew, each weighing
    // for those left out: a pass then costs about the budget.
    let every = pivot_terms.div_ceil(PIVOT_TERM_BUDGET).max(1);
    let mut order: Vec<u32> = (0..n as u32).collect();
    let mut terms: Vec<Term> = Vec::new();
    for pass in 0..passes {
        let eta = eta_max * (decay * pass as f32).exp();
        shuffle(&mut order, &mut rng);
        for block in order.chunks(NODE_BLOCK) {
            terms.clear();
            for &i in block {
                let offset = (rng.next() % every as u64) as usize;
                node_terms(graph, model, i as usize, (every, offset), &mut terms);
            }
            shuffle(&mut terms, &mut rng);
            visit(xy, &terms, eta);
        }
        between(xy);
    }
}

/// One visit of `terms`, in their order, at step `eta`.
fn visit(xy: &mut [[f32; 2]], terms: &[Term], eta: f32) {
    for term in terms {
        let mu = (eta * term.w).min(1.0);
        if term.d < 0.0 {
            pull_both(xy, term.i as usize, term.j as usize, -term.d, mu);
        } else {
            pull(xy, term.i as usize, term.j as usize, term.d, mu);
        }
    }
}

/// Nodes whose terms a pass gathers and shuffles together.
const NODE_BLOCK: usize = 64;
/// Pivot terms a pass visits at most (sampled beyond: see `stress_passes`).
const PIVOT_TERM_BUDGET: usize = 4_000_000;

/// Fisher–Yates.
fn shuffle<T>(items: &mut [T], rng: &mut Rng) {
    for t in (1..items.len()).rev() {
        let u = (rng.next() % (t as u64 + 1)) as usize;
        items.swap(t, u);
    }
}

/// One term: node `i` kept at `d` hops from node `j` with weight `w`; both ends move
/// when `d` is stored negative, `i` only otherwise (16 bytes, so a block of terms stays
/// in the processor's cache).
#[derive(Clone, Copy, Debug)]
struct Term {
    i: u32,
    j: u32,
    d: f32,
    w: f32,
}

impl Term {
    fn new(i: usize, j: u32, d: f32, w: f32, both: bool) -> Self {
        Self {
            i: i as u32,
            j,
            d: if both { -d } else { d },
            w,
        }
    }
}

/// Node `i`'s terms, appended to `terms`: its edges and exact terms to nodes after it
/// in the graph (pairs both ends hold are visited once), and of its pivot terms those
/// at `offset` and every `every`-th after, weighing `every` times as much (a full
/// component's all).
fn node_terms(
    graph: &Graph,
    model: &SparseStress,
    i: usize,
    (every, offset): (usize, usize),
    terms: &mut Vec<Term>,
) {
    for &j in graph.neighbours(i) {
        if (j as usize) > i {
            terms.push(Term::new(i, j, 1.0, 1.0, true));
        }
    }
    let (near, near_hops) = model.near_terms_of(i);
    let scale = model.near_scale[i];
    for (&j, &d) in near.iter().zip(near_hops) {
        let d = f32::from(d);
        terms.push(Term::new(i, j, d, scale / (d * d), false));
    }
    let (pivots, hops) = model.pivot_terms(i);
    let cutoff = model.pivot_cutoff(i);
    let c = model.component[i] as usize;
    let full = model.full[c];
    let first = model.pivot_range[c].0 as usize;
    let (every, offset) = if full { (1, 0) } else { (every, offset) };
    for k in (offset..pivots.len()).step_by(every) {
        let (p, d) = (pivots[k], hops[k]);
        if d <= cutoff || d == UNREACHED || (full && (p as usize) < i) {
            continue;
        }
        let w = model.pivot_weight(first + k, d) * every as f32;
        terms.push(Term::new(i, p, f32::from(d), w, full));
    }
}

/// Moves nodes `i` and `j` by `mu / 2` each of the way to distance `d` apart.
#[inline]
fn pull_both(xy: &mut [[f32; 2]], i: usize, j: usize, d: f32, mu: f32) {
    let (a, b) = (xy[i], xy[j]);
    let (mut dx, mut dy) = (a[0] - b[0], a[1] - b[1]);
    let mut length = (dx * dx + dy * dy).sqrt();
    if length < 1e-6 {
        let angle = i as f32 * 2.399_963 + j as f32 * 0.618_034;
        (dx, dy, length) = (angle.cos() * 1e-3, angle.sin() * 1e-3, 1e-3);
    }
    let step = 0.5 * mu * (length - d) / length;
    xy[i] = [a[0] - step * dx, a[1] - step * dy];
    xy[j] = [b[0] + step * dx, b[1] + step * dy];
}

/// Moves node `i` by `mu` of the way to distance `d` from node `j`.
#[inline]
fn pull(xy: &mut [[f32; 2]], i: usize, j: usize, d: f32, mu: f32) {
    let (a, b) = (xy[i], xy[j]);
    let (mut dx, mut dy) = (a[0] - b[0], a[1] - b[1]);
    let mut length = (dx * dx + dy * dy).sqrt();
    if length < 1e-6 {
        // Coincident: apart along a direction of the pair's own.
        let angle = i as f32 * 2.399_963 + j as f32 * 0.618_034;
        (dx, dy, length) = (angle.cos() * 1e-3, angle.sin() * 1e-3, 1e-3);
    }
    let step = mu * (length - d) / length;
    xy[i] = [a[0] - step * dx, a[1] - step * dy];
}
