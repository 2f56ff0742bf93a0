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

/// A hard constraint between scene nodes, held within a unit at rest.
///
/// # Example
/// ```
/// use graph_canvas_layout::scene::{Axis, Constraint};
/// // Node 2 at least 80 units below node 1; nodes 3, 4 and 5 on one vertical line.
/// let constraints = vec![
///     Constraint::separation(Axis::Y, 1_u32, 2, 80.0),
///     Constraint::align(Axis::X, vec![3, 4, 5]),
/// ];
/// assert_eq!(constraints[1].nodes(), &[3, 4, 5]);
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
