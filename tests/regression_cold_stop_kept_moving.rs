//! Regression: the end of a cooling schedule flagged every body asleep with rapier's
//! `RigidBody::sleep`, which does not take the bodies' island out of the simulation.
//! Whatever still pushed them (springs that outlast repulsion here, stretched springs
//! on `n10000_e25000`) kept moving the flagged bodies, contacts between them were skipped,
//! and the layout reported every node moving on every frame while `is_converged` said
//! it was at rest: 9,936 deltas per frame and overlaps growing from 13,449 to 15,633 in
//! two seconds. The cold stop now halts the bodies and stops stepping the world until
//! a disturbance.

mod common;

use common::*;
use graph_canvas_layout::config::Cooling;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{quality, Layout, RapierLayoutConfig};

#[test]
fn a_cooled_layout_that_was_still_moving_stops_and_stays_stopped() {
    // Springs at heat^0.8 still pull hard at the floor: this 1,000-node graph is moving
    // when the schedule ends (993 bodies awake).
    let config = RapierLayoutConfig {
        cooling: Some(Cooling {
            spring_exponent: 0.8,
            // Springs that outlast repulsion to the end, whatever the graph's stretch.
            stretch_limit: None,
            ..RapierLayoutConfig::force_directed().cooling.unwrap()
        }),
        ..RapierLayoutConfig::force_directed()
    };
    let mut host = Host::new(load_scene("n1000_e2500"), config);
    // The cold stop ends the schedule after 8 s + 0.5 s.
    host.settle(700);
    let at_rest: Vec<Point2D<f32>> = (0..1000).map(|id| host.pos(&id)).collect();
    let overlaps = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
    for frame in 0..120 {
        let deltas = host.frame(FRAME);
        assert!(
            deltas.is_empty() && host.layout.is_converged(&host.state),
            "frame {frame} after rest: {} nodes moved, converged {}",
            deltas.len(),
            host.layout.is_converged(&host.state)
        );
    }
    let moved = (0..1000)
        .map(|id| dist(host.pos(&id), at_rest[id as usize]))
        .fold(0.0_f32, f32::max);
    // Not one unit of rounding: the world is not stepped at all.
    assert!(moved.to_bits() == 0, "a node drifted {moved} after rest");
    assert_eq!(
        quality::overlapping_pairs(&host.scene, 16.0, 0.5),
        overlaps,
        "overlaps changed after rest"
    );
    // A drag still wakes it.
    host.extras.dragging.insert(0);
    let start = host.pos(&0);
    host.set_pos(&0, Point2D::new(start.x + 300.0, start.y));
    host.frame(FRAME);
    host.extras.dragging.clear();
    let deltas = host.frame(FRAME);
    assert!(
        !deltas.is_empty() && !host.layout.is_converged(&host.state),
        "after a drag the layout moves again: {} deltas",
        deltas.len()
    );
}
