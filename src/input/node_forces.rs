//! What a host asks of single nodes beyond pins and drags, in
//! [`LayoutExtras::forces`](crate::LayoutExtras::forces): a pull toward a target x, a
//! target y or a ring, membership of a group that holds together, and a lock of one axis.
//! The forces themselves live in `forces/` (`position.rs`, `radial.rs`, `group.rs`) and
//! the lock in `adapter/node_forces.rs`; this file holds the host's values and what
//! counts as a bad one.

use euclid::default::Point2D;
use serde::{Deserialize, Serialize};

use crate::input::validation::MAX_COORDINATE;

/// A pull toward one coordinate, d3-force's `forceX` or `forceY` for one node.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct AxisTarget {
    /// The coordinate the node is pulled toward, in world units, within
    /// ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub value: f32,
    /// d3-force's strength: the share of the distance to the target the pull closes per
    /// 1/60 s with nothing else acting (d3's default is 0.1). The force on a node of mass
    /// `m` at distance `d` is `m · strength · 3600 · d`, scaled like the edge springs by
    /// the cooling, critically damped on its own and solved implicitly with the springs,
    /// so any strength is stable and the node rests where its forces balance. The edge
    /// springs of [`force_directed`](crate::RapierLayoutConfig::force_directed) have
    /// strength 0.5 at a leaf: 0.1 to 1 is a bias they can overrule, 20 or more holds
    /// nodes near their targets (where targets crowd, disks sit up to a radius off them;
    /// `docs/forces.md` measures how near), and higher strengths also move a node to a
    /// changed target faster.
    /// Must be finite and `>= 0`.
    pub strength: f32,
}

/// A pull toward a circle, d3-force's `forceRadial` for one node.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RingTarget {
    /// The circle's centre, in world units, within ±[`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub center: Point2D<f32>,
    /// The circle's radius, in world units, from 0 to [`MAX_COORDINATE`](crate::MAX_COORDINATE).
    pub radius: f32,
    /// As [`AxisTarget::strength`], along the line from the centre through the node. A
    /// node exactly at the centre feels nothing until something moves it off.
    pub strength: f32,
}

/// One axis of a node fixed where it is, the other free: vis-network's `fixed: {x}`,
/// d3-force's `fx` without `fy`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum AxisLock {
    /// x stays where it is; the node slides along y.
    X,
    /// y stays where it is; the node slides along x.
    Y,
}

/// Per-node forces and constraints, all optional; a node without an entry in
/// [`LayoutExtras::forces`](crate::LayoutExtras::forces) feels none of them.
///
/// Changing an entry moves the node smoothly (the forces pull it over the next frames)
/// and wakes it and, under a [`Cooling`](crate::config::Cooling) schedule, heats its
/// neighbourhood; no rebuild. Group members are not linked for rapier's sleep: a group
/// mate asleep far from a moved member (in hops) stays asleep until something near it
/// wakes it. Bad values (a target beyond ±[`MAX_COORDINATE`](crate::MAX_COORDINATE) or
/// not finite, a negative strength or radius) are [`LayoutError::InvalidNodeForce`](crate::LayoutError::InvalidNodeForce)
/// for [`RapierLayout::try_step`](crate::RapierLayout::try_step);
/// [`step`](crate::Layout::step) leaves that part out and keeps the rest.
///
/// # Example
/// ```
/// use graph_canvas_layout::{LayoutExtras, NodeForces};
/// use graph_canvas_layout::scene::AxisLock;
/// let mut extras = LayoutExtras::<u32>::default();
/// // A timeline: node 7 at x = 300 (its date), its y left to the layout.
/// extras.forces.insert(7, NodeForces::default().toward_x(300.0, 0.5));
/// // Node 8 on a ring of radius 200 around the origin, in group 2.
/// extras.forces.insert(8, NodeForces::default().on_ring(0.0, 0.0, 200.0, 0.3).in_group(2));
/// // Node 9 keeps its y and slides along x only.
/// extras.forces.insert(9, NodeForces::default().locked(AxisLock::Y));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct NodeForces {
    /// A pull toward a target x. Default: `None`.
    pub x: Option<AxisTarget>,
    /// A pull toward a target y. Default: `None`.
    pub y: Option<AxisTarget>,
    /// A pull toward a ring. Default: `None`.
    pub ring: Option<RingTarget>,
    /// The node's group: nodes with the same key are pulled toward their group's centre
    /// of mass, as [`RapierLayoutConfig::groups`](crate::RapierLayoutConfig::groups)
    /// says. Default: `None`.
    pub group: Option<u32>,
    /// One axis fixed where the node is. Default: `None`.
    pub lock: Option<AxisLock>,
}

