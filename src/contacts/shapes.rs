//! The outlines the separation keeps apart: every node is a box swept by a disk
//! ([`ColliderSpec::inner_and_round`](crate::ColliderSpec)): a disk a point swept by its
//! radius, a label box a box swept by nothing, a rounded box both. Two such shapes touch
//! where the offset between their centres is the sum of the disks' radii from the box
//! whose half extents are the sum of theirs (their Minkowski difference), which is what
//! [`contact`] measures: axis-aligned, since rotation is locked, and a few operations a
//! pair, like two disks.
//!
//! A pair of two disks takes the separation's own arithmetic (`pairs.rs`); this file is
//! for the pairs with a box in them.

use std::cmp::Ordering;

use euclid::default::Vector2D;

/// Which side of the boxes' sum an overlapping pair is parted by (see [`contact`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Side {
    /// The side the line between the centres leaves the sum by: how the contacts part
    /// a pair, so that a crowd of overlapping labels spreads evenly.
    CentreLine,
    /// The nearest side: the least move that parts the pair. How deep an overlap is
    /// (an overlap of more than 1 unit is more than 1 unit inside on both axes), and
    /// the last parting before a halt, which moves bodies as little as it can.
    Nearest,
}

/// The contact of two shapes whose centres are `d` apart (from the first to the second),
/// given the sum of their boxes' half extents (`inner`) and of their disks' radii
/// (`round`): the normal (from the first to the second) and the separation along it
/// (negative in an overlap). Where the offset lies inside the boxes' sum (a deep
/// overlap), the normal is the axis of the `side` the pair is parted by, signed by the
/// offset (or by `tie()` where the offset is 0 on that axis: coincident centres), and
/// the separation is the depth along it.
///
/// The contacts part by the centre line, not the nearest side: for a label three times
/// as wide as high, the nearest side of the sum is the top or bottom for five
/// overlapping offsets in six, and a crowd of overlapping labels parted that way only
/// pushed up and down, into a column 2.3 times as tall as wide that was still growing
/// when the layout stopped. The centre line splits the offsets evenly between the axes
/// (it leaves by the side the offset, scaled to a square, points at); on a side of the
/// sum, where touching boxes are, both rules pick that side. The trade: the depth along
/// the centre line's side, which sets how hard a soft contact pushes, is up to the
/// sum's width over its height times the least depth, and jumps where the line crosses
/// a corner of the sum, as the least depth's normal jumped where the two depths meet.
pub(crate) fn contact(
    d: Vector2D<f32>,
    inner: Vector2D<f32>,
    round: f32,
    side: Side,
    tie: impl FnOnce() -> Vector2D<f32>,
) -> (Vector2D<f32>, f32) {
    // `max` then `min`, not `clamp`, which panics on a bound that is NaN or below the
    // other (a shape from a snapshot is not checked for them).
    let nearest = Vector2D::new(
        d.x.max(-inner.x).min(inner.x),
        d.y.max(-inner.y).min(inner.y),
    );
    let out = d - nearest;
    let length = out.length();
    if length > 1e-6 {
        return (out / length, length - round);
    }
    let (depth_x, depth_y) = (inner.x - d.x.abs(), inner.y - d.y.abs());
    // |d.x| / inner.x against |d.y| / inner.y, without dividing by an extent of 0; a
    // tie (the centres at one point, or on the sum's diagonal) takes the nearest side.
    let (wide, tall) = (d.x.abs() * inner.y, d.y.abs() * inner.x);
    let along_x = match (side, wide.partial_cmp(&tall)) {
        (Side::CentreLine, Some(Ordering::Greater)) => true,
        (Side::CentreLine, Some(Ordering::Less)) => false,
        // The nearest side, a tie, or an offset that is NaN (which must not panic).
        _ => depth_x <= depth_y,
    };
    let along = if along_x { d.x } else { d.y };
    let positive = if along == 0.0 {
        let tie = tie();
        (if along_x { tie.x } else { tie.y }) >= 0.0
    } else {
        along > 0.0
    };
    let sign = if positive { 1.0 } else { -1.0 };
    if along_x {
        (Vector2D::new(sign, 0.0), -depth_x - round)
    } else {
        (Vector2D::new(0.0, sign), -depth_y - round)
    }
}

