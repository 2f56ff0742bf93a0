//! Clusters: groups of nodes the layout keeps together in a box of their own
//! ([`Cluster`]). The host lists them in
//! [`LayoutExtras::clusters`](crate::LayoutExtras::clusters); the layout keeps sibling
//! boxes apart and other nodes out of them every substep (`clusters/`) and reports the
//! boxes ([`RapierLayout::cluster_bounds`](crate::RapierLayout::cluster_bounds)).

use serde::{Deserialize, Serialize};

use crate::input::validation::MAX_COORDINATE;

/// The padding a cluster has unless told: its box stands this far (world units) beyond
/// its members' outlines.
pub const DEFAULT_CLUSTER_PADDING: f32 = 10.0;

/// A group of scene nodes drawn as one box: its members' outlines grown by a padding.
/// At rest no node outside the cluster enters the box, and the boxes of siblings (two
/// top-level clusters, or two clusters nested in the same parent) do not overlap.
///
/// A cluster nested in another (`inside`) counts its members as the parent's too; the
/// host need not repeat them in the parent. A node belongs to at most one cluster of a
/// level: the clusters naming it must nest one in the other.
///
/// # Example
/// ```
/// use graph_canvas_layout::scene::Cluster;
/// use graph_canvas_layout::LayoutExtras;
/// let mut extras = LayoutExtras::<u32>::default();
/// extras.clusters.push(Cluster::new(vec![1, 2, 3]).with_padding(12.0)); // cluster 0
/// extras.clusters.push(Cluster::new(vec![2, 3]).inside(0)); // nested in cluster 0
/// extras.clusters.push(Cluster::new(vec![7, 8])); // beside cluster 0
/// assert_eq!(extras.clusters[1].parent(), Some(0));
/// assert_eq!(extras.clusters[0].padding(), 12.0);
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cluster<N> {
    members: Vec<N>,
    /// JSON writes a non-finite padding as `null`, which reads back as NaN (bad input
    /// either way: the cluster is left out the same).
    #[serde(deserialize_with = "padding_or_nan")]
    padding: f32,
    parent: Option<usize>,
}

/// A padding as read: `null` (what JSON made of a non-finite one) is NaN.
fn padding_or_nan<'de, D: serde::Deserializer<'de>>(reader: D) -> Result<f32, D::Error> {
    Option::<f32>::deserialize(reader).map(|p| p.unwrap_or(f32::NAN))
}

impl<N> Cluster<N> {
    /// A top-level cluster of `members`, padded by [`DEFAULT_CLUSTER_PADDING`].
    pub fn new(members: Vec<N>) -> Self {
        Self {
            members,
            padding: DEFAULT_CLUSTER_PADDING,
            parent: None,
        }
    }

    /// The same cluster with its box `padding` world units beyond its members' outlines
    /// (a negative or non-finite padding, or one beyond
    /// [`MAX_COORDINATE`](crate::MAX_COORDINATE), is bad input).
    pub fn with_padding(mut self, padding: f32) -> Self {
        self.padding = padding;
        self
    }

    /// The same cluster nested in the cluster at index `parent` of the same list: its
    /// box lies inside the parent's, apart from its siblings'.
    pub fn inside(mut self, parent: usize) -> Self {
        self.parent = Some(parent);
        self
    }

    /// The nodes the host listed (a nested cluster's members are the parent's too).
    pub fn members(&self) -> &[N] {
        &self.members
    }

    /// How far its box stands beyond its members' outlines.
    pub fn padding(&self) -> f32 {
        self.padding
    }

    /// Whether `other` holds the same: the same members and parent, and the same
    /// padding to the bit or both unusable (a NaN padding equals itself, which `==`
    /// denies, so a host passing the same bad list every call changes nothing; and a
    /// cluster left out is left out whatever its bad padding).
    pub(crate) fn same_as(&self, other: &Self) -> bool
    where
        N: PartialEq,
    {
        let (a, b) = (self.padding, other.padding);
        self.members == other.members
            && (a.to_bits() == b.to_bits() || !(usable_padding(a) || usable_padding(b)))
            && self.parent == other.parent
    }

    /// The index of the cluster it is nested in, `None` at the top level.
    pub fn parent(&self) -> Option<usize> {
        self.parent
    }
}

/// Whether a padding can be held: from 0 to [`MAX_COORDINATE`] (a box grown beyond
/// the range would push every node out of it).
pub(crate) fn usable_padding(padding: f32) -> bool {
    (0.0..=MAX_COORDINATE).contains(&padding)
}

/// The first bad parent link of `clusters[i]`, if any: its parent index out of range,
/// or a chain of parents from it that comes back to it.
pub(crate) fn bad_parent<N>(clusters: &[Cluster<N>], i: usize) -> Option<usize> {
    let mut at = i;
    // A chain longer than the list has repeated a cluster.
    for _ in 0..=clusters.len() {
        match clusters[at].parent {
            None => return None,
            Some(p) if p >= clusters.len() || p == i => return clusters[i].parent,
            Some(p) => at = p,
        }
    }
    clusters[i].parent
}

