//! Snapshots and hard constraints, two ways a save failed its promise. A flow with a
//! NaN gap wrote `null` into the snapshot's JSON, which then would not read back
//! ("invalid type: null, expected f32"): the host lost its save. And a layout restored
//! from a snapshot took its first call's constraints as new, while the saved layout
//! compared them with its last call's: after a node removal renumbered the bodies, one
//! reheated the constrained nodes and the other did not, and their deltas parted. Found
//! by the random sessions once they drew flows and constraints; a flow keeps its gap as
//! it reads it, and a snapshot keeps the constraints the last call held.

mod common;

use common::session::{resumed, run, run_resuming, Action};
use graph_canvas_layout::{Axis, Constraint, Flow, RapierLayout, RapierLayoutConfig};
use Action::*;

#[test]
fn a_flow_with_a_nan_gap_saves_and_reads_back() {
    let config = RapierLayoutConfig::stress().with_flow(Flow::left(f32::NAN));
    let layout = RapierLayout::<u32>::new(config);
    let restored = resumed(&layout).expect("the snapshot reads back");
    let flow = restored.config.flow.expect("the flow is kept");
    assert_eq!(
        (flow.axis(), flow.gap()),
        (Axis::X, 0.0),
        "a NaN gap reads as 0, before the save and after"
    );
}

#[test]
fn a_layout_restored_under_constraints_goes_on_as_the_one_saved_after_a_removal() {
    let mut actions: Vec<Action> = (0..7).map(|i| AddNode(i, 60.0 * i as f32, 0.0)).collect();
    actions.extend((0..6).map(|i| AddEdge(i, i + 1)));
    actions.extend([
        Constrain(Constraint::separation(Axis::X, 5, 6, 90.0)),
        Constrain(Constraint::align(Axis::Y, vec![1, 2, 6])),
        Settle,
        Resume,
        // Node 0's slot goes to the last node: the constraints' bodies renumber.
        RemoveNode(0),
        Settle,
    ]);
    for config in [
        RapierLayoutConfig::stress(),
        RapierLayoutConfig::stress().with_flow(Flow::down(60.0)),
    ] {
        let saved = run(&config, &actions).expect("the session keeps the invariants");
        let restored = run_resuming(&config, &actions).expect("the session keeps the invariants");
        let first = saved.iter().zip(&restored).position(|(a, b)| a != b);
        assert_eq!(
            first, None,
            "under {:?}, the restored layout's deltas part from the saved one's at call {first:?} of {}",
            config.flow,
            saved.len()
        );
    }
}
