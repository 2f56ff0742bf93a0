//! The throw at release: a node let go flies on with the pointer's speed over its last
//! move, whether the pointer accelerated, reported only every other frame, or passed
//! `dt = 0`; a pointer that stood still longer than the throw window throws nothing.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

/// Drags a lone node through `xs` (one call each, the first starting the drag), lets it
/// go without motion and returns how fast it left: its release-frame delta over the
/// frame time (1/60 s). Every call passes `dt` as the frame time.
fn release_speed(config: RapierLayoutConfig, xs: &[f32], dt: f32) -> f32 {
    let scene = CanvasSceneInput::new(vec![node(1_u32, xs[0], 0.0)], vec![]);
    let mut host = Host::new(scene, config);
    host.frame(dt);
    host.extras.dragging.insert(1);
    for &x in xs {
        host.set_pos(&1, Point2D::new(x, 0.0));
        host.frame(dt);
    }
    host.extras.dragging.clear();
    let deltas = host.frame(dt);
    deltas.get(&1).map_or(0.0, |d| d.x) / FRAME
}

/// The configurations a host would throw under: the plain canvas and the layout preset.
fn configs() -> [(&'static str, RapierLayoutConfig); 2] {
    [
        ("default", RapierLayoutConfig::default()),
        ("force_directed", RapierLayoutConfig::force_directed()),
    ]
}

/// The release frame's own damping takes at most 1/61 (1/s, the default material's and
/// `force_directed()`'s flight damping, over one 1/60 s substep), so 3 % bounds it with
/// room for the integration's rounding.
const TOLERANCE: f32 = 0.03;

#[test]
fn an_accelerating_flick_throws_at_the_speed_it_reached() {
    for (name, config) in configs() {
        for dt in [FRAME, 0.0] {
            let v = release_speed(config.clone(), &[0.0, 10.0, 30.0], dt);
            assert!(
                (v - 1_200.0).abs() < 1_200.0 * TOLERANCE,
                "{name}, dt {dt}: 0 -> 10 -> 30 thrown at {v} units/s, the pointer's last move was 1,200"
            );
        }
    }
}

#[test]
fn a_pointer_reporting_every_other_frame_throws_at_its_speed() {
    for (name, config) in configs() {
        for dt in [FRAME, 0.0] {
            let v = release_speed(config.clone(), &[0.0, 0.0, 20.0, 20.0, 40.0, 40.0], dt);
            assert!(
                (v - 600.0).abs() < 600.0 * TOLERANCE,
                "{name}, dt {dt}: 20 units every other frame thrown at {v} units/s, the pointer moved at 600"
            );
        }
    }
}

#[test]
fn a_pointer_that_stood_still_longer_than_the_window_throws_nothing() {
    // Four motionless calls after the last move: 4/60 s, longer than the 0.05 s window.
    let xs = [0.0, 10.0, 30.0, 30.0, 30.0, 30.0, 30.0];
    for (name, config) in configs() {
        for dt in [FRAME, 0.0] {
            let v = release_speed(config.clone(), &xs, dt);
            assert!(
                v.abs() < 1.0,
                "{name}, dt {dt}: a pointer still for 4 frames before the release threw at {v} units/s"
            );
        }
    }
    // Within the window (two motionless calls, 2/60 s), the last move still throws.
    let v = release_speed(RapierLayoutConfig::default(), &xs[..5], FRAME);
    assert!(
        (v - 1_200.0).abs() < 1_200.0 * TOLERANCE,
        "a pointer still for 2 frames before the release threw at {v} units/s, not 1,200"
    );
}

#[test]
fn a_flick_from_rest_is_measured_over_its_own_frame() {
    // The pointer holds the node still for half a second, then moves 30 units in one
    // frame and lets go: 1,800 units/s, not 30 units spread over the pause.
    let mut xs = vec![0.0; 30];
    xs.push(30.0);
    let v = release_speed(RapierLayoutConfig::default(), &xs, FRAME);
    assert!(
        (v - 1_800.0).abs() < 1_800.0 * TOLERANCE,
        "a flick after a pause thrown at {v} units/s, the pointer's move was 1,800"
    );
}