impl NodeForces {
    /// With a pull toward x = `value` of `strength` ([`AxisTarget`]).
    #[must_use]
    pub fn toward_x(mut self, value: f32, strength: f32) -> Self {
        self.x = Some(AxisTarget { value, strength });
        self
    }

    /// With a pull toward y = `value` of `strength` ([`AxisTarget`]).
    #[must_use]
    pub fn toward_y(mut self, value: f32, strength: f32) -> Self {
        self.y = Some(AxisTarget { value, strength });
        self
    }

    /// With a pull toward the circle of `radius` around (`cx`, `cy`) ([`RingTarget`]).
    #[must_use]
    pub fn on_ring(mut self, cx: f32, cy: f32, radius: f32, strength: f32) -> Self {
        self.ring = Some(RingTarget {
            center: Point2D::new(cx, cy),
            radius,
            strength,
        });
        self
    }

    /// In group `key`.
    #[must_use]
    pub fn in_group(mut self, key: u32) -> Self {
        self.group = Some(key);
        self
    }

    /// With `axis` fixed where the node is.
    #[must_use]
    pub fn locked(mut self, axis: AxisLock) -> Self {
        self.lock = Some(axis);
        self
    }

    /// The first bad value, as the part it belongs to and the value: `"x"`, `"y"`,
    /// `"ring centre"` or `"ring radius"` (beyond ±[`MAX_COORDINATE`] or not finite), or
    /// the strength of one of them (negative or not finite).
    pub(crate) fn problem(&self) -> Option<(&'static str, f32)> {
        for (name, strength, target) in [("x", "x strength", self.x), ("y", "y strength", self.y)] {
            if let Some(t) = target {
                if !coordinate_ok(t.value) {
                    return Some((name, t.value));
                }
                if !strength_ok(t.strength) {
                    return Some((strength, t.strength));
                }
            }
        }
        if let Some(ring) = self.ring {
            for v in [ring.center.x, ring.center.y] {
                if !coordinate_ok(v) {
                    return Some(("ring centre", v));
                }
            }
            if !(coordinate_ok(ring.radius) && ring.radius >= 0.0) {
                return Some(("ring radius", ring.radius));
            }
            if !strength_ok(ring.strength) {
                return Some(("ring strength", ring.strength));
            }
        }
        None
    }

    /// What the layout applies of these: the parts with bad values left out.
    pub(crate) fn usable(mut self) -> Self {
        let axis_ok = |t: &AxisTarget| coordinate_ok(t.value) && strength_ok(t.strength);
        self.x = self.x.filter(axis_ok);
        self.y = self.y.filter(axis_ok);
        self.ring = self.ring.filter(|r| {
            coordinate_ok(r.center.x)
                && coordinate_ok(r.center.y)
                && coordinate_ok(r.radius)
                && r.radius >= 0.0
                && strength_ok(r.strength)
        });
        self
    }

    /// A hash of every value (0 for no forces at all), to tell a change from the last
    /// call's forces.
    pub(crate) fn key(&self) -> u64 {
        if *self == Self::default() {
            return 0;
        }
        let mut words: [u32; 13] = [0; 13];
        if let Some(x) = self.x {
            (words[0], words[1], words[2]) = (1, x.value.to_bits(), x.strength.to_bits());
        }
        if let Some(y) = self.y {
            (words[3], words[4], words[5]) = (1, y.value.to_bits(), y.strength.to_bits());
        }
        if let Some(r) = self.ring {
            words[6] = 1;
            (words[7], words[8]) = (r.center.x.to_bits(), r.center.y.to_bits());
            (words[9], words[10]) = (r.radius.to_bits(), r.strength.to_bits());
        }
        words[11] = self.group.map_or(0, |g| g.wrapping_add(1));
        words[12] = match self.lock {
            None => 0,
            Some(AxisLock::X) => 1,
            Some(AxisLock::Y) => 2,
        };
        // FNV-1a over the words; 0 is kept for "none".
        let hash = words.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, w| {
            (h ^ u64::from(*w)).wrapping_mul(0x0000_0100_0000_01b3)
        });
        hash.max(1)
    }
}

fn coordinate_ok(v: f32) -> bool {
    v.abs() <= MAX_COORDINATE
}

fn strength_ok(strength: f32) -> bool {
    strength.is_finite() && strength >= 0.0
}
