//! Every single-value and array damage of a real snapshot (taken mid-drag, with a throw
//! in flight and a pin; `common/damage.rs`) is refused by `restore`, or restores into a
//! layout that carries on (the drag, a release, a pin let go, nodes added and removed,
//! frame times of 0, 5 s and 1 µs) without a panic and with finite positions.
//!
//! Rapier's own sets are sealed (a damaged one is refused before rapier reads it), so
//! `cargo test` damages every value of the layout's own parts and one in
//! [`RAPIER_STRIDE`] of rapier's; `DAMAGE_FULL=1` damages every one (about 49,000
//! damages under `stress()`, a few minutes). `DAMAGE_SKIP=/a,/b` leaves out paths with
//! those prefixes; `DAMAGE_TRACE=1` prints each damage before it is tried.

mod common;

use std::collections::BTreeMap;

use common::damage::{damages, host_mid_drag, restore_and_run, Outcome};
use graph_canvas_layout::RapierLayoutConfig;

/// Of the damages to rapier's sets, one in this many is tried without `DAMAGE_FULL`.
const RAPIER_STRIDE: usize = 8;

/// Rapier's sets in a snapshot, each under its seal.
const SEALED: [&str; 10] = [
    "/world/bodies",
    "/world/colliders",
    "/world/impulse_joints",
    "/world/multibody_joints",
    "/world/soft_bodies",
    "/world/islands",
    "/world/broad_phase",
    "/world/narrow_phase",
    "/world/ccd_solver",
    "/world/params",
];

fn sweep(name: &str, config: RapierLayoutConfig) {
    let full = std::env::var_os("DAMAGE_FULL").is_some();
    let trace = std::env::var_os("DAMAGE_TRACE").is_some();
    let skip = std::env::var("DAMAGE_SKIP").unwrap_or_default();
    let skipped = |path: &str| {
        skip.split(',')
            .any(|p| !p.is_empty() && path.starts_with(p))
    };
    let host = host_mid_drag(config);
    let root = serde_json::to_value(host.layout.snapshot()).expect("a snapshot serialises");
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    let mut bad: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut sealed_seen = 0;
    for damage in damages(&root) {
        if SEALED.iter().any(|p| damage.path.starts_with(p)) {
            sealed_seen += 1;
            if !full && sealed_seen % RAPIER_STRIDE != 0 {
                continue;
            }
        }
        if skipped(&damage.path) {
            continue;
        }
        if trace {
            eprintln!("{} {}", damage.path, damage.what);
        }
        let outcome = restore_and_run(damage.apply(&root), &host);
        let key = match &outcome {
            Outcome::Unread => "unread",
            Outcome::Refused => "refused",
            Outcome::Ran => "ran",
            Outcome::Panicked(_) => "panicked",
            Outcome::NonFinite(_) => "non-finite",
        };
        *counts.entry(key).or_default() += 1;
        if let Outcome::Panicked(m) | Outcome::NonFinite(m) = outcome {
            // Failures grouped by path with indices left out: one line a bug class.
            let pattern: String = damage
                .path
                .split('/')
                .map(|p| match p.parse::<usize>() {
                    Ok(_) => "#",
                    Err(_) => p,
                })
                .collect::<Vec<_>>()
                .join("/");
            let first = m.lines().next().unwrap_or("");
            bad.entry(pattern)
                .or_default()
                .push(format!("{} {}: {first}", damage.path, damage.what));
        }
    }
    eprintln!("{name}: {counts:?}");
    let report: Vec<String> = bad
        .iter()
        .map(|(pattern, cases)| format!("{pattern}: {} cases, e.g. {}", cases.len(), cases[0]))
        .collect();
    assert!(
        report.is_empty(),
        "{name}: damaged snapshots restored and then failed:\n{}",
        report.join("\n")
    );
    // The sweep reached every door: refused, unread and carried on.
    for outcome in ["refused", "unread", "ran"] {
        assert!(
            counts.get(outcome).is_some_and(|&c| c > 0),
            "{name}: no damage {outcome}: {counts:?}"
        );
    }
}

#[test]
fn stress_snapshots() {
    sweep("stress", RapierLayoutConfig::stress());
}

#[test]
fn force_directed_snapshots() {
    sweep("force_directed", RapierLayoutConfig::force_directed());
}

#[test]
fn default_snapshots() {
    sweep("default", RapierLayoutConfig::default());
}
