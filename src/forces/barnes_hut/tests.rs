//! The tree built in subtrees against the tree built in one go.

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

/// Built in subtrees (side by side under `parallel`), a large tree holds the same
/// cells and gives every point the same force, bit for bit, as built in one go: with
/// clusters, coincident points (cells split down to the deepest level) and a point
/// without a position.
#[test]
fn subtrees_give_the_forces_of_one_tree() {
    let mut next = sequence(11);
    let mut points: Vec<Point2D<f32>> = (0..20_000)
        .map(|i| {
            let spread = if i % 3 == 0 { 5_000.0 } else { 300.0 };
            Point2D::new(next() * spread, next() * spread)
        })
        .collect();
    points[7] = points[8];
    points[9] = Point2D::new(f32::NAN, 0.0);
    let forces = |subtrees_from: usize| {
        let mut tree = ManyBody::default();
        tree.build_in_subtrees_from(&points, subtrees_from);
        let mut out = Vec::new();
        tree.forces(400.0, 0.9, 1.0, |_| true, &mut out);
        let bits: Vec<[u32; 2]> = out.iter().map(|f| [f.x.to_bits(), f.y.to_bits()]).collect();
        (tree.nodes.len(), bits)
    };
    let (cells, one_go) = forces(usize::MAX);
    let (cells_in_subtrees, in_subtrees) = forces(SUBTREES_FROM);
    assert_eq!(cells_in_subtrees, cells, "cells");
    let differ = one_go.iter().zip(&in_subtrees).position(|(a, b)| a != b);
    assert_eq!(differ, None, "first point whose force differs");
    assert!(one_go.iter().any(|f| *f != [0, 0]), "no force at all");
}
