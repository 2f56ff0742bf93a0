//! Per-node forces (`LayoutExtras::forces`): rings, timelines, groups and axis locks as a
//! user sees them on the shipped graphs, target changes without a rebuild, and bad
//! values named by `try_step` and left out by `step`.

mod common;

use common::*;
use graph_canvas_layout::config::SpringModel;
use graph_canvas_layout::config::Springs;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::quality::hop_distances;
use graph_canvas_layout::scene::AxisLock;
use graph_canvas_layout::{
    CanvasSceneInput, CanvasViewport, Layout, LayoutError, LayoutExtras, NodeForces,
    RapierLayoutConfig, RapierLayoutState,
};

fn host(name: &str) -> Host<u32> {
    Host::new(load_scene(name), RapierLayoutConfig::force_directed())
}

fn ids(host: &Host<u32>) -> Vec<u32> {
    host.scene.nodes.iter().map(|n| n.id).collect()
}

/// Hops from node 0 (karate's instructor), by node: the rings of a radial tree and the
/// dates of a timeline.
fn depth(host: &Host<u32>) -> std::collections::HashMap<u32, usize> {
    hop_distances(&host.scene, &0)
}

/// Karate under `force_directed()` with `forces(id)` on every node, run to rest: the
/// frames it took, and how far `off` says each node ended from what it was asked, as
/// the mean and the worst node.
fn laid_out(
    forces: impl Fn(u32) -> NodeForces,
    off: impl Fn(&Host<u32>, u32) -> f32,
) -> (usize, f32, (u32, f32), Host<u32>) {
    let mut host = host("karate");
    for id in ids(&host) {
        host.extras.forces.insert(id, forces(id));
    }
    let frames = host.settle(2_000);
    let offs: Vec<(u32, f32)> = ids(&host)
        .into_iter()
        .map(|id| (id, off(&host, id)))
        .collect();
    let worst = offs
        .iter()
        .copied()
        .fold((0, 0.0_f32), |a, b| if b.1 > a.1 { b } else { a });
    let mean = offs.iter().map(|o| o.1).sum::<f32>() / offs.len() as f32;
    (frames, mean, worst, host)
}

#[test]
fn a_radial_layout_puts_every_node_on_its_ring() {
    let depth = depth(&host("karate"));
    let ring = |id: u32| 120.0 * depth[&id] as f32;
    let (frames, mean, worst, _) = laid_out(
        |id| NodeForces::default().on_ring(0.0, 0.0, ring(id), 50.0),
        |host, id| (host.pos(&id).to_vector().length() - ring(id)).abs(),
    );
    // Strength 50 is 100 times a leaf's edge spring in force_directed(): the springs and
    // the repulsion still pull a node off by a few units, against rings 120 apart, and
    // where a ring is crowded a disk sits up to its radius (16) off it (measured: mean
    // 3.1, worst 16.9).
    assert!(
        worst.1 < 20.0 && mean < 5.0,
        "after {frames} frames nodes sit {mean:.2} units off their rings on average, \
         node {} {:.2} units",
        worst.0,
        worst.1
    );
}

#[test]
fn a_timeline_keeps_x_at_the_date_and_spreads_y() {
    let depth = depth(&host("karate"));
    let date = |id: u32| 100.0 * depth[&id] as f32;
    let (frames, mean, worst, host) = laid_out(
        |id| NodeForces::default().toward_x(date(id), 50.0),
        |host, id| (host.pos(&id).x - date(id)).abs(),
    );
    let ys: Vec<f32> = ids(&host).iter().map(|id| host.pos(id).y).collect();
    let mean_y = ys.iter().sum::<f32>() / ys.len() as f32;
    let spread_y = (ys.iter().map(|y| (y - mean_y).powi(2)).sum::<f32>() / ys.len() as f32).sqrt();
    // Nodes of one date share a line and their disks must not overlap on it: where two
    // sit side by side each is a radius (16) off the line; the mean is a few units
    // (measured: mean 6.0, worst 16.1).
    assert!(
        worst.1 < 20.0 && mean < 8.0,
        "after {frames} frames nodes sit {mean:.2} units off their dates on average, \
         node {} {:.2} units (dates 100 apart)",
        worst.0,
        worst.1
    );
    assert!(
        spread_y > 60.0,
        "y collapsed: standard deviation {spread_y:.1} units"
    );
}

/// Mean distance of each node from its group's centre, groups by `id % 4` (unrelated to
/// the graph's own communities).
fn group_spread(host: &Host<u32>) -> f32 {
    let mut total = 0.0;
    for g in 0..4 {
        let members: Vec<Point2D<f32>> = ids(host)
            .into_iter()
            .filter(|id| id % 4 == g)
            .map(|id| host.pos(&id))
            .collect();
        let centre = members
            .iter()
            .fold(Point2D::zero(), |s, p| s + p.to_vector())
            / members.len() as f32;
        total += members.iter().map(|p| dist(*p, centre)).sum::<f32>();
    }
    total / host.scene.nodes.len() as f32
}

