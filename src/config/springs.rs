//! The springs group ([`Springs`]): how edge springs are solved ([`SpringModel`]), what
//! an edge's weight scales ([`EdgeWeight`]), how hubs share their pull and how unevenly
//! a spring pulls its two ends. Read where joints are built and tuned (`adapter/edits.rs`)
//! and by the spring force (`forces/springs.rs`).

use serde::{Deserialize, Serialize};

use crate::world::EdgeJoint;

#[cfg(doc)]
use crate::config::Repulsion;

/// How edge springs are solved and tuned: the part of
/// [`RapierLayoutConfig`](crate::RapierLayoutConfig) that travels with
/// [`edge_joint`](crate::RapierLayoutConfig::edge_joint). Changing `model`, `weight` or
/// `degree_exponent` between calls replaces every joint in place (bodies keep their
/// motion); `link_bias` takes effect at once.
///
/// # Example
/// ```
/// use graph_canvas_layout::config::{SpringModel, Springs};
/// use graph_canvas_layout::RapierLayoutConfig;
/// let config = RapierLayoutConfig {
///     springs: Springs { model: SpringModel::Forces, ..Springs::default() },
///     ..RapierLayoutConfig::default()
/// };
/// assert_eq!(config.springs.degree_exponent, 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Springs {
    /// How spring edges are solved: as rapier joints, or as forces of the layout's own
    /// ([`SpringModel`], where the trade is described). Default: [`SpringModel::Joints`].
    pub model: SpringModel,
    /// What each edge's [`CanvasEdge::weight`](crate::CanvasEdge::weight) scales: the
    /// joint's strength or its length ([`EdgeWeight`], with the formulas and when to
    /// pick which). Costs nothing while every weight is 1. Default:
    /// [`EdgeWeight::Strength`].
    pub weight: EdgeWeight,
    /// Divides each [`EdgeJoint::Spring`]'s stiffness and damping by
    /// `min(degree)^exponent`, the smaller degree of its two ends: a hub's many springs
    /// then pull less hard in sum, so hubs do not crush their neighbourhoods. `0` keeps
    /// every spring as configured; `1` is d3-force's link strength `1 / min(degree)`.
    /// Lower exponents stiffen the springs between well-connected nodes, which physical
    /// springs need more than d3's links (a subtree's whole pull reaches its root edge),
    /// and narrow the spread of edge lengths on trees; lower still pulls dense cores into
    /// piles of touching disks, compacts the layout and makes large random graphs unfold
    /// slower (contacts). `docs/performance.md` measures the trade. Degrees count
    /// distinct neighbours; a topology edit re-tunes the springs whose ends changed
    /// degree. Costs nothing per step. Default: `0.0`
    /// ([`force_directed`](crate::RapierLayoutConfig::force_directed) uses `0.6`).
    pub degree_exponent: f32,
    /// How unevenly a spring pulls its two ends, from 0 to 1. At 0 a spring is a
    /// physical one: equal and opposite pulls. At 1 it shares its pull like d3-force's
    /// link bias: each end takes a part proportional to the *other* end's degree (twice
    /// the spring force in total, as at 0), so a leaf is drawn to its hub harder than
    /// the hub to the leaf, and hubs are not dragged about by their many leaves. The
    /// difference is an extra force on each end, applied with the body forces every
    /// substep; it does not conserve momentum (the centre pull of [`Repulsion`] keeps
    /// the graph in place). It narrows the spread of edge lengths on trees and leaves
    /// small dense graphs as they were (`docs/performance.md`). Costs one pass over the
    /// springs per substep. Clamped to `[0, 1]` (higher gains are explicit forces
    /// stiffer than the step resolves); not finite counts as 0. Default: `0.0`
    /// ([`force_directed`](crate::RapierLayoutConfig::force_directed) uses `1.0`).
    pub link_bias: f32,
}

impl Default for Springs {
    fn default() -> Self {
        Self {
            model: SpringModel::Joints,
            weight: EdgeWeight::Strength,
            degree_exponent: 0.0,
            link_bias: 0.0,
        }
    }
}

