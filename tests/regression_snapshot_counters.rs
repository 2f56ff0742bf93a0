//! A snapshot holding a count near `u64::MAX` (the call stamp, the patch count, the
//! world's version or its next serial) restored without error, and the next call that
//! counted on overflowed and panicked. Counts above 2⁵³, which no session reaches, are
//! now refused when a snapshot is restored, naming the count.

mod common;

use common::damage::{host_mid_drag, Damage};
use graph_canvas_layout::{LayoutSnapshot, RapierLayout, RapierLayoutConfig, SnapshotError};
use serde_json::Value;

#[test]
fn counts_no_session_reaches_are_refused_by_name() {
    let host = host_mid_drag(RapierLayoutConfig::stress());
    let root = serde_json::to_value(host.layout.snapshot()).unwrap();
    for (path, name) in [
        ("/stamp", "stamp"),
        ("/patches", "patches"),
        ("/rebuilds", "rebuilds"),
        ("/world/version", "world.version"),
        ("/world/next_serial", "world.next_serial"),
        ("/world/dropped_events", "world.dropped_events"),
    ] {
        let damaged = Damage::set(path, Value::from(u64::MAX)).apply(&root);
        let snapshot: LayoutSnapshot<u32> = serde_json::from_value(damaged).unwrap();
        match RapierLayout::default().restore(snapshot) {
            Err(SnapshotError::Inconsistent(what)) => assert!(
                what.starts_with(name),
                "{path} at u64::MAX: refused, but naming {what:?}"
            ),
            other => panic!("{path} at u64::MAX: {other:?}"),
        }
    }
}
