//! Keep and resume: a layout saved through serde_json mid-motion (a drag in progress, a
//! thrown node in flight) and restored into a new layout continues bit for bit as the
//! one that never stopped; one saved at rest restores at rest; a scene that changed
//! meanwhile is an edit; a damaged snapshot is refused and changes nothing.

mod common;

use common::*;
use graph_canvas_layout::config::Contacts;
use graph_canvas_layout::euclid::default::Vector2D;
use graph_canvas_layout::{
    CanvasSceneInput, DeltaMap, Layout, LayoutSnapshot, RapierLayout, RapierLayoutConfig,
    SnapshotError,
};

/// The configurations a snapshot must carry exactly: the default and every preset (the
/// stress one with its pivot terms held over 4 substeps, so a snapshot lands between
/// two evaluations).
fn configs() -> Vec<(&'static str, RapierLayoutConfig)> {
    vec![
        ("default", RapierLayoutConfig::default()),
        ("force_directed", RapierLayoutConfig::force_directed()),
        (
            "force_directed_fast",
            RapierLayoutConfig::force_directed_fast(),
        ),
        (
            "events",
            RapierLayoutConfig {
                contacts: Contacts {
                    events: true,
                    ..Default::default()
                },
                ..RapierLayoutConfig::default()
            },
        ),
    ]
}

/// The host's part of frame `frame` of the scripted session on `les_miserables`: node 11
/// thrown at frames 80 to 83 (in flight at 100), node 48 dragged from frame 95 and let
/// go at frame 110, node 0 pinned from frame 120.
fn script(host: &mut Host<u32>, frame: usize) {
    let flick = Vector2D::new(30.0, -12.0);
    match frame {
        80 => {
            host.extras.dragging.insert(11);
        }
        81..=83 => {
            let p = host.pos(&11);
            host.set_pos(&11, p + flick);
        }
        84 => {
            host.extras.dragging.remove(&11);
        }
        95 => {
            host.extras.dragging.insert(48);
        }
        96..=109 => {
            let p = host.pos(&48);
            host.set_pos(&48, p + Vector2D::new(-6.0, 4.0));
        }
        110 => {
            host.extras.dragging.remove(&48);
        }
        120 => {
            host.extras.pinned.insert(0);
        }
        _ => {}
    }
}

/// One call's deltas as sorted `(id, x bits, y bits)`.
fn bits(deltas: &DeltaMap<u32>) -> Vec<(u32, u32, u32)> {
    let mut row: Vec<_> = deltas
        .iter()
        .map(|(id, d)| (*id, d.x.to_bits(), d.y.to_bits()))
        .collect();
    row.sort_unstable();
    row
}

/// `layout`'s snapshot written as JSON and read back into a new layout.
fn through_json(layout: &RapierLayout<u32>) -> RapierLayout<u32> {
    let json = serde_json::to_string(&layout.snapshot()).expect("a snapshot serialises");
    let snapshot: LayoutSnapshot<u32> = serde_json::from_str(&json).expect("and reads back");
    let mut restored = RapierLayout::default();
    restored.restore(snapshot).expect("a snapshot restores");
    restored
}

#[test]
fn a_snapshot_taken_mid_motion_continues_bit_for_bit() {
    for (name, config) in configs() {
        let mut host = Host::new(load_scene("les_miserables"), config);
        for frame in 0..100 {
            script(&mut host, frame);
            host.frame(FRAME);
        }
        assert!(
            host.extras.dragging.contains(&48),
            "a drag is in progress when the snapshot is taken"
        );
        let flying = speed(host.layout.world().unwrap().linear_velocity(&11).unwrap());
        assert!(
            flying > 50.0,
            "{name}: the thrown node is in flight when the snapshot is taken ({flying} units/s)"
        );
        let mut resumed = Host {
            scene: host.scene.clone(),
            layout: through_json(&host.layout),
            state: host.state.clone(),
            extras: host.extras.clone(),
        };
        let mut moved = 0;
        for frame in 100..300 {
            script(&mut host, frame);
            script(&mut resumed, frame);
            let (a, b) = (host.frame(FRAME), resumed.frame(FRAME));
            moved += a.len();
            assert_eq!(
                bits(&a),
                bits(&b),
                "{name}: frame {frame} differs after the restore"
            );
            assert_eq!(
                host.layout.is_converged(&host.state),
                resumed.layout.is_converged(&resumed.state),
                "{name}: frame {frame}"
            );
            assert_eq!(
                host.layout.heat(),
                resumed.layout.heat(),
                "{name}: frame {frame}"
            );
            assert_eq!(
                host.layout.drain_events(),
                resumed.layout.drain_events(),
                "{name}: frame {frame}"
            );
        }
        assert!(
            moved > 1_000,
            "{name}: only {moved} deltas in 200 frames: nothing to compare"
        );
        assert_eq!(
            host.layout.rebuild_count(),
            resumed.layout.rebuild_count(),
            "{name}"
        );
    }
}

