//! What a call left out and why: `step` never fails, so the nodes, edges and forces it
//! could not use are listed here for the host to read after the call, and every problem
//! of a scene can be listed at once before a call. Counting what was left out is part of
//! matching, the topology and the per-node forces; only a call that left something out
//! works out the list.

use std::hash::Hash;

use super::RapierLayout;
use crate::input::layout::LayoutExtras;
use crate::input::scene::CanvasSceneInput;
use crate::input::validation::{problems, LayoutError};
use crate::world::RapierSceneWorld;

/// What a call reports beside its deltas: the nodes whose bodies were recovered from a
/// non-finite state, and what it left out.
#[derive(Debug)]
pub(super) struct Report<N> {
    /// Nodes whose bodies were recovered this call ([`RapierLayout::recovered_nodes`]).
    pub(super) recovered: Vec<N>,
    /// What the last call left out ([`RapierLayout::skipped`]).
    pub(super) skipped: Vec<LayoutError<N>>,
}

impl<N> Default for Report<N> {
    fn default() -> Self {
        Self {
            recovered: Vec::new(),
            skipped: Vec::new(),
        }
    }
}

impl<N: Clone + Eq + Hash> Report<N> {
    /// Takes the nodes rapier quarantined during this call's steps.
    pub(super) fn collect_recovered(&mut self, world: Option<&mut RapierSceneWorld<N>>) {
        self.recovered.clear();
        if let Some(world) = world {
            self.recovered.extend(world.take_recovered_nodes());
        }
    }
}

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// What the last call left out and why, in scene order (nodes, then edges, then the
    /// nodes' forces), as [`RapierLayout::try_step`] would have named each: nodes with a
    /// non-finite or out-of-range position or a bad radius (they get no body, or keep
    /// theirs frozen, and no delta), repeated ids (the first is used), edges naming a
    /// node not in the scene (dropped), bad edge weights (no force) and bad parts of
    /// [`LayoutExtras::forces`] (left out). Empty when the call used everything.
    ///
    /// [`is_converged`](crate::Layout::is_converged) speaks of what the call used: a
    /// layout can be at rest while a node listed here waits for usable values. A call
    /// that [`try_step`](Self::try_step) rejected did not run and leaves the list as the
    /// last call that ran left it. Each call that leaves something out works the list
    /// out anew, an O(n + e) pass over the scene, so a host that keeps a bad element
    /// around pays that every frame until it fixes it.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::euclid::default::Point2D;
    /// use graph_canvas_layout::{
    ///     CanvasEdge, CanvasNode, CanvasSceneInput, Layout, LayoutError, LayoutExtras,
    ///     RapierLayout, RapierLayoutState,
    /// };
    /// let scene = CanvasSceneInput::new(
    ///     vec![CanvasNode::new(1, Point2D::new(0.0, 0.0)), CanvasNode::new(2, Point2D::new(f32::NAN, 0.0))],
    ///     vec![CanvasEdge::new(1, 2), CanvasEdge::new(1, 9)],
    /// );
    /// let mut layout = RapierLayout::default();
    /// let (mut state, extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    /// assert!(matches!(
    ///     layout.skipped(),
    ///     [
    ///         LayoutError::NonFinitePosition { node: 2, .. },
    ///         LayoutError::UnknownEdgeEndpoint { missing: 9, .. },
    ///     ]
    /// ));
    /// ```
    pub fn skipped(&self) -> &[LayoutError<N>] {
        &self.report.skipped
    }

    /// Every problem in `scene` and `extras` at once, in the order
    /// [`try_step`](Self::try_step) meets them (it reports the first): nodes, then
    /// edges, then the nodes' forces. Empty when `try_step` would accept the call.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::euclid::default::Point2D;
    /// use graph_canvas_layout::{CanvasEdge, CanvasNode, CanvasSceneInput, LayoutExtras, RapierLayout};
    /// let scene = CanvasSceneInput::new(
    ///     vec![CanvasNode::new(1, Point2D::new(0.0, 0.0))],
    ///     (2..6).map(|stale| CanvasEdge::new(1, stale)).collect(),
    /// );
    /// let problems = RapierLayout::problems(&scene, &LayoutExtras::default());
    /// assert_eq!(problems.len(), 4, "four stale edges, four problems");
    /// ```
    pub fn problems(scene: &CanvasSceneInput<N>, extras: &LayoutExtras<N>) -> Vec<LayoutError<N>> {
        problems(scene, extras)
    }

    /// Lists what this call left out, when matching, the topology or the forces counted
    /// anything.
    pub(super) fn note_skipped(&mut self, scene: &CanvasSceneInput<N>, extras: &LayoutExtras<N>) {
        let counted = self.matching.bad_nodes
            + self.matching.topology_problems
            + self.forces.targets.problems
            + self.constraints.skipped
            + self.clusters.skipped();
        if counted > 0 || (scene.nodes.is_empty() && !scene.edges.is_empty()) {
            self.report.skipped = problems(scene, extras);
        } else {
            self.report.skipped.clear();
        }
    }
}
