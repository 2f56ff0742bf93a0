//! Regression: growing a node's radius in a cooled layout was not a disturbance. The
//! heat stayed at its floor, the end of the schedule put the woken bodies back to sleep
//! after one step, and the grown node stayed overlapping its neighbours while
//! `is_converged` said the layout was at rest. A radius edit now reheats the layout.

mod common;

use common::*;
use graph_canvas_layout::{quality, Layout, RapierLayoutConfig};

#[test]
fn a_grown_node_pushes_its_neighbours_out_before_rest() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    for _ in 0..600 {
        host.frame(FRAME);
    }
    assert!(host.layout.is_converged(&host.state), "karate not at rest");
    // The hub grows from radius 16 to 60: it now overlaps its nearest neighbours.
    host.scene.nodes[0].radius = 60.0;
    let overlapping = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
    assert!(
        overlapping > 0,
        "the edit should create overlaps to resolve"
    );
    let mut frames = 0;
    loop {
        host.frame(FRAME);
        frames += 1;
        if host.layout.is_converged(&host.state) || frames >= 600 {
            break;
        }
    }
    let left = quality::overlapping_pairs(&host.scene, 16.0, 0.5);
    assert_eq!(
        left, 0,
        "{left} of {overlapping} overlapping pairs left when the layout reported rest after {frames} frames"
    );
}
