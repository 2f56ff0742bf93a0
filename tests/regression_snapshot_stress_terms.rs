//! A snapshot whose stress model's saved terms did not agree with each other (a node's
//! component past the components, `near_start` out of order, a pivot range past the
//! pivots, a pivot past the nodes, a row past the hop table) restored without error,
//! and the next step indexed past the end of a term table and panicked: the host lost
//! its document. The model is now checked against the shape it was built for when a
//! snapshot is restored, and a snapshot whose model disagrees is refused, naming it.

mod common;

use common::damage::{host_mid_drag, restore_and_run, Damage, Outcome};
use graph_canvas_layout::{LayoutSnapshot, RapierLayout, RapierLayoutConfig, SnapshotError};
use serde_json::Value;

#[test]
fn a_stress_model_whose_terms_disagree_is_refused_by_name() {
    let host = host_mid_drag(RapierLayoutConfig::stress());
    let root = serde_json::to_value(host.layout.snapshot()).unwrap();
    let model = "/forces/stress/model";
    let damages = [
        Damage::set(&format!("{model}/component/0"), Value::from(7)),
        Damage::array(&format!("{model}/near_start"), 4, 0, 0),
        Damage::set(&format!("{model}/pivot_range/0/1"), Value::from(u32::MAX)),
        Damage::set(&format!("{model}/pivots/0"), Value::from(30)),
        Damage::set(&format!("{model}/row/3"), Value::from(u32::MAX)),
        Damage::set(&format!("{model}/sizes/0"), Value::from(u32::MAX)),
        Damage::array(&format!("{model}/weight_start"), 0, 5, 30),
    ];
    for damage in &damages {
        let snapshot: LayoutSnapshot<u32> = serde_json::from_value(damage.apply(&root))
            .unwrap_or_else(|e| panic!("{} {} still reads: {e}", damage.path, damage.what));
        let mut layout = RapierLayout::default();
        match layout.restore(snapshot) {
            Err(SnapshotError::Inconsistent(what)) => assert!(
                what.starts_with("forces.stress.model"),
                "{} {}: refused, but naming {what:?}",
                damage.path,
                damage.what
            ),
            other => panic!("{} {}: {other:?}", damage.path, damage.what),
        }
        assert_eq!(
            restore_and_run(damage.apply(&root), &host),
            Outcome::Refused
        );
    }
}

#[test]
fn an_undamaged_stress_model_restores_and_carries_on() {
    let host = host_mid_drag(RapierLayoutConfig::stress());
    let root = serde_json::to_value(host.layout.snapshot()).unwrap();
    assert_eq!(restore_and_run(root, &host), Outcome::Ran);
}
