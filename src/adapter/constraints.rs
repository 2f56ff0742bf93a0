//! What the hard constraints and a flow report to the host: the edges a flow leaves
//! free and the constraints a call could not hold. The constraints themselves are
//! compiled and held in `constraints/`; the host's pins and drags reach them in stage 4;
//! at the cold stop they settle here, by turns with the overlaps' parting.

use std::hash::Hash;

use super::node_forces::hold_locked_axes;
use euclid::default::Box2D;

use super::RapierLayout;
use crate::input::layout::LayoutExtras;
use crate::input::scene::CanvasSceneInput;
use crate::profile::Stopwatch;

/// At the cold stop: the most rounds of constraint settling and overlap parting.
const HALT_ROUNDS: usize = 16;

/// The most rounds of passes one settling of the constraints takes.
const SETTLE_ROUNDS: usize = 64;

/// A parting that moved no body farther than this (world units) leaves the rounds.
const PARTED: f32 = 0.01;

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// Stage 4: compiles the host's constraints, a flow's edges and the clusters for
    /// the world. Returns whether they changed (a disturbance: the slots they name are
    /// reheated with their neighbourhoods).
    pub(super) fn sync_constraints(
        &mut self,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
    ) -> bool {
        let Some(world) = self.world.as_ref() else {
            return false;
        };
        let generation = (self.built.rebuilds, world.version());
        let flow = self.config.flow;
        let edits = [
            self.constraints
                .sync(flow, scene, extras, world, generation),
            self.clusters.sync(&extras.clusters, world, generation),
        ];
        let mut disturbed = false;
        for edit in edits.into_iter().flatten() {
            disturbed = true;
            self.heat
                .spread
                .touch_constraints(&edit, world.slot_count());
        }
        disturbed
    }

    /// After the call's substeps: at the cold stop, settles the constraints and parts
    /// the overlaps they leave, by turns, until the parting moves nothing (at most
    /// [`HALT_ROUNDS`]); the constraints have the last word. Then notes which do not
    /// hold.
    pub(super) fn hold_constraints(&mut self) {
        let Some(world) = self.world.as_mut() else {
            return;
        };
        if self.heat.state.halted && !(self.constraints.is_empty() && self.clusters.is_empty()) {
            let watch = Stopwatch::start(&self.forces.profile);
            let rounds = (self.config.solver.constraint_passes(), SETTLE_ROUNDS);
            let parts = self.config.contacts.separates_disks()
                && world.contacts_enabled()
                && !self
                    .constraints
                    .holds_all_apart(world, &self.forces.targets.locks);
            let locks = std::mem::take(&mut self.forces.targets.locks);
            for _ in 0..HALT_ROUNDS {
                self.constraints.settle(world, rounds, &locks);
                let boxed = self.clusters.project(world, &locks, (SETTLE_ROUNDS, None));
                if !parts && boxed < PARTED {
                    break;
                }
                let moved = if parts {
                    self.forces.part_overlaps(world)
                } else {
                    0.0
                };
                hold_locked_axes(world, &locks);
                if moved.max(boxed) < PARTED {
                    break;
                }
            }
            self.constraints.settle(world, rounds, &locks);
            self.forces.targets.locks = locks;
            // The balance at rest is the forces' where the bodies now stand: kept from
            // before the settling, it would pull every body the settling moved once a
            // disturbance wakes it, and the motion would spread over the whole layout.
            let dt = world.integration_parameters().dt;
            let alpha = self.heat.state.alpha;
            self.forces.capture_rest(world, &self.config, alpha, dt);
            watch.stop(&mut self.forces.profile, |p| &mut p.constraints);
        }
        self.constraints.check(world);
    }

    /// At the end of a call: notes the clusters' boxes, and checks what holds where the
    /// call moved the layout or the lists changed (a call that did neither leaves the
    /// last reports standing).
    pub(super) fn note_reports(&mut self, listed: usize) {
        let stepped = self.heat.stepped;
        self.clusters
            .note_bounds(self.world.as_ref(), listed, stepped);
        if let Some(world) = self.world.as_ref() {
            self.constraints.check_if_unchecked(world);
        }
    }

    /// Each cluster's box as of the last call, index-aligned with that call's
    /// [`LayoutExtras::clusters`]: its members' outlines (disks, or the boxes of
    /// [`NodeShape::Rect`](crate::NodeShape::Rect) nodes) and its nested clusters' boxes,
    /// grown by its padding, for the host to draw. A cluster left out as bad input, or
    /// none of whose members has a body, gets an empty box at the origin
    /// (`Box2D::zero()`); one whose bad members alone were left out gets the box of the
    /// rest.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::euclid::default::Point2D;
    /// use graph_canvas_layout::scene::Cluster;
    /// use graph_canvas_layout::{CanvasEdge, CanvasNode, CanvasSceneInput, Layout, LayoutExtras,
    ///     RapierLayout, RapierLayoutState};
    /// let node = |i: u32| CanvasNode::new(i, Point2D::new(i as f32 * 30.0, 0.0)).with_radius(10.0);
    /// let edges = (0..5_u32).map(|i| CanvasEdge::new(i, i + 1)).collect();
    /// let mut scene = CanvasSceneInput::new((0..6).map(node).collect(), edges);
    /// let mut layout = RapierLayout::default();
    /// let (mut state, mut extras) = (RapierLayoutState::default(), LayoutExtras::default());
    /// extras.clusters.push(Cluster::new(vec![0, 1, 2]).with_padding(8.0));
    /// extras.clusters.push(Cluster::new(vec![3, 4, 5]).with_padding(8.0));
    /// for _ in 0..600 {
    ///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
    ///     scene.apply_deltas(&deltas);
    ///     if layout.is_converged(&state) {
    ///         break;
    ///     }
    /// }
    /// let [a, b] = [layout.cluster_bounds()[0], layout.cluster_bounds()[1]];
    /// let p = |k: usize| scene.nodes[k].position;
    /// let inside = |k: usize| a.inflate(-9.99, -9.99).contains(p(k));
    /// assert!((0..3).all(inside), "the members' disks are inside their box");
    /// let outside = |k: usize| !a.inflate(9.99, 9.99).contains(p(k));
    /// assert!((3..6).all(outside), "the other cluster's members are outside it");
    /// assert!(a.intersection(&b).map_or(true, |i| i.area() <= 1.0), "{a:?} and {b:?} overlap");
    /// ```
    pub fn cluster_bounds(&self) -> &[Box2D<f32>] {
        &self.clusters.bounds
    }

    /// The clusters (indices into the last call's
    /// [`LayoutExtras::clusters`](crate::LayoutExtras::clusters)) whose box the last call
    /// left overlapping a sibling's box, or a node that is not its member, by more than a
    /// unit: clusters that cannot all be held (pinned members pressed against another
    /// box, a dragged node held inside a box it is not in), or still being parted in the
    /// first frames of a disturbance. Empty when every cluster holds. Checked after each
    /// call that moved the layout, from the boxes of [`cluster_bounds`](Self::cluster_bounds).
    pub fn violated_clusters(&self) -> &[usize] {
        &self.clusters.violated
    }

    /// The scene edges (indices into `scene.edges`) a [`Flow`](crate::config::Flow)
    /// leaves free, as of the last call: self-loops and the few edges that close a
    /// directed cycle (a greedy feedback arc set; removing them leaves the graph
    /// acyclic). The same scene gives the same set; it is worked out again when the
    /// topology changes. Empty without a flow.
    pub fn flow_exempt_edges(&self) -> &[usize] {
        self.constraints.exempt()
    }

    /// The host constraints (indices into
    /// [`LayoutExtras::constraints`](crate::LayoutExtras::constraints)) that the last
    /// call left more than a unit from holding: conflicting constraints that cannot all
    /// hold (the layout holds what it can and stays finite), or constraints still being
    /// reached in a layout's first frames. Empty when every constraint holds.
    pub fn violated_constraints(&self) -> &[usize] {
        &self.constraints.violated
    }

    /// The flow's edges (indices into `scene.edges`, exempt ones aside) that the last
    /// call left more than a unit short of the flow's gap.
    pub fn violated_flow_edges(&self) -> &[usize] {
        &self.constraints.violated_edges
    }
}
