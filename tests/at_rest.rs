//! A finished picture comes back as it was: `RapierLayout::at_rest` builds its first
//! world cold on the host's saved positions, nothing moves until a disturbance, and a
//! disturbance then moves its neighbourhood only, as in a layout that came to rest.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{quality, CanvasSceneInput, Layout, RapierLayout, RapierLayoutConfig};

/// The positions of `name` laid out to rest under `config`: what a host saved.
fn saved_picture(name: &str, config: RapierLayoutConfig) -> CanvasSceneInput<u32> {
    let mut host = Host::new(load_scene(name), config);
    host.settle(3_000);
    host.scene
}

/// A host that reopens `picture` with an `at_rest` layout.
fn reopened(picture: &CanvasSceneInput<u32>, config: RapierLayoutConfig) -> Host<u32> {
    let mut host = Host::new(picture.clone(), RapierLayoutConfig::default());
    host.layout = RapierLayout::at_rest(config);
    host
}

#[test]
fn a_saved_picture_comes_back_still() {
    for (name, config) in [
        ("force_directed", RapierLayoutConfig::force_directed()),
        (
            "force_directed_fast",
            RapierLayoutConfig::force_directed_fast(),
        ),
        ("default", RapierLayoutConfig::default()),
    ] {
        let picture = saved_picture("1138_bus", RapierLayoutConfig::force_directed());
        let mut host = reopened(&picture, config);
        for frame in 0..300 {
            let deltas = host.frame(FRAME);
            assert!(
                deltas.is_empty(),
                "{name}: {} nodes moved at frame {frame}",
                deltas.len()
            );
            assert!(
                host.layout.is_converged(&host.state),
                "{name}: frame {frame}"
            );
        }
        let moved = farthest_moved(&host.scene, &positions(&picture));
        assert!(moved <= 0.01, "{name}: a node moved {moved} units");
    }
}

#[test]
fn a_drag_on_the_reopened_picture_moves_its_neighbourhood_only() {
    for config in [
        RapierLayoutConfig::force_directed(),
        RapierLayoutConfig::stress(),
    ] {
        drag_on_the_reopened_picture(config);
    }
}

/// `1138_bus` laid out and reopened under `config`, its outermost leaf dragged 100 units
/// and let go: its neighbour follows, the nodes three or more hops away stay.
fn drag_on_the_reopened_picture(config: RapierLayoutConfig) {
    let picture = saved_picture("1138_bus", config.clone());
    let mut host = reopened(&picture, config);
    host.frame(FRAME);
    // The leaf farthest from the centre, dragged 100 units outward over 10 frames.
    let n = picture.nodes.len() as f32;
    let centre = picture.nodes.iter().fold(Point2D::origin(), |c, node| {
        c + node.position.to_vector() / n
    });
    let degree = |id: u32| {
        picture
            .edges
            .iter()
            .filter(|e| e.source == id || e.target == id)
            .count()
    };
    let leaf = picture
        .nodes
        .iter()
        .filter(|node| degree(node.id) == 1)
        .max_by(|a, b| dist(a.position, centre).total_cmp(&dist(b.position, centre)))
        .map(|node| node.id)
        .unwrap();
    let neighbour = picture
        .edges
        .iter()
        .find_map(|e| match (e.source, e.target) {
            (a, b) if a == leaf => Some(b),
            (a, b) if b == leaf => Some(a),
            _ => None,
        })
        .unwrap();
    let out: Vector2D<f32> = (host.pos(&leaf) - centre).normalize() * 10.0;
    host.extras.dragging.insert(leaf);
    for _ in 0..10 {
        let p = host.pos(&leaf);
        host.set_pos(&leaf, p + out);
        host.frame(FRAME);
    }
    host.extras.dragging.clear();
    let frames = host.settle(600);
    let pulled = dist(
        host.pos(&neighbour),
        picture.nodes[neighbour as usize].position,
    );
    assert!(
        pulled > 1.0,
        "the dragged leaf's neighbour moved {pulled} units: the reopened layout is not alive"
    );
    let far = quality::displacement_by_hops(&picture, &host.scene, &leaf, 4)[3];
    assert!(
        far.nodes > 1_000 && far.mean < 1.0,
        "nodes 3+ hops from the drag moved: {far:?} ({frames} frames)"
    );
}

#[test]
fn pins_in_the_first_call_hold_and_a_drag_in_it_moves() {
    let picture = saved_picture("karate", RapierLayoutConfig::force_directed());
    let mut host = reopened(&picture, RapierLayoutConfig::force_directed());
    host.extras.pinned.insert(0);
    let deltas = host.frame(FRAME);
    assert!(
        deltas.is_empty(),
        "a pin in the first call moved {deltas:?}"
    );
    assert!(host.layout.is_converged(&host.state));
    // A reopened layout grabbed at once: the drag is a disturbance like any other.
    let mut host = reopened(&picture, RapierLayoutConfig::force_directed());
    host.extras.dragging.insert(33);
    assert!(
        host.frame(FRAME).is_empty(),
        "held still, the grab moved nothing"
    );
    let p = host.pos(&33);
    host.set_pos(&33, p + Vector2D::new(40.0, 0.0));
    host.frame(FRAME);
    assert_eq!(
        host.world_pos(&33),
        host.pos(&33),
        "the dragged body is at the pointer"
    );
    assert!(
        !host.layout.is_converged(&host.state),
        "a drag wakes the layout"
    );
}
