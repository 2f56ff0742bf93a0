//! A node dragged across the whole canvas in one call stalled the layout. The disk
//! separation searches the grid cells along the path of a body that moves further than a
//! cell in a substep, row by row; a drag from x = -9e8 to 9e8 (inside ±MAX_COORDINATE)
//! is millions of rows per substep, and a session of such drags ran for minutes (the
//! fuzzer's smoke run in CI hung on one). A path longer than the grid has cells now
//! checks every body once instead.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[test]
fn a_drag_across_the_whole_canvas_in_one_call_is_cheap_and_exact() {
    let scene = CanvasSceneInput::new(
        vec![
            node(0_u32, 0.0, 0.0),
            node(1, 40.0, 0.0),
            node(2, 0.0, 40.0),
        ],
        vec![edge(0, 1), edge(1, 2)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::force_directed());
    host.frames(5);
    host.extras.dragging.insert(0);
    for (call, x) in [-9.0e8_f32, 9.0e8, -9.0e8, 9.0e8].into_iter().enumerate() {
        let to = Point2D::new(x, -x);
        host.set_pos(&0, to);
        host.frame(0.25);
        assert_eq!(
            host.world_pos(&0),
            to,
            "call {call}: the dragged node is not where the host put it"
        );
        for id in [1, 2] {
            let p = host.pos(&id);
            assert!(
                p.x.is_finite() && p.y.is_finite(),
                "call {call}: node {id} at {p:?}"
            );
        }
    }
}
