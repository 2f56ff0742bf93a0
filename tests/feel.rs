//! Feel on a settled graph, as a user meets it with the pointer: a throw flies on and is
//! drawn back softly, and an edit or a drag moves its neighbourhood only.
//! `cargo run --release --example feel` prints the same measures as tables.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{
    quality, CanvasEdge, CanvasNode, CanvasSceneInput, Layout, RapierLayoutConfig,
};

/// 30 units a frame at 60 frames per second.
const THROW_SPEED: f32 = 1_800.0;
/// Frames a disturbed layout gets to rest again (d3-force's 300 ticks, twice).
const REST_BUDGET: usize = 600;

/// A settled layout of a shipped graph.
fn settled(name: &str, config: RapierLayoutConfig) -> Host<u32> {
    let mut host = Host::new(load_scene(name), config);
    host.settle(3_000);
    host
}

fn centre(host: &Host<u32>) -> Point2D<f32> {
    let nodes = &host.scene.nodes;
    let sum = nodes
        .iter()
        .fold(Vector2D::zero(), |s, n| s + n.position.to_vector());
    (sum / nodes.len() as f32).to_point()
}

/// The node farthest from the centre among those `keep` accepts.
fn outermost(host: &Host<u32>, keep: impl Fn(u32) -> bool) -> u32 {
    let c = centre(host);
    host.scene
        .nodes
        .iter()
        .filter(|n| keep(n.id))
        .max_by(|a, b| dist(a.position, c).total_cmp(&dist(b.position, c)))
        .map(|n| n.id)
        .expect("a node")
}

fn degree(host: &Host<u32>, id: u32) -> usize {
    let edges = &host.scene.edges;
    edges
        .iter()
        .filter(|e| e.source == id || e.target == id)
        .count()
}

/// Drags `id` by `step` a frame for 10 frames and lets go.
fn drag(host: &mut Host<u32>, id: u32, step: Vector2D<f32>) {
    host.extras.dragging.insert(id);
    for _ in 0..10 {
        let p = host.pos(&id);
        host.set_pos(&id, p + step);
        host.frame(FRAME);
    }
    host.extras.dragging.remove(&id);
}

/// What a throw of the outermost node, 300 units outward over 10 frames, did.
#[derive(Debug)]
struct Throw {
    /// Outward speed over the frame after the release.
    speed_out: f32,
    /// How much further out than the release point it got.
    flew: f32,
    /// Its fastest speed back toward the centre.
    fastest_back: f32,
    /// Frames from the release until the layout rested.
    frames: usize,
    cv_before: f32,
    cv_after: f32,
}

fn throw(name: &str, config: RapierLayoutConfig) -> Throw {
    let mut host = settled(name, config);
    let cv_before = quality::edge_length_cv(&host.scene).unwrap();
    let c = centre(&host);
    let far = outermost(&host, |_| true);
    let out = (host.pos(&far) - c).normalize();
    drag(&mut host, far, out * (THROW_SPEED * FRAME));
    let released = host.pos(&far);
    host.frame(FRAME);
    let speed_out = (host.pos(&far) - released).dot(out) / FRAME;
    let (mut flew, mut fastest_back, mut last) = (0.0_f32, 0.0_f32, host.pos(&far));
    let mut frames = 1;
    while frames < REST_BUDGET && !host.layout.is_converged(&host.state) {
        host.frame(FRAME);
        frames += 1;
        let p = host.pos(&far);
        flew = flew.max((p - released).dot(out));
        fastest_back = fastest_back.max((last - p).dot(out) / FRAME);
        last = p;
    }
    Throw {
        speed_out,
        flew,
        fastest_back,
        frames,
        cv_before,
        cv_after: quality::edge_length_cv(&host.scene).unwrap(),
    }
}

/// The throw targets: out in the frame after the release, at least 50 units further
/// out, never back faster than thrown, at rest within [`REST_BUDGET`] frames with the
/// edge-length spread within 10 % of before.
fn assert_flies_and_comes_back(name: &str, preset: &str, t: &Throw) {
    let context = format!("{name}, {preset}: {t:?}");
    assert!(t.speed_out > 0.5 * THROW_SPEED, "snapped back: {context}");
    assert!(t.flew >= 50.0, "flew too short: {context}");
    assert!(
        t.fastest_back < THROW_SPEED,
        "came back too fast: {context}"
    );
    assert!(t.frames < REST_BUDGET, "not at rest again: {context}");
    let change = (t.cv_after - t.cv_before).abs() / t.cv_before;
    assert!(change <= 0.10, "spread changed by {change}: {context}");
}

