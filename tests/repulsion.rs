//! Many-body repulsion: the Barnes–Hut sum matches the exact one, and a force-directed
//! layout spreads a graph that springs alone pack into a blob.

mod common;

use common::*;
use graph_canvas_layout::config::Repulsion;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    quality, CanvasSceneInput, Layout, ManyBody, PhysicsMaterial, RapierLayoutConfig,
};

fn scene_points(name: &str) -> Vec<Point2D<f32>> {
    load_scene(name).nodes.iter().map(|n| n.position).collect()
}

/// The scene's positions and the tree built over them.
fn tree_over(name: &str) -> (Vec<Point2D<f32>>, ManyBody) {
    let points = scene_points(name);
    let mut tree = ManyBody::default();
    tree.build(&points);
    (points, tree)
}

fn brute_force(points: &[Point2D<f32>], i: usize, r: &Repulsion) -> Vector2D<f32> {
    let mut f = Vector2D::zero();
    for (j, q) in points.iter().enumerate() {
        let d = points[i] - *q;
        if j != i && d.square_length() > 0.0 {
            f += d * (r.strength / d.square_length().max(r.min_distance * r.min_distance));
        }
    }
    f
}

#[test]
fn theta_zero_is_the_exact_sum() {
    let (points, mut tree) = tree_over("n200_e500");
    let r = Repulsion::default();
    for i in 0..points.len() {
        let exact = brute_force(&points, i, &r);
        let bh = tree.force_on(i, r.strength, 0.0, r.min_distance);
        // Only the summation order differs: f32 rounding over 199 terms.
        let err = (bh - exact).length() / exact.length();
        assert!(
            err < 1e-4,
            "node {i}: exact {exact:?} vs theta 0 {bh:?} ({err:e})"
        );
    }
}

#[test]
fn default_theta_stays_within_a_few_percent() {
    let (points, mut tree) = tree_over("n1000_e2500");
    let r = Repulsion::default();
    let mut total = 0.0;
    for i in 0..points.len() {
        let exact = brute_force(&points, i, &r);
        total += (tree.force_on(i, r.strength, r.theta, r.min_distance) - exact).length()
            / exact.length();
    }
    let mean = total / points.len() as f32;
    assert!(
        mean < 0.03,
        "mean relative error {mean} at theta {}",
        r.theta
    );
}

#[test]
fn coincident_points_build_and_push_finitely() {
    let points = vec![Point2D::new(5.0, 5.0); 40];
    let mut tree = ManyBody::default();
    tree.build(&points);
    let f = tree.force_on(3, 1000.0, 0.9, 1.0);
    assert_eq!(
        f,
        Vector2D::zero(),
        "coincident points have no direction to push along"
    );
}

#[test]
fn one_pass_never_takes_a_cell_holding_the_point_whole() {
    // A coincident cluster and one lone point: with a huge theta the whole tree would
    // pass as one far body for the lone point, counting its own charge.
    let mut points = vec![Point2D::new(100.0, 0.0); 20];
    points.push(Point2D::new(0.0, 0.0));
    let r = Repulsion {
        theta: 10.0,
        ..Repulsion::default()
    };
    let mut tree = ManyBody::default();
    tree.build(&points);
    let mut all = Vec::new();
    tree.forces(r.strength, r.theta, r.min_distance, |_| true, &mut all);
    for (i, f) in all.iter().enumerate() {
        let exact = brute_force(&points, i, &r);
        // One or two terms each: only f32 rounding differs.
        assert!(
            (*f - exact).length() <= 1e-5 * exact.length(),
            "point {i}: {f:?} against the exact {exact:?}"
        );
    }
}

#[test]
fn one_pass_leaves_non_finite_points_out() {
    let mut points = scene_points("n200_e500");
    points[7] = Point2D::new(f32::NAN, 0.0);
    points[9] = Point2D::new(f32::INFINITY, 3.0);
    let r = Repulsion::default();
    let mut tree = ManyBody::default();
    tree.build(&points);
    let mut all = Vec::new();
    tree.forces(r.strength, 0.0, r.min_distance, |_| true, &mut all);
    assert_eq!((all[7], all[9]), (Vector2D::zero(), Vector2D::zero()));
    let finite: Vec<Point2D<f32>> = points
        .iter()
        .copied()
        .filter(|p| p.x.is_finite() && p.y.is_finite())
        .collect();
    let mut k = 0;
    for (i, f) in all.iter().enumerate() {
        if i == 7 || i == 9 {
            continue;
        }
        let exact = brute_force(&finite, k, &r);
        k += 1;
        assert!(
            (*f - exact).length() < 1e-4 * exact.length(),
            "point {i}: {f:?} against the exact {exact:?} without the non-finite points"
        );
    }
}

