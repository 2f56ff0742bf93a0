//! Each edge joint kind does what its name says: springs pull and push toward their
//! rest length, ropes are slack until taut, rods hold their length both ways.

mod common;

use common::*;
use graph_canvas_layout::config::SpringModel;
use graph_canvas_layout::config::{Contacts, Springs};
use graph_canvas_layout::euclid::default::Point2D;
use graph_canvas_layout::{CanvasSceneInput, EdgeJoint, RapierLayoutConfig};

fn config(joint: EdgeJoint) -> RapierLayoutConfig {
    // Collisions off so only the joint acts between the two disks.
    RapierLayoutConfig {
        edge_joint: joint,
        contacts: Contacts {
            enabled: false,
            ..Default::default()
        },
        ..Default::default()
    }
}

fn pair_at(gap: f32, joint: EdgeJoint) -> Host<u32> {
    let scene = CanvasSceneInput::new(vec![node(0, 0.0, 0.0), node(1, gap, 0.0)], vec![edge(0, 1)]);
    Host::new(scene, config(joint))
}

fn gap(host: &Host<u32>) -> f32 {
    dist(host.pos(&0), host.pos(&1))
}

const SPRING: EdgeJoint = EdgeJoint::Spring {
    rest_length: 100.0,
    stiffness: 50.0,
    damping: 1.0,
};

#[test]
fn spring_pulls_a_stretched_pair_toward_rest_length() {
    let mut host = pair_at(200.0, SPRING);
    host.frames(600);
    let g = gap(&host);
    assert!(
        (g - 100.0).abs() < 2.0,
        "stretched spring settled at {g}, rest 100"
    );
}

#[test]
fn spring_pushes_a_compressed_pair_toward_rest_length() {
    let mut host = pair_at(40.0, SPRING);
    host.frame(FRAME);
    let after_one = gap(&host);
    assert!(
        after_one > 40.0,
        "compressed spring did not push: gap {after_one}"
    );
    host.frames(600);
    let g = gap(&host);
    assert!(
        (g - 100.0).abs() < 2.0,
        "compressed spring settled at {g}, rest 100"
    );
}

#[test]
fn spring_stiffness_is_force_per_unit_of_stretch() {
    // Two disks of mass m = 0.005 π 16² each, 50 units stretched, stiffness 50:
    // a = k x / m in the first instant, so the first frame moves each end ~ a dt² / 2.
    let mut host = pair_at(
        150.0,
        EdgeJoint::Spring {
            rest_length: 100.0,
            stiffness: 50.0,
            damping: 0.0,
        },
    );
    host.config_no_damping();
    host.frame(FRAME);
    let m = 0.005 * std::f32::consts::PI * 256.0;
    let expected_v = 50.0 * 50.0 / m * FRAME; // velocity after one step (semi-implicit)
    let v = host.layout.world().unwrap().linear_velocity(&0).unwrap().x;
    assert!(
        (v - expected_v).abs() < expected_v * 0.15,
        "velocity after one frame {v}, expected ~{expected_v}"
    );
}

trait NoDamping {
    fn config_no_damping(&mut self);
}
impl NoDamping for Host<u32> {
    fn config_no_damping(&mut self) {
        self.layout.config.material.linear_damping = 0.0;
    }
}

#[test]
fn rope_exerts_nothing_while_slack() {
    let mut host = pair_at(
        60.0,
        EdgeJoint::Rope {
            max_length: 100.0,
            stiffness: 1e4,
        },
    );
    host.frames(120);
    assert_eq!(
        (host.pos(&0), host.pos(&1)),
        (Point2D::new(0.0, 0.0), Point2D::new(60.0, 0.0)),
        "a slack rope moved its ends"
    );
    assert_eq!(host.layout.world().unwrap().joint_count(), 1);
}

#[test]
fn rope_holds_max_length_when_taut_and_never_pushes() {
    let mut host = pair_at(
        100.0,
        EdgeJoint::Rope {
            max_length: 100.0,
            stiffness: 1e6,
        },
    );
    host.config_no_damping();
    // Pull node 1 away at 600 units/s through a short drag, then let go.
    host.extras.dragging.insert(1);
    host.frame(FRAME);
    host.set_pos(
        &1,
        graph_canvas_layout::euclid::default::Point2D::new(110.0, 0.0),
    );
    host.frame(FRAME);
    host.extras.dragging.clear();
    let mut max_gap: f32 = 0.0;
    for _ in 0..120 {
        host.frame(FRAME);
        max_gap = max_gap.max(gap(&host));
    }
    assert!(
        max_gap < 112.0,
        "a stiff rope stretched to {max_gap} (max 100)"
    );
    // Once taut, the pair moves together: the rope did not bounce them closer (no
    // spring toward half length, no push).
    let g = gap(&host);
    assert!(
        (95.0..=112.0).contains(&g),
        "after the throw the rope holds the pair at {g}"
    );
    let v0 = host.layout.world().unwrap().linear_velocity(&0).unwrap().x;
    assert!(v0 > 50.0, "the taut rope towed node 0 along: v = {v0}");
}

#[test]
fn distance_joint_holds_length_both_ways() {
    for start in [60.0_f32, 160.0] {
        let mut host = pair_at(start, EdgeJoint::Distance { length: 100.0 });
        host.frames(60);
        let g = gap(&host);
        assert!(
            (g - 100.0).abs() < 1.0,
            "rod from {start} settled at {g}, length 100"
        );
    }
}

