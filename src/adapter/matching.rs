//! Matching: which body each scene node is this call, and the cheap checks that tell
//! whether the scene's topology can differ from the world's before any hash is computed.

use std::hash::Hash;

use super::RapierLayout;
use crate::input::layout::LayoutExtras;
use crate::input::scene::CanvasSceneInput;
use crate::input::topology::Topology;
use crate::input::validation::node_is_valid;
use crate::world::RapierSceneWorld;

/// A scene node without a body this call (none yet, or a repeated id).
pub(super) const NO_SLOT: u32 = u32::MAX;

/// Where a scene node stands this call.
#[derive(Clone, Copy, Debug)]
pub(super) struct NodeMatch {
    /// Its body's slot, or [`NO_SLOT`].
    pub(super) slot: u32,
    /// Whether its values are usable this call.
    pub(super) valid: bool,
    pub(super) pinned: bool,
}

/// The matches of the scene's nodes to bodies, by scene index, and what is kept to make
/// the next call's matching cheap.
#[derive(Debug)]
pub(super) struct Matching<N> {
    /// Incremented per matching pass; marks which bodies the scene named.
    stamp: u64,
    matches: Vec<NodeMatch>,
    /// Last pass's matches, kept to reuse slots and the buffer.
    previous: Vec<NodeMatch>,
    /// The edges of the scene the topology was last computed from, to skip that work
    /// while the host passes the same edges; `None` when not known (forgotten, or a
    /// layout restored from a snapshot), so the next call computes the topology.
    edges: Option<Vec<(N, N, u32)>>,
    /// Scene nodes this call left out: unusable values or a repeated id.
    pub(super) bad_nodes: usize,
    /// Repeated ids and bad edges in the scene the topology was last computed from.
    pub(super) topology_problems: usize,
    /// The slots the last call gave a delta, in the order it read them (`known.rs`).
    moved: Vec<u32>,
}

impl<N> Default for Matching<N> {
    fn default() -> Self {
        Self {
            stamp: 0,
            matches: Vec::new(),
            previous: Vec::new(),
            edges: None,
            bad_nodes: 0,
            topology_problems: 0,
            moved: Vec::new(),
        }
    }
}

impl<N> Matching<N> {
    /// The matching pass counter, which the world's nodes are stamped with.
    pub(super) fn stamp(&self) -> u64 {
        self.stamp
    }

    /// A matching that continues a saved layout, whose nodes carry stamps up to `stamp`.
    pub(super) fn resumed(stamp: u64) -> Self {
        Self {
            stamp,
            ..Self::default()
        }
    }
}

impl<N: Clone + Eq + Hash> Matching<N> {
    /// The slots the last call gave a delta.
    pub(super) fn moved(&self) -> &[u32] {
        &self.moved
    }

    /// Where the slots this call gives a delta are kept.
    pub(super) fn moved_mut(&mut self) -> &mut Vec<u32> {
        &mut self.moved
    }

    /// Whether the edges the topology was last computed from are known.
    pub(super) fn knows_edges(&self) -> bool {
        self.edges.is_some()
    }

    /// This call's matches, by scene index.
    pub(super) fn matches(&self) -> &[NodeMatch] {
        &self.matches
    }

    /// Matches scene nodes to bodies and returns whether anything told apart the
    /// scene's node set or pins from the world's.
    fn match_nodes(
        &mut self,
        world: Option<&mut RapierSceneWorld<N>>,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> bool {
        self.stamp += 1;
        let stamp = self.stamp;
        let Some(world) = world else {
            self.matches.clear();
            self.bad_nodes = 0;
            return true;
        };
        let check_pins = !extras.pinned.is_empty();
        let mut changed = false;
        let mut seen = 0;
        let mut bad = 0;
        std::mem::swap(&mut self.matches, &mut self.previous);
        self.matches.clear();
        for (i, node) in scene.nodes.iter().enumerate() {
            let valid = node_is_valid(node);
            let pinned = check_pins && extras.pinned.contains(&node.id);
            // The host usually passes its nodes in the same order: the slot found for
            // this index last call is checked with one id comparison instead of a hash
            // lookup.
            let cached = self
                .previous
                .get(i)
                .map(|m| m.slot as usize)
                .filter(|&s| s < world.slot_count() && *world.id_at(s) == node.id);
            let slot = match cached.or_else(|| world.slot_of(&node.id)) {
                Some(s) if world.host_at(s).stamp != stamp => {
                    let host = world.host_at_mut(s);
                    host.stamp = stamp;
                    seen += 1;
                    // Recorded here, for every matched node whatever its values or
                    // sync: a pin counts in the topology of any node with a body.
                    changed |= host.pinned != pinned;
                    host.pinned = pinned;
                    s as u32
                }
                Some(_) => {
                    bad += 1;
                    NO_SLOT // a repeated id
                }
                None => {
                    // A usable node without a body is new (or a repeat of a new id).
                    changed |= valid;
                    NO_SLOT
                }
            };
            bad += usize::from(!valid);
            self.matches.push(NodeMatch {
                slot,
                valid,
                pinned,
            });
        }
        self.bad_nodes = bad;
        changed || seen != world.slot_count()
    }

    /// Whether the scene passes the same edges, in the same order and with the same
    /// weights, as when the topology was last computed.
    fn edges_unchanged(&self, scene: &CanvasSceneInput<N>) -> bool {
        self.edges.as_ref().is_some_and(|edges| {
            edges.len() == scene.edges.len()
                && edges.iter().zip(&scene.edges).all(|((s, t, w), e)| {
                    *s == e.source && *t == e.target && *w == e.weight.to_bits()
                })
        })
    }

    /// Remembers the scene's edges as the ones the topology was computed from.
    pub(super) fn remember_edges(&mut self, scene: &CanvasSceneInput<N>) {
        let edges = self.edges.get_or_insert_with(Vec::new);
        edges.clear();
        edges.extend(
            scene
                .edges
                .iter()
                .map(|e| (e.source.clone(), e.target.clone(), e.weight.to_bits())),
        );
    }

    /// Forgets the remembered edges, so the next call computes the topology again.
    pub(super) fn forget_edges(&mut self) {
        self.edges = None;
    }
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Matches scene nodes to bodies (this call's matches).
    pub(super) fn match_nodes(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> bool {
        self.matching
            .match_nodes(self.world.as_mut(), scene, extras)
    }

    /// Matches scene nodes to bodies and returns the scene's topology when it may differ
    /// from the world's; `None` when the cheap checks show it cannot.
    pub(super) fn candidate_topology(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> Option<Topology> {
        let nodes_changed = self.match_nodes(scene, extras);
        let world = self.world.as_ref();
        let topology = || {
            Topology::of(scene, extras, |id| {
                world.is_some_and(|w| w.contains_node(id))
            })
        };
        if !nodes_changed && self.built.topology_hash != 0 && self.matching.edges_unchanged(scene) {
            // Debug builds (the tests), up to a few thousand nodes: the cheap checks
            // skip only what the topology's hash would not see either, or a layout
            // restored from a save (which computes it afresh) would part ways.
            #[cfg(debug_assertions)]
            if scene.nodes.len() <= CHECKED_NODES {
                let hash = topology().hash;
                assert_eq!(
                    hash, self.built.topology_hash,
                    "the cheap checks saw no change, but the scene's topology hash {hash} is \
                     not the world's {}",
                    self.built.topology_hash
                );
            }
            return None;
        }
        Some(topology())
    }
}

/// Debug builds check the skipped topology of scenes up to this many nodes.
#[cfg(debug_assertions)]
const CHECKED_NODES: usize = 4_096;
