//! Nodes added to a settled layout appear beside their neighbours: a host that adds
//! leaves at their neighbour's own position (the natural place for a node created from
//! another) sees them seated around it at about an edge length, without flinging it and
//! without moving the far side of the graph.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{quality, CanvasEdge, CanvasNode, RapierLayoutConfig};

/// What adding leaves at one node of a settled graph did, once the layout rested again.
#[derive(Debug)]
pub struct Added {
    /// How far the node the leaves were added to moved.
    pub anchor_moved: f32,
    /// The farthest any new leaf rests from it.
    pub farthest_leaf: f32,
    /// Overlapping disks in the whole graph at rest (by more than 0.5 units).
    pub overlaps: usize,
    /// Nodes three or more hops from the anchor: how far they moved.
    pub far: quality::Displacement,
    pub frames: usize,
}

/// Settles `name` under `config`, adds `count` leaves at the position of the node
/// nearest the layout's centre (an interior node), and settles again.
pub fn add_leaves(name: &str, config: RapierLayoutConfig, count: u32) -> Added {
    let mut host = Host::new(load_scene(name), config);
    host.settle(3_000);
    let before = host.scene.clone();
    let n = before.nodes.len() as f32;
    let centre = before.nodes.iter().fold(Point2D::origin(), |c, node| {
        c + node.position.to_vector() / n
    });
    let anchor = before
        .nodes
        .iter()
        .min_by(|a, b| dist(a.position, centre).total_cmp(&dist(b.position, centre)))
        .map(|node| node.id)
        .unwrap();
    let at = host.pos(&anchor);
    for k in 0..count {
        let id = 1_000_000 + k;
        host.scene.nodes.push(CanvasNode::new(id, at));
        host.scene.edges.push(CanvasEdge::new(anchor, id));
    }
    let frames = host.settle(600);
    if std::env::var("DEBUG_ADDED").is_ok() {
        for n in &before.nodes {
            let moved = dist(host.pos(&n.id), n.position);
            if moved > 10.0 {
                eprintln!(
                    "node {} moved {moved} from {:?}, {} from the anchor",
                    n.id,
                    n.position,
                    dist(n.position, at)
                );
            }
        }
    }
    let farthest_leaf = (0..count)
        .map(|k| dist(host.pos(&(1_000_000 + k)), host.pos(&anchor)))
        .fold(0.0, f32::max);
    Added {
        anchor_moved: dist(host.pos(&anchor), at),
        farthest_leaf,
        overlaps: quality::overlapping_pairs(&host.scene, 16.0, 0.5),
        far: quality::displacement_by_hops(&before, &host.scene, &anchor, 4)[3],
        frames,
    }
}

#[test]
fn twenty_leaves_added_at_an_interior_node_sit_beside_it() {
    let added = add_leaves("1138_bus", RapierLayoutConfig::force_directed(), 20);
    eprintln!("{added:?}");
    assert!(added.anchor_moved < 40.0, "the anchor was flung: {added:?}");
    assert!(
        added.farthest_leaf < 250.0,
        "a new leaf rests too far from its anchor: {added:?}"
    );
    assert_eq!(added.overlaps, 0, "disks overlap at rest: {added:?}");
    assert!(
        added.far.nodes > 1_000 && added.far.mean < 10.0 && added.far.max < 40.0,
        "the far side moved: {added:?}"
    );
}

#[test]
fn twenty_leaves_added_at_an_interior_node_sit_beside_it_under_stress() {
    let added = add_leaves("1138_bus", RapierLayoutConfig::stress(), 20);
    eprintln!("{added:?}");
    assert!(added.anchor_moved < 40.0, "the anchor was flung: {added:?}");
    assert!(
        added.farthest_leaf < 250.0,
        "a new leaf rests too far from its anchor: {added:?}"
    );
    assert_eq!(added.overlaps, 0, "disks overlap at rest: {added:?}");
    assert!(
        added.far.nodes > 1_000 && added.far.mean < 10.0 && added.far.max < 40.0,
        "the far side moved: {added:?}"
    );
}
