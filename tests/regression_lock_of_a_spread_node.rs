//! A node locked on x moved along x in the call that inserted it. A node added at the
//! same point as another is spread a little (the k-th at √k units on the golden angle)
//! so that contacts can part them; the lock then held the spread body's x, 0.74 units
//! off the host's. Found by the session fuzzer: a node added at an occupied point, locked in
//! the same call. The lock now holds the host's coordinate.

mod common;

use common::*;
use graph_canvas_layout::scene::AxisLock;
use graph_canvas_layout::{CanvasSceneInput, NodeForces, RapierLayoutConfig};

#[test]
fn a_node_locked_as_it_is_added_keeps_the_hosts_coordinate() {
    for (axis, config) in [
        (AxisLock::X, RapierLayoutConfig::default()),
        (AxisLock::Y, RapierLayoutConfig::default()),
        (AxisLock::X, RapierLayoutConfig::force_directed()),
        (AxisLock::Y, RapierLayoutConfig::force_directed()),
    ] {
        let scene = CanvasSceneInput::new(vec![node(8_u32, 500.0, 500.0)], vec![]);
        let mut host = Host::new(scene, config);
        host.frame(FRAME);
        // Two nodes added at one point in one call: the second is spread by
        // (-0.74, 0.68) so that their contact can part them.
        host.scene.nodes.push(node(0, 0.0, 0.0));
        host.scene.nodes.push(node(1, 0.0, 0.0));
        host.extras
            .forces
            .insert(1, NodeForces::default().locked(axis));
        for call in 0..60 {
            host.frame(1.0 / 144.0);
            let p = host.pos(&1);
            let along = match axis {
                AxisLock::X => p.x,
                AxisLock::Y => p.y,
            };
            assert_eq!(
                along.to_bits(),
                0.0_f32.to_bits(),
                "call {call}: locked on {axis:?}, the node is at {p:?}"
            );
        }
        // Their contact parted them, the locked node along its free axis.
        let apart = dist(host.pos(&0), host.pos(&1));
        assert!(
            apart > 20.0,
            "locked on {axis:?}: the two nodes are {apart} apart ({:?}, {:?})",
            host.pos(&0),
            host.pos(&1)
        );
    }
}
