//! Disks as wide as the coordinate range (a radius of 4e9 read from a damaged scene
//! file) pushed their neighbours to positions beyond ±`MAX_COORDINATE`, and the host's
//! next `try_step` refused the positions the layout itself had handed out. A radius
//! beyond `MAX_COORDINATE` is now bad input (`LayoutError::InvalidRadius`), and a node
//! pushed to the range's edge stops there, so every position the layout gives stays
//! one `try_step` takes.

mod common;

use common::{node, Host, FRAME};
use graph_canvas_layout::{CanvasSceneInput, LayoutError, RapierLayoutConfig, MAX_COORDINATE};

#[test]
fn disks_as_wide_as_the_range_keep_their_neighbours_inside_it() {
    let mut nodes: Vec<_> = (0..6).map(|i| node(i, i as f32 * 10.0, 0.0)).collect();
    nodes[0].radius = MAX_COORDINATE;
    nodes[3].radius = MAX_COORDINATE * 0.9;
    let mut host = Host::new(
        CanvasSceneInput::new(nodes, vec![]),
        RapierLayoutConfig::force_directed(),
    );
    for frame in 0..60 {
        if let Err(e) = host.try_frame(FRAME) {
            panic!("frame {frame}: the layout's own positions refused: {e}");
        }
    }
    for n in &host.scene.nodes {
        assert!(
            n.position.x.abs() <= MAX_COORDINATE && n.position.y.abs() <= MAX_COORDINATE,
            "node {} at {:?}",
            n.id,
            n.position
        );
    }
}

#[test]
fn a_radius_beyond_the_range_is_named() {
    let mut nodes = vec![node(1_u32, 0.0, 0.0)];
    nodes[0].radius = 4e9;
    let mut host = Host::new(
        CanvasSceneInput::new(nodes, vec![]),
        RapierLayoutConfig::default(),
    );
    let error = host.try_frame(FRAME).unwrap_err();
    assert!(
        matches!(error, LayoutError::InvalidRadius { node: 1, .. }),
        "{error:?}"
    );
}
