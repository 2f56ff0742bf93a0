//! The call's constraints by world slot: the host's, compiled every call, and a flow's
//! edges (`flow.rs`), compiled when the flow, the edges or the world change; and, after
//! the call, which of them rest more than [`HELD_WITHIN`] from holding.

use std::hash::Hash;

use super::flow::FlowEdges;
use super::local::Local;
use super::{changed_rows, changed_slots, Row, Separation, HELD_WITHIN};
use crate::config::Flow;
use crate::input::constraints::{usable_gap, Constraint};
use crate::input::layout::LayoutExtras;
use crate::input::scene::CanvasSceneInput;
use crate::world::RapierSceneWorld;

/// The constraints of the last call, by world slot.
#[derive(Clone, Debug)]
pub(crate) struct Compiled<N> {
    /// The host's separations and rows.
    pub(super) separations: Vec<Separation>,
    pub(super) rows: Vec<Row>,
    /// A flow's edges.
    pub(super) flow: FlowEdges<N>,
    /// All of them by local index, as the projection holds them, and the separations a
    /// projection's passes visit (with the bits they are found on).
    pub(super) local: Local,
    pub(super) active: Vec<u32>,
    pub(super) active_bits: Vec<u64>,
    /// Host constraints left out this call (a node the scene or world lacks, a bad gap).
    pub(crate) skipped: usize,
    /// For each host separation and row, its index in `extras.constraints`.
    origin: Vec<usize>,
    row_origin: Vec<usize>,
    /// The host constraints more than [`HELD_WITHIN`] from holding after the last call.
    pub(crate) violated: Vec<usize>,
    /// The flow's separations more than [`HELD_WITHIN`] from holding after the last
    /// call, as scene edge indices.
    pub(crate) violated_edges: Vec<usize>,
    /// Whether a call compiled them since the layout was made or restored: the first
    /// compile is no edit (the world it holds them on is new, or restored as it was).
    pub(super) primed: bool,
    /// Whether the host's list moved under the reports since the last check (a
    /// reordered list, a bad constraint inserted: no disturbance, but the indices
    /// [`violated`](Self::violated) gives change).
    unchecked: bool,
}

impl<N> Default for Compiled<N> {
    fn default() -> Self {
        Self {
            separations: Vec::new(),
            rows: Vec::new(),
            flow: FlowEdges::default(),
            local: Local::default(),
            active: Vec::new(),
            active_bits: Vec::new(),
            skipped: 0,
            origin: Vec::new(),
            row_origin: Vec::new(),
            violated: Vec::new(),
            violated_edges: Vec::new(),
            primed: false,
            unchecked: true,
        }
    }
}

impl<N: Clone + Eq + Hash> Compiled<N> {
    /// Compiles `extras.constraints` and `flow`'s edges for `world` (`generation`: its
    /// rebuild count and version). When the constraints changed (a disturbance),
    /// returns the slots of those added or removed, which the heat stage reheats with
    /// their neighbourhoods. The first compile after the layout was made or restored,
    /// and a change of order alone, are no disturbance.
    pub(crate) fn sync(
        &mut self,
        flow: Option<Flow>,
        scene: &CanvasSceneInput<N>,
        extras: &LayoutExtras<N>,
        world: &RapierSceneWorld<N>,
        generation: (u64, u64),
    ) -> Option<Vec<u32>> {
        let primed = std::mem::replace(&mut self.primed, true);
        let before = (
            std::mem::take(&mut self.separations),
            std::mem::take(&mut self.rows),
        );
        self.skipped = 0;
        let origins = (
            std::mem::take(&mut self.origin),
            std::mem::take(&mut self.row_origin),
        );
        for (i, constraint) in extras.constraints.iter().enumerate() {
            let (separations, rows) = (self.separations.len(), self.rows.len());
            if !self.add(constraint, world) {
                self.skipped += 1;
            }
            self.origin
                .extend((separations..self.separations.len()).map(|_| i));
            self.row_origin.extend((rows..self.rows.len()).map(|_| i));
        }
        self.unchecked |= origins.0 != self.origin || origins.1 != self.row_origin;
        let mut edit = Vec::new();
        let flow_changed = self.flow.sync(flow, scene, world, generation, &mut edit);
        let same = before.0 == self.separations && before.1 == self.rows;
        // With nothing to hold, no index is needed for the world's new size (a layout
        // without constraints indexes nothing per node added).
        let none = self.separations.is_empty() && self.rows.is_empty() && self.flow.is_empty();
        if !flow_changed && same && (none || self.local.fits(world.slot_count())) {
            return None;
        }
        self.local.index(
            self.separations
                .iter()
                .chain(&self.flow.separations)
                .chain(&self.flow.order),
            self.rows.iter().chain(&self.flow.rows),
            world.slot_count(),
        );
        changed_slots(&before.0, &self.separations, &mut edit);
        changed_rows(&before.1, &self.rows, &mut edit);
        edit.sort_unstable();
        edit.dedup();
        (primed && !edit.is_empty()).then_some(edit)
    }