#[test]
fn a_snapshot_taken_at_rest_restores_at_rest() {
    for (name, config) in configs() {
        let mut host = Host::new(load_scene("karate"), config);
        host.settle(5_000);
        let mut resumed = Host {
            scene: host.scene.clone(),
            layout: through_json(&host.layout),
            state: host.state.clone(),
            extras: host.extras.clone(),
        };
        assert!(resumed.layout.is_converged(&resumed.state), "{name}");
        for frame in 0..60 {
            let deltas = resumed.frame(FRAME);
            assert!(
                deltas.is_empty(),
                "{name}: the restored layout moved {} nodes at frame {frame}",
                deltas.len()
            );
            assert!(resumed.layout.is_converged(&resumed.state), "{name}");
        }
    }
}

#[test]
fn a_scene_that_changed_since_the_snapshot_is_an_edit() {
    // One node gone and one new since the snapshot: the restored layout meets them as
    // the layout that never stopped meets the same edit, bit for bit.
    let mut host = Host::new(
        load_scene("les_miserables"),
        RapierLayoutConfig::force_directed(),
    );
    host.frames(60);
    let mut resumed = Host {
        scene: host.scene.clone(),
        layout: through_json(&host.layout),
        state: host.state.clone(),
        extras: host.extras.clone(),
    };
    for h in [&mut host, &mut resumed] {
        h.scene.nodes.retain(|n| n.id != 30);
        h.scene.edges.retain(|e| e.source != 30 && e.target != 30);
        h.scene.nodes.push(node(500, 40.0, 40.0));
        h.scene.edges.push(edge(500, 11));
    }
    for frame in 0..120 {
        let (a, b) = (host.frame(FRAME), resumed.frame(FRAME));
        assert_eq!(bits(&a), bits(&b), "frame {frame} differs after the edit");
    }
    let world = resumed.layout.world().unwrap();
    assert!(world.contains_node(&500) && !world.contains_node(&30));
    assert_eq!(resumed.layout.patch_count(), host.layout.patch_count());
}

#[test]
fn a_damaged_snapshot_is_refused_and_changes_nothing() {
    let mut host = Host::new(load_scene("karate"), RapierLayoutConfig::force_directed());
    host.frames(30);
    let mut json: serde_json::Value = serde_json::to_value(host.layout.snapshot()).unwrap();
    let mut target = Host::new(
        CanvasSceneInput::new(vec![node(1_u32, 0.0, 0.0)], vec![]),
        RapierLayoutConfig::default(),
    );
    target.frame(FRAME);

    // Another format.
    let mut other = json.clone();
    other["format"] = serde_json::json!(99);
    assert_eq!(
        restore_json(&mut target, other),
        Err(SnapshotError::Format {
            found: 99,
            expected: LayoutSnapshot::<u32>::FORMAT
        })
    );
    // A format-1 snapshot (written before rapier's state was sealed) reads, and is
    // refused by its format.
    let mut old = json.clone();
    old["format"] = serde_json::json!(1);
    old["world"].as_object_mut().unwrap().remove("seals");
    assert_eq!(
        restore_json(&mut target, old),
        Err(SnapshotError::Format {
            found: 1,
            expected: 3
        })
    );
    // A format-2 snapshot (its configuration's fields flat, before they were grouped)
    // reads, and is refused by its format: its flat fields would otherwise fall back
    // to defaults and the layout would go on under another configuration.
    let mut flat = json.clone();
    flat["format"] = serde_json::json!(2);
    for part in ["config", "applied"] {
        flat[part] = serde_json::json!({
            "default_radius": 16.0, "spring_model": "Forces", "contact_model": "Disks",
            "collisions": true, "max_substeps": 16, "throw_window": 0.05, "link_bias": 1.0,
        });
    }
    assert_eq!(
        restore_json(&mut target, flat),
        Err(SnapshotError::Format {
            found: 2,
            expected: 3
        })
    );
    // A node whose body is another node's.
    let slots = json["world"]["slots"].as_array_mut().unwrap();
    let body = slots[1]["body"].clone();
    slots[0]["body"] = body;
    let snapshot: LayoutSnapshot<u32> = serde_json::from_value(json).unwrap();
    let error = target.layout.restore(snapshot).unwrap_err();
    assert!(matches!(error, SnapshotError::Inconsistent(_)), "{error:?}");
    assert!(error.to_string().contains("body"), "{error}");
    // Neither touched the layout.
    let world = target.layout.world().unwrap();
    assert_eq!((world.body_count(), world.contains_node(&1)), (1, true));
    assert_eq!(target.layout.config, RapierLayoutConfig::default());
}

/// Reads `value` as a snapshot (it must read) and restores `host`'s layout from it.
fn restore_json(host: &mut Host<u32>, value: serde_json::Value) -> Result<(), SnapshotError> {
    let snapshot: LayoutSnapshot<u32> = serde_json::from_value(value).unwrap();
    host.layout.restore(snapshot)
}