/// How [`EdgeJoint::Spring`] edges are solved. Ropes and rods are rapier joints either
/// way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
pub enum SpringModel {
    /// Each spring is a rapier spring joint, solved implicitly with the contacts in
    /// rapier's constraint solver, so a stretched spring and a contact that resists it
    /// are solved together. A connected graph is one rapier island: anything that wakes
    /// one node wakes them all. Rapier solves this joint kind one at a time (it has no
    /// SIMD path for it), which makes springs a large part of a big graph's step.
    #[default]
    Joints,
    /// Springs are forces of the layout's own, evaluated for every edge in one loop per
    /// substep beside the other body forces. Each body's total force is then divided by
    /// `1 + (dt² k + dt c) / m`, with `k` and `c` the stiffness and damping of its
    /// springs: an implicit Euler step on the body's own springs, so springs as stiff as
    /// the timestep resolves stay stable, and a body still rests where its forces
    /// balance. Rapier then sees no joint between nodes: its islands are groups of nodes
    /// in contact, so a disturbance wakes only the nodes it reaches, and the spring
    /// loop is one cheap pass over the edges (`docs/performance.md` gives its time per
    /// edge). The price: springs and contacts are no longer solved together (a spring
    /// pressing two disks into each other is resolved over a few steps by the contact),
    /// and a spring's pull on its two ends comes one substep late to rapier's solver.
    /// [`RapierSceneWorld::joint_count`](crate::RapierSceneWorld::joint_count)
    /// still counts these springs;
    /// [`rapier_joint_count`](crate::RapierSceneWorld::rapier_joint_count) does not.
    Forces,
}

/// What [`CanvasEdge::weight`](crate::CanvasEdge::weight) does to an edge's joint. In
/// both mappings weight 1 leaves the joint as [`RapierLayoutConfig::edge_joint`](crate::RapierLayoutConfig::edge_joint)
/// (and the degree share) make it, bit for bit, and weight 0 gives the edge no joint:
/// it stays topology (the topology hash, the degrees) and exerts nothing. A negative or
/// non-finite weight is bad input ([`LayoutError::InvalidEdgeWeight`](crate::LayoutError::InvalidEdgeWeight));
/// `step` treats it as 0 for that call. A weight edit re-tunes that joint in place: no
/// rebuild, and the bodies keep their motion.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[non_exhaustive]
pub enum EdgeWeight {
    /// Weights are strengths (similarities, affinities, co-occurrence counts): a
    /// spring's stiffness and damping are multiplied by the weight, so weight 2 pulls
    /// twice as hard as weight 1 (d3-force's `link.strength`), and a rope's stiffness
    /// past its length likewise. A rod ([`EdgeJoint::Distance`]) is rigid whatever its
    /// weight. A node held between two springs of weights `w1` and `w2` and the same
    /// rest length `L`, their anchors `D` apart, rests at `x = (w1 L + w2 (D - L)) /
    /// (w1 + w2)` from the first anchor: nearer the heavier edge's anchor.
    #[default]
    Strength,
    /// Weights are lengths (distances, dissimilarities, road lengths): a spring's rest
    /// length, a rope's length and a rod's length are multiplied by the weight, so weight
    /// 2 draws the edge twice as long (vis-network's `edges.length`, d3-force's
    /// `link.distance`), at the configured stiffness.
    Length,
}

impl EdgeWeight {
    /// `joint` for an edge of weight `weight` under this mapping: a weight that is not
    /// positive (0, negative, NaN) gives no joint. Weight 1 gives the joint itself, bit
    /// for bit.
    pub(crate) fn weigh(self, joint: EdgeJoint, weight: f32) -> EdgeJoint {
        if !(weight > 0.0 && weight.is_finite()) {
            return EdgeJoint::None;
        }
        match (self, joint) {
            (
                EdgeWeight::Strength,
                EdgeJoint::Spring {
                    rest_length,
                    stiffness,
                    damping,
                },
            ) => EdgeJoint::Spring {
                rest_length,
                stiffness: stiffness * weight,
                damping: damping * weight,
            },
            (
                EdgeWeight::Strength,
                EdgeJoint::Rope {
                    max_length,
                    stiffness,
                },
            ) => EdgeJoint::Rope {
                max_length,
                stiffness: stiffness * weight,
            },
            (
                EdgeWeight::Length,
                EdgeJoint::Spring {
                    rest_length,
                    stiffness,
                    damping,
                },
            ) => EdgeJoint::Spring {
                rest_length: rest_length * weight,
                stiffness,
                damping,
            },
            (
                EdgeWeight::Length,
                EdgeJoint::Rope {
                    max_length,
                    stiffness,
                },
            ) => EdgeJoint::Rope {
                max_length: max_length * weight,
                stiffness,
            },
            (EdgeWeight::Length, EdgeJoint::Distance { length }) => EdgeJoint::Distance {
                length: length * weight,
            },
            (_, kind) => kind,
        }
    }
}