    /// Whether there is nothing to hold.
    pub(crate) fn is_empty(&self) -> bool {
        self.local.is_empty()
    }

    /// Whether a flow in layers keeps every body of `world` apart as the world stands
    /// (`flow.rs`), with no host constraint and no axis lock (`locks`) to fight it:
    /// then the disk contacts would find no pair to part, and are not searched for.
    /// With a pinned or dragged node, a host constraint or a lock, the contacts run.
    pub(crate) fn holds_all_apart<L>(&self, world: &RapierSceneWorld<N>, locks: &[L]) -> bool {
        locks.is_empty()
            && self.separations.is_empty()
            && self.rows.is_empty()
            && self.flow.holds_all_apart(world)
    }

    /// The scene edges a flow leaves free, ascending.
    pub(crate) fn exempt(&self) -> &[usize] {
        &self.flow.exempt
    }

    /// [`check`](Self::check)s, if the host's list moved under the reports since the
    /// last check.
    pub(crate) fn check_if_unchecked(&mut self, world: &RapierSceneWorld<N>) {
        if self.unchecked {
            self.check(world);
        }
    }

    /// After the call's substeps: which constraints rest more than [`HELD_WITHIN`] from
    /// holding (conflicting ones that cannot all hold, or ones still settling).
    pub(crate) fn check(&mut self, world: &RapierSceneWorld<N>) {
        self.unchecked = false;
        self.local.refresh(world);
        self.violated.clear();
        self.violated_edges.clear();
        for (k, c) in self.separations.iter().enumerate() {
            if c.shortfall(world) > HELD_WITHIN {
                self.violated.push(self.origin[k]);
            }
        }
        for (k, row) in self.rows.iter().enumerate() {
            if row.spread(world) > 2.0 * HELD_WITHIN {
                self.violated.push(self.row_origin[k]);
            }
        }
        self.violated.sort_unstable();
        self.violated.dedup();
        // The flow's, of which there are as many as edges, from the kept arrays (what
        // the world holds, caught up); a link's id past the host's separations is its
        // place among the flow's (its edges', then its layers' order, not reported).
        let host = self.separations.len();
        for c in &self.local.links {
            let Some(k) = (c.id as usize).checked_sub(host) else {
                continue;
            };
            let Some(&edge) = self.flow.edge_of.get(k) else {
                continue;
            };
            if self.local.shortfall(c) > HELD_WITHIN {
                self.violated_edges.push(edge);
            }
        }
        self.violated_edges.sort_unstable();
    }

    /// Before the world forgets its changes: catches the kept bodies up.
    pub(crate) fn catch_up(&mut self, world: &RapierSceneWorld<N>) {
        self.local.catch_up(world);
    }

    /// Whether a projection moved a body since [`catch_up`](Self::catch_up): rapier
    /// counts a body woken that way as awake only from its next step.
    pub(crate) fn moved_bodies(&self) -> bool {
        self.local.wrote
    }

    /// Adds one host constraint; false when it names a node without a body or has an
    /// unusable gap (left out this call).
    fn add(&mut self, constraint: &Constraint<N>, world: &RapierSceneWorld<N>) -> bool {
        let slots: Option<Vec<u32>> = constraint
            .nodes()
            .iter()
            .map(|n| world.slot_of(n).map(|s| s as u32))
            .collect();
        let Some(slots) = slots else {
            return false;
        };
        match (constraint.gap(), &slots[..]) {
            (Some(gap), &[first, second]) if usable_gap(gap) => {
                self.separations.push(Separation {
                    first,
                    second,
                    axis: constraint.axis(),
                    gap,
                });
                true
            }
            (Some(_), _) => false,
            (None, _) => {
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
