//! A flow's edges as separations, by world slot, less the few that close a directed
//! cycle (a greedy feedback arc set, Eades, Lin and Smyth 1993). Compiled again only
//! when the flow, the scene's edges or the world's slots change: a graph of 10,000
//! nodes does not look up 25,000 edges' ends every call.

use std::hash::Hash;

use petgraph::algo::greedy_feedback_arc_set;
use petgraph::graph::DiGraph;
use serde::{Deserialize, Serialize};

use super::layers::layers;
use super::{changed_rows, changed_slots, Row, Separation};
use crate::config::Flow;
use crate::input::constraints::Axis;
use crate::input::scene::CanvasSceneInput;
use crate::world::RapierSceneWorld;

/// A flow as compared between calls: its axis, whether reversed, its gap's bits, whether
/// in layers.
type FlowKey = (Axis, bool, u32, bool);

/// A flow's separations and what they were compiled from.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(bound(serialize = "N: Serialize", deserialize = "N: Deserialize<'de>"))]
pub(super) struct FlowEdges<N> {
    pub(super) separations: Vec<Separation>,
    /// The scene edge of each separation, in order.
    pub(super) edge_of: Vec<usize>,
    /// In layers: a row per layer, and the separations that keep each layer's order
    /// across the flow and each layer a gap beyond the one before.
    #[serde(default)]
    pub(super) rows: Vec<Row>,
    #[serde(default)]
    pub(super) order: Vec<Separation>,
    /// Scene edges left free, ascending: self-loops and those that close a cycle.
    pub(super) exempt: Vec<usize>,
    /// The flow (its axis, whether reversed, its gap's bits) and the world (its rebuild
    /// count and version) they were compiled for.
    key: Option<(FlowKey, (u64, u64))>,
    /// The scene's edges they were compiled from, `(source, target)` in order.
    pub(super) edges: Vec<(N, N)>,
}

impl<N> Default for FlowEdges<N> {
    fn default() -> Self {
        Self {
            separations: Vec::new(),
            edge_of: Vec::new(),
            rows: Vec::new(),
            order: Vec::new(),
            exempt: Vec::new(),
            key: None,
            edges: Vec::new(),
        }
    }
}

impl<N: Clone + Eq + Hash> FlowEdges<N> {
    /// Compiles `flow`'s edges for `world` (`generation`: its rebuild count and
    /// version). Returns whether the separations changed, and adds the slots of those
    /// added or removed to `edit`.
    pub(super) fn sync(
        &mut self,
        flow: Option<Flow>,
        scene: &CanvasSceneInput<N>,
        world: &RapierSceneWorld<N>,
        generation: (u64, u64),
        edit: &mut Vec<u32>,
    ) -> bool {
        let Some(flow) = flow else {
            changed_slots(&self.all_separations(), &[], edit);
            changed_rows(&self.rows, &[], edit);
            let changed = !self.is_empty();
            *self = Self::default();
            return changed;
        };
        let same_edges = self.edges.len() == scene.edges.len()
            && self
                .edges
                .iter()
                .zip(&scene.edges)
                .all(|((s, t), e)| *s == e.source && *t == e.target);
        let key = Some(key(flow, generation));
        if same_edges && self.key == key {
            return false;
        }
        self.exempt = exempt_edges(scene);
        if !same_edges {
            self.edges.clear();
            self.edges.extend(
                scene
                    .edges
                    .iter()
                    .map(|e| (e.source.clone(), e.target.clone())),
            );
        }
        self.key = key;
        let before = (self.all_separations(), std::mem::take(&mut self.rows));
        self.compile(flow, world);
        let after = self.all_separations();
        changed_slots(&before.0, &after, edit);
        changed_rows(&before.1, &self.rows, edit);
        before.0 != after || before.1 != self.rows
    }

    /// The edges' separations, then the layers' order.
    fn all_separations(&self) -> Vec<Separation> {
        self.separations
            .iter()
            .chain(&self.order)
            .copied()
            .collect()
    }

