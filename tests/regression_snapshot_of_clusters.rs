//! A snapshot that forgot the clusters. A layout restored from a snapshot started with
//! no cluster list, so the first call after the restore took the host's list as the
//! first ever, no edit, while the saved layout compared it with its last call's: when
//! the host changed a cluster in that call, the saved layout reheated the members and
//! the restored one, at rest, did not move, and the grown box kept its neighbours
//! inside. A snapshot now keeps the list the last call held, and the members a change
//! reheats are found in the current world for both.

mod common;

use common::session::{run, run_resuming, Action};
use graph_canvas_layout::scene::Cluster;
use graph_canvas_layout::RapierLayoutConfig;
use Action::*;

#[test]
fn a_layout_restored_with_clusters_takes_a_change_as_the_saved_one_does() {
    let mut actions: Vec<Action> = (0..8)
        .map(|i| AddNode(i, 50.0 * (i % 4) as f32, 50.0 * (i / 4) as f32))
        .collect();
    actions.extend((0..7).map(|i| AddEdge(i, i + 1)));
    actions.extend([
        Group(Cluster::new(vec![0, 1, 2])),
        Group(Cluster::new(vec![5, 6, 7])),
        Settle,
        Resume,
        // The first call after the restore: a cluster's box grows into the other's.
        Ungroup,
        Group(Cluster::new(vec![0, 1, 2]).with_padding(80.0)),
        Group(Cluster::new(vec![5, 6, 7])),
        Settle,
    ]);
    let config = RapierLayoutConfig::stress();
    let saved = run(&config, &actions).expect("the session keeps the invariants");
    let restored = run_resuming(&config, &actions).expect("the session keeps the invariants");
    let first = saved.iter().zip(&restored).position(|(a, b)| a != b);
    assert_eq!(
        first,
        None,
        "the restored layout's deltas part from the saved one's at call {first:?} of {}",
        saved.len()
    );
}
