//! The springs summed body by body (the `parallel` path) against one pass over the
//! links in order.

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

/// Every body's spring force and resistance, as bits.
fn bits(out: &ForceSums) -> Vec<[u32; 3]> {
    out.springs
        .iter()
        .zip(&out.resistance)
        .map(|(f, r)| [f.x.to_bits(), f.y.to_bits(), r.to_bits()])
        .collect()
}

/// Summed body by body, in runs, every body's spring force and resistance are the bits
/// one pass over the links in order gives: each body takes its links' pulls in the
/// order the links reach it. With springs as forces and as the link bias's uneven part
/// alone, with bodies asleep (not pushed), one without a position, a spring from a
/// body to itself and forces that start from what other forces summed.
#[test]
fn sums_by_body_are_the_sums_in_link_order() {
    let mut next = sequence(7);
    let n = 5_000;
    let mut springs = Vec::new();
    for a in 0..n {
        for _ in 0..3 {
            let b = (next() * n as f32) as usize % n;
            springs.push(SpringView {
                a,
                b,
                rest_length: 20.0 + next() * 40.0,
                stiffness: 0.5 + next(),
                damping: next() * 0.2,
                cap: 1.2,
            });
        }
    }
    springs.push(SpringView {
        a: 5,
        b: 5,
        rest_length: 10.0,
        stiffness: 1.0,
        damping: 0.1,
        cap: 1.2,
    });
    // At most one spring between two bodies, as the world keeps them.
    springs.sort_by_key(|s| (s.a.min(s.b), s.a.max(s.b)));
    springs.dedup_by_key(|s| (s.a.min(s.b), s.a.max(s.b)));
    let mut force = SpringForce::default();
    force.set_links(n, springs.into_iter());
    assert!(
        force.links.len() > 2 * RUN,
        "{} links: several runs",
        force.links.len()
    );
    let mut points: Vec<Point2D<f32>> = (0..n)
        .map(|_| Point2D::new(next() * 2_000.0, next() * 2_000.0))
        .collect();
    points.truncate(n - 1);
    let velocities: Vec<Vector2D<f32>> = (0..n)
        .map(|_| Vector2D::new(next() - 0.5, next() - 0.5) * 50.0)
        .collect();
    let pushed: Vec<bool> = (0..n).map(|s| s % 7 != 0).collect();
    let bodies = LinkBodies {
        points: &points,
        velocities: &velocities,
        pushed: &pushed,
        dt: 1.0 / 60.0,
    };
    for as_forces in [true, false] {
        let pull = Pull {
            scale: 0.8,
            gain: 0.7,
            as_forces,
        };
        let start = || ForceSums {
            springs: (0..n)
                .map(|s| Vector2D::new(s as f32 * 0.01, -1.0))
                .collect(),
            resistance: (0..n).map(|s| (s % 3) as f32).collect(),
            ..ForceSums::default()
        };
        let mut in_order = start();
        for link in &force.links {
            pull.apply(link, bodies, &mut in_order);
        }
        let mut by_body = start();
        force.apply_by_body(&pull, bodies, &mut by_body);
        let (expected, got) = (bits(&in_order), bits(&by_body));
        let differ = expected.iter().zip(&got).position(|(e, g)| e != g);
        assert_eq!(
            differ,
            None,
            "as_forces {as_forces}: first body whose sums differ (in order {:?}, by body {:?})",
            differ.map(|s| (in_order.springs[s], in_order.resistance[s])),
            differ.map(|s| (by_body.springs[s], by_body.resistance[s])),
        );
        let moved = expected != bits(&start());
        assert!(moved, "as_forces {as_forces}: the springs pulled nothing");
    }
}
