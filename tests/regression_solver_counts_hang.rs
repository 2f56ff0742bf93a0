//! A configuration asking for `u32::MAX` internal PGS iterations (here from a damaged
//! snapshot; a host can set the same) made the next call run for hours. The counts an
//! `Accuracy::Custom` asks for are now capped (256 iterations of each kind, 64 substeps
//! per timestep), as is `max_substeps` (1,024), so a call's cost is bounded whatever a
//! configuration says.

mod common;

use common::damage::{host_mid_drag, restore_and_run, Damage, Outcome};
use graph_canvas_layout::config::{Accuracy, SolverSettings};
use graph_canvas_layout::RapierLayoutConfig;
use serde_json::Value;

#[test]
fn custom_counts_are_capped() {
    let absurd = Accuracy::Custom {
        solver_iterations: usize::MAX,
        internal_pgs_iterations: usize::MAX,
        substeps: u32::MAX,
    };
    assert_eq!(
        absurd.solver_settings(),
        SolverSettings {
            solver_iterations: 256,
            internal_pgs_iterations: 256,
            substeps: 64
        }
    );
}

#[test]
fn a_snapshot_asking_for_endless_iterations_carries_on() {
    let mut config = RapierLayoutConfig::stress();
    config.solver.accuracy = Accuracy::Custom {
        solver_iterations: 2,
        internal_pgs_iterations: 1,
        substeps: 1,
    };
    let host = host_mid_drag(config);
    let root = serde_json::to_value(host.layout.snapshot()).unwrap();
    for path in [
        "/config/accuracy/Custom/internal_pgs_iterations",
        "/config/accuracy/Custom/solver_iterations",
        "/config/max_substeps",
    ] {
        let damaged = Damage::set(path, Value::from(u32::MAX)).apply(&root);
        let outcome = restore_and_run(damaged, &host);
        assert_eq!(outcome, Outcome::Ran, "{path} at u32::MAX");
    }
}