/// How far apart two shapes are: the distance between their outlines, or in an overlap
/// minus its depth on the shallower axis ([`Side::Nearest`]).
pub(crate) fn gap(d: Vector2D<f32>, inner: Vector2D<f32>, round: f32) -> f32 {
    contact(d, inner, round, Side::Nearest, Vector2D::zero).1
}

/// The contact of local bodies `a` and `b`, `d` apart, when either is a box (`None` for
/// two disks, which the separation measures as it always has), an overlap parted by
/// `side`. `tie` gives the direction coincident centres part along; it is asked for
/// only then.
#[inline]
pub(super) fn box_contact(
    inner: &[Vector2D<f32>],
    round: &[f32],
    (a, b): (usize, usize),
    d: Vector2D<f32>,
    side: Side,
    tie: impl FnOnce() -> Vector2D<f32>,
) -> Option<(Vector2D<f32>, f32)> {
    let (ia, ib) = (inner[a], inner[b]);
    if ia == Vector2D::zero() && ib == Vector2D::zero() {
        return None;
    }
    Some(contact(d, ia + ib, round[a] + round[b], side, tie))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two label boxes of 60 × 20 (half extents 30 × 10): side by side, stacked, corner
    /// to corner, overlapping, and with centres at one point.
    #[test]
    fn boxes_touch_by_their_outlines() {
        let inner = Vector2D::new(60.0, 20.0);
        let tie = || Vector2D::new(0.6, -0.8);
        let cases = [
            // (offset, normal, separation)
            ((70.0, 5.0), (1.0, 0.0), 10.0),
            ((-10.0, -25.0), (0.0, -1.0), 5.0),
            ((63.0, 24.0), (0.6, 0.8), 5.0),
            ((55.0, 2.0), (1.0, 0.0), -5.0),
            ((10.0, 19.0), (0.0, 1.0), -1.0),
            ((0.0, 0.0), (0.0, -1.0), -20.0),
            // Deep: the centre line leaves by the right side (40 / 60 > 5 / 20), though
            // the top is nearer (15 against 20).
            ((40.0, 5.0), (1.0, 0.0), -20.0),
            ((-40.0, -10.0), (-1.0, 0.0), -20.0),
        ];
        for ((dx, dy), (nx, ny), separation) in cases {
            let (normal, got) = contact(Vector2D::new(dx, dy), inner, 0.0, Side::CentreLine, tie);
            assert!(
                (normal - Vector2D::new(nx, ny)).length() < 1e-5 && (got - separation).abs() < 1e-4,
                "offset ({dx}, {dy}): normal {normal:?} separation {got}, expected ({nx}, {ny}) {separation}"
            );
        }
    }

    /// How deep an overlap is: the shallower axis, whichever way the pair is parted.
    #[test]
    fn an_overlap_is_as_deep_as_its_shallower_axis() {
        let inner = Vector2D::new(60.0, 20.0);
        let cases = [
            // (offset, round, gap)
            ((70.0, 5.0), 0.0, 10.0),
            ((40.0, 5.0), 0.0, -15.0),
            ((59.5, 0.0), 0.0, -0.5),
            ((0.0, 0.0), 4.0, -24.0),
            ((63.0, 24.0), 4.0, 1.0),
        ];
        for ((dx, dy), round, expected) in cases {
            let got = gap(Vector2D::new(dx, dy), inner, round);
            assert!(
                (got - expected).abs() < 1e-4,
                "offset ({dx}, {dy}), round {round}: gap {got}, expected {expected}"
            );
        }
    }

    /// A box and a disk: the disk's radius counts from the box's outline, along the
    /// axis beside a side and from the corner beyond it.
    #[test]
    fn a_disk_touches_a_box_by_its_side_and_its_corner() {
        let inner = Vector2D::new(30.0, 10.0);
        let (normal, separation) = contact(
            Vector2D::new(0.0, 30.0),
            inner,
            16.0,
            Side::CentreLine,
            Vector2D::zero,
        );
        assert!(
            normal == Vector2D::new(0.0, 1.0) && (separation - 4.0).abs() < 1e-5,
            "above the side: {normal:?} {separation}"
        );
        let (normal, separation) = contact(
            Vector2D::new(33.0, 14.0),
            inner,
            16.0,
            Side::CentreLine,
            Vector2D::zero,
        );
        assert!(
            (normal - Vector2D::new(0.6, 0.8)).length() < 1e-5 && (separation + 11.0).abs() < 1e-4,
            "beyond the corner: {normal:?} {separation}"
        );
    }
}