    /// The separations of the edges in `self.edges` but the exempt ones, for `world`;
    /// in layers, the layers too.
    fn compile(&mut self, flow: Flow, world: &RapierSceneWorld<N>) {
        self.separations.clear();
        self.edge_of.clear();
        // In layers, neighbouring layers far enough apart that no two bodies of them
        // overlap (their outlines along the flow, and a quarter of the gap between).
        let extent = |slot: u32, axis: usize| {
            let (inner, round) = world.shape_at(slot as usize).inner_and_round();
            [inner.x, inner.y][axis] + round
        };
        let (along, across) = match flow.axis() {
            Axis::X => (0, 1),
            Axis::Y => (1, 0),
        };
        // Across the flow, a quarter of the gap between neighbours' outlines.
        let spacing = flow.gap() / 4.0;
        let gap = if flow.layered() {
            let largest = (0..world.slot_count() as u32)
                .map(|s| extent(s, along))
                .fold(0.0_f32, f32::max);
            flow.gap().max(2.0 * largest + spacing)
        } else {
            flow.gap()
        };
        let mut exempt = self.exempt.iter().peekable();
        for (i, (source, target)) in self.edges.iter().enumerate() {
            if exempt.next_if(|&&e| e == i).is_some() {
                continue;
            }
            let (Some(a), Some(b)) = (world.slot_of(source), world.slot_of(target)) else {
                continue;
            };
            let (first, second) = flow.order(a, b);
            self.edge_of.push(i);
            self.separations.push(Separation {
                first: first as u32,
                second: second as u32,
                axis: flow.axis(),
                gap,
            });
        }
        self.rows.clear();
        self.order.clear();
        if flow.layered() {
            let ends: Vec<(u32, u32)> = self
                .separations
                .iter()
                .map(|c| (c.first, c.second))
                .collect();
            let layered = layers(
                world.slot_count(),
                &ends,
                (flow.axis(), gap),
                spacing,
                |s| extent(s, across),
            );
            (self.rows, self.order) = (layered.rows, layered.order);
        }
    }

    /// Whether there is nothing to hold: no edge's separation, no layer.
    pub(super) fn is_empty(&self) -> bool {
        self.separations.is_empty() && self.order.is_empty() && self.rows.is_empty()
    }

    /// Whether the layers keep every body of `world` apart: compiled in layers (for this
    /// world: the key holds its generation), so every body is in a layer (a body
    /// without an edge has one too), and every body dynamic (a pinned or dragged body
    /// can hold two layers on one line, and nothing would part what they leave). A
    /// push not yet settled may leave two layers closer for a few substeps; at rest the
    /// layers hold.
    pub(super) fn holds_all_apart(&self, world: &RapierSceneWorld<N>) -> bool {
        let layered = matches!(self.key, Some(((.., true), _)));
        layered && (0..world.slot_count()).all(|s| world.body_at(s).is_dynamic())
    }
}

/// A flow and the world's generation as compared between calls.
fn key(flow: Flow, generation: (u64, u64)) -> (FlowKey, (u64, u64)) {
    (
        (
            flow.axis(),
            flow.order(false, true).0,
            flow.gap().to_bits(),
            flow.layered(),
        ),
        generation,
    )
}

/// The scene edges a flow leaves free, ascending: self-loops, and a greedy feedback arc
/// set of the rest (removing them leaves the directed graph acyclic). Deterministic: the
/// same scene gives the same set.
fn exempt_edges<N: Clone + Eq + Hash>(scene: &CanvasSceneInput<N>) -> Vec<usize> {
    let index: std::collections::HashMap<&N, u32, crate::input::layout::IdHasher> = scene
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| (&n.id, i as u32))
        .collect();
    let mut graph = DiGraph::<(), usize, u32>::with_capacity(scene.nodes.len(), scene.edges.len());
    for _ in &scene.nodes {
        graph.add_node(());
    }
    let mut exempt = Vec::new();
    for (i, edge) in scene.edges.iter().enumerate() {
        match (index.get(&edge.source), index.get(&edge.target)) {
            (Some(&a), Some(&b)) if a == b => exempt.push(i),
            (Some(&a), Some(&b)) => {
                graph.add_edge(a.into(), b.into(), i);
            }
            _ => {}
        }
    }
    exempt.extend(greedy_feedback_arc_set(&graph).map(|e| *e.weight()));
    exempt.sort_unstable();
    exempt
}
