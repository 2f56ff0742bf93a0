//! Regression: under `TopologyUpdate::Rebuild`, a topology change during a drag built
//! new bodies with no drag history, so releasing on the next frame dropped the node
//! dead instead of throwing it.

mod common;

use common::*;
use graph_canvas_layout::config::TopologyUpdate;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[test]
fn a_rebuild_mid_drag_keeps_the_throw() {
    let config = RapierLayoutConfig {
        topology_update: TopologyUpdate::Rebuild,
        ..Default::default()
    };
    let mut host = Host::new(
        CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0)], vec![]),
        config,
    );
    host.frame(FRAME);
    host.extras.dragging.insert(0);
    host.frame(FRAME);
    host.set_pos(&0, Point2D::new(20.0, 0.0));
    host.frame(FRAME); // 1,200 units/s
    host.scene.nodes.push(node(1, -500.0, -500.0)); // rebuild while dragging
    host.set_pos(&0, Point2D::new(40.0, 0.0));
    host.frame(FRAME);
    assert_eq!(host.layout.rebuild_count(), 2);
    host.extras.dragging.clear();
    host.frame(FRAME);
    let v = host.layout.world().unwrap().linear_velocity(&0).unwrap();
    assert!(
        v.x > 1000.0,
        "released after a rebuild at {v:?}, expected ~1,200 along x"
    );
}