/// Whether each cluster is held: its padding usable and its chain of parents good.
pub(crate) fn usable<N>(clusters: &[Cluster<N>]) -> Vec<bool> {
    (0..clusters.len())
        .map(|i| usable_padding(clusters[i].padding) && bad_parent(clusters, i).is_none())
        .collect()
}

/// The nearest held cluster `i` is nested in (skipping those left out), given `held`
/// from [`usable`]: `None` at the top level.
pub(crate) fn held_parent<N>(clusters: &[Cluster<N>], held: &[bool], i: usize) -> Option<usize> {
    let mut at = clusters[i].parent;
    while let Some(p) = at {
        if held[p] {
            return Some(p);
        }
        at = clusters[p].parent;
    }
    None
}

/// What one listed member of a held cluster comes to (see [`walk_members`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Membership {
    /// The node is not known (not in the scene, or without a body).
    Unknown,
    /// The node belongs to the cluster (and to every cluster it is nested in).
    Kept(usize),
    /// The node already belongs to `other`, a cluster this one does not nest with:
    /// the membership is left out.
    Clash { index: usize, other: usize },
}

/// Walks the members of the held clusters in list order. `index_of` gives a known
/// node's dense index (below `count`); `each(cluster, node, membership)` hears of every
/// member. A node listed by clusters that nest keeps the innermost; one listed by a
/// cluster that does not nest with its own clashes, and the later listing is left out.
/// Returns, by dense index, the innermost held cluster of each node ([`NO_CLUSTER`] for
/// none).
pub(crate) fn walk_members<'a, N>(
    clusters: &'a [Cluster<N>],
    held: &[bool],
    count: usize,
    mut index_of: impl FnMut(&N) -> Option<usize>,
    mut each: impl FnMut(usize, &'a N, Membership),
) -> Vec<u32> {
    const NONE: u32 = NO_CLUSTER;
    let mut innermost = vec![NONE; count];
    let within = |inner: usize, outer: usize| {
        let mut at = Some(inner);
        while let Some(c) = at {
            if c == outer {
                return true;
            }
            at = clusters[c].parent;
        }
        false
    };
    for (c, cluster) in clusters.iter().enumerate().filter(|&(c, _)| held[c]) {
        for node in &cluster.members {
            let Some(index) = index_of(node).filter(|&k| k < count) else {
                each(c, node, Membership::Unknown);
                continue;
            };
            let had = innermost[index];
            let membership = if had == NONE || within(c, had as usize) {
                innermost[index] = c as u32;
                Membership::Kept(index)
            } else if within(had as usize, c) {
                Membership::Kept(index)
            } else {
                Membership::Clash {
                    index,
                    other: had as usize,
                }
            };
            each(c, node, membership);
        }
    }
    innermost
}

/// In [`walk_members`]' result: a node in no cluster.
pub(crate) const NO_CLUSTER: u32 = u32::MAX;

#[cfg(test)]
mod tests {
    use super::{bad_parent, Cluster};

    #[test]
    fn a_cluster_with_a_non_finite_padding_saves_and_reads_back() {
        for padding in [f32::NAN, f32::INFINITY, -1.0, 12.5] {
            let cluster = Cluster::new(vec![1_u32, 2]).with_padding(padding).inside(3);
            let text = serde_json::to_string(&cluster).unwrap();
            let read: Cluster<u32> = serde_json::from_str(&text)
                .unwrap_or_else(|e| panic!("padding {padding}: {text} does not read back: {e}"));
            assert!(
                read.same_as(&cluster),
                "padding {padding}: {read:?} from {text}"
            );
        }
    }

    #[test]
    fn parents_out_of_range_and_cycles_are_found() {
        let ok = vec![
            Cluster::new(vec![1_u32]),
            Cluster::new(vec![2]).inside(0),
            Cluster::new(vec![3]).inside(1),
        ];
        assert_eq!(
            (0..3).map(|i| bad_parent(&ok, i)).collect::<Vec<_>>(),
            [None; 3]
        );
        let out = vec![Cluster::new(vec![1_u32]).inside(5)];
        assert_eq!(bad_parent(&out, 0), Some(5));
        let cycle = vec![
            Cluster::new(vec![1_u32]).inside(1),
            Cluster::new(vec![2]).inside(0),
            Cluster::new(vec![3]).inside(1),
        ];
        assert_eq!(bad_parent(&cycle, 0), Some(1), "0 -> 1 -> 0");
        assert_eq!(bad_parent(&cycle, 1), Some(0), "1 -> 0 -> 1");
        // Nested in a cycle without being on it: the chain never comes back to 2.
        assert_eq!(bad_parent(&cycle, 2), Some(1), "2 -> 1 -> 0 -> 1 ...");
        let own = vec![Cluster::new(vec![1_u32]).inside(0)];
        assert_eq!(bad_parent(&own, 0), Some(0));
    }
}
