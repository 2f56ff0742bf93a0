//! The host's clusters by world slot: which are held (usable padding, good parents),
//! what each one's box is made of (its own members, outside its nested clusters, and
//! its nested clusters' boxes), and an order that puts nested clusters before their
//! parents, so boxes are made from the inside out.

use std::hash::Hash;

use crate::graph::Lists;
use crate::input::clusters::{held_parent, usable, walk_members, Cluster, Membership, NO_CLUSTER};
use crate::world::RapierSceneWorld;

/// The clusters of the last call, by world slot.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Tree {
    /// By cluster (index in the host's list): whether it is held.
    pub(super) held: Vec<bool>,
    /// By cluster: its padding (world units).
    pub(super) padding: Vec<f32>,
    /// By cluster: the slots whose innermost held cluster it is.
    pub(super) own: Lists,
    /// By cluster: the held clusters nested directly in it.
    pub(super) children: Lists,
    /// The held top-level clusters.
    pub(super) top: Vec<u32>,
    /// The held clusters, each after every cluster nested in it.
    pub(super) inside_out: Vec<u32>,
    /// By slot: whether the node belongs to a held cluster.
    pub(super) clustered: Vec<bool>,
    /// Memberships and clusters left out (bad input).
    pub(super) skipped: usize,
}

impl Tree {
    /// Compiles `clusters` for `world`.
    pub(super) fn compile<N: Clone + Eq + Hash>(
        clusters: &[Cluster<N>],
        world: &RapierSceneWorld<N>,
    ) -> Self {
        let held = usable(clusters);
        let mut skipped = held.iter().filter(|&&h| !h).count();
        let slots = world.slot_count();
        let index_of = |n: &N| world.slot_of(n);
        let innermost = walk_members(clusters, &held, slots, index_of, |_, _, m| {
            if !matches!(m, Membership::Kept(_)) {
                skipped += 1;
            }
        });
        let own: Vec<(u32, u32)> = (0..slots as u32)
            .filter(|&s| innermost[s as usize] != NO_CLUSTER)
            .map(|s| (innermost[s as usize], s))
            .collect();
        let parent: Vec<Option<usize>> = (0..clusters.len())
            .map(|c| held[c].then(|| held_parent(clusters, &held, c)).flatten())
            .collect();
        let nested: Vec<(u32, u32)> = (0..clusters.len())
            .filter(|&c| held[c])
            .filter_map(|c| parent[c].map(|p| (p as u32, c as u32)))
            .collect();
        let children = Lists::from_pairs(clusters.len(), &nested);
        let top: Vec<u32> = (0..clusters.len())
            .filter(|&c| held[c] && parent[c].is_none())
            .map(|c| c as u32)
            .collect();
        // Depth first from the top, each cluster after its nested ones.
        let mut inside_out = Vec::with_capacity(clusters.len());
        let mut stack: Vec<(u32, bool)> = top.iter().rev().map(|&c| (c, false)).collect();
        while let Some((c, expanded)) = stack.pop() {
            if expanded {
                inside_out.push(c);
            } else {
                stack.push((c, true));
                stack.extend(children.of(c as usize).iter().rev().map(|&k| (k, false)));
            }
        }
        let mut clustered = vec![false; slots];
        for &(_, s) in &own {
            clustered[s as usize] = true;
        }
        Self {
            padding: clusters.iter().map(Cluster::padding).collect(),
            held,
            own: Lists::from_pairs(clusters.len(), &own),
            children,
            top,
            inside_out,
            clustered,
            skipped,
        }
    }

    /// Whether no held cluster has a body in it (nothing to hold, no box to make).
    pub(super) fn is_empty(&self) -> bool {
        self.own.is_empty()
    }

    /// Calls `each` with every slot of cluster `c`, nested clusters' included.
    pub(super) fn for_each_slot(&self, c: usize, mut each: impl FnMut(usize)) {
        let mut stack = vec![c as u32];
        while let Some(k) = stack.pop() {
            self.own
                .of(k as usize)
                .iter()
                .for_each(|&s| each(s as usize));
            stack.extend_from_slice(self.children.of(k as usize));
        }
    }
}
