//! A snapshot whose rapier state was damaged (a body's `active_set_id`, an island's
//! body handle index or generation) restored without error; rapier's island manager
//! then met a handle that led nowhere, or a body in two islands, and panicked in the next
//! step. Rapier's state cannot be checked from outside (its islands and ids are private),
//! so each of its sets is sealed with a hash of what rapier wrote when the snapshot is
//! taken, and a set that no longer matches its seal is refused, naming it.

mod common;

use common::damage::{host_mid_drag, Damage};
use common::{load_scene, Host, FRAME};
use graph_canvas_layout::{LayoutSnapshot, RapierLayout, RapierLayoutConfig, SnapshotError};
use serde_json::Value;

#[test]
fn damaged_rapier_handles_are_refused_by_name() {
    let host = host_mid_drag(RapierLayoutConfig::stress());
    let root = serde_json::to_value(host.layout.snapshot()).unwrap();
    let cases = [
        (
            "/world/bodies/bodies/items/0/Occupied/value/ids/active_set_id",
            "rapier's bodies",
        ),
        (
            "/world/islands/islands/v/0/bodies/0/index",
            "rapier's islands",
        ),
        (
            "/world/islands/islands/v/0/bodies/0/generation",
            "rapier's islands",
        ),
    ];
    for (path, part) in cases {
        for value in [Value::from(0), Value::from(1), Value::from(u32::MAX)] {
            let damage = Damage::set(path, value);
            let damaged = damage.apply(&root);
            if damaged == root {
                continue;
            }
            let Ok(snapshot) = serde_json::from_value::<LayoutSnapshot<u32>>(damaged) else {
                continue;
            };
            let mut layout = RapierLayout::default();
            match layout.restore(snapshot) {
                Err(SnapshotError::Inconsistent(what)) => assert!(
                    what.starts_with(part),
                    "{path} {}: refused, but naming {what:?}",
                    damage.what
                ),
                other => panic!("{path} {}: {other:?}", damage.what),
            }
        }
    }
}

#[test]
fn an_undamaged_snapshot_passes_its_seals_after_a_round_trip_through_text() {
    let host = host_mid_drag(RapierLayoutConfig::force_directed());
    let text = serde_json::to_string(&host.layout.snapshot()).unwrap();
    let snapshot: LayoutSnapshot<u32> = serde_json::from_str(&text).unwrap();
    let mut layout = RapierLayout::default();
    layout
        .restore(snapshot)
        .expect("a snapshot read back as written restores");
}

#[test]
fn snapshots_of_a_large_layout_with_rapiers_contacts_pass_their_seals() {
    // Contacts come and go over 300 frames (rapier's pair maps grow and shrink), and a
    // snapshot read back from text every 100 frames restores.
    let mut host = Host::new(load_scene("n1000_e2500"), RapierLayoutConfig::default());
    for frame in 1..=300 {
        host.frame(FRAME);
        if frame % 100 == 0 {
            let text = serde_json::to_string(&host.layout.snapshot()).unwrap();
            let snapshot: LayoutSnapshot<u32> = serde_json::from_str(&text).unwrap();
            let mut layout = RapierLayout::default();
            if let Err(e) = layout.restore(snapshot) {
                panic!("frame {frame}: an undamaged snapshot was refused: {e}");
            }
        }
    }
}
