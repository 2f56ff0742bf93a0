//! Damaged snapshots handed to `restore`, then the session carried on
//! (`tests/common/damage.rs`): a restore either refuses or gives a layout whose next calls
//! neither panic nor go non-finite. The first byte picks the input's kind:
//! - even: the rest is the snapshot's bytes as a host would read them from disk (the
//!   committed corpus seeds real snapshots, which libFuzzer mutates byte by byte);
//! - odd: structured damage of a real snapshot taken mid-drag (under `stress()` or
//!   `force_directed()`): up to 8 values or arrays, each picked by path and set to a number
//!   the fuzzer chooses, a flipped bool, an emptied string or an array edit.
#![no_main]

use std::sync::OnceLock;

use arbitrary::{Result, Unstructured};
use graph_canvas_layout::RapierLayoutConfig;
use libfuzzer_sys::fuzz_target;
use serde_json::Value;

#[path = "../../tests/common/mod.rs"]
mod common;

use common::damage::{host_mid_drag, paths, restore_and_run, Damage, Outcome};
use common::Host;

/// A real snapshot under each preset, its JSON and its paths, built once.
struct Taken {
    host: Host<u32>,
    root: Value,
    paths: Vec<String>,
}

fn taken() -> &'static [Taken; 2] {
    static TAKEN: OnceLock<[Taken; 2]> = OnceLock::new();
    TAKEN.get_or_init(|| {
        [
            RapierLayoutConfig::stress(),
            RapierLayoutConfig::force_directed(),
        ]
        .map(|config| {
            let host = host_mid_drag(config);
            let root = serde_json::to_value(host.layout.snapshot()).expect("a snapshot serialises");
            let paths = paths(&root);
            Taken { host, root, paths }
        })
    })
}

/// One damage drawn from the fuzzer's bytes.
fn damage(u: &mut Unstructured, taken: &Taken) -> Result<Damage> {
    let path = &taken.paths[u.choose_index(taken.paths.len())?];
    let here = taken.root.pointer(path);
    Ok(match here {
        Some(Value::Array(items)) => {
            Damage::array(path, u.arbitrary()?, u.arbitrary()?, items.len())
        }
        Some(Value::Bool(b)) => Damage::set(path, Value::Bool(!b)),
        Some(Value::String(_)) => Damage::set(path, Value::String(String::new())),
        _ => {
            let value = match u.int_in_range(0..=3)? {
                0 => Value::from(u.arbitrary::<u64>()?),
                1 => Value::from(u.arbitrary::<i64>()?),
                2 => Value::from(u.arbitrary::<u32>()? % 64),
                _ => serde_json::Number::from_f64(u.arbitrary::<f64>()?)
                    .map_or(Value::Null, Value::Number),
            };
            Damage::set(path, value)
        }
    })
}

fuzz_target!(|bytes: &[u8]| {
    let Some((&kind, rest)) = bytes.split_first() else {
        return;
    };
    let outcome = if kind % 2 == 0 {
        let Ok(value) = serde_json::from_slice::<Value>(rest) else {
            return;
        };
        // A snapshot read from disk continues the session it was taken in.
        restore_and_run(value, &taken()[0].host)
    } else {
        let mut u = Unstructured::new(rest);
        let taken = &taken()[usize::from(kind / 2 % 2)];
        let mut root = taken.root.clone();
        let count = u.int_in_range(1..=8).unwrap_or(1);
        for _ in 0..count {
            let Ok(damage) = damage(&mut u, taken) else {
                break;
            };
            damage.apply_in(&mut root);
        }
        restore_and_run(root, &taken.host)
    };
    if let Outcome::Panicked(what) | Outcome::NonFinite(what) = outcome {
        panic!("a damaged snapshot restored and then failed: {what}");
    }
});
