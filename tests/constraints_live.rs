//! Hard constraints while the user works: a drag carries everything it pushes along
//! within the drag's first frames, a dependency graph rests with every edge down and
//! no disks overlapping, an edited constraint wakes only its neighbourhood, fewer
//! projection passes still rest with every constraint held, a restored layout stays
//! at rest, and a node locked on an axis does not give way along it.

mod common;

use common::{load_scene, Host, FRAME};
use graph_canvas_layout::config::Solver;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::scene::AxisLock;
// The contract's names, from the root.
use graph_canvas_layout::{
    quality, Axis, CanvasEdge, CanvasNode, CanvasSceneInput, Constraint, Flow, Layout, NodeForces,
    RapierLayout, RapierLayoutConfig,
};

const GAP: f32 = 60.0;

/// `(least target.y - source.y, the edge)` over the scene's edges.
fn least_drop(scene: &CanvasSceneInput<u32>) -> (f32, usize) {
    let y = |id: u32| scene.nodes.iter().find(|n| n.id == id).unwrap().position.y;
    scene
        .edges
        .iter()
        .enumerate()
        .map(|(i, e)| (y(e.target) - y(e.source), i))
        .fold((f32::INFINITY, 0), |a, b| if b.0 < a.0 { b } else { a })
}

/// A path `0 -> 1 -> ... -> n - 1` laid along x, every edge level (short of the gap).
fn path(n: u32) -> CanvasSceneInput<u32> {
    CanvasSceneInput::new(
        (0..n)
            .map(|i| CanvasNode::new(i, Point2D::new(i as f32 * 40.0, 0.0)))
            .collect(),
        (1..n).map(|i| CanvasEdge::new(i - 1, i)).collect(),
    )
}

/// This workspace's dependency graph under `stress()` with `Flow::down(GAP)`.
fn dependency_graph() -> Host<u32> {
    Host::new(
        load_scene("crate_deps"),
        RapierLayoutConfig::stress().with_flow(Flow::down(GAP)),
    )
}

#[test]
fn dragging_the_bottom_of_a_chain_up_pushes_the_whole_chain_up_within_the_frame() {
    // 40 nodes under Flow::down: node 39 is 39 gaps below node 0. Dragging it up 30 units
    // a frame must lift every node above it, each frame, however long the chain.
    let mut host = Host::new(
        path(40),
        RapierLayoutConfig::stress().with_flow(Flow::down(GAP)),
    );
    host.settle(900);
    host.extras.dragging = [39_u32].into_iter().collect();
    let start = host.pos(&0).y;
    // The room the chain has to close before the top must give way.
    let slack = host.pos(&39).y - start - 39.0 * GAP;
    for frame in 1..=30 {
        let up = host.pos(&39) - Vector2D::new(0.0, 30.0);
        host.set_pos(&39, up);
        host.frame(FRAME);
        let (drop, edge) = least_drop(&host.scene);
        assert!(
            drop >= GAP - 1.0,
            "frame {frame}: edge {edge} drops {drop}, short of the gap {GAP} by more than 1"
        );
    }
    let lifted = start - host.pos(&0).y;
    assert!(
        lifted >= 900.0 - slack - 1.0,
        "the top of the chain was lifted {lifted} units by a 900-unit drag (slack {slack})"
    );
}

#[test]
fn a_dependency_graph_keeps_every_edge_down_while_its_busiest_node_is_dragged() {
    let mut host = dependency_graph();
    host.settle(900);
    let mut degree = vec![0; host.scene.nodes.len()];
    for e in &host.scene.edges {
        degree[e.source as usize] += 1;
        degree[e.target as usize] += 1;
    }
    let busiest = (0..degree.len() as u32)
        .max_by_key(|&i| degree[i as usize])
        .unwrap();
    let centre = host.pos(&busiest);
    host.extras.dragging = [busiest].into_iter().collect();
    for frame in 1..=60 {
        let angle = (frame as f32 * 3.0).to_radians();
        let at = centre + Vector2D::new(angle.cos() - 1.0, angle.sin()) * 200.0;
        host.set_pos(&busiest, at);
        host.frame(FRAME);
        if frame > 10 {
            let (drop, edge) = least_drop(&host.scene);
            assert!(
                drop >= GAP - 1.0,
                "frame {frame} of dragging node {busiest}: edge {edge} drops only {drop}"
            );
        }
    }
}

#[test]
fn a_dependency_graph_rests_with_every_edge_down_and_no_disks_overlapping() {
    let mut host = dependency_graph();
    let frames = host.settle(900);
    let (drop, edge) = least_drop(&host.scene);
    assert!(
        drop >= GAP - 1.0,
        "edge {edge} drops only {drop} at rest after {frames} frames"
    );
    // Half a unit: the disk separation's own resting tolerance.
    let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
    assert_eq!(
        overlaps, 0,
        "overlapping disks at rest after {frames} frames"
    );
    assert!(
        frames <= 300,
        "at rest only after {frames} frames (target: 300)"
    );
}

#[test]
fn one_projection_pass_a_substep_still_rests_with_every_edge_down() {
    let config = RapierLayoutConfig::stress().with_flow(Flow::down(GAP));
    let config = RapierLayoutConfig {
        solver: Solver {
            constraint_passes: 1,
            ..config.solver
        },
        ..config
    };
    let mut host = Host::new(load_scene("tree_1023"), config);
    let frames = host.settle(900);
    let (drop, edge) = least_drop(&host.scene);
    assert!(
        drop >= GAP - 1.0,
        "one pass: edge {edge} drops only {drop} at rest after {frames} frames"
    );
}

