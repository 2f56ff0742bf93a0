//! Directed flow ([`Flow`]): every edge `source -> target` points one way, its target at
//! least a gap beyond its source, held as a hard separation (`constraints/`).

use serde::{Deserialize, Serialize};

use crate::config::RapierLayoutConfig;
use crate::input::constraints::Axis;
use crate::sanitize::finite_or;

/// Which way edges point, and how far a target rests beyond its source at least.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::Flow;
/// use graph_canvas_layout::RapierLayoutConfig;
/// // Dependencies read top to bottom, a target at least 80 units below its source.
/// let config = RapierLayoutConfig::stress().with_flow(Flow::down(80.0));
/// assert_eq!(config.flow, Some(Flow::down(80.0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Flow {
    axis: Axis,
    /// Whether targets lie toward lower coordinates (up, left).
    reversed: bool,
    gap: f32,
    /// Whether nodes sit in layers ([`in_layers`](Self::in_layers)).
    #[serde(default)]
    layers: bool,
}

impl Flow {
    /// Targets below their sources (canvas y grows downward): `target.y >= source.y + gap`.
    pub fn down(gap: f32) -> Self {
        Self::along(Axis::Y, false, gap)
    }

    /// Targets above their sources: `target.y <= source.y - gap`.
    pub fn up(gap: f32) -> Self {
        Self::along(Axis::Y, true, gap)
    }

    /// Targets right of their sources: `target.x >= source.x + gap`.
    pub fn right(gap: f32) -> Self {
        Self::along(Axis::X, false, gap)
    }

    /// Targets left of their sources: `target.x <= source.x - gap`.
    pub fn left(gap: f32) -> Self {
        Self::along(Axis::X, true, gap)
    }

    fn along(axis: Axis, reversed: bool, gap: f32) -> Self {
        let flow = Self {
            axis,
            reversed,
            gap,
            layers: false,
        };
        // Kept as `gap()` reads it: a snapshot's JSON has no NaN to write.
        Self {
            gap: flow.gap(),
            ..flow
        }
    }

    /// This flow with the nodes in layers, the picture of Graphviz `dot` and other
    /// Sugiyama layouts, held live: each node on its layer's line across the flow
    /// (every edge goes at least a layer on; a node without an edge has a layer too),
    /// the layers [`gap`](Self::gap) apart at least (or, where the tallest node along
    /// the flow is taller than that, its height plus a quarter of the gap), and each
    /// layer's nodes in an order that crosses few edges (none on a tree), a quarter of
    /// the gap apart outline to outline. The layers and their order are worked out
    /// when the edges or the nodes change; a drag moves a node's whole layer along the
    /// flow and its neighbours aside. While every node is dynamic and no host
    /// constraint fights the layers, the layers keep the nodes apart and the disk
    /// contacts are not searched for; with a pinned or dragged node they run. The
    /// layers' own rows and order are not reported in
    /// [`violated_flow_edges`](crate::RapierLayout::violated_flow_edges), which lists
    /// the edges.
    ///
    /// The trade: far fewer crossings on trees and tree-like graphs (none on a tree),
    /// a much higher stress (a layer's nodes side by side make a wide picture, and the
    /// graph's distances give way to the layers), and on a dense DAG no fewer
    /// crossings than the free flow. Without it, the stress model places the nodes
    /// freely within the flow's separations. `docs/flow.md` has the figures. Default:
    /// off.
    ///
    /// Turning the layers off between calls (to the free flow or to no flow) starts a
    /// [`stress()`](crate::RapierLayoutConfig::stress) layout that makes its own start
    /// ([`StressStart::Global`](crate::config::StressStart::Global), one restored
    /// [`at_rest`](crate::RapierLayout::at_rest) too) anew: the next call places every
    /// node where a new layout under the new flow starts, placed onto the pinned and
    /// dragged nodes, and returns the move in its deltas. Settled from the layers,
    /// which are no stress layout, the nodes rested tangled.
    ///
    /// # Example
    /// ```
    /// use graph_canvas_layout::config::Flow;
    /// let flow = Flow::down(80.0).in_layers();
    /// assert!(flow.layered() && !Flow::down(80.0).layered());
    /// ```
    pub fn in_layers(self) -> Self {
        Self {
            layers: true,
            ..self
        }
    }

    /// Whether the nodes sit in layers ([`in_layers`](Self::in_layers)).
    pub fn layered(&self) -> bool {
        self.layers
    }

    /// The axis edges point along.
    pub fn axis(&self) -> Axis {
        self.axis
    }

    /// The least distance from a source to its target along the axis. Not finite or
    /// negative counts as 0.
    pub fn gap(&self) -> f32 {
        // A deserialized flow has not been through `along`.
        finite_or(self.gap, 0.0).max(0.0)
    }

    /// `(first, second)` of an edge `source -> target` as a separation: the second at
    /// least [`gap`](Self::gap) beyond the first along the axis.
    pub(crate) fn order<T>(&self, source: T, target: T) -> (T, T) {
        if self.reversed {
            (target, source)
        } else {
            (source, target)
        }
    }
}

impl RapierLayoutConfig {
    /// This configuration with its edges pointing along `flow`.
    pub fn with_flow(self, flow: Flow) -> Self {
        Self {
            flow: Some(flow),
            ..self
        }
    }
}
