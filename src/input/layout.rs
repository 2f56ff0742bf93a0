//! The layout trait and the per-frame extras a host passes with the scene.

use std::collections::{HashMap, HashSet};

use euclid::default::Vector2D;
use serde::{de::DeserializeOwned, Serialize};

use crate::input::clusters::Cluster;
use crate::input::constraints::Constraint;
use crate::input::node_forces::NodeForces;
use crate::input::scene::{CanvasSceneInput, CanvasViewport};

/// The hasher behind [`DeltaMap`] and [`NodeSet`]: ahash, seeded per map.
pub type IdHasher = ahash::RandomState;

/// What [`Layout::step`] returns: per node, the displacement this call produced, in
/// world units. A node absent from the map did not move.
pub type DeltaMap<N> = HashMap<N, Vector2D<f32>, IdHasher>;

/// A set of node ids, as used in [`LayoutExtras`].
pub type NodeSet<N> = HashSet<N, IdHasher>;

/// A map from node ids, as used in [`LayoutExtras::forces`].
pub type NodeMap<N, V> = HashMap<N, V, IdHasher>;

/// Per-frame interaction state the host passes beside the scene.
///
/// # Example
/// ```
/// use graph_canvas_layout::LayoutExtras;
/// let mut extras = LayoutExtras::<u32>::default();
/// extras.pinned.insert(3);   // immovable until unpinned
/// extras.dragging.insert(5); // under the pointer this frame
/// ```
#[derive(Clone, Debug)]
pub struct LayoutExtras<N> {
    /// Nodes the user wants immovable. The physics never moves them; the host may.
    pub pinned: NodeSet<N>,
    /// Nodes the user's pointer holds this frame. The host moves them; the body sits
    /// exactly where the host puts it, and the release throws it with the drag's speed.
    pub dragging: NodeSet<N>,
    /// Per-node pulls toward a target x, y or ring, group membership and axis locks
    /// ([`NodeForces`]); nodes without an entry feel none of them. Ids not in the scene
    /// are ignored. Default: empty.
    pub forces: NodeMap<N, NodeForces>,
    /// Hard constraints between nodes: separations along an axis and rows on one line
    /// ([`Constraint`]), held every substep, not pulled toward. A dragged or pinned
    /// node does not give way: its partners move. Default: empty.
    pub constraints: Vec<Constraint<N>>,
    /// Groups of nodes kept in boxes of their own ([`Cluster`]), nested by index: no
    /// other node and no sibling's box enters a cluster's box
    /// ([`RapierLayout::cluster_bounds`](crate::RapierLayout::cluster_bounds)). Default:
    /// empty.
    pub clusters: Vec<Cluster<N>>,
}

impl<N> Default for LayoutExtras<N> {
    fn default() -> Self {
        Self {
            pinned: NodeSet::default(),
            dragging: NodeSet::default(),
            forces: NodeMap::default(),
            constraints: Vec::new(),
            clusters: Vec::new(),
        }
    }
}

/// A layout a graph canvas drives once per frame.
///
/// The host owns the positions: it passes them in the scene, adds the returned deltas to
/// its store and hands the new positions back on the next call.
pub trait Layout<N> {
    /// State the host keeps between frames and may persist.
    type State: Default + Clone + Serialize + DeserializeOwned;

    /// Advances the layout by `dt` seconds of frame time and returns, per node, the
    /// displacement this call produced. Pinned and dragged nodes never appear in it.
    fn step(
        &mut self,
        scene: &CanvasSceneInput<N>,
        state: &mut Self::State,
        dt: f32,
        viewport: &CanvasViewport,
        extras: &LayoutExtras<N>,
    ) -> DeltaMap<N>;

    /// Whether the layout was at rest after the last call to `step`, so the host may
    /// stop calling it every frame until something changes. It reports on the last
    /// call: an edit, a drag or a pin made since is seen by the next `step`, not here,
    /// so a host loop steps first and asks after:
    ///
    /// ```text
    /// loop {
    ///     let deltas = layout.step(&scene, &mut state, dt, &viewport, &extras);
    ///     scene.apply_deltas(&deltas);
    ///     if layout.is_converged(&state) { break; }
    /// }
    /// ```
    ///
    /// Layouts that keep their own rest state may ignore `state`. Default: `false`.
    fn is_converged(&self, _state: &Self::State) -> bool {
        false
    }
}
