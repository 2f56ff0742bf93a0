//! The passes cut into blocks against one block: every pair solved, and the same
//! velocities as one Gauss–Seidel pass in the blocks' order.

use euclid::default::Point2D;

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

const DT: f32 = 1.0 / 60.0;

/// 3,000 disks of radius 8 scattered over 1,500 × 1,500 units, rushing about at up to
/// 150 units a second (one in ten asleep), their pairs found and shared.
fn crowd(seed: u64) -> Collide {
    let mut next = sequence(seed);
    let mut collide = Collide::default();
    let mut points = Vec::new();
    for s in 0..3_000 {
        points.push(Point2D::new(next() * 1_500.0, next() * 1_500.0));
        let velocity = Vector2D::new(next() - 0.5, next() - 0.5) * 300.0;
        let asleep = s % 10 == 0;
        let by = &mut collide.by_slot;
        by.radius.push(8.0);
        by.inverse_mass.push(if asleep { 0.0 } else { 1.0 });
        by.velocity
            .push(if asleep { Vector2D::zero() } else { velocity });
        by.motion.push(if asleep {
            Vector2D::zero()
        } else {
            velocity * DT
        });
        by.sleeping.push(asleep);
    }
    collide.take_in_grid_order(&points);
    collide.find_pairs(0.0);
    collide.share();
    collide.wake_inverse_mass = vec![1.0; collide.order.len()];
    collide
}

fn rule() -> PassRule {
    PassRule {
        soft: Softness {
            bias_rate: 0.0,
            mass_scale: 1.0,
            impulse_scale: 0.0,
        },
        inverse_dt: 1.0 / DT,
        sleepers: true,
    }
}

/// The most a pair still closes faster than its gap allows (world units a second).
fn worst_closing(collide: &Collide) -> f32 {
    collide
        .pairs
        .iter()
        .map(|p| {
            let closing =
                (collide.velocity[p.b as usize] - collide.velocity[p.a as usize]).dot(p.normal);
            let allowed = p.separation.max(0.0) / DT;
            -(closing + allowed)
        })
        .fold(0.0, f32::max)
}

/// Cut into four blocks, a pass still solves every pair (each inside one block or
/// listed across), and the passes end with no pair closing faster than its gap allows
/// (a pair left out would keep its speed, up to 300 units a second here). The blocks
/// and the pairs across them are one Gauss–Seidel order, so the velocities are those
/// of the same pairs solved one by one in that order: checked against one block whose
/// pairs are put in that order.
#[test]
fn blocks_solve_every_pair_in_one_gauss_seidel_order() {
    let mut blocked = crowd(3);
    let before = worst_closing(&blocked);
    assert!(
        blocked.pairs.len() > 400 && before > 50.0,
        "{} pairs closing at up to {before}: a crowd to solve",
        blocked.pairs.len()
    );
    blocked.cut_into(4);
    let blocks = blocked.cut.blocks.clone();
    assert_eq!(blocks.len(), 5, "four blocks: {blocks:?}");
    let block_of = |l: u32| blocks.windows(2).position(|w| w[0] <= l && l < w[1]);
    // The pairs across, by the boundary they cross (`None`: past the next block).
    let crossing = |k: u32| -> Option<Option<usize>> {
        let p = blocked.pairs[k as usize];
        let (a, b) = (block_of(p.a)?, block_of(p.b)?);
        (a != b).then_some((b == a + 1).then_some(a))
    };
    let across: Vec<u32> = (0..blocked.pairs.len() as u32)
        .filter(|&k| crossing(k).is_some())
        .collect();
    assert!(
        !across.is_empty() && across.len() * 5 < blocked.pairs.len(),
        "{} of {} pairs across: blocks of neighbours",
        across.len(),
        blocked.pairs.len()
    );
    // One pass, against the same pairs solved one by one in the blocks' order: each
    // block's own pairs, four far-apart runs of them in turn; then the pairs across
    // boundaries 0 and 2, then 1; then those reaching further.
    let mut order = Vec::new();
    for w in blocks.windows(2) {
        let first = blocked.rows[w[0] as usize] as usize;
        let count = blocked.rows[w[1] as usize] as usize - first;
        let stride = count.div_ceil(STREAMS);
        for i in 0..stride {
            for run in 0..STREAMS {
                let k = first + run * stride + i;
                if run * stride + i < count && !across.contains(&(k as u32)) {
                    order.push(k);
                }
            }
        }
    }
    for boundary in [Some(0), Some(2), Some(1), None] {
        let crossing_it = across.iter().filter(|&&k| crossing(k) == Some(boundary));
        order.extend(crossing_it.map(|&k| k as usize));
    }
    assert_eq!(order.len(), blocked.pairs.len(), "every pair solved once");
    let mut one_by_one = crowd(3);
    {
        let c = &mut one_by_one;
        let mut lane = Lane {
            first: 0,
            pairs: &mut c.pairs,
            impulses: &mut c.impulses,
            velocity: &mut c.velocity,
            wake: Wake {
                sleeping: &mut c.sleeping,
                inverse_mass: &mut c.inverse_mass,
                wake_inverse_mass: &c.wake_inverse_mass,
                woken: Vec::new(),
            },
            largest: 0.0,
        };
        let order: Vec<u32> = order.iter().map(|&k| k as u32).collect();
        lane.listed::<false>(&order, rule());
    }
    let (_, mut woken) = blocked.pass_with::<false>(rule());
    let bits = |c: &Collide| -> Vec<[u32; 2]> {
        c.velocity
            .iter()
            .map(|v| [v.x.to_bits(), v.y.to_bits()])
            .collect()
    };
    let (expected, got) = (bits(&one_by_one), bits(&blocked));
    let differ = expected.iter().zip(&got).position(|(e, g)| e != g);
    assert_eq!(
        differ, None,
        "first body whose velocity differs from the pairs one by one"
    );
    let mut passes = 1;
    while passes < 200 {
        let (largest, woke) = blocked.pass_with::<false>(rule());
        woken.extend(woke);
        if !woken.is_empty() {
            blocked.share();
        }
        passes += 1;
        if largest < 1e-3 {
            break;
        }
    }
    let after = worst_closing(&blocked);
    assert!(
        after < 0.05,
        "after {passes} passes a pair still closes {after} units/s faster than its gap allows (from {before})"
    );
    assert!(!woken.is_empty(), "no sleeping body was pushed into");
    woken.sort_unstable();
    let before_dedup = woken.len();
    woken.dedup();
    assert_eq!(woken.len(), before_dedup, "a body woke twice");
}
