//! A host move to a huge but finite coordinate broke the host's positions. A free node
//! moved to y = −1.7e38 was put there as any host edit is; rapier could not simulate it
//! (its bounds overflow) and put it back where it last was valid, and the delta that
//! reported the way back (1.7e38) rounded the host's position to y = 0, 29 units from
//! the body (found by the session fuzzer). Positions beyond ±`MAX_COORDINATE` are now
//! bad input, like a NaN: the node is held where it was and gets no delta until the
//! host gives it a usable position again.

mod common;

use common::*;
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig, MAX_COORDINATE};

#[test]
fn a_node_moved_out_of_range_is_held_and_comes_back() {
    let scene = CanvasSceneInput::new(
        vec![node(1, 92.0, -29.0), node(2, 300.0, 0.0)],
        vec![edge(1, 2)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frames(2);
    let held = host.world_pos(&1);
    let far = Point2D::new(-144.0_f32, -1.7e38);
    assert!(far.y.abs() > MAX_COORDINATE, "{far:?} is out of range");
    host.set_pos(&1, far);
    for frame in 0..20 {
        let deltas = host.frame(FRAME);
        assert!(
            !deltas.contains_key(&1),
            "frame {frame}: a delta for the out-of-range node"
        );
        assert_eq!(host.world_pos(&1), held, "frame {frame}: its body moved");
    }
    let back = Point2D::new(-144.0, 40.0);
    host.set_pos(&1, back);
    host.frame(FRAME);
    let (p, w) = (host.pos(&1), host.world_pos(&1));
    assert!(
        dist(p, w) < 1e-3,
        "back in range, host and body agree: host {p:?}, body {w:?}"
    );
    assert!(
        dist(w, back) < 50.0,
        "the body went where the host put it: {w:?}"
    );
}