#[test]
fn a_constraint_added_at_rest_wakes_only_its_neighbourhood() {
    // A path of 120 at rest; a separation between its first two nodes. The nodes 20 hops
    // and more away must not move at all; the separation must hold.
    let mut host = Host::new(path(120), RapierLayoutConfig::stress());
    host.settle(2_000);
    let before: Vec<Point2D<f32>> = (0..120).map(|id| host.pos(&id)).collect();
    let (a, b) = (before[0], before[1]);
    // Node 1 at least 50 units farther from node 0 along x than it now is.
    let gap = (b.x - a.x).abs() + 50.0;
    let (left, right) = if a.x <= b.x { (0, 1) } else { (1, 0) };
    host.extras.constraints = vec![Constraint::separation(Axis::X, left, right, gap)];
    let frames = host.settle(900);
    let moved: Vec<u32> = (20..120)
        .filter(|&id| host.pos(&id) != before[id as usize])
        .collect();
    assert!(
        moved.is_empty(),
        "{} nodes 20 hops or more from the edit moved (the first: {:?}, by {})",
        moved.len(),
        moved.first(),
        moved
            .first()
            .map_or(0.0, |&id| (host.pos(&id) - before[id as usize]).length())
    );
    let held = host.pos(&right).x - host.pos(&left).x;
    assert!(
        held >= gap - 1.0,
        "the new separation rests at {held} of {gap} after {frames} frames"
    );
    assert!(
        host.layout.violated_constraints().is_empty(),
        "{:?}",
        host.layout.violated_constraints()
    );
}

#[test]
fn a_layout_restored_at_rest_under_a_flow_stays_at_rest() {
    let mut host = dependency_graph();
    host.extras.constraints = vec![Constraint::align(Axis::Y, vec![3, 4, 5])];
    host.settle(900);
    let mut restored = RapierLayout::<u32>::default();
    restored
        .restore(host.layout.snapshot())
        .expect("a snapshot of a resting layout restores");
    host.layout = restored;
    let deltas = host.frame(FRAME);
    assert!(
        deltas.is_empty(),
        "the restored layout moved {} nodes in its first call",
        deltas.len()
    );
    assert!(host.layout.is_converged(&host.state));
}

#[test]
fn a_node_locked_on_the_flow_axis_makes_its_partners_move() {
    // 0 -> 1 -> 2 at rest on one level, node 1's y locked; then a flow is turned on.
    // From the first frame, the other two give way along y and node 1 keeps its y. One
    // pass a substep: the sweep alone must know the lock (more passes hide it).
    let config = RapierLayoutConfig::stress();
    let solver = Solver {
        constraint_passes: 1,
        ..config.solver
    };
    let mut host = Host::new(path(3), RapierLayoutConfig { solver, ..config });
    host.extras
        .forces
        .insert(1, NodeForces::default().locked(AxisLock::Y));
    host.settle(900);
    let locked = host.pos(&1).y;
    host.layout.config = host.layout.config.clone().with_flow(Flow::down(GAP));
    for frame in 1..=200 {
        host.frame(FRAME);
        let (drop, edge) = least_drop(&host.scene);
        assert!(
            drop >= GAP - 1.0,
            "frame {frame}: edge {edge} drops only {drop}"
        );
        let y = host.pos(&1).y;
        assert!(
            (y - locked).abs() <= 0.01,
            "frame {frame}: the locked node moved along its locked axis from {locked} to {y}"
        );
    }
}

#[test]
fn separations_that_conflict_stay_finite_and_are_reported() {
    // 0 at least 50 left of 1, and 1 at least 50 left of 0: both cannot hold.
    let mut host = Host::new(path(6), RapierLayoutConfig::stress());
    host.extras.constraints = vec![
        Constraint::separation(Axis::X, 0, 1, 50.0),
        Constraint::separation(Axis::X, 1, 0, 50.0),
        Constraint::align(Axis::Y, vec![2, 3]),
    ];
    let frames = host.settle(900);
    for n in &host.scene.nodes {
        assert!(
            n.position.is_finite(),
            "node {} at {:?} after {frames} frames",
            n.id,
            n.position
        );
    }
    let violated = host.layout.violated_constraints();
    assert!(
        !violated.is_empty() && violated.iter().all(|&c| c < 2),
        "the conflicting pair is reported, the row is not: {violated:?}"
    );
    let spread = (host.pos(&2).y - host.pos(&3).y).abs();
    assert!(spread <= 2.0, "the row beside the conflict holds: {spread}");
}

#[test]
fn a_node_added_under_a_flow_rests_with_every_edge_down() {
    let mut host = dependency_graph();
    host.settle(900);
    // A new crate that depends on the first two, placed above nothing in particular.
    let id = host.scene.nodes.len() as u32;
    let at = host.pos(&0);
    host.scene.nodes.push(CanvasNode::new(id, at));
    host.scene.edges.push(CanvasEdge::new(id, 0));
    host.scene.edges.push(CanvasEdge::new(id, 1));
    let frames = host.settle(900);
    let (drop, edge) = least_drop(&host.scene);
    assert!(
        drop >= GAP - 1.0,
        "after the edit, edge {edge} drops only {drop} at rest ({frames} frames)"
    );
}
