//! Regression: a host move smaller than a fixed 0.01-unit floor was taken for float
//! noise, so the next delta put the node back (an undo of a tiny nudge was undone), and
//! a `delta_epsilon` above that floor made slow nodes look host-moved every call and
//! froze them. Host moves are now measured against the position the host was told.

mod common;

use common::*;
use graph_canvas_layout::config::RestDetection;
use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::{CanvasSceneInput, Layout, RapierLayoutConfig};

#[test]
fn a_tiny_host_nudge_is_kept() {
    let scene = CanvasSceneInput::new(vec![node(0_u32, 0.0, 0.0), node(1, 300.0, 0.0)], vec![]);
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frames(3);
    let nudged = host.pos(&1) + Vector2D::new(0.0, 0.005);
    host.set_pos(&1, nudged);
    host.frames(3);
    assert_eq!(host.pos(&1), nudged, "the 0.005 nudge was undone");
    assert_eq!(host.world_pos(&1), nudged);
}

#[test]
fn a_large_report_threshold_does_not_freeze_slow_nodes() {
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 130.0, 0.0)],
        vec![edge(0, 1)],
    );
    let config = RapierLayoutConfig {
        rest: RestDetection {
            delta_epsilon: 0.5,
            ..Default::default()
        },
        ..Default::default()
    };
    let mut host = Host::new(scene, config);
    for _ in 0..3000 {
        host.frame(FRAME);
        if host.layout.is_converged(&host.state) {
            break;
        }
    }
    assert!(host.layout.is_converged(&host.state), "never came to rest");
    let gap = dist(host.pos(&0), host.pos(&1));
    assert!(
        (gap - 100.0).abs() < 2.0,
        "the spring settled the host's pair at {gap}, rest 100"
    );
}
