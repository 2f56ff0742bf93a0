//! Regression: the end of a cooling schedule (every body put to sleep after half a
//! second at the heat floor) was only held off while the heat was above its floor. With
//! `Cooling::reheat` at the floor, a disturbance never lifted it, and every call after
//! the first cold half second stopped the world again: a thrown node froze after one
//! frame. Any disturbance now restarts that half second.

mod common;

use common::*;
use graph_canvas_layout::config::Cooling;
use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::{Layout, PhysicsMaterial, RapierLayoutConfig};

#[test]
fn a_throw_flies_even_when_a_reheat_cannot_lift_the_heat() {
    let config = RapierLayoutConfig {
        cooling: Some(Cooling {
            duration: 1.0,
            reheat: 0.0, // clamped to the floor
            ..Cooling::default()
        }),
        material: PhysicsMaterial {
            linear_damping: 2.0,
            ..PhysicsMaterial::default()
        },
        ..RapierLayoutConfig::force_directed()
    };
    let mut host = Host::new(load_scene("florentine"), config);
    for _ in 0..300 {
        host.frame(FRAME);
    }
    assert!(
        host.layout.is_converged(&host.state),
        "florentine not at rest"
    );
    // Throw node 0 at 1,200 units/s.
    host.extras.dragging.insert(0);
    let start = host.pos(&0);
    for k in 1..=3 {
        host.set_pos(&0, start + Vector2D::new(20.0 * k as f32, 0.0));
        host.frame(FRAME);
    }
    host.extras.dragging.clear();
    let released = host.pos(&0);
    host.frames(30);
    // Half a second at 1,200 units/s under damping 2 covers about 380 units (its
    // springs pull some of it back); frozen after one frame it would cover 20.
    let flown = dist(host.pos(&0), released);
    assert!(flown > 150.0, "the thrown node flew only {flown}");
}