#[test]
fn a_group_force_draws_each_group_together() {
    let mut free = host("les_miserables");
    free.settle(2_000);
    let mut grouped = host("les_miserables");
    grouped.layout.config.groups.pull = 0.1;
    grouped.layout.config.groups.separation = 10.0;
    for id in ids(&grouped) {
        grouped
            .extras
            .forces
            .insert(id, NodeForces::default().in_group(id % 4));
    }
    let frames = grouped.settle(2_000);
    let (off, on) = (group_spread(&free), group_spread(&grouped));
    assert!(
        on < 0.6 * off,
        "groups spread {on:.1} units from their centres with the force, {off:.1} without \
         ({frames} frames)"
    );
}

#[test]
fn an_axis_lock_keeps_one_coordinate_and_frees_the_other() {
    // A node hanging from two others by springs, locked on x: its springs and the
    // repulsion pull it along both axes, yet x stays to the bit.
    let scene = CanvasSceneInput::new(
        vec![
            node(0_u32, 0.0, 0.0),
            node(1, 150.0, 40.0),
            node(2, 60.0, 200.0),
        ],
        vec![edge(0, 1), edge(1, 2), edge(0, 2)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::force_directed());
    host.extras
        .forces
        .insert(2, NodeForces::default().locked(AxisLock::X));
    host.frames(120);
    let p = host.pos(&2);
    assert_eq!(
        p.x.to_bits(),
        60.0_f32.to_bits(),
        "locked x moved to {} (y went to {})",
        p.x,
        p.y
    );
    assert!(
        (p.y - 200.0).abs() > 20.0,
        "y stayed near 200 ({}) though the springs pull it",
        p.y
    );
    // Unlocked, x is free again.
    host.extras.forces.remove(&2);
    host.set_pos(&0, Point2D::new(-300.0, 0.0));
    host.frames(120);
    assert!(
        (host.pos(&2).x - 60.0).abs() > 5.0,
        "after the unlock x stayed at {}",
        host.pos(&2).x
    );
}

#[test]
fn a_target_change_moves_the_node_smoothly_without_a_rebuild() {
    let mut host = host("karate");
    for id in ids(&host) {
        host.extras
            .forces
            .insert(id, NodeForces::default().toward_y(0.0, 0.3));
    }
    host.settle(2_000);
    let rebuilds = host.layout.rebuild_count();
    // Node 16 (a leaf) moves to y = 200, held there hard.
    host.extras
        .forces
        .insert(16, NodeForces::default().toward_y(200.0, 20.0));
    let mut largest_step = 0.0_f32;
    let mut last = host.pos(&16);
    let mut frames = 0;
    let mut arrived = None;
    for _ in 0..600 {
        host.frame(FRAME);
        frames += 1;
        largest_step = largest_step.max(dist(host.pos(&16), last));
        last = host.pos(&16);
        if arrived.is_none() && (last.y - 200.0).abs() < 10.0 {
            arrived = Some(frames);
        }
        if host.layout.is_converged(&host.state) {
            break;
        }
    }
    assert_eq!(
        host.layout.rebuild_count(),
        rebuilds,
        "a target change rebuilt the world"
    );
    assert!(
        (host.pos(&16).y - 200.0).abs() < 10.0,
        "node 16 ended at y {} after {frames} frames, target 200",
        host.pos(&16).y
    );
    // A glide, not a jump: no frame covers a quarter of the way, and it takes frames
    // to arrive (strength 20 is fast: measured 26.5 units in its fastest frame).
    assert!(
        largest_step < 50.0 && arrived.is_some_and(|f| f >= 5),
        "node 16 moved {largest_step:.1} units in its fastest frame and was within 10 units \
         of the target after {arrived:?} frames"
    );
}

#[test]
fn a_bad_force_is_named_by_try_step_and_left_out_by_step() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 100.0, 0.0)], vec![]);
    let mut extras = LayoutExtras::default();
    extras.forces.insert(
        1,
        NodeForces::default()
            .toward_x(f32::NAN, 0.5)
            .toward_y(80.0, 0.5),
    );
    let mut layout = graph_canvas_layout::RapierLayout::new(RapierLayoutConfig::default());
    let mut state = RapierLayoutState::default();
    let viewport = CanvasViewport::default();
    let mut try_step =
        |extras: &LayoutExtras<u32>| layout.try_step(&scene, &mut state, FRAME, &viewport, extras);
    match try_step(&extras) {
        Err(LayoutError::InvalidNodeForce {
            node: 1,
            part: "x",
            value,
        }) if value.is_nan() => {}
        other => panic!("expected InvalidNodeForce for node 1's x, got {other:?}"),
    }
    extras
        .forces
        .insert(0, NodeForces::default().on_ring(0.0, 0.0, -5.0, 0.5));
    // A target beyond the coordinates a node may have is bad too.
    let mut far = extras.clone();
    far.forces
        .insert(0, NodeForces::default().toward_x(5e9, 1.0));
    assert!(
        matches!(
            try_step(&far),
            Err(LayoutError::InvalidNodeForce {
                node: 0,
                part: "x",
                ..
            })
        ),
        "a target of 5e9 (beyond MAX_COORDINATE) was taken"
    );
    let err = try_step(&extras);
    assert_eq!(state.step_count, 0, "a rejected call changed the state");
    assert!(!layout.has_world(), "a rejected call built a world");
    assert!(
        matches!(
            err,
            Err(LayoutError::InvalidNodeForce {
                node: 0,
                part: "ring radius",
                ..
            })
        ),
        "scene order: node 0's ring radius comes first, got {err:?}"
    );
    // `step` keeps node 1's y pull and drops its x.
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.extras = extras;
    host.frames(300);
    let p = host.pos(&1);
    assert!(
        (p.y - 80.0).abs() < 2.0 && (p.x - 100.0).abs() < 1.0,
        "node 1 at {p:?}: expected y pulled to 80, x left where it was"
    );
    assert!(p.x.is_finite() && host.pos(&0).x.is_finite());
}

