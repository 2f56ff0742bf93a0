//! The call's constraints by world slot: the host's, and a flow's edges less the few
//! that close a directed cycle (a greedy feedback arc set, Eades, Lin and Smyth 1993,
//! worked out again when the edges change).

use std::hash::Hash;

use petgraph::algo::greedy_feedback_arc_set;
use petgraph::graph::DiGraph;

use super::{Row, Separation};
use crate::config::Flow;
use crate::input::constraints::Constraint;
use crate::input::layout::LayoutExtras;
use crate::input::scene::CanvasSceneInput;
use crate::world::RapierSceneWorld;

/// The constraints of the last call, by world slot.
#[derive(Clone, Debug, Default)]
pub(crate) struct Compiled {
    pub(crate) separations: Vec<Separation>,
    pub(crate) rows: Vec<Row>,
    /// Scene edges a flow leaves free, by index in `scene.edges`: those that close a
    /// directed cycle, and self-loops.
    pub(crate) exempt: Vec<usize>,
    /// The topology the exemptions were worked out for.
    exempt_for: Option<u64>,
    /// Host constraints left out this call (a node the scene or world lacks, a bad gap).
    pub(crate) skipped: usize,
    /// For each separation and row from the host, its index in `extras.constraints`
    /// (separations first, in order, then rows); a flow's separations follow the
    /// host's and have none.
    origin: Vec<usize>,
    row_origin: Vec<usize>,
    /// The host constraints more than [`HELD_WITHIN`] from holding after the last call.
    pub(crate) violated: Vec<usize>,
    /// The flow's separations more than [`HELD_WITHIN`] from holding after the last
    /// call, as scene edge indices.
    pub(crate) violated_edges: Vec<usize>,
    /// The scene edge of each of a flow's separations, in order.
    edge_of: Vec<usize>,
}

/// How far from holding a constraint may rest and still count as held (world units).
pub(crate) const HELD_WITHIN: f32 = 1.0;

impl Compiled {
    /// Compiles `extras.constraints` and `flow`'s edges for `world`. `topology` is the
    /// order-free hash of the scene's topology: the exemptions are kept while it holds.
    /// Returns whether the constraints changed (a disturbance).
    pub(crate) fn sync<N: Clone + Eq + Hash>(
        &mut self,
        flow: Option<Flow>,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        world: &RapierSceneWorld<N>,
        topology: u64,
    ) -> bool {
        let before = (
            std::mem::take(&mut self.separations),
            std::mem::take(&mut self.rows),
        );
        self.skipped = 0;
        self.origin.clear();
        self.row_origin.clear();
        self.edge_of.clear();
        for (i, constraint) in extras.constraints.iter().enumerate() {
            let (separations, rows) = (self.separations.len(), self.rows.len());
            if !self.add(constraint, world) {
                self.skipped += 1;
            }
            self.origin
                .extend((separations..self.separations.len()).map(|_| i));
            self.row_origin.extend((rows..self.rows.len()).map(|_| i));
        }
        if let Some(flow) = flow {
            if self.exempt_for != Some(topology) {
                self.exempt = exempt_edges(scene);
                self.exempt_for = Some(topology);
            }
            let mut exempt = self.exempt.iter().peekable();
            for (i, edge) in scene.edges.iter().enumerate() {
                if exempt.next_if(|&&e| e == i).is_some() {
                    continue;
                }
                let (Some(a), Some(b)) = (world.slot_of(&edge.source), world.slot_of(&edge.target))
                else {
                    continue;
                };
                let (first, second) = flow.order(a, b);
                self.edge_of.push(i);
                self.separations.push(Separation {
                    first: first as u32,
                    second: second as u32,
                    axis: flow.axis(),
                    gap: flow.gap(),
                });
            }
        } else {
            self.exempt.clear();
            self.exempt_for = None;
        }
        before.0 != self.separations || before.1 != self.rows
    }

    /// After the call's substeps: which constraints rest more than [`HELD_WITHIN`] from
    /// holding (conflicting ones that cannot all hold, or ones still settling).
    pub(crate) fn check<N: Clone + Eq + Hash>(&mut self, world: &RapierSceneWorld<N>) {
        self.violated.clear();
        self.violated_edges.clear();
        let host = self.origin.len();
        for (k, c) in self.separations.iter().enumerate() {
            if c.shortfall(world) > HELD_WITHIN {
                match k.checked_sub(host) {
                    None => self.violated.push(self.origin[k]),
                    Some(e) => self.violated_edges.push(self.edge_of[e]),
                }
            }
        }
        for (k, row) in self.rows.iter().enumerate() {
            if row.spread(world) > 2.0 * HELD_WITHIN {
                self.violated.push(self.row_origin[k]);
            }
        }
        self.violated.sort_unstable();
        self.violated.dedup();
    }

    /// Adds one host constraint; false when it names a node without a body or has an
    /// unusable gap (left out this call).
    fn add<N: Clone + Eq + Hash>(
        &mut self,
        constraint: &Constraint<N>,
        world: &RapierSceneWorld<N>,
    ) -> bool {
        let slots: Option<Vec<u32>> = constraint
            .nodes()
            .iter()
            .map(|n| world.slot_of(n).map(|s| s as u32))
            .collect();
        let Some(slots) = slots else {
            return false;
        };
        match constraint.gap() {
            Some(gap) if gap.is_finite() && gap >= 0.0 => {
                self.separations.push(Separation {
                    first: slots[0],
                    second: slots[1],
                    axis: constraint.axis(),
                    gap,
                });
                true
            }
            Some(_) => false,
            None => {
                if slots.len() > 1 {
                    self.rows.push(Row {
                        axis: constraint.axis(),
                        slots,
                    });
                }
                true
            }
        }
    }
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
