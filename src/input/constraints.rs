//! Hard constraints between nodes ([`Constraint`]): a separation along an axis, or a
//! row of nodes sharing one coordinate. The host lists them in
//! [`LayoutExtras::constraints`](crate::LayoutExtras::constraints); the layout holds
//! them every substep (`constraints/`), beside its forces, not as springs.

use serde::{Deserialize, Serialize};

/// A canvas axis. Canvas y grows downward.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Axis {
    /// The horizontal axis.
    X,
    /// The vertical axis (growing downward).
    Y,
}

/// A hard constraint between scene nodes, held within a unit at rest, as a
/// [`Flow`](crate::config::Flow)'s edges are.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::Flow;
/// use graph_canvas_layout::scene::{Axis, Constraint};
/// use graph_canvas_layout::{euclid::default::Point2D, CanvasEdge, CanvasNode, CanvasSceneInput,
///     Layout, LayoutExtras, RapierLayout, RapierLayoutConfig, RapierLayoutState};
/// // A build graph: app depends on two libraries, both on core.
/// let nodes = (0..4_u32).map(|i| CanvasNode::new(i, Point2D::new(i as f32 * 10.0, 0.0)));
/// let edges = vec![CanvasEdge::new(0, 1), CanvasEdge::new(0, 2), CanvasEdge::new(1, 3), CanvasEdge::new(2, 3)];
/// let mut scene = CanvasSceneInput::new(nodes.collect(), edges);
/// let mut layout = RapierLayout::new(RapierLayoutConfig::stress().with_flow(Flow::down(80.0)));
/// let (mut state, mut extras) = (RapierLayoutState::default(), LayoutExtras::default());
/// // The two libraries side by side, on one line.
/// extras.constraints.push(Constraint::align(Axis::Y, vec![1, 2]));
/// for _ in 0..600 {
///     let deltas = layout.step(&scene, &mut state, 1.0 / 60.0, &Default::default(), &extras);
///     scene.apply_deltas(&deltas);
///     if layout.is_converged(&state) {
///         break;
///     }
/// }
/// let y = |i: usize| scene.nodes[i].position.y;
/// assert!(y(1) >= y(0) + 79.0 && y(3) >= y(2) + 79.0, "every edge points down");
/// assert!((y(1) - y(2)).abs() <= 2.0, "the libraries share a line");
/// assert!(layout.violated_constraints().is_empty() && layout.violated_flow_edges().is_empty());
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Parts<N>", bound(deserialize = "N: Deserialize<'de>"))]
pub struct Constraint<N> {
    kind: Kind,
    axis: Axis,
    /// `[left, right]` of a separation; the row of an alignment.
    nodes: Vec<N>,
}

/// A [`Constraint`] as read: refused unless a separation names two nodes.
#[derive(Deserialize)]
struct Parts<N> {
    kind: Kind,
    axis: Axis,
    nodes: Vec<N>,
}

impl<N> TryFrom<Parts<N>> for Constraint<N> {
    type Error = String;

    fn try_from(parts: Parts<N>) -> Result<Self, String> {
        match (parts.kind, parts.nodes.len()) {
            (Kind::Separation { .. }, n) if n != 2 => {
                Err(format!("a separation names two nodes, not {n}"))
            }
            _ => Ok(Self {
                kind: parts.kind,
                axis: parts.axis,
                nodes: parts.nodes,
            }),
        }
    }
}

/// What a [`Constraint`] holds.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
enum Kind {
    Separation { gap: f32 },
    Align,
}

impl<N> Constraint<N> {
    /// `right`'s coordinate on `axis` at least `left`'s plus `gap` (world units; a
    /// negative or non-finite gap is bad input).
    pub fn separation(axis: Axis, left: N, right: N, gap: f32) -> Self {
        Self {
            kind: Kind::Separation { gap },
            axis,
            nodes: vec![left, right],
        }
    }

    /// Every node of `nodes` at one coordinate on `axis`: [`Axis::X`] puts them on one
    /// vertical line, [`Axis::Y`] on one horizontal line.
    pub fn align(axis: Axis, nodes: Vec<N>) -> Self {
        Self {
            kind: Kind::Align,
            axis,
            nodes,
        }
    }

    /// The axis the constraint holds along.
    pub fn axis(&self) -> Axis {
        self.axis
    }

    /// The nodes it names: `[left, right]` of a separation, the row of an alignment.
    pub fn nodes(&self) -> &[N] {
        &self.nodes
    }

    /// The gap of a separation, `None` for an alignment.
    pub fn gap(&self) -> Option<f32> {
        match self.kind {
            Kind::Separation { gap } => Some(gap),
            Kind::Align => None,
        }
    }

    /// Whether `other` holds the same: `==` with the gaps compared to the bit (a NaN gap
    /// equals itself, which `==` denies, so a host passing the same bad list every
    /// frame sends nothing new).
    pub(crate) fn same_as(&self, other: &Self) -> bool
    where
        N: PartialEq,
    {
        let kinds = match (self.kind, other.kind) {
            (Kind::Separation { gap: a }, Kind::Separation { gap: b }) => {
                a.to_bits() == b.to_bits()
            }
            (a, b) => a == b,
        };
        kinds && self.axis == other.axis && self.nodes == other.nodes
    }
}

/// Whether a separation's gap can be held: finite and not negative. What `try_step`
/// refuses, `step` leaves out and a restored snapshot drops.
pub(crate) fn usable_gap(gap: f32) -> bool {
    gap.is_finite() && gap >= 0.0
}

#[cfg(test)]
mod tests {
    use super::{Axis, Constraint};

    #[test]
    fn a_separation_read_with_other_than_two_nodes_is_refused() {
        let good = Constraint::separation(Axis::Y, 1_u32, 2, 80.0);
        let text = serde_json::to_string(&good).unwrap();
        let read: Constraint<u32> = serde_json::from_str(&text).unwrap();
        assert_eq!(read, good);
        let three = text.replace("[1,2]", "[1,2,3]");
        assert_ne!(three, text, "the nodes were found in {text}");
        let error = serde_json::from_str::<Constraint<u32>>(&three).unwrap_err();
        assert!(error.to_string().contains("not 3"), "{error}");
    }
}
