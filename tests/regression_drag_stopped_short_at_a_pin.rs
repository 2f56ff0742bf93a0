//! A dragged node stopped short of where the host put it. Rapier flags a fast dynamic
//! body for continuous collision detection and keeps the flag when the body is flipped to
//! kinematic (a drag start). In a later step in which some other body moved fast enough
//! to run the CCD pass, the stale flag swept the dragged body against the fixed
//! colliders (pinned nodes) and clamped its commanded motion at the first one it would
//! touch: in a long random session a dragged node ended a 1/144 s call 0.6 units short
//! of the host's position. A grab of a flying node, a throw of another node and a drag
//! past a pin in the same call reproduce it.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::{Point2D, Vector2D};
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[test]
fn a_grabbed_flying_node_reaches_the_host_position_past_a_pin() {
    let scene = CanvasSceneInput::new(
        vec![node(0, 60.0, 0.0), node(1, 0.0, 0.0), node(2, 300.0, 300.0)],
        vec![],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.extras.pinned.insert(0); // a fixed body under `PinnedStatic`
    host.frames(2);
    // Node 1 is thrown away from the pin at 2,400 units/s (fast: its CCD flag goes up);
    // node 2 is dragged just as fast and held.
    host.extras.dragging.extend([1, 2]);
    for _ in 0..3 {
        for id in [1, 2] {
            let p = host.pos(&id);
            host.set_pos(
                &id,
                p + Vector2D::new(0.0, if id == 1 { -40.0 } else { 40.0 }),
            );
        }
        host.frame(FRAME);
    }
    host.extras.dragging.remove(&1);
    let p = host.pos(&2);
    host.set_pos(&2, p + Vector2D::new(0.0, 40.0));
    host.frame(FRAME);
    let flying = host
        .layout
        .world()
        .and_then(|w| w.linear_velocity(&1))
        .expect("node 1 has a body");
    assert!(flying.y < -2000.0, "node 1 was thrown: {flying:?}");
    // The same call: node 1 is grabbed in flight and dragged past the pin while node 2
    // is thrown (its fast flight runs the CCD pass).
    host.extras.dragging.insert(1);
    host.extras.dragging.remove(&2);
    let target = Point2D::new(80.0, 0.0);
    host.set_pos(&1, target);
    host.frame(1.0 / 144.0);
    let body = host.world_pos(&1);
    assert_eq!(
        body,
        target,
        "the dragged node's body sits where the host put it ({} units short)",
        (body - target).length()
    );
}