#[test]
fn no_joint_kind_builds_no_joint() {
    let mut host = pair_at(300.0, EdgeJoint::None);
    host.frames(60);
    assert_eq!(host.layout.world().unwrap().joint_count(), 0);
    assert_eq!(
        host.pos(&1),
        Point2D::new(300.0, 0.0),
        "nothing pulls without a joint"
    );
}

#[test]
fn repeated_and_reversed_edges_make_one_joint_and_self_loops_none() {
    let scene = CanvasSceneInput::new(
        vec![node(0_u32, 0.0, 0.0), node(1, 100.0, 0.0)],
        vec![edge(0, 1), edge(1, 0), edge(0, 1), edge(1, 1)],
    );
    let mut host = Host::new(scene, RapierLayoutConfig::default());
    host.frame(FRAME);
    assert_eq!(host.layout.world().unwrap().joint_count(), 1);
}

#[test]
fn switching_the_joint_kind_replaces_joints_without_a_rebuild() {
    let mut host = pair_at(200.0, SPRING);
    host.frames(5);
    host.layout.config.edge_joint = EdgeJoint::Distance { length: 150.0 };
    host.frames(60);
    let g = gap(&host);
    assert!(
        (g - 150.0).abs() < 1.0,
        "after switching to a 150 rod the gap is {g}"
    );
    assert_eq!(host.layout.rebuild_count(), 1);
    assert_eq!(host.layout.world().unwrap().joint_count(), 1);
}

fn as_forces(joint: EdgeJoint) -> RapierLayoutConfig {
    RapierLayoutConfig {
        springs: Springs {
            model: SpringModel::Forces,
            ..config(joint).springs
        },
        ..config(joint)
    }
}

#[test]
fn springs_as_forces_rest_where_spring_joints_do() {
    for start in [200.0, 40.0] {
        let scene = CanvasSceneInput::new(
            vec![node(0, 0.0, 0.0), node(1, start, 0.0)],
            vec![edge(0, 1)],
        );
        let mut host = Host::new(scene, as_forces(SPRING));
        host.frames(600);
        let g = gap(&host);
        assert!(
            (g - 100.0).abs() < 2.0,
            "from {start}: a spring applied as a force settled at {g}, rest 100"
        );
        let world = host.layout.world().unwrap();
        assert_eq!(
            (world.joint_count(), world.rapier_joint_count()),
            (1, 0),
            "counted as a joint, not built as one"
        );
    }
}

#[test]
fn a_spring_force_pulls_as_hard_as_a_spring_joint() {
    // The first frame's velocity from a 50-unit stretch: the joint's and the force's
    // agree within 2 % (both implicit in the spring, the force one substep late to
    // rapier's solver; at stiffness 50 the implicit correction is 0.2 %).
    let kick = |config: RapierLayoutConfig| {
        let mut host = Host::new(
            CanvasSceneInput::new(
                vec![node(0, 0.0, 0.0), node(1, 150.0, 0.0)],
                vec![edge(0, 1)],
            ),
            config,
        );
        host.config_no_damping();
        host.frame(FRAME);
        host.layout.world().unwrap().linear_velocity(&0).unwrap().x
    };
    let joint = kick(config(SPRING));
    let force = kick(as_forces(SPRING));
    assert!(
        (force - joint).abs() <= 0.02 * joint.abs(),
        "first-frame velocity {force} as a force, {joint} as a joint"
    );
}

#[test]
fn ropes_and_rods_stay_rapier_joints_with_springs_as_forces() {
    for joint in [
        EdgeJoint::Rope {
            max_length: 150.0,
            stiffness: 1e6,
        },
        EdgeJoint::Distance { length: 150.0 },
    ] {
        let mut host = pair_at(300.0, joint);
        host.layout.config.springs.model = SpringModel::Forces;
        host.frames(120);
        let world = host.layout.world().unwrap();
        assert_eq!(world.rapier_joint_count(), 1, "{joint:?}");
        let g = gap(&host);
        assert!((g - 150.0).abs() < 1.0, "{joint:?} held the pair at {g}");
    }
}

#[test]
fn switching_the_spring_model_moves_springs_in_place() {
    let mut switched = pair_at(200.0, SPRING);
    let mut kept = pair_at(200.0, SPRING);
    switched.frames(5);
    kept.frames(5);
    switched.layout.config.springs.model = SpringModel::Forces;
    switched.frame(FRAME);
    kept.frame(FRAME);
    let world = switched.layout.world().unwrap();
    assert_eq!(world.rapier_joint_count(), 0);
    assert_eq!(switched.layout.rebuild_count(), 1, "no rebuild");
    // The motion carries on: the frame after the switch moves the pair as the joint
    // would have (within 2 %, as the first-frame comparison above).
    let v = world.linear_velocity(&0).unwrap();
    let w = kept.layout.world().unwrap().linear_velocity(&0).unwrap();
    assert!(
        (v - w).length() <= 0.02 * w.length(),
        "velocity {v:?} after the switch, {w:?} without it"
    );
    switched.frames(600);
    let g = gap(&switched);
    assert!((g - 100.0).abs() < 2.0, "settled at {g}");
}