#[test]
fn removing_the_last_pull_leaves_no_force_behind() {
    // The default configuration has no force of its own: once the host's last pull is
    // gone nothing resets the bodies' forces but the layout.
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 100.0, 0.0)],
        vec![edge(0, 1)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.extras.pinned.insert(0);
    host.extras
        .forces
        .insert(1, NodeForces::default().toward_y(200.0, 0.5));
    host.frames(120);
    let pulled = host.pos(&1);
    host.extras.forces.clear();
    host.settle(2_000);
    let length = dist(host.pos(&1), host.pos(&0));
    // Back at the spring's rest length (100), hanging from the pin with no gravity, up
    // to where a soft spring falls asleep (about 2 units); the last pull, left on, would
    // have carried it off toward y = 1,000.
    assert!(
        (length - 100.0).abs() < 5.0,
        "pulled to {pulled:?}, then let go: the edge is {length} long, not its rest length 100"
    );
}

#[test]
fn a_lock_dropped_as_another_node_leaves_is_gone() {
    // Removing node 0 moves the last body (node 2) into its slot; node 2's lock, dropped
    // in the same call, must still come off.
    let scene = CanvasSceneInput::new(
        vec![
            node(0_u32, -500.0, 0.0),
            node(1, 0.0, 0.0),
            node(2, 60.0, 80.0),
        ],
        vec![edge(1, 2)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.extras.pinned.insert(1);
    host.extras
        .forces
        .insert(2, NodeForces::default().locked(AxisLock::X));
    host.frames(10);
    host.scene.nodes.remove(0);
    host.extras.forces.clear();
    host.frame(FRAME);
    // The pin moves 200 units to the left: free again, node 2 follows it along x.
    host.set_pos(&1, Point2D::new(-200.0, 0.0));
    host.settle(2_000);
    let p = host.pos(&2);
    assert!(
        p.x < 0.0,
        "node 2 at {p:?} after the pin moved to x = -200: still locked at x = 60"
    );
}

#[test]
fn a_pull_along_x_leaves_y_as_free_as_without_it() {
    // A node hanging below a pin on a spring (applied as forces, as force_directed()
    // does), let go from a stretch along y: with a strong pull holding its x, it comes
    // to rest along y as fast as without one.
    let frames_to_rest = |pull: Option<NodeForces>| {
        let scene = CanvasSceneInput::new(
            vec![node(0_u32, 0.0, 0.0), node(1, 0.0, 300.0)],
            vec![edge(0, 1)],
        );
        let config = RapierLayoutConfig {
            springs: Springs {
                model: SpringModel::Forces,
                ..Default::default()
            },
            ..RapierLayoutConfig::default()
        };
        let mut host = Host::new(scene, config);
        host.extras.pinned.insert(0);
        if let Some(pull) = pull {
            host.extras.forces.insert(1, pull);
        }
        (1..=600)
            .find(|_| {
                host.frame(FRAME);
                (host.pos(&1).y - 100.0).abs() < 5.0
            })
            .unwrap_or(600)
    };
    let free = frames_to_rest(None);
    let held = frames_to_rest(Some(NodeForces::default().toward_x(0.0, 50.0)));
    assert!(
        (held as f32) < 1.25 * free as f32 + 2.0,
        "y reached its rest in {free} frames free, in {held} with x held at strength 50"
    );
}
