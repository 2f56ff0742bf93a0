//! The pair search against a search of every two bodies (disks and boxes), and its budget.

use super::*;

/// A fixed sequence in `[0, 1)`.
fn sequence(seed: u64) -> impl FnMut() -> f32 {
    let mut state = seed;
    move || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 40) as f32 / (1_u64 << 24) as f32
    }
}

/// Every two bodies that touch as they move over the substep are found once, in
/// order, whether they move within a cell or further: the grid's cells allow the
/// motion of nine bodies in ten, the rest search the strip along their path, and two
/// fast bodies crossing paths find each other by their swept boxes. Pairs moving
/// fast relative to each other are kept only where their paths come close.
#[test]
fn finds_every_pair_that_may_touch_once_and_in_order() {
    for seed in 1..=6 {
        let mut next = sequence(seed);
        let n = 600;
        let mut collide = Collide::default();
        let mut points = Vec::new();
        for s in 0..n {
            // A dense cluster, with one body in eight moving far (up to 12 radii)
            // and one in fifty across it and beyond, diagonally (a path far longer
            // than the cells, searched row by row along its strip).
            points.push(Point2D::new(next() * 400.0, next() * 300.0));
            let reach = if s % 50 == 0 {
                3_000.0
            } else if s % 8 == 0 {
                200.0
            } else {
                6.0
            };
            collide.by_slot.radius.push(4.0 + next() * 12.0);
            collide.by_slot.inverse_mass.push(1.0);
            collide.by_slot.velocity.push(Vector2D::zero());
            collide.by_slot.motion.push(Vector2D::new(
                (next() - 0.5) * reach,
                (next() - 0.5) * reach,
            ));
            collide.by_slot.sleeping.push(false);
        }
        // Two fast bodies that cross paths, far from where either starts.
        for k in 0..10 {
            let meet = Point2D::new(500.0 + 60.0 * k as f32, 100.0 * seed as f32);
            for (from, motion) in [
                (Vector2D::new(-300.0, 0.0), Vector2D::new(600.0, 0.0)),
                (Vector2D::new(0.0, -300.0), Vector2D::new(0.0, 600.0)),
            ] {
                points.push(meet + from);
                collide.by_slot.radius.push(8.0);
                collide.by_slot.inverse_mass.push(1.0);
                collide.by_slot.velocity.push(Vector2D::zero());
                collide.by_slot.motion.push(motion);
                collide.by_slot.sleeping.push(false);
            }
        }
        let n = points.len();
        collide.take_in_grid_order(&points);
        collide.find_pairs(0.0);
        let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
        assert!(
            found.windows(2).all(|w| w[0] < w[1]),
            "seed {seed}: pairs out of order or twice"
        );
        let (p, r, m) = (&collide.points, &collide.radius, &collide.motion);
        // The closest two bodies come as they move over the substep.
        let closest = |a: usize, b: usize| {
            let (d, v) = (p[b] - p[a], m[b] - m[a]);
            let t = if v.square_length() > 0.0 {
                (-d.dot(v) / v.square_length()).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (d + v * t).length()
        };
        let mut expected = Vec::new();
        for a in 0..n {
            for b in a + 1..n {
                if closest(a, b) <= r[a] + r[b] {
                    expected.push((a as u32, b as u32));
                }
            }
        }
        // Exactly the pairs the rule keeps: within their relative motion of touching
        // at the start, and, when that motion is above the usual one (the slack),
        // coming within the slack of touching on their paths. Fast bodies' paths and
        // swept boxes must find every such pair the neighbouring cells do not hold.
        let slack = collide.grid.usual_motion();
        let mut kept = Vec::new();
        for a in 0..n {
            for b in a + 1..n {
                let (reach, moved) = (r[a] + r[b], (m[b] - m[a]).length());
                if (p[b] - p[a]).length() <= reach + moved
                    && (moved <= slack || closest(a, b) <= reach + slack)
                {
                    kept.push((a as u32, b as u32));
                }
            }
        }
        let unfound: Vec<_> = kept
            .iter()
            .filter(|e| found.binary_search(e).is_err())
            .collect();
        assert!(
            found.len() == kept.len() && unfound.is_empty(),
            "seed {seed}: found {} pairs, the rule keeps {}; first not found {:?}",
            found.len(),
            kept.len(),
            unfound.first()
        );
        let missing: Vec<_> = expected
            .iter()
            .filter(|e| found.binary_search(e).is_err())
            .collect();
        assert!(
            missing.is_empty() && !expected.is_empty(),
            "seed {seed}: {} of {} pairs missed, first {:?}",
            missing.len(),
            expected.len(),
            missing.first()
        );
    }
}

/// Label boxes of many widths and heights, still: every two whose outlines touch or
/// overlap are found (the grid's cells are as wide as the widest box and as high as
/// the highest, and the test of a pair drops only bounding boxes apart on an axis).
#[test]
fn finds_every_pair_of_boxes_that_touch() {
    for seed in 1..=4 {
        let mut next = sequence(seed);
        let mut collide = Collide::default();
        let mut points = Vec::new();
        for _ in 0..500 {
            points.push(Point2D::new(next() * 600.0, next() * 300.0));
            let half = Vector2D::new(5.0 + next() * 35.0, 3.0 + next() * 9.0);
            collide.by_slot.radius.push(half.length());
            collide.by_slot.half.push(half);
            collide.by_slot.inner.push(half);
            collide.by_slot.round.push(0.0);
            collide.by_slot.inverse_mass.push(1.0);
            collide.by_slot.velocity.push(Vector2D::zero());
            collide.by_slot.motion.push(Vector2D::zero());
            collide.by_slot.sleeping.push(false);
        }
        collide.take_in_grid_order(&points);
        collide.find_pairs(0.0);
        let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
        let (p, inner) = (&collide.points, &collide.inner);
        let mut missing = Vec::new();
        let mut touching = 0;
        for a in 0..p.len() {
            for b in a + 1..p.len() {
                let d = p[b] - p[a];
                let separation = super::super::shapes::gap(d, inner[a] + inner[b], 0.0);
                if separation <= 0.0 {
                    touching += 1;
                    if found.binary_search(&(a as u32, b as u32)).is_err() {
                        missing.push((a, b, separation));
                    }
                }
            }
        }
        assert!(
            missing.is_empty() && touching > 0,
            "seed {seed}: {} of {touching} touching boxes missed, first {:?}",
            missing.len(),
            missing.first()
        );
    }
}

/// A crowd far denser than disks can be (every body within a unit of one point, as
/// when thousands of nodes are added at one point): every two bodies touch, and the
/// search keeps to its budget, the pairs found first, in order and each once,
/// instead of the half-million pairs of all two of them.
#[test]
fn a_crowd_denser_than_disks_keeps_to_the_budget() {
    let mut next = sequence(7);
    // Three runs of the search: the budget is the whole substep's, whatever run finds
    // the pairs.
    let n = 3_000;
    let mut collide = Collide::default();
    let points: Vec<_> = (0..n)
        .map(|_| Point2D::new(next() - 0.5, next() - 0.5))
        .collect();
    for _ in 0..n {
        collide.by_slot.radius.push(16.0);
        collide.by_slot.inverse_mass.push(1.0);
        collide.by_slot.velocity.push(Vector2D::zero());
        collide.by_slot.motion.push(Vector2D::zero());
        collide.by_slot.sleeping.push(false);
    }
    collide.take_in_grid_order(&points);
    collide.find_pairs(0.0);
    let budget = PAIRS_PER_BODY * n + PAIRS_AT_LEAST;
    let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
    assert_eq!(
        found.len(),
        budget,
        "{} pairs kept of the {} that touch",
        found.len(),
        n * (n - 1) / 2
    );
    assert!(
        found.windows(2).all(|w| w[0] < w[1]),
        "pairs out of order or twice"
    );
    // Every body in one cell: the pairs in order are every (a, b > a), and the kept
    // ones their first `budget`.
    let first = (0..n as u32)
        .flat_map(|a| (a + 1..n as u32).map(move |b| (a, b)))
        .take(budget);
    let differ = found.iter().zip(first).position(|(f, e)| *f != e);
    assert_eq!(differ, None, "first kept pair not in the search's order");
    assert_eq!(
        collide.rows[n] as usize, budget,
        "rows count every pair kept"
    );
}

/// The pairs one search of the whole grid finds in order, up to the budget, as a
/// single thread found them before the search was cut into runs.
fn searched_in_one_run(collide: &Collide) -> Vec<(u32, u32)> {
    let test = Candidates {
        points: &collide.points,
        radius: &collide.radius,
        half: &collide.half,
        inner: &collide.inner,
        round: &collide.round,
        boxes: collide.boxes,
        inverse_mass: &collide.inverse_mass,
        motion: &collide.motion,
        order: &collide.order,
        slack: collide.grid.usual_motion(),
        margin: 0.0,
    };
    let budget = PAIRS_PER_BODY * collide.points.len() + PAIRS_AT_LEAST;
    let mut pairs = Vec::new();
    collide.grid.near_pairs(0..collide.grid.len(), |a, b| {
        pairs.extend(test.pair(a, b).map(|p| (p.a, p.b)));
        pairs.len() < budget
    });
    pairs
}

/// Four runs of the search over crowds from loose to far denser than disks can be,
/// and one half loose, half at one point: the runs' pairs joined in order are the
/// pairs one search of the whole grid keeps, whether every run ends within its bound
/// and the joined pairs pass the budget, or a run reaches its bound and the search
/// goes on from it.
#[test]
fn runs_of_the_search_keep_the_pairs_one_search_keeps() {
    let n = 4 * RUN;
    let budget = PAIRS_PER_BODY * n + PAIRS_AT_LEAST;
    let (mut over_budget_complete, mut resumed) = (0, 0);
    let sides = (0..=30).map(|k| 380.0 + 5.0 * k as f32);
    for (case, side) in sides.map(Some).chain([None]).enumerate() {
        let mut next = sequence(11 + case as u64);
        let points: Vec<_> = (0..n)
            .map(|i| match side {
                Some(side) => Point2D::new(next() * side, next() * side),
                None if i % 2 == 0 => Point2D::new(next() * 3_000.0, next() * 3_000.0),
                None => Point2D::new(1_500.0 + next(), 1_500.0 + next()),
            })
            .collect();
        let mut collide = Collide::default();
        for _ in 0..n {
            collide.by_slot.radius.push(16.0);
            collide.by_slot.inverse_mass.push(1.0);
            collide.by_slot.velocity.push(Vector2D::zero());
            collide.by_slot.motion.push(Vector2D::zero());
            collide.by_slot.sleeping.push(false);
        }
        collide.take_in_grid_order(&points);
        collide.find_pairs(0.0);
        let found: Vec<(u32, u32)> = collide.pairs.iter().map(|p| (p.a, p.b)).collect();
        let expected = searched_in_one_run(&collide);
        let all_complete = collide.runs.iter().all(|r| r.complete);
        let joined: usize = collide.runs.iter().map(|r| r.pairs.len()).sum();
        over_budget_complete += usize::from(all_complete && joined > budget);
        resumed += usize::from(collide.runs.iter().skip(1).any(|r| !r.complete));
        let differ = found.iter().zip(&expected).position(|(f, e)| f != e);
        assert!(
            found.len() == expected.len() && differ.is_none(),
            "case {case} (side {side:?}): {} pairs against one search's {}, first \
             difference at {differ:?}; runs complete {all_complete}, joined {joined}, \
             budget {budget}",
            found.len(),
            expected.len()
        );
    }
    assert!(
        over_budget_complete > 0 && resumed > 0,
        "the crowds tested {over_budget_complete} searches whose complete runs passed the \
         budget and {resumed} that went on from a run after the first"
    );
}
