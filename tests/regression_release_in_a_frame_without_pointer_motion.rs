//! A release in a frame in which the pointer reported no motion threw nothing. A
//! release threw with the last frame's pointer velocity, and egui (like every toolkit)
//! reports the pointer at the device's rate, not the display's: under egui_graphs with
//! a pointer that moved every other frame, a node dragged 137 units and let go stayed
//! where it was let go. The throw now measures the pointer's last move over the time
//! since its previous report, and keeps it through a pause of up to `throw_window`
//! seconds.

mod common;

use common::*;
use graph_canvas_layout::config::Throw;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

/// A pointer that reports every other frame (a 60 Hz mouse on a 120 Hz display) drags
/// a node 10 units per report, 600 units/s on average. Released in a frame without a
/// report, the throw still carries about that speed.
fn throw_with_pointer_gaps(config: RapierLayoutConfig, release_on_still_frame: bool) -> f32 {
    let dt = 1.0 / 120.0;
    let scene = CanvasSceneInput::new(vec![node(3_u32, 0.0, 0.0)], vec![]);
    let mut host = Host::new(scene, config);
    host.frame(dt);
    host.extras.dragging.insert(3);
    let mut x = 0.0;
    for k in 0..24 {
        if k % 2 == 0 {
            x += 10.0;
            host.set_pos(&3, Point2D::new(x, 0.0));
        }
        host.frame(dt);
    }
    if !release_on_still_frame {
        host.set_pos(&3, Point2D::new(x + 10.0, 0.0));
        host.frame(dt);
    }
    host.extras.dragging.clear();
    host.frame(dt);
    host.layout.world().unwrap().linear_velocity(&3).unwrap().x
}

#[test]
fn a_release_in_a_frame_the_pointer_did_not_report_still_throws() {
    // Each report moves 10 units over the two frames since the last (1/60 s): 600
    // units/s, released a frame after a report or in the frame of one, less one 1/120 s
    // substep of the default damping (1/s, under 1 %).
    for still in [true, false] {
        let v = throw_with_pointer_gaps(RapierLayoutConfig::default(), still);
        assert!(
            (v - 600.0).abs() < 600.0 * 0.03,
            "released {} a report: thrown at {v} units/s, pointer averaged 600",
            if still {
                "a frame after"
            } else {
                "in the frame of"
            }
        );
    }
    // With a window of 0, only a move in the frame just before the release counts: the
    // same release a frame after a report throws nothing.
    let last_frame_only = RapierLayoutConfig {
        throw: Throw {
            window: 0.0,
            ..Default::default()
        },
        ..RapierLayoutConfig::default()
    };
    let v = throw_with_pointer_gaps(last_frame_only, true);
    assert!(
        v.abs() < 1.0,
        "throw_window 0: a release after a frame without motion threw at {v} units/s"
    );
}
