//! Regression: under `TopologyUpdate::Rebuild`, a topology change while a node's
//! position was NaN rebuilt the world without that node (there was no usable position
//! to build it at), so the node lost its body and its motion for good. A rebuild now
//! builds a frozen node at its old body's position.

mod common;

use common::*;
use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[test]
fn a_rebuild_keeps_a_node_whose_position_is_nan() {
    let config = RapierLayoutConfig {
        topology_update: TopologyUpdate::Rebuild,
        ..Default::default()
    };
    let mut host = Host::new(
        CanvasSceneInput::new(vec![node(6_u32, 0.0, 0.0)], vec![]),
        config,
    );
    host.frame(FRAME);
    host.set_pos(&6, Point2D::new(f32::NAN, 0.0));
    host.scene.nodes.push(node(0, 50.0, 0.0)); // a topology change: rebuild
    host.frame(FRAME);
    let world = host.layout.world().unwrap();
    assert_eq!(host.layout.rebuild_count(), 2);
    assert!(
        world.contains_node(&6),
        "node 6 lost its body in the rebuild: {:?}",
        world.node_ids().collect::<Vec<_>>()
    );
    assert_eq!(
        world.get_position(&6),
        Some(Point2D::new(0.0, 0.0)),
        "rebuilt where its body was"
    );
}
