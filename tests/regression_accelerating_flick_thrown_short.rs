//! An accelerating flick was thrown at three quarters of the pointer's speed. A release
//! threw with the pointer's mean velocity over the drag's last `throw_window` seconds,
//! so a drag 0 -> 10 -> 30 over three 1/60 s frames (the pointer reaching 1,200
//! units/s) carried 15 units in the release frame (900 units/s) instead of 20: the
//! window averaged the flick's slow start into its end. The throw now takes the
//! pointer's velocity over its last move.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[test]
fn an_accelerating_flick_carries_the_pointers_last_speed_into_the_release_frame() {
    let scene = CanvasSceneInput::new(vec![node(5_u32, 0.0, 0.0)], vec![]);
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frame(FRAME);
    host.extras.dragging.insert(5);
    for x in [0.0, 10.0, 30.0] {
        host.set_pos(&5, Point2D::new(x, 0.0));
        host.frame(FRAME);
    }
    host.extras.dragging.clear();
    let carried = host.frame(FRAME)[&5].x;
    // 20 units at the pointer's speed, less one frame of the default damping (1/61).
    assert!(
        carried > 19.5 && carried < 20.1,
        "the release frame carried {carried} units; the pointer's last frame moved 20"
    );
}
