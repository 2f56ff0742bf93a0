//! Components side by side: stress says nothing about how far apart two components are,
//! so each is laid out on its own and the layouts are packed in rows (largest first, a
//! gap between them), the whole centred on a point.

use euclid::default::{Box2D, Point2D, Vector2D};

/// Moves each component's points (`members[c]` index `points`) so no two components'
/// boxes (grown by `margin`) overlap, in rows about as wide as the packing is tall, and
/// centres the packing on `centre`.
pub(crate) fn pack_components(
    points: &mut [Point2D<f32>],
    members: &[Vec<u32>],
    margin: f32,
    centre: Point2D<f32>,
) {
    let boxes: Vec<Box2D<f32>> = members
        .iter()
        .map(|m| Box2D::from_points(m.iter().map(|&i| points[i as usize])).inflate(margin, margin))
        .collect();
    // Largest first (by members, then by order), the way a reader scans a page.
    let mut order: Vec<usize> = (0..members.len()).collect();
    order.sort_by_key(|&c| (std::cmp::Reverse(members[c].len()), c));
    let area: f32 = boxes.iter().map(|b| b.width() * b.height()).sum();
    let widest = boxes.iter().map(Box2D::width).fold(0.0, f32::max);
    let row_width = widest.max(area.sqrt() * 1.2);
    let (mut x, mut y, mut row_height) = (0.0_f32, 0.0_f32, 0.0_f32);
    let mut placed = vec![Vector2D::zero(); members.len()];
    for &c in &order {
        let b = boxes[c];
        if x > 0.0 && x + b.width() > row_width {
            (x, y, row_height) = (0.0, y + row_height, 0.0);
        }
        placed[c] = Vector2D::new(x - b.min.x, y - b.min.y);
        x += b.width();
        row_height = row_height.max(b.height());
    }
    // NOTE: boxes grown by the margin are never empty, so `union` takes in each (it
    // ignores an empty box: a lone node's own).
    let total = boxes
        .iter()
        .zip(&placed)
        .map(|(b, &at)| b.translate(at))
        .reduce(|a, b| a.union(&b))
        .unwrap_or_default();
    let shift = centre - total.center();
    for (c, m) in members.iter().enumerate() {
        for &i in m {
            points[i as usize] += placed[c] + shift;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_at_one_point_are_put_side_by_side() {
        // Three components of three nodes each, all on top of each other.
        let mut points = [
            Point2D::new(0.0, 0.0),
            Point2D::new(10.0, 0.0),
            Point2D::new(40.0, 0.0),
        ]
        .repeat(3);
        let members = vec![vec![0, 1, 2], vec![3, 4, 5], vec![6, 7, 8]];
        pack_components(&mut points, &members, 5.0, Point2D::new(100.0, 100.0));
        let span = |c: usize| Box2D::from_points(points[3 * c..3 * c + 3].iter().copied());
        for a in 0..3 {
            for b in a + 1..3 {
                let (x, y) = (span(a).inflate(5.0, 5.0), span(b).inflate(5.0, 5.0));
                assert!(!x.intersects(&y), "components {a} and {b}: {x:?} {y:?}");
            }
            assert_eq!(points[3 * a + 2] - points[3 * a], Vector2D::new(40.0, 0.0));
        }
        let whole = Box2D::from_points(points.iter().copied()).inflate(5.0, 5.0);
        let off = (whole.center() - Point2D::new(100.0, 100.0)).length();
        assert!(
            off < 1e-3,
            "the packing is centred {off} units off: {whole:?}"
        );
    }
}
