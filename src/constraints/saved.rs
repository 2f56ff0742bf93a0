//! What a snapshot keeps of the constraints: those the last call held, as it held them
//! (by world slot, a flow's edges with what they were compiled from), so that the first
//! call after a restore tells an edit of the constraints from none exactly as the saved
//! layout would have. A damaged save is not trusted: a flow that does not add up is
//! compiled anew, slots beyond the world are left out.

use std::hash::Hash;

use serde::{Deserialize, Serialize};

use super::flow::FlowEdges;
use super::{Compiled, Row, Separation};
use crate::input::constraints::usable_gap;

/// The constraints a layout held in its last call.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(bound(serialize = "N: Serialize", deserialize = "N: Deserialize<'de>"))]
pub(crate) struct SavedConstraints<N> {
    /// Whether a call had compiled them (a layout saved before its first call had not).
    primed: bool,
    /// The host's separations and rows that held bodies.
    separations: Vec<Separation>,
    rows: Vec<Row>,
    /// A flow's edges.
    flow: FlowEdges<N>,
}

impl<N> Default for SavedConstraints<N> {
    fn default() -> Self {
        Self {
            primed: false,
            separations: Vec::new(),
            rows: Vec::new(),
            flow: FlowEdges::default(),
        }
    }
}

impl<N: Clone + Eq + Hash> Compiled<N> {
    /// What a snapshot keeps of the constraints.
    pub(crate) fn save(&self) -> SavedConstraints<N> {
        SavedConstraints {
            primed: self.primed,
            separations: self.separations.clone(),
            rows: self.rows.clone(),
            flow: self.flow.clone(),
        }
    }

    /// The constraints a restored layout compares its first call's with: those of the
    /// saved layout's last call.
    pub(crate) fn restored(saved: SavedConstraints<N>) -> Self {
        let usable = |c: &Separation| usable_gap(c.gap);
        let mut compiled = Self::default();
        compiled.primed = saved.primed;
        compiled.separations = saved.separations;
        compiled.separations.retain(usable);
        compiled.rows = saved.rows;
        let flow = saved.flow;
        let edges = flow.edges.len();
        if flow.separations.iter().chain(&flow.order).all(usable)
            && flow.edge_of.len() == flow.separations.len()
            && flow.edge_of.iter().chain(&flow.exempt).all(|&e| e < edges)
        {
            compiled.flow = flow;
        }
        compiled
    }
}
