//! Frame time as the contract says: equal substeps no longer than the fixed timestep,
//! capped per call; unusable `dt` means one fixed step.

mod common;

use common::*;
use graph_canvas_layout::{CanvasSceneInput, RapierLayoutConfig, StepPlan};

fn falling() -> Host<u32> {
    let scene = CanvasSceneInput::new(vec![node(0, 0.0, 0.0)], vec![]);
    let mut config = RapierLayoutConfig::default();
    config.material.linear_damping = 0.0;
    let mut host = Host::new(scene, config);
    host.state.gravity_y = 1000.0;
    host
}

#[test]
fn dt_is_simulated_time() {
    // Free fall under g = 1000 for 0.5 s: y = g t² / 2 = 125 (semi-implicit Euler at
    // 1/60 s overshoots by g t dt / 2 = 4.2).
    for (dt, calls) in [(1.0 / 60.0, 30), (1.0 / 30.0, 15), (0.1, 5), (0.25, 2)] {
        let mut host = falling();
        for _ in 0..calls {
            host.frame(dt);
        }
        let y = host.pos(&0).y;
        assert!(
            (y - 125.0).abs() < 6.0,
            "dt {dt} × {calls}: fell {y}, expected ~125"
        );
        assert!(
            (host.state.simulated_time - 0.5).abs() < 1e-4,
            "dt {dt}: simulated {}",
            host.state.simulated_time
        );
    }
}

#[test]
fn time_beyond_the_cap_is_dropped_not_integrated() {
    let mut host = falling();
    host.frame(10.0); // a stall: only max_frame_time (0.25 s) is simulated
    assert!(
        (host.state.simulated_time - 0.25).abs() < 1e-6,
        "simulated {}",
        host.state.simulated_time
    );
    let y = host.pos(&0).y;
    assert!(
        y < 40.0,
        "a 10 s stall moved the node by {y}; 0.25 s of fall is ~33"
    );
}

#[test]
fn unusable_dt_means_one_fixed_step() {
    for dt in [0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let mut host = falling();
        host.frame(dt);
        let t = host.state.simulated_time;
        assert!(
            (t - 1.0 / 60.0).abs() < 1e-7,
            "dt {dt}: simulated {t}, expected one 1/60 step"
        );
    }
}

#[test]
fn the_state_timestep_sets_the_substep_length() {
    let mut host = falling();
    host.state.dt = 1.0 / 240.0;
    host.frame(1.0 / 60.0);
    let substep = host.layout.world().unwrap().integration_parameters().dt;
    assert!(
        (substep - 1.0 / 240.0).abs() < 1e-7,
        "substep {substep}, expected 1/240"
    );
    assert!((host.state.simulated_time - 1.0 / 60.0).abs() < 1e-6);
}

#[test]
fn precise_accuracy_still_takes_one_whole_fixed_step_for_unusable_dt() {
    let mut host = falling();
    host.layout.config.solver.accuracy = graph_canvas_layout::config::Accuracy::Precise;
    host.frame(f32::NAN);
    let t = host.state.simulated_time;
    assert!(
        (t - 1.0 / 60.0).abs() < 1e-7,
        "simulated {t}, expected one 1/60 step in two substeps"
    );
    let substep = host.layout.world().unwrap().integration_parameters().dt;
    assert!((substep - 1.0 / 120.0).abs() < 1e-7, "substep {substep}");
}

#[test]
fn step_plans_are_equal_substeps_no_longer_than_the_timestep() {
    for dt in [
        1e-7_f32,
        0.001,
        1.0 / 60.0,
        0.02,
        0.05,
        0.1,
        0.2499,
        0.25,
        1.0,
        f32::MAX,
    ] {
        let plan = StepPlan::new(dt, 1.0 / 60.0, 0.25, 16);
        assert!(
            plan.substep_dt <= 1.0 / 60.0 + 1e-9,
            "dt {dt}: substep {}",
            plan.substep_dt
        );
        assert!(
            plan.substeps >= 1 && plan.substeps <= 16,
            "dt {dt}: {} substeps",
            plan.substeps
        );
        let expected = dt.min(0.25);
        assert!(
            (plan.simulated() - expected).abs() <= expected * 1e-5,
            "dt {dt}: simulates {}",
            plan.simulated()
        );
    }
}
