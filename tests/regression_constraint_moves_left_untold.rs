//! A hard constraint added to a layout at rest moved nodes the host was never told
//! about. The projection moves bodies after rapier's step, and rapier counts a body it
//! wakes that way as awake only from its next step. A call skipped reading the bodies
//! when rapier counted none awake before its step and none after, so in the first call
//! after the edit the alignment moved two resting nodes 171 units each and the call
//! returned no delta: the host's nodes stayed where they were, 171 units from their
//! bodies (found by the long random sessions in CI). A call now reads the bodies the
//! world logged as changed whenever the projection moved one.

mod common;

use common::session::{run, Action};
use common::{node, Host, FRAME};
use graph_canvas_layout::{Axis, CanvasSceneInput, Constraint, Layout, RapierLayoutConfig};
use Action::*;

/// Three nodes on one point, one dragged in and thrown still, then two aligned.
#[test]
fn the_session_that_parted_host_and_body_keeps_them_together() {
    let actions = [
        AddNode(2, 0.0, 0.0),
        AddDragged(10, 0.0, 0.0),
        AddNode(3, 0.0, 0.0),
        Throw(10, 0.0, 0.0),
        Settle,
        Constrain(Constraint::align(Axis::X, vec![10, 2])),
        Settle,
    ];
    // `run` checks after every call that the host's positions (its own plus every
    // delta) are the bodies'.
    if let Err(broken) = run(&RapierLayoutConfig::default(), &actions) {
        panic!("{broken}");
    }
}

/// The constraint shows in the first call after it is added, in the host's positions.
#[test]
fn an_alignment_added_at_rest_moves_the_hosts_nodes_in_the_next_call() {
    let mut host = Host::new(CanvasSceneInput::default(), RapierLayoutConfig::default());
    host.scene
        .nodes
        .extend([node(2, 0.0, 0.0), node(10, 0.0, 0.0), node(3, 0.0, 0.0)]);
    let rested = (0..600).any(|_| {
        host.frame(FRAME);
        host.layout.is_converged(&host.state)
    });
    assert!(rested, "three disks parted and rested within 10 s");
    let apart = (host.pos(&2).x - host.pos(&10).x).abs();
    assert!(apart > 10.0, "the disks parted sideways too: {apart}");

    host.extras
        .constraints
        .push(Constraint::align(Axis::X, vec![10, 2]));
    let deltas = host.frame(FRAME);
    let apart = (host.pos(&2).x - host.pos(&10).x).abs();
    // A unit: the tolerance `violated_constraints` reports against.
    assert!(
        apart <= 1.0,
        "after the first call the host's nodes 2 and 10 are {apart} apart in x \
         (deltas {deltas:?})"
    );
}
