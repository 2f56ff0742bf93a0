//! The scene file is the other door from outside: any bytes a host reads as a
//! [`SceneFile`] give a typed error (the JSON crate's, or a [`LayoutError`] from
//! `try_into_scene`) or a scene a layout steps without a panic, to finite positions.

mod common;

use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};

use common::damage::damages;
use common::{Host, FRAME};
use graph_canvas_layout::scene::SceneFile;
use graph_canvas_layout::{LayoutError, RapierLayoutConfig};

/// What reading one damaged file came to.
#[derive(Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Read {
    /// The JSON crate's error.
    Unparsed,
    /// `try_into_scene`'s error.
    Refused,
    /// Laid out for a few frames.
    LaidOut,
}

/// Reads `bytes` as a host would and lays the scene out for 20 frames with `try_step`;
/// `Err` says how a step failed, panicked or went non-finite.
fn read(bytes: &[u8]) -> Result<Read, String> {
    let Ok(file) = serde_json::from_slice::<SceneFile>(bytes) else {
        return Ok(Read::Unparsed);
    };
    let scene = match catch_unwind(AssertUnwindSafe(|| file.try_into_scene())) {
        Err(_) => return Err("try_into_scene panicked".into()),
        Ok(Err(_)) => return Ok(Read::Refused),
        Ok(Ok(scene)) => scene,
    };
    let mut host = Host::new(scene, RapierLayoutConfig::stress());
    let run = catch_unwind(AssertUnwindSafe(|| -> Result<(), String> {
        for frame in 0..20 {
            host.try_frame(FRAME)
                .map_err(|e| format!("a checked scene was refused at frame {frame}: {e}"))?;
            if let Some(n) = host.scene.nodes.iter().find(|n| !n.position.is_finite()) {
                return Err(format!(
                    "node {} at {:?} after frame {frame}",
                    n.id, n.position
                ));
            }
        }
        Ok(())
    }));
    match run {
        Err(_) => Err("a step panicked".into()),
        Ok(Err(what)) => Err(what),
        Ok(Ok(())) => Ok(Read::LaidOut),
    }
}

fn shipped() -> Vec<u8> {
    std::fs::read(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/florentine.json"
    ))
    .expect("the florentine scene ships with the crate")
}

#[test]
fn every_value_and_array_damage_is_an_error_or_a_layout() {
    let root: serde_json::Value = serde_json::from_slice(&shipped()).unwrap();
    let mut outcomes: BTreeMap<Read, usize> = BTreeMap::new();
    let mut failures = Vec::new();
    for damage in damages(&root) {
        let bytes = serde_json::to_vec(&damage.apply(&root)).unwrap();
        match read(&bytes) {
            Ok(outcome) => *outcomes.entry(outcome).or_default() += 1,
            Err(what) => failures.push(format!("{} {}: {what}", damage.path, damage.what)),
        }
    }
    assert!(
        failures.is_empty(),
        "{} damages failed, e.g. {:?}",
        failures.len(),
        &failures[..failures.len().min(5)]
    );
    // Every way a damage can end was met: the sweep reaches each door.
    assert_eq!(outcomes.len(), 3, "outcomes: {outcomes:?}");
}

#[test]
fn every_truncation_and_byte_change_is_an_error_or_a_layout() {
    let bytes = shipped();
    let mut failures = Vec::new();
    let mut unparsed = 0;
    // Cut at every 7th byte, and 64 spread positions each overwritten with bytes that
    // change JSON's meaning (a digit, a sign, an exponent, a bracket, a quote, a NUL).
    for cut in (0..bytes.len()).step_by(7) {
        match read(&bytes[..cut]) {
            Ok(Read::Unparsed) => unparsed += 1,
            Ok(_) => {}
            Err(what) => failures.push(format!("cut at {cut}: {what}")),
        }
    }
    for at in (0..bytes.len()).step_by(bytes.len() / 64) {
        for b in [b'9', b'-', b'e', b']', b'"', 0, 0xff] {
            let mut damaged = bytes.clone();
            damaged[at] = b;
            if let Err(what) = read(&damaged) {
                failures.push(format!("byte {at} set to {b}: {what}"));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} damages failed, e.g. {:?}",
        failures.len(),
        &failures[..failures.len().min(5)]
    );
    assert!(unparsed > 0, "no truncation was refused by the JSON reader");
}

#[test]
fn a_file_a_layout_cannot_use_says_which_node() {
    let text = r#"{"nodes":[{"id":1,"x":0,"y":0},{"id":2,"x":2e9,"y":0}],"edges":[]}"#;
    let file: SceneFile = serde_json::from_str(text).unwrap();
    match file.try_into_scene() {
        Err(LayoutError::PositionOutOfRange { node: 2, .. }) => {}
        other => panic!("a coordinate beyond the range is named: {other:?}"),
    }
    let text = r#"{"nodes":[{"id":1,"x":0,"y":0,"radius":2e9}],"edges":[]}"#;
    let file: SceneFile = serde_json::from_str(text).unwrap();
    assert!(
        matches!(
            file.try_into_scene(),
            Err(LayoutError::InvalidRadius { node: 1, .. })
        ),
        "a disk wider than the range is named"
    );
    let text = r#"{"nodes":[{"id":1,"x":0,"y":0},{"id":1,"x":5,"y":0}],"edges":[[1,1]]}"#;
    let file: SceneFile = serde_json::from_str(text).unwrap();
    assert!(
        matches!(
            file.try_into_scene(),
            Err(LayoutError::DuplicateNode {
                node: 1,
                first: 0,
                second: 1
            })
        ),
        "a repeated id is named with both places"
    );
}
