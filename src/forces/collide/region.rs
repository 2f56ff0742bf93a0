//! Where contacts can happen this substep when few bodies move: a drag or an edit on a
//! large layout at rest wakes a few dozen bodies among 100,000 asleep, and two bodies
//! that both stay where they are need no contact. The separation then takes only the
//! bodies whose bounding boxes reach the box around the moving ones' swept bounding
//! boxes, instead of sorting and searching every body of the world each substep.

use euclid::default::{Point2D, Vector2D};

use super::Collide;

/// Below this many bodies every body is taken: a full grid costs well under a
/// millisecond there.
const REGION_AT_LEAST: usize = 10_000;
/// The region is used while at most one body in this many moves: under one in ten, the
/// motion the grid's cells allow (that of nine bodies in ten) is none, so the full
/// search keeps no pair beyond a moving body's path and reach.
const MOVING_SHARE: usize = 16;

impl Collide {
    /// Marks in `self.region` (by slot) the bodies the separation takes this substep, or
    /// leaves it empty for all of them: with at least [`REGION_AT_LEAST`] bodies of
    /// which at most one in [`MOVING_SHARE`] moves (gives way or is driven), those whose
    /// bounding box reaches the box around the moving bodies' swept bounding boxes
    /// (widened by their motion).
    /// Two bodies outside it cannot touch a moving one, and two still bodies need no
    /// contact.
    pub(super) fn mark_region(&mut self, points: &[Point2D<f32>]) {
        self.region.clear();
        let by = &self.by_slot;
        let n = points.len();
        if n < REGION_AT_LEAST || by.half.len() < n {
            return;
        }
        let moving = |s: usize| by.inverse_mass[s] > 0.0 || by.motion[s] != Vector2D::zero();
        let (mut lo, mut hi) = (
            Point2D::new(f32::INFINITY, f32::INFINITY),
            Point2D::new(f32::NEG_INFINITY, f32::NEG_INFINITY),
        );
        let mut count = 0;
        for (s, &p) in points.iter().enumerate() {
            if !moving(s) || !p.is_finite() {
                continue;
            }
            count += 1;
            if count * MOVING_SHARE > n {
                return;
            }
            // The swept bounding box, widened by the motion's length: the full search
            // keeps a pair within the bodies' reach and their relative motion.
            let motion = by.motion[s];
            let pad = by.half[s] + Vector2D::new(motion.length(), motion.length());
            let to = p + motion;
            lo = lo.min(p.min(to) - pad);
            hi = hi.max(p.max(to) + pad);
        }
        if !(lo.is_finite() && hi.is_finite()) {
            // Nothing moves: nothing to separate but overlaps among still bodies.
            return;
        }
        self.region
            .extend(points.iter().zip(&by.half).map(|(&p, &half)| {
                p.x + half.x >= lo.x
                    && p.x - half.x <= hi.x
                    && p.y + half.y >= lo.y
                    && p.y - half.y <= hi.y
            }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 12,100 still disks on a square lattice, a few moving through them: the pairs with
    /// a moving body are the same whether every body is searched or only the region,
    /// which holds under a tenth of the bodies (the box around the moving ones spans 26
    /// rows of the lattice's 110).
    #[test]
    fn the_region_keeps_every_pair_of_a_moving_body() {
        let side = 110;
        let points: Vec<Point2D<f32>> = (0..side * side)
            .map(|i| Point2D::new((i % side) as f32 * 30.0, (i / side) as f32 * 30.0))
            .collect();
        let moving = [5_000_usize, 5_001, 5_110, 7_777];
        let pairs_with_moving = |region: bool| {
            let mut collide = Collide::default();
            for s in 0..points.len() {
                let by = &mut collide.by_slot;
                by.radius.push(16.0);
                by.half.push(Vector2D::new(16.0, 16.0));
                by.inner.push(Vector2D::zero());
                by.round.push(16.0);
                let moves = moving.contains(&s);
                by.inverse_mass.push(if moves { 1.0 } else { 0.0 });
                by.velocity.push(Vector2D::zero());
                by.motion.push(if moves {
                    Vector2D::new(7.0, -4.0)
                } else {
                    Vector2D::zero()
                });
                by.sleeping.push(!moves);
            }
            if region {
                collide.mark_region(&points);
                assert!(!collide.region.is_empty(), "the region is in use");
            }
            collide.take_in_grid_order(&points);
            collide.find_pairs(0.0);
            let order = &collide.order;
            let mut found: Vec<(u32, u32)> = collide
                .pairs
                .iter()
                .map(|p| {
                    let (a, b) = (order[p.a as usize], order[p.b as usize]);
                    (a.min(b), a.max(b))
                })
                .filter(|&(a, b)| moving.contains(&(a as usize)) || moving.contains(&(b as usize)))
                .collect();
            found.sort_unstable();
            (found, collide.order.len())
        };
        let (all, searched_all) = pairs_with_moving(false);
        let (near, searched_near) = pairs_with_moving(true);
        assert!(
            all == near && !all.is_empty(),
            "{} pairs with a moving body over every body, {} over the region",
            all.len(),
            near.len()
        );
        assert!(
            searched_near * 10 < searched_all,
            "the region holds {searched_near} of {searched_all} bodies"
        );
    }
}