#[test]
fn a_throw_flies_on_and_comes_back_softly_in_the_layout_presets() {
    for name in ["les_miserables", "karate"] {
        let t = throw(name, RapierLayoutConfig::force_directed());
        assert_flies_and_comes_back(name, "force_directed", &t);
        let t = throw(name, RapierLayoutConfig::force_directed_fast());
        assert_flies_and_comes_back(name, "force_directed_fast", &t);
        let t = throw(name, RapierLayoutConfig::stress());
        assert_flies_and_comes_back(name, "stress", &t);
    }
}

#[test]
fn the_default_throw_keeps_the_pointer_speed() {
    let t = throw("les_miserables", RapierLayoutConfig::default());
    // Within 3 %: one frame of the default damping and of the springs' pull.
    assert!(
        (t.speed_out - THROW_SPEED).abs() <= 0.03 * THROW_SPEED,
        "{t:?}"
    );
    assert!(t.flew > 200.0, "{t:?}");
}

/// Mean and most moved by the nodes three or more hops from `origin` between `before`
/// and `host`'s scene now.
fn far_side(
    host: &Host<u32>,
    before: &CanvasSceneInput<u32>,
    origin: u32,
) -> quality::Displacement {
    quality::displacement_by_hops(before, &host.scene, &origin, 4)[3]
}

/// The leaf farthest from the centre.
fn outer_leaf(host: &Host<u32>) -> u32 {
    outermost(host, |id| degree(host, id) == 1)
}

/// A new leaf 50 units beyond the outermost leaf of `les_miserables` at rest, and that
/// leaf dragged 100 units outward and let go: the nodes three or more hops away move
/// less than `mean` on average and 40 units at most.
fn only_the_neighbourhood_moves(config: RapierLayoutConfig, mean: f32) {
    let mut host = settled("les_miserables", config.clone());
    let before = host.scene.clone();
    let parent = outer_leaf(&host);
    let out = (host.pos(&parent) - centre(&host)).normalize();
    let at = host.pos(&parent) + out * 50.0;
    host.scene.nodes.push(CanvasNode::new(1_000, at));
    host.scene.edges.push(CanvasEdge::new(parent, 1_000));
    let frames = host.settle(REST_BUDGET);
    let far = far_side(&host, &before, parent);
    assert!(
        far.nodes > 30 && far.mean < mean && far.max < 40.0,
        "an added leaf moved the far side: {far:?} ({frames} frames)"
    );
    // A leaf dragged 100 units outward and let go.
    let mut host = settled("les_miserables", config);
    let before = host.scene.clone();
    let dragged = outer_leaf(&host);
    let out = (host.pos(&dragged) - centre(&host)).normalize();
    drag(&mut host, dragged, out * 10.0);
    let frames = host.settle(REST_BUDGET);
    let far = far_side(&host, &before, dragged);
    assert!(
        far.nodes > 30 && far.mean < mean && far.max < 40.0,
        "a drag moved the far side: {far:?} ({frames} frames)"
    );
}

#[test]
fn an_edit_or_a_drag_moves_only_its_neighbourhood() {
    only_the_neighbourhood_moves(RapierLayoutConfig::force_directed(), 10.0);
    only_the_neighbourhood_moves(RapierLayoutConfig::stress(), 1.0);
}

#[test]
fn a_whole_graph_reheat_is_still_there_for_a_relayout() {
    // Without a reach, the same drag reheats everything and the far side moves.
    let mut config = RapierLayoutConfig::force_directed();
    config.cooling.as_mut().unwrap().reheat_hops = None;
    let mut host = settled("les_miserables", config);
    let before = host.scene.clone();
    let dragged = outer_leaf(&host);
    let out = (host.pos(&dragged) - centre(&host)).normalize();
    drag(&mut host, dragged, out * 10.0);
    host.settle(REST_BUDGET);
    let far = far_side(&host, &before, dragged);
    assert!(far.mean > 10.0, "{far:?}");
}
