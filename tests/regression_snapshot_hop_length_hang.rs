//! A snapshot whose stress hop length was huge (1.8e19, a damaged value) restored, and
//! the next call that added a node never returned: seating the new node looked for free
//! room within one edge length of its neighbour by walking every grid cell in reach,
//! 10³⁶ of them. Seating now reads the occupied cells when the reach spans more cells
//! than are occupied (the same nearest disk, found in bounded time), so a layout whose
//! edges are far longer than its disks adds nodes as fast as any other.

mod common;

use common::damage::{host_mid_drag, restore_and_run, Damage, Outcome};
use graph_canvas_layout::RapierLayoutConfig;
use serde_json::Value;

#[test]
fn a_far_hop_length_still_seats_added_nodes() {
    let host = host_mid_drag(RapierLayoutConfig::stress());
    let root = serde_json::to_value(host.layout.snapshot()).unwrap();
    // `carry_on` adds node 30 on top of the others, which needs a seat.
    for hop in [1.8e19, 1e30, 1e9] {
        let damaged = Damage::set("/world/hop_length", Value::from(hop)).apply(&root);
        let outcome = restore_and_run(damaged, &host);
        assert!(
            matches!(outcome, Outcome::Ran | Outcome::Refused),
            "hop length {hop}: {outcome:?}"
        );
    }
}
