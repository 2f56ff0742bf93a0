//! The stress model's settings ([`StressModel`]), read by
//! [`RapierLayoutConfig::stress`](crate::RapierLayoutConfig::stress): which node pairs the
//! layout keeps at their graph distance, the length of a hop, and where a new layout
//! starts.

use serde::{Deserialize, Serialize};

/// Where a stress layout's first world starts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
pub enum StressStart {
    /// A layout of its own, whatever positions the scene holds (a spiral, one point, a
    /// scatter): each component by pivot MDS refined by stress SGD passes, packed side
    /// by side and centred where the host's nodes are. The first call reports the way
    /// from the host's positions to it, so the first frame already shows the graph's
    /// shape; the physics refines it.
    #[default]
    Global,
    /// The host's positions, as they are: the physics unfolds the layout from there
    /// (slower, and a poor start can end in a poorer layout).
    HostPositions,
}

/// The stress model (Kamada–Kawai's energy, as stress majorization and stress SGD
/// minimise it): every two nodes pulled toward their graph distance, `hops × hop
/// length`, by a spring of stiffness `edge stiffness / hops²`, so near pairs weigh most.
/// Made sparse so a step stays near linear: exact terms for the pairs within
/// [`exact_hops`](Self::exact_hops), and for the rest a term to each of
/// [`pivots`](Self::pivots) pivots standing for the nodes around it (Ortmann, Klimenta &
/// Brandes 2016). Edges are the layout's edge springs (rest length one hop); the other
/// terms are forces of the layout's own, solved implicitly like
/// [`SpringModel::Forces`](crate::config::SpringModel::Forces) springs, and scale with the heat
/// as they do. Distances count hops: edge weights scale the edge springs' strength, not
/// the distances.
///
/// The hop distances are searched when the graph changes: from every pivot (O(pivots ×
/// (n + e))), except when the only change is leaves added, whose distances are their
/// neighbour's plus one (no other pair's distance changes). `docs/quality.md` gives what
/// an edit costs.
///
/// # Example
/// ```
/// use graph_canvas_layout::RapierLayoutConfig;
/// use graph_canvas_layout::config::StressModel;
/// // The full stress (every pair) for a small graph, at exactly 120 units a hop.
/// let config = RapierLayoutConfig {
///     stress: Some(StressModel { pivots: None, fit_length: false, hop_length: 120.0, ..StressModel::default() }),
///     ..RapierLayoutConfig::stress()
/// };
/// assert!(config.stress.is_some());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct StressModel {
    /// Pivots in all for graphs larger than [`full_up_to`](Self::full_up_to), shared
    /// among the components by size, or `None` for the full stress at any size (every
    /// pair a term: O(n²) a substep). A component with no more nodes than its share is
    /// laid out with the full stress. More pivots approximate far pairs more finely and
    /// cost more per substep, and more hop distances to search at the start and after
    /// each edit (`docs/quality.md` gives stress, frames and step time from 20 pivots to
    /// the full stress). Changing it builds the model's terms again on the next step
    /// (bodies keep their motion). Default: `Some(100)`.
    pub pivots: Option<usize>,
    /// Graphs of up to this many nodes (all components together) use the full stress
    /// whatever [`pivots`](Self::pivots) says: every pair a term, the layouts of least
    /// stress, at O(n²) a substep while they move. Default: `2_000`.
    pub full_up_to: usize,
    /// Pairs within this many hops are exact terms (up to 48 a node, nearest first);
    /// farther ones go through the pivots. 1 keeps only the edges exact. Default: `2`.
    pub exact_hops: u16,
    /// The length of a hop in world units, or the shortest it may be with
    /// [`fit_length`](Self::fit_length). Default: `100.0`.
    pub hop_length: f32,
    /// Whether the layout lengthens the hop until the nodes' disks are seated: a graph's
    /// stress layout has a density of its own (a hub's leaves all one hop from it, a
    /// random graph's nodes crowded at a few hops from everything), and at 100 units a
    /// hop its disks would overlap, which the contacts then part at the cost of the
    /// picture. The length is chosen once, when the first world is built, from the start
    /// layout: the shortest at which nine nodes in ten are a gap of two units clear of
    /// their nearest neighbour (never below [`hop_length`](Self::hop_length)); the
    /// densest tenth is left to the contacts. Normalised stress does not depend on the
    /// scale, so the trade is the picture's size. Default: `true`.
    pub fit_length: bool,
    /// Where the first world starts ([`StressStart`]). Default: [`StressStart::Global`].
    pub start: StressStart,
    /// Stress SGD passes of the global start after pivot MDS, for graphs of up to
    /// 20,000 nodes; larger ones take fewer, in proportion (`30 × 20,000 / n`: 6 at
    /// 100,000), so a large graph shows its shape soon (`docs/quality.md` times the first
    /// call) and the physics refines it. More passes start closer to the stress minimum.
    /// Default: `30`.
    pub start_passes: u32,
    /// The pivot terms are worked out every this many substeps and held in between as
    /// their first-order model (the force less their stiffness times the way moved since),
    /// while the exact terms and edges are worked out every substep. Far pairs change
    /// slowly, so holding them for a few substeps takes most of the pivot work off a step
    /// and leaves the stress at rest the same (`docs/quality.md` and `docs/performance.md`
    /// measure it); longer periods lag a fast node's far pulls more. Default: `4`.
    pub pivot_period: u32,
}

impl Default for StressModel {
    fn default() -> Self {
        Self {
            pivots: Some(100),
            full_up_to: 2_000,
            exact_hops: 2,
            hop_length: 100.0,
            fit_length: true,
            start: StressStart::Global,
            start_passes: 30,
            pivot_period: 4,
        }
    }
}

impl StressModel {
    /// The pivots as the model counts them for a graph of `nodes` nodes (`usize::MAX`
    /// for the full stress).
    pub(crate) fn pivot_count(&self, nodes: usize) -> usize {
        match self.pivots {
            Some(pivots) if nodes > self.full_up_to => pivots,
            _ => usize::MAX,
        }
    }

    /// The start's SGD passes for a graph of `nodes` nodes.
    pub(crate) fn passes_for(&self, nodes: usize) -> usize {
        let passes = self.start_passes as usize;
        if nodes <= 20_000 {
            passes
        } else {
            passes * 20_000 / nodes
        }
    }
}
