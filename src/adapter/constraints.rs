//! What the hard constraints and a flow report to the host: the edges a flow leaves
//! free and the constraints a call could not hold. The constraints themselves are
//! compiled and held in `constraints/`; the host's pins and drags reach them in stage 4.

use std::hash::Hash;

use super::RapierLayout;

impl<N: Clone + Eq + Hash> RapierLayout<N> {
    /// The scene edges (indices into `scene.edges`) a [`Flow`](crate::config::Flow)
    /// leaves free, as of the last call: self-loops and the few edges that close a
    /// directed cycle (a greedy feedback arc set; removing them leaves the graph
    /// acyclic). The same scene gives the same set; it is worked out again when the
    /// topology changes. Empty without a flow.
    pub fn flow_exempt_edges(&self) -> &[usize] {
        &self.constraints.exempt
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
