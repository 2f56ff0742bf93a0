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

use euclid::default::Vector2D;

/// The contact of two shapes whose centres are `d` apart (from the first to the second),
/// given the sum of their boxes' half extents (`inner`) and of their disks' radii
/// (`round`): the normal (from the first to the second) and the separation along it
/// (negative in an overlap). Where the offset lies inside the boxes' sum (a deep
/// overlap), the normal is the axis the pair leaves by soonest, signed by the offset, or
/// by `tie()` where the offset is 0 on that axis (coincident centres).
pub(crate) fn contact(
    d: Vector2D<f32>,
    inner: Vector2D<f32>,
    round: f32,
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
    let along_x = depth_x <= depth_y;
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

/// The contact of local bodies `a` and `b`, `d` apart, when either is a box (`None` for
/// two disks, which the separation measures as it always has). `tie` gives the
/// direction coincident centres part along; it is asked for only then.
#[inline]
pub(super) fn box_contact(
    inner: &[Vector2D<f32>],
    round: &[f32],
    (a, b): (usize, usize),
    d: Vector2D<f32>,
    tie: impl FnOnce() -> Vector2D<f32>,
) -> Option<(Vector2D<f32>, f32)> {
    let (ia, ib) = (inner[a], inner[b]);
    if ia == Vector2D::zero() && ib == Vector2D::zero() {
        return None;
    }
    Some(contact(d, ia + ib, round[a] + round[b], tie))
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
        ];
        for ((dx, dy), (nx, ny), separation) in cases {
            let (normal, got) = contact(Vector2D::new(dx, dy), inner, 0.0, tie);
            assert!(
                (normal - Vector2D::new(nx, ny)).length() < 1e-5 && (got - separation).abs() < 1e-4,
                "offset ({dx}, {dy}): normal {normal:?} separation {got}, expected ({nx}, {ny}) {separation}"
            );
        }
    }

    /// A box and a disk: the disk's radius counts from the box's outline, along the
    /// axis beside a side and from the corner beyond it.
    #[test]
    fn a_disk_touches_a_box_by_its_side_and_its_corner() {
        let inner = Vector2D::new(30.0, 10.0);
        let (normal, separation) = contact(Vector2D::new(0.0, 30.0), inner, 16.0, Vector2D::zero);
        assert!(
            normal == Vector2D::new(0.0, 1.0) && (separation - 4.0).abs() < 1e-5,
            "above the side: {normal:?} {separation}"
        );
        let (normal, separation) = contact(Vector2D::new(33.0, 14.0), inner, 16.0, Vector2D::zero);
        assert!(
            (normal - Vector2D::new(0.6, 0.8)).length() < 1e-5 && (separation + 11.0).abs() < 1e-4,
            "beyond the corner: {normal:?} {separation}"
        );
    }
}
