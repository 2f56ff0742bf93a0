//! The topology of a scene: which nodes and edges the world models, and the
//! order-free hash that says whether it changed.

use std::collections::{HashMap, HashSet};
use std::hash::Hash;

use crate::input::layout::{IdHasher, LayoutExtras};
use crate::input::scene::CanvasSceneInput;
use crate::input::validation::node_is_valid;

/// Fixed seeds: the hash of a topology is the same in every layout of a build, so two
/// layouts fed the same session agree on it.
fn id_hasher() -> ahash::RandomState {
    ahash::RandomState::with_seeds(
        0x243f_6a88_85a3_08d3,
        0x1319_8a2e_0370_7344,
        0xa409_3822_299f_31d0,
        0x082e_fa98_ec4e_6c89,
    )
}

/// splitmix64's finalizer: spreads every input bit over the output, so sums of mixed
/// values behave like a hash of the multiset.
fn mix(mut x: u64) -> u64 {
    x ^= x >> 30;
    x = x.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x ^= x >> 27;
    x = x.wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

const NODE_TAG: u64 = 0x6e6f_6465;
const EDGE_TAG: u64 = 0x6564_6765;
const PIN_TAG: u64 = 0x7069_6e6e;
const WEIGHT_TAG: u64 = 0x7765_6967;

/// The topology the world should model this call, in scene order.
#[derive(Debug)]
pub(crate) struct Topology {
    /// Scene indices of the modelled nodes: each id's first occurrence, when its values
    /// are usable or it already has a body.
    pub(crate) nodes: Vec<usize>,
    /// Unordered, de-duplicated edges between modelled nodes, as scene indices, in the
    /// order of their first occurrence; self-loops left out.
    pub(crate) edges: Vec<(usize, usize)>,
    /// Each edge's weight, from its first occurrence: finite and non-negative (an
    /// unusable weight counts as 0, no force, for the call).
    pub(crate) weights: Vec<f32>,
    /// The order-free hash of nodes, edges and pins (never 0).
    pub(crate) hash: u64,
    /// The order-free hash of the edges' weights.
    pub(crate) weight_hash: u64,
    /// Repeated node ids, edges left out for naming a node the world does not model,
    /// and edges with an unusable weight: bad input a host may want reported.
    pub(crate) problems: usize,
}

impl Topology {
    /// The topology of `scene`; `has_body` says which ids the world already models (they
    /// stay in it while the host's values for them are unusable).
    pub(crate) fn of<N: Clone + Eq + Hash>(
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        has_body: impl Fn(&N) -> bool,
    ) -> Self {
        let hasher = id_hasher();
        let mut first: HashMap<&N, usize, IdHasher> =
            HashMap::with_capacity_and_hasher(scene.nodes.len(), IdHasher::default());
        let mut nodes = Vec::with_capacity(scene.nodes.len());
        let mut hash: u64 = 0;
        let mut ids = Vec::with_capacity(scene.nodes.len());
        let mut problems = 0;
        for (i, node) in scene.nodes.iter().enumerate() {
            if first.contains_key(&node.id) {
                problems += 1;
                ids.push(0);
                continue;
            }
            let id_hash = hasher.hash_one(&node.id);
            ids.push(id_hash);
            if node_is_valid(node) || has_body(&node.id) {
                first.insert(&node.id, i);
                nodes.push(i);
                hash = hash.wrapping_add(mix(id_hash ^ NODE_TAG));
                if extras.pinned.contains(&node.id) {
                    hash = hash.wrapping_add(mix(id_hash ^ PIN_TAG));
                }
            }
        }
        let mut seen: HashSet<(usize, usize), IdHasher> =
            HashSet::with_capacity_and_hasher(scene.edges.len(), IdHasher::default());
        let mut edges = Vec::with_capacity(scene.edges.len());
        let mut weights = Vec::with_capacity(scene.edges.len());
        let mut weight_hash: u64 = 0;
        for edge in &scene.edges {
            if usable_weight(edge.weight).to_bits() != edge.weight.to_bits() {
                problems += 1;
            }
            let (Some(&a), Some(&b)) = (first.get(&edge.source), first.get(&edge.target)) else {
                problems += 1;
                continue;
            };
            if a == b || !seen.insert((a.min(b), a.max(b))) {
                continue;
            }
            edges.push((a, b));
            let (ha, hb) = (ids[a], ids[b]);
            let edge_hash = mix(mix(ha.min(hb) ^ EDGE_TAG) ^ ha.max(hb));
            hash = hash.wrapping_add(edge_hash);
            let weight = usable_weight(edge.weight);
            weights.push(weight);
            weight_hash =
                weight_hash.wrapping_add(mix(edge_hash ^ WEIGHT_TAG ^ u64::from(weight.to_bits())));
        }
        Self {
            nodes,
            edges,
            weights,
            hash: if hash == 0 { 1 } else { hash },
            weight_hash,
            problems,
        }
    }
}

/// An edge's weight as the layout uses it: finite and non-negative, else 0.
pub(crate) fn usable_weight(weight: f32) -> f32 {
    if weight.is_finite() && weight >= 0.0 {
        weight
    } else {
        0.0
    }
}

impl Topology {
    /// Distinct neighbours of each scene node (indexed like `scene.nodes`, of length
    /// `node_count`), counted over the modelled edges.
    pub(crate) fn degrees(&self, node_count: usize) -> Vec<u32> {
        let mut degrees = vec![0_u32; node_count];
        for &(a, b) in &self.edges {
            degrees[a] += 1;
            degrees[b] += 1;
        }
        degrees
    }
}

/// The order-free topology hash of a scene: node ids, undirected de-duplicated edges
/// (self-loops and edges naming missing nodes left out) and the pinned nodes. Input
/// order does not change it; ids need `Hash + Eq`, never `Ord`. Nodes with unusable
/// values are left out (the layout keeps those that already have a body).
///
/// # Example
/// ```
/// use graph_canvas_layout::scene::topology_hash;
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode,
///     CanvasSceneInput, LayoutExtras};
/// let a = CanvasSceneInput::new(
///     vec![CanvasNode::new(1_u32, Point2D::origin()), CanvasNode::new(2, Point2D::origin())],
///     vec![CanvasEdge::new(1, 2)],
/// );
/// let mut b = a.clone();
/// b.nodes.reverse();
/// b.edges[0] = CanvasEdge::new(2, 1);
/// let extras = LayoutExtras::default();
/// assert_eq!(topology_hash(&a, &extras), topology_hash(&b, &extras));
/// ```
pub fn topology_hash<N: Clone + Eq + Hash>(
    scene: &CanvasSceneInput<N>,
    extras: &LayoutExtras<N>,
) -> u64 {
    Topology::of(scene, extras, |_| false).hash
}
