//! Regression: unpinning a node whose values were unusable (here a box of negative
//! height) went unnoticed. The pin was counted in the world's topology when it came, but
//! the layout's record of the node's pin was only written for usable nodes, so the
//! unpin looked like no change and the world kept the topology with the pin. A layout
//! restored from a save at that point computed the topology afresh, found the pin gone,
//! patched its world and reheated, and from then on moved the nodes differently from
//! the layout that carried on. A pin or unpin of an unusable node is now recorded like
//! any other: both layouts patch on the unpin and move alike.

mod common;

use common::session::{resumed, run, run_resuming, Action};
use common::*;
use graph_canvas_layout::{CanvasSceneInput, CanvasViewport, Layout, RapierLayoutConfig};

/// A resting layout with an unusable, pinned node 7 and a dragged node 2 tied to node 6,
/// shaken by a long frame; then node 7 is unpinned.
fn session() -> Vec<Action> {
    vec![
        Action::AddNode(7, 0.0, 0.0),
        Action::Step(FRAME),
        Action::Reshape(7, 20.0, -1.0, 0.0),
        Action::AddDragged(2, 0.0, 0.0),
        Action::Pin(7),
        Action::AddNode(6, 0.0, 0.0),
        Action::Settle,
        Action::AddEdge(2, 6),
        Action::Step(5.0),
        Action::Unpin(7),
        Action::Resume,
        Action::Step(FRAME),
        Action::Step(FRAME),
    ]
}

#[test]
fn a_save_after_unpinning_an_unusable_node_resumes_bit_for_bit() {
    let config = RapierLayoutConfig::force_directed();
    let carried_on = run(&config, &session()).expect("the session keeps its invariants");
    let restored = run_resuming(&config, &session()).expect("the session keeps its invariants");
    assert_eq!(carried_on.len(), restored.len());
    let last = carried_on.len();
    for call in last - 2..last {
        assert_eq!(
            carried_on[call], restored[call],
            "call {call} after the restore: deltas (id, x bits, y bits) of the layout that \
             carried on vs the restored one"
        );
    }
}

#[test]
fn unpinning_an_unusable_node_patches_the_world() {
    let mut host = Host::new(
        CanvasSceneInput::new(vec![node(7_u32, 0.0, 0.0), node(6, 200.0, 0.0)], vec![]),
        RapierLayoutConfig::force_directed(),
    );
    host.frame(FRAME);
    host.scene.nodes[0] = host.scene.nodes[0]
        .clone()
        .with_rounded_rect(20.0, -1.0, 0.0);
    host.extras.pinned.insert(7);
    host.frame(FRAME);
    let pinned = (
        host.layout.patch_count(),
        host.layout.current_topology_hash(),
    );
    host.extras.pinned.remove(&7);
    host.frame(FRAME);
    let unpinned = (
        host.layout.patch_count(),
        host.layout.current_topology_hash(),
    );
    assert_eq!(
        unpinned.0,
        pinned.0 + 1,
        "patches after the pin {} and after the unpin {}: the unpin was not seen",
        pinned.0,
        unpinned.0
    );
    // The restored layout agrees with the topology the first one now models.
    let mut restored = resumed(&host.layout).expect("a snapshot restores");
    let mut state = host.state.clone();
    restored.step(
        &host.scene,
        &mut state,
        FRAME,
        &CanvasViewport::default(),
        &host.extras,
    );
    assert_eq!(
        restored.current_topology_hash(),
        unpinned.1,
        "the restored layout models another topology than the one that carried on"
    );
}
