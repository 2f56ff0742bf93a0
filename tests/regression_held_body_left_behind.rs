//! A dragged node's body stayed a move behind the host: in a call after one shorter
//! than the fixed timestep, with an unusable node just added, rapier's step left the
//! driven kinematic body where it was (its next position set, its position not), and
//! the host found its held node at (3, 307) where it had put it at (6, 305). Found by
//! the `session` fuzz target; the layout now puts a driven body rapier left short where
//! the host holds it.

mod common;

use common::session::{run, run_resuming, Action};
use graph_canvas_layout::{BodyKindPolicy, EdgeJoint, RapierLayoutConfig};
use Action::*;

#[test]
fn a_dragged_node_is_where_the_host_put_it_after_a_short_frame_and_an_unusable_node() {
    let config = RapierLayoutConfig {
        edge_joint: EdgeJoint::Rope {
            max_length: 120.0,
            stiffness: 10_000.0,
        },
        body_kind_policy: BodyKindPolicy::PinnedStatic,
        ..RapierLayoutConfig::force_directed_fast()
    };
    // The fuzz target's input, as it found it.
    let actions = vec![
        AddNode(1, 0.0, 14.0),
        RemoveNode(6),
        Throw(3, 0.0, -2.363345e21),
        RemoveNode(1),
        AddDragged(10, 0.0, 309.0),
        AddEdge(2, 3),
        AddEdge(3, 3),
        AddDragged(11, 0.0, -393.0),
        AddEdge(1, 0),
        AddEdge(10, 11),
        DragEnd(3),
        AddNode(6, 2.3694323e-38, 0.0),
        Poison(1),
        AddEdge(1, 0),
        Weigh(13, 2.9415e-41),
        Throw(0, -256.0, 0.0),
        AddDragged(10, -182.0, -182.0),
        Step(0.0069444445),
        AddNode(0, 2.067167e35, -177.0),
        Step(0.0),
    ];
    // `run` checks after every call that each held body is where the host put it.
    let first = run(&config, &actions).unwrap_or_else(|e| panic!("{e}"));
    let second = run_resuming(&config, &actions).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(first, second, "the resumed run differs");
}
