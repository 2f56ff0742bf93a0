//! The sweep that makes every separation hold ran one way first (on along the order,
//! then back), and gave the speed that closed a separation to the body it pushed. A
//! chain squeezed by the forces was pushed on every substep and never back: the whole
//! layout drifted along the chain (a flow's picture down, a layer in
//! `Flow::in_layers` sideways at 40,000 units a second on a 10,000-node graph). The
//! sweep now runs both ways from the same start and ends halfway, and splits the speed
//! by mass.

mod common;

use common::{edge, node, Host};
use graph_canvas_layout::scene::{Axis, Constraint};
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig};

#[test]
fn a_chain_squeezed_by_the_forces_does_not_drift_along_itself() {
    // A path of 20 whose stress layout wants its nodes a hop (about 100 units) apart,
    // held 300 apart along x by a chain of separations: the forces squeeze it. Centred
    // on the origin, where the centre pull has nothing to do.
    let nodes = (0..20)
        .map(|i| node(i, (i as f32 - 9.5) * 300.0, 0.0))
        .collect();
    let edges = (0..19).map(|i| edge(i, i + 1)).collect();
    let mut host = Host::new(
        CanvasSceneInput::new(nodes, edges),
        RapierLayoutConfig::stress(),
    );
    host.extras.constraints = (0..19)
        .map(|i| Constraint::separation(Axis::X, i, i + 1, 300.0))
        .collect();
    let centre =
        |host: &Host<u32>| host.scene.nodes.iter().map(|n| n.position.x).sum::<f32>() / 20.0;
    // The first frame lays the path out (the stress start); the drift is measured from
    // there on.
    host.frame(1.0 / 60.0);
    let before = centre(&host);
    let frames = host.settle(600);
    let drift = centre(&host) - before;
    // The one-way sweep moved the centre 6,007 units; both ways, 61 (the start's layout
    // is not symmetric across the chain, nor are the passes' turns). Half a gap between.
    assert!(
        drift.abs() <= 150.0,
        "the chain's centre moved {drift} units along it in {frames} frames"
    );
    assert!(host.layout.violated_constraints().is_empty());
}