#[test]
fn repulsion_spreads_what_springs_alone_pack() {
    let run = |config: RapierLayoutConfig| {
        let mut host = Host::new(load_scene("les_miserables"), config);
        for _ in 0..3000 {
            host.frame(FRAME);
            if host.layout.is_converged(&host.state) {
                break;
            }
        }
        host.scene
    };
    let plain = run(RapierLayoutConfig::default());
    let spread = run(RapierLayoutConfig::force_directed());
    let overlaps = quality::overlapping_pairs(&spread, 16.0, 0.5);
    assert_eq!(
        overlaps, 0,
        "force-directed les_miserables has {overlaps} overlapping pairs"
    );
    let crossings = (
        quality::edge_crossings(&plain),
        quality::edge_crossings(&spread),
    );
    assert!(
        crossings.1 * 2 < crossings.0,
        "repulsion did not halve the crossings: {crossings:?}"
    );
}

#[test]
fn pinned_nodes_push_but_are_not_pushed() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 60.0, 0.0)], vec![]);
    // The repulsion alone, run to its equilibrium: no cooling schedule to freeze the
    // approach, and light damping so the node does not creep asleep far short of it.
    let config = RapierLayoutConfig {
        cooling: None,
        material: PhysicsMaterial {
            linear_damping: 2.0,
            ..PhysicsMaterial::default()
        },
        ..RapierLayoutConfig::force_directed()
    };
    let mut host = Host::new(scene, config);
    host.extras.pinned.insert(0);
    host.frames(900);
    assert_eq!(
        host.pos(&0),
        Point2D::new(0.0, 0.0),
        "the pinned node moved"
    );
    // Equilibrium of the push strength / x against the centre pull c x: x = √(strength / c).
    // The approach is overdamped and the body sleeps once it creeps slower than the rest
    // speed (5 units/s), a little short of it.
    let r = Repulsion::default();
    let expected = (r.strength / r.center_pull).sqrt();
    let x = host.pos(&1).x;
    assert!(
        (0.75 * expected..=1.02 * expected).contains(&x),
        "free node settled at x = {x}, expected a little short of {expected}"
    );
}

#[test]
fn one_pass_over_all_points_is_at_least_as_fine_as_a_query_per_point() {
    let (points, mut tree) = tree_over("n1000_e2500");
    let r = Repulsion::default();
    let exact: Vec<Vector2D<f32>> = (0..points.len())
        .map(|i| brute_force(&points, i, &r))
        .collect();
    let relative = |f: Vector2D<f32>, i: usize| (f - exact[i]).length() / exact[i].length();

    // Theta 0 in one pass: the exact sum up to f32 rounding, point by point.
    let mut all = Vec::new();
    tree.forces(r.strength, 0.0, r.min_distance, |_| true, &mut all);
    for (i, f) in all.iter().enumerate() {
        assert!(
            relative(*f, i) < 1e-4,
            "point {i}: {f:?} vs exact {:?}",
            exact[i]
        );
    }

    // Every third point wanted: the others stay zero, and the pass opens at least the
    // cells each query opens, so its mean error is no larger.
    tree.forces(
        r.strength,
        r.theta,
        r.min_distance,
        |i| i % 3 == 0,
        &mut all,
    );
    assert_eq!(all.len(), points.len());
    let (mut pass, mut query, mut wanted) = (0.0, 0.0, 0);
    for (i, f) in all.iter().enumerate() {
        if i % 3 != 0 {
            assert_eq!(*f, Vector2D::zero(), "point {i} was not wanted");
            continue;
        }
        pass += relative(*f, i);
        query += relative(tree.force_on(i, r.strength, r.theta, r.min_distance), i);
        wanted += 1;
    }
    let (pass, query) = (pass / wanted as f32, query / wanted as f32);
    assert!(
        pass <= query,
        "mean relative error of the pass {pass:e} above the per-point queries' {query:e}"
    );
}

#[test]
fn a_point_gets_the_same_bits_whichever_points_share_its_pass() {
    // A group's members are summed two at a time (the last one of an odd count beside a
    // copy of itself): which points are wanted changes who is paired with whom, and
    // must not change a bit of anyone's force.
    let (_, mut tree) = tree_over("n1000_e2500");
    let r = Repulsion::default();
    let mut all = Vec::new();
    tree.forces(r.strength, r.theta, r.min_distance, |_| true, &mut all);
    type Wanted = fn(usize) -> bool;
    let wanted_sets: [(&str, Wanted); 4] = [
        ("every third", |i| i % 3 == 0),
        ("odd", |i| i % 2 == 1),
        ("the first 501", |i| i <= 500),
        ("point 7 alone", |i| i == 7),
    ];
    let mut some = Vec::new();
    for (label, wanted) in wanted_sets {
        tree.forces(r.strength, r.theta, r.min_distance, wanted, &mut some);
        for (i, (f, g)) in some.iter().zip(&all).enumerate() {
            if wanted(i) {
                assert!(
                    f.x.to_bits() == g.x.to_bits() && f.y.to_bits() == g.y.to_bits(),
                    "{label}: point {i} got {f:?}, {g:?} with every point wanted"
                );
            }
        }
    }
}
