//! A layout on its own thread ([`LayoutWorker`]): what the host sends reaches the
//! layout whole and in order, a drag reads where the host put it in the same frame, a
//! throw flies on, a pin holds, an edit lands, the worker rests and says so, and
//! dropping it stops the thread. The worker follows real time, so these tests wait
//! for outcomes (with a generous bound, 60 s, for a shared machine), never for a time.

use std::time::{Duration, Instant};

use graph_canvas_layout::config::Throw;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::worker::LayoutWorker;
use graph_canvas_layout::{
    CanvasEdge, CanvasNode, CanvasSceneInput, LayoutExtras, RapierLayoutConfig,
};

const BOUND: Duration = Duration::from_secs(60);

/// A ring of `n` nodes, every node at the origin.
fn ring(n: u32) -> CanvasSceneInput<u32> {
    CanvasSceneInput::new(
        (0..n)
            .map(|i| CanvasNode::new(i, Point2D::origin()))
            .collect(),
        (0..n).map(|i| CanvasEdge::new(i, (i + 1) % n)).collect(),
    )
}

/// Reads frames until the worker rests; panics after [`BOUND`].
fn rest(worker: &mut LayoutWorker<u32>) {
    let started = Instant::now();
    while !{
        worker.frame();
        worker.is_converged()
    } {
        assert!(started.elapsed() < BOUND, "not at rest after {BOUND:?}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

fn at(worker: &LayoutWorker<u32>, id: u32) -> Point2D<f32> {
    worker
        .position(&id)
        .unwrap_or_else(|| panic!("node {id} has no position"))
}

#[test]
fn a_graph_sent_to_the_worker_is_laid_out_to_rest() {
    let mut worker = LayoutWorker::spawn(ring(12), RapierLayoutConfig::stress());
    rest(&mut worker);
    let frame = worker.frame();
    assert_eq!(frame.positions.len(), 12);
    assert!(frame
        .positions
        .iter()
        .all(|p| p.x.is_finite() && p.y.is_finite()));
    let opposite = (at(&worker, 6) - at(&worker, 0)).length();
    let next = (at(&worker, 1) - at(&worker, 0)).length();
    assert!(
        opposite > 2.5 * next,
        "a ring laid out: opposite nodes {opposite} apart, neighbours {next}"
    );
    let steps = worker.frame().steps;
    std::thread::sleep(Duration::from_millis(200));
    assert_eq!(
        worker.frame().steps,
        steps,
        "a resting worker sleeps: it stepped without a message"
    );
}

#[test]
fn a_dragged_node_reads_where_the_host_put_it_in_the_same_frame_and_a_throw_flies_on() {
    // A throw window of 0.5 s: a host thread held up between two pointer moves on a busy
    // machine still throws (the default 0.05 s is three frames).
    let config = RapierLayoutConfig {
        throw: Throw {
            window: 0.5,
            ..RapierLayoutConfig::stress().throw
        },
        ..RapierLayoutConfig::stress()
    };
    let mut worker = LayoutWorker::spawn(ring(8), config);
    rest(&mut worker);
    let applied = worker.frame().applied;
    let start = at(&worker, 0);
    let out = (start - (at(&worker, 4) + (start - at(&worker, 4)) / 2.0)).normalize();
    // The pointer moves 30 units a frame outward for 10 frames.
    let mut pointer = start;
    for _ in 0..10 {
        pointer += out * 30.0;
        worker.drag(0, pointer);
        assert_eq!(
            at(&worker, 0),
            pointer,
            "the drag reads where the host put it"
        );
        assert_eq!(worker.frame().positions[0], pointer, "the frame agrees");
        std::thread::sleep(Duration::from_millis(16));
    }
    // The worker has stepped with the last pointer position before the release comes.
    let started = Instant::now();
    while worker.frame().applied < applied + 10 {
        assert!(started.elapsed() < BOUND, "the drags were not applied");
        std::thread::sleep(Duration::from_millis(1));
    }
    worker.release(0);
    let released = pointer;
    let mut farthest: f32 = 0.0;
    let started = Instant::now();
    loop {
        worker.frame();
        if worker.is_converged() {
            break;
        }
        assert!(started.elapsed() < BOUND, "not at rest after the throw");
        farthest = farthest.max((at(&worker, 0) - released).dot(out));
        std::thread::sleep(Duration::from_millis(2));
    }
    assert!(
        farthest > 20.0,
        "a node let go at about 1,800 units/s flew on only {farthest} units past the release"
    );
}

#[test]
fn a_pinned_node_holds_while_the_rest_is_laid_out() {
    let mut scene = ring(10);
    scene.nodes[3].position = Point2D::new(500.0, -200.0);
    let mut extras = LayoutExtras::default();
    extras.pinned.insert(3);
    let mut worker = LayoutWorker::spawn_with(
        scene,
        RapierLayoutConfig::force_directed(),
        extras,
        Duration::from_secs_f64(1.0 / 60.0),
    );
    rest(&mut worker);
    assert_eq!(at(&worker, 3), Point2D::new(500.0, -200.0), "the pin held");
    let far = (0..10)
        .filter(|&i| i != 3)
        .map(|i| (at(&worker, i) - Point2D::new(500.0, -200.0)).length())
        .fold(0.0, f32::max);
    assert!(
        far > 100.0,
        "the others were laid out around it (farthest {far})"
    );
}

#[test]
fn edits_land_in_the_order_they_were_sent_and_none_is_lost() {
    let mut worker = LayoutWorker::spawn(ring(4), RapierLayoutConfig::stress());
    // 200 nodes added, every other one removed again, each kept one joined to node 0,
    // sent without waiting for a step in between.
    for id in 100..300_u32 {
        worker.add_node(CanvasNode::new(id, Point2D::new(id as f32, 0.0)));
        worker.add_edge(CanvasEdge::new(0, id));
        if id % 2 == 1 {
            worker.remove_node(id);
        }
    }
    worker.move_node(2, Point2D::new(-400.0, 0.0));
    rest(&mut worker);
    let frame = worker.frame();
    let expected: Vec<u32> = (0..4).chain((100..300).filter(|id| id % 2 == 0)).collect();
    assert_eq!(
        frame.ids.as_slice(),
        expected.as_slice(),
        "the worker's nodes after the edits ({} of {})",
        frame.ids.len(),
        expected.len()
    );
    assert_eq!(frame.applied, 200 + 200 + 100 + 1, "every message applied");
    for id in (100..300).filter(|id| id % 2 == 0) {
        let d = (at(&worker, id) - at(&worker, 0)).length();
        assert!(
            d < 1_000.0,
            "leaf {id} rests {d} from node 0, its only edge"
        );
    }
}

#[test]
fn a_worker_that_rests_wakes_on_a_message_and_dropping_it_stops_the_thread() {
    let mut worker = LayoutWorker::spawn(ring(6), RapierLayoutConfig::stress());
    rest(&mut worker);
    let steps = worker.frame().steps;
    worker.add_node(CanvasNode::new(6, at(&worker, 0) + Vector2D::new(0.0, 1.0)));
    worker.add_edge(CanvasEdge::new(0, 6));
    assert!(!worker.is_converged(), "a message in flight is not at rest");
    rest(&mut worker);
    assert!(worker.frame().steps > steps, "the edit woke the worker");
    assert!(worker.position(&6).is_some(), "the new node has a position");
    assert!(worker.is_running());
    let started = Instant::now();
    drop(worker);
    assert!(
        started.elapsed() < BOUND,
        "dropping the worker took {:?}",
        started.elapsed()
    );
}

#[test]
fn an_empty_worker_rests_and_lays_out_what_it_is_sent() {
    let mut worker = LayoutWorker::spawn(CanvasSceneInput::default(), RapierLayoutConfig::stress());
    rest(&mut worker);
    assert!(worker.frame().positions.is_empty());
    for i in 0..5_u32 {
        worker.add_node(CanvasNode::new(i, Point2D::origin()));
    }
    for i in 0..4_u32 {
        worker.add_edge(CanvasEdge::new(i, i + 1));
    }
    rest(&mut worker);
    let ends = (at(&worker, 4) - at(&worker, 0)).length();
    let step = (at(&worker, 1) - at(&worker, 0)).length();
    assert!(
        ends > 3.0 * step,
        "a path laid out: its ends {ends} apart, a step {step}"
    );
    for i in 0..5_u32 {
        worker.remove_node(i);
    }
    rest(&mut worker);
    assert!(worker.frame().positions.is_empty(), "every node removed");
}

/// A node reshaped through the worker into a wide box pushes the node it now covers off
/// its outline.
#[test]
fn a_reshape_through_the_worker_reaches_the_layout() {
    let scene = CanvasSceneInput::new(
        vec![
            CanvasNode::new(0_u32, Point2D::new(0.0, 0.0)),
            CanvasNode::new(1, Point2D::new(60.0, 0.0)),
        ],
        vec![],
    );
    let config = RapierLayoutConfig {
        repulsion: None,
        ..RapierLayoutConfig::force_directed()
    };
    let mut worker = LayoutWorker::spawn(scene, config);
    rest(&mut worker);
    let before = (at(&worker, 1) - at(&worker, 0)).length();
    // 200 × 20: its side reaches 100 units out, the disk's centre must be 116 out.
    worker.reshape(
        0,
        0.0,
        graph_canvas_layout::NodeShape::Rect {
            width: 200.0,
            height: 20.0,
            corner_radius: 0.0,
        },
    );
    rest(&mut worker);
    let d = at(&worker, 1) - at(&worker, 0);
    assert!(
        d.x.abs() > 114.0 || d.y.abs() > 25.0,
        "the disk {before} units away, covered by the box, is now at {d:?} from its centre"
    );
}

/// `hold` sends a host's own `LayoutExtras` as it changes: a pin from the next frame on,
/// a drag where the host's scene has the node, and the release when it leaves
/// `dragging`.
#[test]
fn hold_sends_the_hosts_drags_and_pins_as_they_change() {
    let mut scene = ring(10);
    let mut worker = LayoutWorker::spawn(scene.clone(), RapierLayoutConfig::stress());
    rest(&mut worker);
    let mut extras = LayoutExtras::default();
    let pinned_at = at(&worker, 3);
    extras.pinned.insert(3);
    extras.dragging.insert(0);
    let far = at(&worker, 0) + Vector2D::new(400.0, 0.0);
    scene.nodes[0].position = far;
    worker.hold(&scene, &extras);
    assert_eq!(
        at(&worker, 0),
        far,
        "the dragged node reads where the host put it"
    );
    assert!(!worker.is_converged(), "a drag in progress is motion");
    extras.dragging.clear();
    worker.hold(&scene, &extras);
    rest(&mut worker);
    assert_eq!(at(&worker, 3), pinned_at, "the pin held through the drag");
    assert_ne!(at(&worker, 0), far, "released, node 0 was pulled back");
}

/// `hold` sends the host's constraints and clusters when the lists change, and each
/// frame carries the cluster boxes and the constraints left unheld: a host drawing
/// boxes on a worker sees them held at rest, and a list sent again sends nothing.
#[test]
fn hold_sends_clusters_and_constraints_and_frames_carry_their_boxes() {
    use graph_canvas_layout::quality::cluster_violations;
    use graph_canvas_layout::scene::{Axis, Cluster, Constraint};
    // Two rings of 8 joined by one edge, all at the origin.
    let mut scene = ring(8);
    scene
        .nodes
        .extend((8..16).map(|i| CanvasNode::new(i, Point2D::origin())));
    scene
        .edges
        .extend((8..16).map(|i| CanvasEdge::new(i, 8 + (i - 8 + 1) % 8)));
    scene.edges.push(CanvasEdge::new(0, 8));
    let mut worker = LayoutWorker::spawn(scene.clone(), RapierLayoutConfig::stress());
    let mut extras = LayoutExtras {
        clusters: vec![
            Cluster::new((0..8).collect()),
            Cluster::new((8..16).collect()),
        ],
        constraints: vec![Constraint::separation(Axis::X, 3, 12, 100.0)],
        ..LayoutExtras::default()
    };
    worker.hold(&scene, &extras);
    rest(&mut worker);
    let sent = worker.frame().applied;
    worker.hold(&scene, &extras);
    assert_eq!(
        worker.frame().applied,
        sent,
        "an unchanged list is not sent again"
    );
    let frame = worker.frame().clone();
    assert_eq!(frame.cluster_bounds.len(), 2, "one box per cluster");
    assert!(
        frame.violated_constraints.is_empty(),
        "at rest the separation holds: {:?} unheld",
        frame.violated_constraints
    );
    let mut laid = scene.clone();
    for node in &mut laid.nodes {
        node.position = frame.positions[frame.index[&node.id]];
    }
    let v = cluster_violations(&laid, &extras.clusters, &frame.cluster_bounds, 10.0, 1.0);
    assert!(v.is_empty(), "the worker's clusters held at rest: {v:?}");
    assert!(
        frame.violated_clusters.is_empty(),
        "and said so: {:?} unheld",
        frame.violated_clusters
    );
    let x = |id: u32| laid.nodes[id as usize].position.x;
    assert!(
        x(12) >= x(3) + 99.0,
        "separation by 100 along x: 3 at {}, 12 at {}",
        x(3),
        x(12)
    );
    // A cluster dropped: the next frames carry one box.
    extras.clusters.pop();
    worker.hold(&scene, &extras);
    rest(&mut worker);
    assert_eq!(
        worker.frame().cluster_bounds.len(),
        1,
        "the dropped cluster's box is gone"
    );
}
